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
// sweep's 12-digit results); the rounding it does exactly can be done in double arithmetic
// for all but a vanishing set of values, which go to it:
//   |v| 10^s = q + c exactly, q the rounded product and c the rest, by an error-free product
//   (fma: for |s| <= 22, 10^s is exact in double; up to 44 by two exact factors), so the p-digit
//   integer nearest to |v| 10^s, s = p - 1 - E, is floor(q) + [frac(q) + c > 1/2], decided
//   exactly unless frac(q) + c is within kTieMargin of 1/2, where the rounding error of that
//   sum (~1e-16) could decide it: such values are left to std::to_chars, as are p > 15 (the
//   integer passes 2^53 / 10), the non-finite and |v| outside about [1e-30, 1e30]; zero is
//   "0" (or "-0") at every precision, written directly.
// The output is the same bytes: format_test holds it against printf's "%.{p}g" on every
// precision, over random doubles, exact ties and values next to them.

// 10^0 .. 10^22: each exact in double (5^22 < 2^53).
constexpr std::array<double, 23> kExactPowers = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                 1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                                 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxExactPower = 22;
constexpr int kMaxFastPrecision = 15;
// Nearer a tie than this (in units of the last kept digit) goes to std::to_chars: the sum
// frac(q) + c is in error by at most ~1e-16 (one rounding of a number below 2).
constexpr double kTieMargin = 1e-9;
// Scaled values at or above this are left to std::to_chars (2^63: an int64 holds the rest).
constexpr double kTruncationLimit = 9.2e18;

// a 10^s = q + c (c to within ~1e-16 |c|); nullopt for |s| beyond what two exact factors reach.
struct Scaled {
  double q, c;
};
// Inlined into each precision's copy (a call, out of line in the copies, was ~29 instructions
// of a number against ~10 inline).
[[gnu::always_inline]] inline std::optional<Scaled> scale_by_power_of_ten(double a, int s) {
  if (s >= 0 && s <= kMaxExactPower) {
    const double P = kExactPowers[s];
    const double q = a * P;
    return Scaled{q, std::fma(a, P, -q)};
  }
  if (s < 0 && s >= -kMaxExactPower) {
    const double D = kExactPowers[-s];
    const double q = a / D;
    return Scaled{q, std::fma(-q, D, a) / D};  // a - q D is exact for the rounded quotient q
  }
  if (s > kMaxExactPower && s <= 2 * kMaxExactPower) {
    const double P1 = kExactPowers[kMaxExactPower], P2 = kExactPowers[s - kMaxExactPower];
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
template <int p>
std::optional<Rounded> round_to_digits(double a) {
  // E = floor(log10 a) from the binary exponent (floor((e2 - 1) log10 2), 78913 / 2^18 being
  // log10 2 to 6 digits: exact for |e2| < 1000), then one compare with the nearest power of ten
  // (a double near 10^(E+1): a value within an ulp of it may get E one off, which the loop below
  // corrects)
  std::uint64_t bits = 0;
  std::memcpy(&bits, &a, sizeof a);
  const int e2 = static_cast<int>((bits >> 52) & 0x7ff) - 1022;  // a in [2^(e2-1), 2^e2)
  int E = ((e2 - 1) * 78913) >> 18;
  if (E + 1 >= -kMaxExactPower && E + 1 <= kMaxExactPower &&
      a >= (E + 1 >= 0 ? kExactPowers[E + 1] : 1.0 / kExactPowers[-(E + 1)]))
    ++E;
  const double lo = kExactPowers[p - 1], hi = kExactPowers[p];
  for (int attempt = 0; attempt < 3; ++attempt) {
    const std::optional<Scaled> sc = scale_by_power_of_ten(a, p - 1 - E);
    // q > 0 and below 2^63 (it is near 10^(p-1) <= 10^14 unless E is far off): floor(q) is
    // its truncation to an integer, two instructions against the library floor's ~18
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
    if (whole < lo) {
      --E;
      continue;
    }
    if (whole >= hi) {
      ++E;
      continue;
    }
    if (std::abs(fraction - 0.5) < kTieMargin) return std::nullopt;
    std::uint64_t digits = static_cast<std::uint64_t>(whole) + (fraction > 0.5 ? 1 : 0);
    if (digits == static_cast<std::uint64_t>(hi)) {  // 9.99...5 rounded up to 10.0...
      digits /= 10;
      ++E;
    }
    return Rounded{digits, E};
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
char* write_rounded(char* out, bool negative, const Rounded& r) {
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

// general(v, p) for finite v != 0 by the rounding above, or null where it leaves v to
// std::to_chars. One copy for each precision 1 ... kMaxFastPrecision: p a constant, the digits
// written are only those p needs and the layout's tests fold (~40 instructions fewer a 12-digit
// number than one copy for every p, callgrind).
template <int p>
char* write_fast(char* out, double v) {
  const std::optional<Rounded> r = round_to_digits<p>(std::abs(v));
  return r ? write_rounded<p>(out, std::signbit(v), *r) : nullptr;
}
using FastWriter = char* (*)(char*, double);
template <std::size_t... k>
constexpr std::array<FastWriter, sizeof...(k)> fast_writers(std::index_sequence<k...>) {
  return {&write_fast<static_cast<int>(k) + 1>...};
}
constexpr std::array<FastWriter, kMaxFastPrecision> kFastWriters =
    fast_writers(std::make_index_sequence<kMaxFastPrecision>{});

}  // namespace

char* write_general(char* first, double v, int precision) {
  precision = std::clamp(precision, 0, kMaxPrecision);
  const int p = std::max(precision, 1);
  if (p <= kMaxFastPrecision && std::isfinite(v)) {
    if (v == 0) {  // "0" or "-0" at any precision (a sweep's rows hold about one zero a row)
      if (std::signbit(v)) *first++ = '-';
      *first = '0';
      return first + 1;
    }
    if (char* end = kFastWriters[p - 1](first, v)) return end;
  }
  return std::to_chars(first, first + kMaxNumberChars, v, std::chars_format::general, precision)
      .ptr;
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
