#include "solver/format.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <utility>

namespace ivv {
namespace {

// ---- general(v, p) for p <= 15 without Ryu's printf tables ---------------------------------
//
// std::to_chars with a precision (Ryu printf) costs ~690 instructions a number (callgrind, the
// sweep's 12-digit results); the rounding it does exactly can be done in double arithmetic for
// all but a vanishing set of values, in two tiers:
//  1. One product. With s = p - 1 - E (E the decimal exponent of |v|'s leading digit) and
//     t = |v| 10^s, q = fl(|v| fl(10^s)) = t (1 + d), |d| <= 2u + u^2 (u = 2^-53: the power and
//     the product each rounded once), so |q - t| < q 2^-51. q - floor(q) is exact (q < 2^53), so
//     when that fraction is further than q 2^-51 from 0, 1/2 and 1, floor(t) = floor(q) and
//     t rounds to the integer on the fraction's side of 1/2: p <= kMaxProductPrecision digits,
//     |v| in [2^-100, 2^100). At p = 12 the band is ~2e-4 of the last digit either side of those
//     three points, so about 1 number in 1,000 goes on (18 of 17,246 in a 60 x 30 paper map's
//     rows; ~140 instructions a 12-digit number there through write_general<12>, against ~195
//     for tier 2 alone through write_general(v, 12), callgrind).
//  2. An error-free product: |v| 10^s = q + c exactly (fma: for |s| <= 22, 10^s is exact in
//     double; up to 44 by two exact factors), so the p-digit integer nearest to |v| 10^s is
//     floor(q) + [frac(q) + c > 1/2], decided exactly unless frac(q) + c is within kTieMargin of
//     1/2, where the rounding error of that sum (~1e-16) could decide it: such values are left
//     to std::to_chars, as are p > 15 (the integer passes 2^53 / 10), the non-finite and |v|
//     outside about [1e-30, 1e30]; zero is "0" (or "-0") at every precision, written directly.
// The output is the same bytes: format_test holds it against printf's "%.{p}g" on every
// precision, over random doubles, exact ties, values next to them and values on either side of
// tier 1's band.

// 10^k for k = kMinPower ... kMaxPower, each the double nearest to it (a decimal literal is
// rounded to nearest); 10^0 ... 10^22 are exact (5^22 < 2^53).
constexpr int kMinPower = -32, kMaxPower = 46;
constexpr std::array<double, kMaxPower - kMinPower + 1> kPowers = {
    1e-32, 1e-31, 1e-30, 1e-29, 1e-28, 1e-27, 1e-26, 1e-25, 1e-24, 1e-23, 1e-22, 1e-21,
    1e-20, 1e-19, 1e-18, 1e-17, 1e-16, 1e-15, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-9,
    1e-8,  1e-7,  1e-6,  1e-5,  1e-4,  1e-3,  1e-2,  1e-1,  1e0,   1e1,   1e2,   1e3,
    1e4,   1e5,   1e6,   1e7,   1e8,   1e9,   1e10,  1e11,  1e12,  1e13,  1e14,  1e15,
    1e16,  1e17,  1e18,  1e19,  1e20,  1e21,  1e22,  1e23,  1e24,  1e25,  1e26,  1e27,
    1e28,  1e29,  1e30,  1e31,  1e32,  1e33,  1e34,  1e35,  1e36,  1e37,  1e38,  1e39,
    1e40,  1e41,  1e42,  1e43,  1e44,  1e45,  1e46};
constexpr double power_of_ten(int k) {
  return kPowers[static_cast<std::size_t>(k - kMinPower)];
}
constexpr int kMaxExactPower = 22;
constexpr int kMaxFastPrecision = 15;
// Tier 1's products: |q - t| < q 2^-51 (above).
constexpr double kProductError = 0x1p-51;
// Above 14 digits that band is wider than a quarter of the last digit (q 2^-51 > 0.25 for q
// near 10^15): tier 1 would hardly ever decide.
constexpr int kMaxProductPrecision = 14;
// Tier 1 takes |v| in [2^-kProductRange, 2^kProductRange): E in [-31, 30] and s in [-31, 46]
// stay inside kPowers (with the one step of E a retry may add).
constexpr int kProductRange = 100;
// Nearer a tie than this (in units of the last kept digit) goes to std::to_chars: the sum
// frac(q) + c is in error by at most ~1e-16 (one rounding of a number below 2).
constexpr double kTieMargin = 1e-9;
// Scaled values at or above this are left to std::to_chars (2^63: an int64 holds the rest).
constexpr double kTruncationLimit = 9.2e18;

static_assert(power_of_ten(0) == 1 && power_of_ten(22) == 1e22 && power_of_ten(-32) == 1e-32 &&
              power_of_ten(46) == 1e46);

// a 10^s = q + c (c to within ~1e-16 |c|); nullopt for |s| beyond what two exact factors reach.
struct Scaled {
  double q, c;
};
std::optional<Scaled> scale_by_power_of_ten(double a, int s) {
  if (s >= 0 && s <= kMaxExactPower) {
    const double P = power_of_ten(s);
    const double q = a * P;
    return Scaled{q, std::fma(a, P, -q)};
  }
  if (s < 0 && s >= -kMaxExactPower) {
    const double D = power_of_ten(-s);
    const double q = a / D;
    return Scaled{q, std::fma(-q, D, a) / D};  // a - q D is exact for the rounded quotient q
  }
  if (s > kMaxExactPower && s <= 2 * kMaxExactPower) {
    const double P1 = power_of_ten(kMaxExactPower), P2 = power_of_ten(s - kMaxExactPower);
    const double q1 = a * P1, r1 = std::fma(a, P1, -q1);
    const double q = q1 * P2;
    return Scaled{q, std::fma(q1, P2, -q) + r1 * P2};
  }
  return std::nullopt;
}

// a > 0 rounded to p significant digits: digits in [10^(p-1), 10^p), a ~ digits 10^(E - p + 1).
struct Rounded {
  std::uint64_t digits;
  int exponent;  // E: the decimal exponent of the leading digit
};

// floor(log10 a) for a > 0 with biased binary exponent `biased` (a normal double): from the
// binary exponent, floor((e2 - 1) log10 2) (78913 / 2^18 is log10 2 to 6 digits: exact for
// |e2| < 1000), then one compare with the nearest double to the next power of ten (a value
// within an ulp of that power may get E one off, which the callers' retries correct). Needs
// E + 1 inside kPowers.
int decimal_exponent(double a, int biased) {
  const int e2 = biased - 1022;  // a in [2^(e2-1), 2^e2)
  const int E = ((e2 - 1) * 78913) >> 18;
  return a >= power_of_ten(E + 1) ? E + 1 : E;
}

// The tiers' two shared steps. exponent_off: the correction of E that moves the scaled value's
// integer part `whole` into [lo, hi) = [10^(p-1), 10^p) on the retry (-1 below, +1 at or above,
// 0 inside). rounded: `whole` rounded up when `up`, 9.99...5 carried to 10.0... (E + 1).
inline int exponent_off(double whole, double lo, double hi) {
  return whole < lo ? -1 : (whole >= hi ? 1 : 0);
}
inline Rounded rounded(std::uint64_t whole, bool up, double hi, int E) {
  std::uint64_t digits = whole + (up ? 1 : 0);
  if (digits == static_cast<std::uint64_t>(hi)) {
    digits /= 10;
    ++E;
  }
  return Rounded{digits, E};
}

// Tier 1 (above): a in [2^-kProductRange, 2^kProductRange), E its decimal_exponent; nullopt
// where the product's band leaves the rounding open.
template <int p>
std::optional<Rounded> round_by_product(double a, int E) {
  constexpr double lo = power_of_ten(p - 1), hi = power_of_ten(p);
  for (int attempt = 0; attempt < 2; ++attempt) {
    // q < 10^(p+1): E is floor(log10 a), or one off where a is within an ulp of a power, and a
    // retry moves q towards [lo, hi): its truncation to an int64 is floor(q), two instructions
    // against the library floor's ~18
    const double q = a * power_of_ten(p - 1 - E);
    const std::int64_t truncated = static_cast<std::int64_t>(q);
    const double whole = static_cast<double>(truncated);
    if (const int off = exponent_off(whole, lo, hi)) {
      E += off;
      continue;
    }
    const double fraction = q - whole;  // exact
    const double bound = q * kProductError;
    const double from_half = std::abs(fraction - 0.5);
    if (!(from_half > bound && from_half < 0.5 - bound)) return std::nullopt;
    return rounded(static_cast<std::uint64_t>(truncated), fraction > 0.5, hi, E);
  }
  return std::nullopt;
}

// Tier 2 (above): a and E as for tier 1; nullopt where it leaves a to std::to_chars.
template <int p>
std::optional<Rounded> round_exactly(double a, int E) {
  const double lo = power_of_ten(p - 1), hi = power_of_ten(p);
  for (int attempt = 0; attempt < 3; ++attempt) {
    const std::optional<Scaled> sc = scale_by_power_of_ten(a, p - 1 - E);
    // q > 0 and below 2^63 (it is near 10^(p-1) <= 10^14 unless E is far off)
    if (!sc || !(sc->q < kTruncationLimit)) return std::nullopt;
    double whole = static_cast<double>(static_cast<std::int64_t>(sc->q));
    double fraction = (sc->q - whole) + sc->c;  // q - floor(q) is exact
    if (fraction < 0) {
      whole -= 1;
      fraction += 1;
    } else if (fraction >= 1) {
      whole += 1;
      fraction -= 1;
    }
    if (const int off = exponent_off(whole, lo, hi)) {
      E += off;
      continue;
    }
    if (std::abs(fraction - 0.5) < kTieMargin) return std::nullopt;
    return rounded(static_cast<std::uint64_t>(whole), fraction > 0.5, hi, E);
  }
  return std::nullopt;
}

// Decimal digits two at a time.
constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";
// The 8 decimal digits of n < 10^8 at d: in 32-bit arithmetic (a 64-bit n % 100 a pair cost
// ~20 instructions, a third of a 12-digit number's formatting).
void write_eight_digits(char* d, std::uint32_t n) {
  const std::uint32_t high = n / 10000, low = n % 10000;
  std::memcpy(d, kDigitPairs + 2 * (high / 100), 2);
  std::memcpy(d + 2, kDigitPairs + 2 * (high % 100), 2);
  std::memcpy(d + 4, kDigitPairs + 2 * (low / 100), 2);
  std::memcpy(d + 6, kDigitPairs + 2 * (low % 100), 2);
}
// The 4 decimal digits of n < 10^4 at d.
void write_four_digits(char* d, std::uint32_t n) {
  std::memcpy(d, kDigitPairs + 2 * (n / 100), 2);
  std::memcpy(d + 2, kDigitPairs + 2 * (n % 100), 2);
}
// The decimal digits of n < 10^p as the last p of d[0, 16) (the characters before them, up to
// a multiple of four, are leading zeros; the rest before are left as they fall): only the groups
// of four or eight digits that hold them are written (all sixteen were 8 pairs, ~60 instructions a
// 12-digit number; the 4 + 8 of p = 12 are 6).
template <int p>
void write_last_digits(char* d, std::uint64_t n) {
  static_assert(p >= 1 && p <= 16);
  constexpr std::uint64_t kTenToEight = 100000000;
  if constexpr (p <= 4) {
    write_four_digits(d + 12, static_cast<std::uint32_t>(n));
  } else if constexpr (p <= 8) {
    write_eight_digits(d + 8, static_cast<std::uint32_t>(n));
  } else {
    const auto high = static_cast<std::uint32_t>(n / kTenToEight);
    if constexpr (p <= 12)
      write_four_digits(d + 4, high);
    else
      write_eight_digits(d, high);
    write_eight_digits(d + 8, static_cast<std::uint32_t>(n % kTenToEight));
  }
}

// printf's "%.{p}g" of a rounded value: trailing zeros dropped, scientific when E < -4 or
// E >= p (exponent of at least two digits). The digits are copied sixteen bytes at a time
// whatever their count (the library's copy of a few bytes was a call to memmove a run): `out` has
// room for kMaxNumberChars (32), and the widest case, fixed with E = p - 2 = 13, ends its last
// copy at out + 32; the characters past the number are left as they fall.
template <int p>
[[gnu::always_inline]] inline char* write_rounded(char* out, bool negative, const Rounded& r) {
  static_assert(kMaxFastPrecision <= 15 && kMaxNumberChars >= 32,
                "sixteen-byte copies of at most 15 digits stay inside the caller's 32 characters");
  char digits[32];  // the sixteen digits, then '0's: a copy of 16 from any of the first p is inside
  write_last_digits<p>(digits, r.digits);
  std::memset(digits + 16, '0', 16);
  const char* d = digits + 16 - p;
  int k = p;
  while (k > 1 && d[k - 1] == '0') --k;
  const int E = r.exponent;
  if (negative) *out++ = '-';
  if (E < -4 || E >= p) {
    *out++ = d[0];
    if (k > 1) {
      *out++ = '.';
      std::memcpy(out, d + 1, 16);
      out += k - 1;
    }
    *out++ = 'e';
    *out++ = E < 0 ? '-' : '+';
    int m = E < 0 ? -E : E;  // at least two digits: e-05, e+12, e-308
    if (m >= 100) {
      *out++ = static_cast<char>('0' + m / 100);
      m %= 100;
    }
    std::memcpy(out, kDigitPairs + 2 * m, 2);
    return out + 2;
  }
  if (E >= 0) {  // d[k..p) are '0': the integer part is the first E + 1 digits as they stand
    std::memcpy(out, d, 16);
    out += E + 1;
    if (k <= E + 1) return out;
    *out++ = '.';
    std::memcpy(out, d + E + 1, 16);
    return out + (k - E - 1);
  }
  std::memcpy(out, "0.000", 5);  // "0." and the -E - 1 <= 3 zeros after the point
  out += 2 - E - 1;
  std::memcpy(out, d, 16);
  return out + k;
}

// general(v, p) where tier 1 leaves it: tier 2, zero, or std::to_chars. Out of line, and reached
// by a jump from write_fast: the common path then makes no call and keeps no register across one
// (its saves and restores were ~14 instructions a number, callgrind).
template <int p>
[[gnu::noinline]] char* write_rare(char* out, double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof v);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  const bool negative = (bits >> 63) != 0;
  if (static_cast<unsigned>(biased - (1023 - kProductRange)) < 2u * kProductRange) {
    const double a = std::abs(v);
    if (const std::optional<Rounded> r = round_exactly<p>(a, decimal_exponent(a, biased)))
      return write_rounded<p>(out, negative, *r);
  } else if (v == 0) {  // "0" or "-0" at any precision
    if (negative) *out++ = '-';
    *out = '0';
    return out + 1;
  }
  return std::to_chars(out, out + kMaxNumberChars, v, std::chars_format::general, p).ptr;
}

// general(v, p) for p <= kMaxFastPrecision: tier 1, else write_rare. One copy for each
// precision: p a constant, the digits written are only those p needs and the layout's tests fold
// (~40 instructions fewer a 12-digit number than one copy for every p, callgrind).
template <int p>
char* write_fast(char* out, double v) {
  if constexpr (p <= kMaxProductPrecision) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &v, sizeof v);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    // |v| in [2^-kProductRange, 2^kProductRange): one unsigned compare
    if (static_cast<unsigned>(biased - (1023 - kProductRange)) < 2u * kProductRange) {
      const double a = std::abs(v);
      if (const std::optional<Rounded> r = round_by_product<p>(a, decimal_exponent(a, biased)))
        return write_rounded<p>(out, (bits >> 63) != 0, *r);
    }
  }
  return write_rare<p>(out, v);
}

}  // namespace

template <int p>
char* write_general(char* first, double v) {
  static_assert(p >= 0 && p <= kMaxPrecision);
  if constexpr (p <= kMaxFastPrecision) return write_fast<std::max(p, 1)>(first, v);
  return std::to_chars(first, first + kMaxNumberChars, v, std::chars_format::general, p).ptr;
}

namespace {
using GeneralWriter = char* (*)(char*, double);
template <std::size_t... p>
constexpr std::array<GeneralWriter, sizeof...(p)> general_writers(std::index_sequence<p...>) {
  return {&write_general<static_cast<int>(p)>...};
}
constexpr std::array<GeneralWriter, kMaxPrecision + 1> kGeneralWriters =
    general_writers(std::make_index_sequence<kMaxPrecision + 1>{});
}  // namespace

// Each precision's copy, for callers that name theirs.
template char* write_general<0>(char*, double);
template char* write_general<1>(char*, double);
template char* write_general<2>(char*, double);
template char* write_general<3>(char*, double);
template char* write_general<4>(char*, double);
template char* write_general<5>(char*, double);
template char* write_general<6>(char*, double);
template char* write_general<7>(char*, double);
template char* write_general<8>(char*, double);
template char* write_general<9>(char*, double);
template char* write_general<10>(char*, double);
template char* write_general<11>(char*, double);
template char* write_general<12>(char*, double);
template char* write_general<13>(char*, double);
template char* write_general<14>(char*, double);
template char* write_general<15>(char*, double);
template char* write_general<16>(char*, double);
template char* write_general<17>(char*, double);

char* write_general(char* first, double v, int precision) {
  return kGeneralWriters[static_cast<std::size_t>(std::clamp(precision, 0, kMaxPrecision))](first,
                                                                                            v);
}

char* write_shortest(char* first, double v) {
  return std::to_chars(first, first + kMaxNumberChars, v).ptr;
}

void append_general(std::string& out, double v, int precision) {
  char buf[kMaxNumberChars];
  out.append(buf, write_general(buf, v, precision));
}

void append_shortest(std::string& out, double v) {
  char buf[kMaxNumberChars];
  out.append(buf, write_shortest(buf, v));
}

char* write_integer(char* first, long long v) {
  return std::to_chars(first, first + kMaxIntegerChars, v).ptr;
}

void append_integer(std::string& out, long long v) {
  char buf[kMaxIntegerChars];
  out.append(buf, write_integer(buf, v));
}

std::string fmt(double v, int precision) {
  std::string s;
  append_general(s, v, precision);
  return s;
}

}  // namespace ivv
