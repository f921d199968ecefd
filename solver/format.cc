#include "solver/format.h"

#include <algorithm>
#include <charconv>

namespace ivv {

char* write_general(char* first, double v, int precision) {
  precision = std::clamp(precision, 0, kMaxPrecision);
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

void append_integer(std::string& out, long long v) {
  char buf[24];  // "-9223372036854775808" is 20
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

std::string fmt(double v, int precision) {
  std::string s;
  append_general(s, v, precision);
  return s;
}

}  // namespace ivv
