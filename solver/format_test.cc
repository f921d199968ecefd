// solver/format.h: the same bytes as printf's "%.{p}g" and an std::ostream at precision p, and
// shortest forms that read back exactly.
#include "solver/format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

namespace ivv {
namespace {

// Doubles over the whole exponent range (subnormals to the largest), both signs, plus the
// values whose formatting has edges: zeros, integers, round decimals, ties at 12 and 17 digits,
// the limits, the non-finite.
std::vector<double> samples() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  std::vector<double> v = {0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           0.1,
                           1.0 / 3.0,
                           2.0 / 3.0,
                           0.5,
                           1e-4,
                           9.9999999999999e-5,
                           1e-5,
                           123456789012.0,
                           999999999999.5,
                           1e12,
                           1e17,
                           1e23,
                           0.30000000000000004,
                           std::numeric_limits<double>::min(),
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::epsilon(),
                           inf,
                           -inf,
                           std::numeric_limits<double>::quiet_NaN(),
                           -std::numeric_limits<double>::quiet_NaN()};
  std::mt19937_64 gen(20);
  std::uniform_int_distribution<std::uint64_t> bits;
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> exponent(-12, 12);
  for (int i = 0; i < 4000; ++i) {
    // any bit pattern: every exponent, subnormals, NaN payloads
    const std::uint64_t b = bits(gen);
    double x;
    static_assert(sizeof x == sizeof b);
    std::memcpy(&x, &b, sizeof x);
    v.push_back(x);
    // and the magnitudes a sweep prints
    v.push_back((i % 2 ? -1 : 1) * mantissa(gen) * std::pow(10.0, exponent(gen)));
  }
  return v;
}

std::string printf_g(double x, int precision) {
  char buf[64];
  const int n = std::snprintf(buf, sizeof buf, "%.*g", precision, x);
  return std::string(buf, n);
}

// append_general against printf's %.*g for every value at every precision; the first ten
// mismatches are reported.
int mismatches_against_printf(const std::vector<double>& values) {
  int mismatches = 0;
  for (double x : values)
    for (int p = 0; p <= kMaxPrecision; ++p) {
      std::string s;
      append_general(s, x, p);
      if (s != printf_g(x, p) && ++mismatches <= 10)
        ADD_FAILURE() << "precision " << p << ": " << s << " vs printf " << printf_g(x, p);
    }
  return mismatches;
}

TEST(Format, GeneralIsPrintfGAtEveryPrecision) {
  EXPECT_EQ(mismatches_against_printf(samples()), 0);
}

// write_general's fast path (p <= 15, format.cc) decides the rounding in double arithmetic and
// hands values within 1e-9 of a tie to std::to_chars: exact ties (k + 1/2 at p digits, each
// representable: 2.5, 123456789012.5), their neighbours an ulp either side, values that round
// up to the next power of ten (9.9999999999995 at 12 digits), and the range edges of its scaling
// (|v| near 1e-30 and 1e30, where it stops), against printf at every precision. 20,000 random
// magnitudes of each decade a sweep prints (1e-40 to 1e40) are held the same way.
TEST(Format, FastRoundingAgreesWithPrintfAtTiesAndEdges) {
  std::vector<double> v;
  std::mt19937_64 gen(32);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> exponent(-40, 40);
  std::uniform_int_distribution<int> shift(-8, 8);
  for (int i = 0; i < 20000; ++i) {
    const double x = mantissa(gen) * std::pow(10.0, exponent(gen));
    v.push_back(i % 2 ? -x : x);
  }
  for (int p = 1; p <= 15; ++p) {
    for (int i = 0; i < 200; ++i) {
      const double tie =
          (std::floor(mantissa(gen) * std::pow(10.0, p - 1)) + 0.5) * std::pow(10.0, shift(gen));
      for (double x : {tie, std::nextafter(tie, 0.0), std::nextafter(tie, 1e300)}) v.push_back(x);
    }
    const double below_power = 10.0 - 5.0 * std::pow(10.0, -p);  // rounds up to 10 at p digits
    for (double x : {below_power, std::nextafter(below_power, 0.0), 0.5, 2.5, 123456789012.5})
      v.push_back(x);
  }
  for (double edge : {1e-30, 1e-29, 1e-33, 1e-34, 1e30, 1e31, 1e36, 1e37})
    for (double x : {edge, std::nextafter(edge, 0.0), std::nextafter(edge, 1e300)}) v.push_back(x);
  EXPECT_EQ(mismatches_against_printf(v), 0);
}

// Tier 1 of write_general (format.cc) decides the rounding from one rounded product q when its
// fraction is further than q 2^-51 (2 to 4 ulps of q) from 0, 1/2 and 1, and hands the rest on.
// Values a few ulps either side of that band, at every precision it serves (1 to 14): walks of
// 1 to 48 ulps up and down from exact ties k + 1/2 (the band around 1/2), from p-digit decimals
// (the band around 0 and 1: their doubles lie within an ulp of the decimal) and from powers of
// ten 10^E for E in [-34, 34] (the decimal exponent estimated from the binary one, and one
// retry, at the edges of a decade and of tier 1's range 2^-100 ... 2^100), against printf.
TEST(Format, ProductRoundingAgreesWithPrintfAcrossItsBand) {
  constexpr int kWalk = 48;  // ulps: the band is at most 4 ulps of q, q within 2 ulps of v 10^s
  std::vector<double> starts;
  std::mt19937_64 gen(51);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0);
  std::uniform_int_distribution<int> shift(-30, 16);
  for (int p = 1; p <= 14; ++p)
    for (int i = 0; i < 40; ++i) {
      const double integer = std::floor(mantissa(gen) * std::pow(10.0, p - 1));
      const double scale = std::pow(10.0, shift(gen));
      starts.push_back((integer + 0.5) * scale);
      starts.push_back(integer * scale);
    }
  for (int e = -34; e <= 34; ++e) starts.push_back(std::pow(10.0, e));
  for (double x : {0x1p-100, 0x1p100}) starts.push_back(x);
  std::vector<double> v;
  for (double start : starts) {
    double up = start, down = start;
    for (int k = 0; k <= kWalk; ++k) {
      v.push_back(up);
      v.push_back(-down);
      up = std::nextafter(up, 1e300);
      down = std::nextafter(down, 0.0);
    }
  }
  EXPECT_EQ(mismatches_against_printf(v), 0);
}

template <int p>
int fixed_precision_mismatches(const std::vector<double>& values) {
  int mismatches = 0;
  for (double x : values) {
    char text[kMaxNumberChars];
    const std::string fixed(text, write_general<p>(text, x));
    if (fixed != printf_g(x, p) && ++mismatches <= 10)
      ADD_FAILURE() << "precision " << p << ": " << fixed << " vs printf " << printf_g(x, p);
  }
  return mismatches;
}

template <std::size_t... p>
int fixed_precision_mismatches(const std::vector<double>& values, std::index_sequence<p...>) {
  return (fixed_precision_mismatches<static_cast<int>(p)>(values) + ...);
}

// write_general<p>, the copy a caller names (the sweep's rows: 12), against printf at every p.
TEST(Format, FixedPrecisionIsPrintfG) {
  EXPECT_EQ(fixed_precision_mismatches(samples(), std::make_index_sequence<kMaxPrecision + 1>{}),
            0);
}

TEST(Format, FmtIsAnOstreamAtItsPrecision) {
  for (double x : samples()) {
    if (std::isnan(x)) continue;  // an ostream prints a NaN's sign as printf does; not its job
    for (int p : {3, 6, 12}) {
      std::ostringstream os;
      os.precision(p);
      os << x;
      EXPECT_EQ(fmt(x, p), os.str()) << p;
    }
    std::ostringstream os;
    os << x;
    EXPECT_EQ(fmt(x), os.str());
  }
}

TEST(Format, SeventeenDigitsAndShortestReadBackExactly) {
  for (double x : samples()) {
    if (!std::isfinite(x)) continue;
    std::string g, s;
    append_general(g, x, 17);
    append_shortest(s, x);
    EXPECT_EQ(std::strtod(g.c_str(), nullptr), x) << g;
    EXPECT_EQ(std::strtod(s.c_str(), nullptr), x) << s;
    EXPECT_LE(s.size(), g.size()) << s << " vs " << g;
  }
  std::string s;
  append_shortest(s, 0.1);
  EXPECT_EQ(s, "0.1");
  s.clear();
  append_general(s, 0.1, 17);
  EXPECT_EQ(s, "0.10000000000000001");
}

TEST(Format, PrecisionOutsideZeroToSeventeenIsClamped) {
  EXPECT_EQ(fmt(1.0 / 3.0, -5), printf_g(1.0 / 3.0, 0));
  EXPECT_EQ(fmt(1.0 / 3.0, 40), printf_g(1.0 / 3.0, 17));
}

TEST(Format, Integers) {
  std::string s;
  append_integer(s, 0);
  s += ',';
  append_integer(s, -42);
  s += ',';
  append_integer(s, std::numeric_limits<long long>::min());
  EXPECT_EQ(s, "0,-42,-9223372036854775808");
}

TEST(Format, AppendingWithinCapacityDoesNotReallocate) {
  std::string s;
  s.reserve(256);
  const char* data = s.data();
  for (int i = 0; i < 5; ++i) append_general(s, -1.2345678901234567e-308, 17);
  EXPECT_EQ(s.data(), data);
  EXPECT_EQ(s.size(), 5 * 24u);
}

}  // namespace
}  // namespace ivv
