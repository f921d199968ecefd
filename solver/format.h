// Numbers as text, one formatter for the whole of ivv.
//
// general(v, p): printf's "%.{p}g" (the C locale): p significant digits (p = 0 is taken as 1),
//   trailing zeros and a trailing point dropped, scientific notation ("1.5e-07") when the
//   decimal exponent is below -4 or at least p; "inf", "-inf", "nan", "-nan" for the
//   non-finite. The same bytes as std::snprintf("%.*g", p, v) and as an std::ostream with
//   precision p in its default float format (C++20 [charconv.to.chars]: std::to_chars with a
//   precision formats "as if by printf"), held by format_test at every precision over 8,000
//   values. With p = 17 every double reads back exactly (17 significant digits always round-trip,
//   IEEE 754 5.12.2).
// shortest(v): the fewest digits that read back as the same double (std::to_chars without a
//   precision; e.g. 0.1, not 0.10000000000000001), in the style "%g" would choose.
//
// Why std::to_chars: it formats from the binary value with Ryu (no locale, no multi-precision
// arithmetic), about 4x faster than glibc's printf at 12-17 digits; a sweep prints 12 numbers a
// point and was bound by printf (callgrind: glibc's __printf_fp_l and hack_digit were 14 % of
// a 300 x 300 sweep's instructions). general() with p <= 15 goes faster still: it rounds in
// double arithmetic, from one rounded product where that decides it and else with an exact
// residual, in one copy for each precision, and leaves only values next to a rounding tie (and
// the non-finite, |v| outside ~[1e-30, 1e30]) to std::to_chars (format.cc; ~140 against ~715
// instructions a 12-digit number of a sweep's rows, callgrind; zero is written directly). The
// append_* forms write into a caller's buffer and allocate nothing once its capacity suffices.
#pragma once

#include <cstddef>
#include <string>

namespace ivv {

// Characters the longest double takes in either format: "-1.2345678901234567e-308" is 24;
// the rest is headroom for any precision up to kMaxPrecision.
inline constexpr int kMaxPrecision = 17;  // beyond 17 digits a double has nothing more to say
inline constexpr std::size_t kMaxNumberChars = 32;

// Writes general(v, precision) at `first` (room for kMaxNumberChars) and returns the end.
// precision is clamped to [0, kMaxPrecision].
char* write_general(char* first, double v, int precision);
// The same with the precision fixed where it is called, p in [0, kMaxPrecision] (each has its
// copy in format.cc): no dispatch on the precision (~30 instructions of a number, callgrind).
template <int p>
char* write_general(char* first, double v);
// Writes shortest(v) at `first` (room for kMaxNumberChars) and returns the end.
char* write_shortest(char* first, double v);
// Characters the longest integer takes: "-9223372036854775808" is 20.
inline constexpr std::size_t kMaxIntegerChars = 20;
// Writes v in decimal at `first` (room for kMaxIntegerChars) and returns the end.
char* write_integer(char* first, long long v);

void append_general(std::string& out, double v, int precision);
void append_shortest(std::string& out, double v);
void append_integer(std::string& out, long long v);

// general(v, precision) as a string: the fmt(double) of messages and reports (an std::ostream's
// default of 6 digits).
std::string fmt(double v, int precision = 6);

}  // namespace ivv
