#include "app/cli_args.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "scene/input_error.h"
#include "scene/scene_values.h"
#include "solver/sweep/sweep.h"

namespace ivv {

double parse_number(const std::string& s, const std::string& field) {
  // strtod skips leading white space; a value with any is refused like trailing junk
  const bool blank_start = !s.empty() && std::isspace(static_cast<unsigned char>(s.front()));
  if (s.empty()) throw InputError(field, "an empty value is not a number");
  char* end = nullptr;
  errno = 0;
  const double v = blank_start ? 0.0 : std::strtod(s.c_str(), &end);
  const bool whole = !blank_start && end == s.c_str() + s.size() && end != s.c_str();
  // out of range is named as such, not "not a finite number" (as 1e-320 once was); a subnormal
  // (1e-320) is a number like any other, and the field's own range check judges it
  if (whole && errno == ERANGE && !(std::isfinite(v) && v != 0.0)) {
    throw InputError(field, "'" + s + "' is " +
                                (v != 0.0 ? "beyond the largest double, 1.8e308"
                                          : "below the smallest positive double, 4.9e-324"));
  }
  if (!whole || !std::isfinite(v)) throw InputError(field, "'" + s + "' is not a finite number");
  return v;
}

long parse_count(const std::string& s, const std::string& field, long lo, long hi) {
  std::ostringstream range;
  range << "must be an integer in [" << lo << ", " << hi << "], got '" << s << "'";
  std::size_t i = (!s.empty() && (s[0] == '+' || s[0] == '-')) ? 1 : 0;
  if (i == s.size()) throw InputError(field, range.str());
  for (std::size_t k = i; k < s.size(); ++k)
    if (!std::isdigit(static_cast<unsigned char>(s[k]))) throw InputError(field, range.str());
  long v = 0;
  try {
    v = std::stol(s);
  } catch (const std::exception&) {  // out of long's range
    throw InputError(field, range.str());
  }
  if (v < lo || v > hi) throw InputError(field, range.str());
  return v;
}

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep)) parts.push_back(item);
  if (!s.empty() && s.back() == sep) parts.emplace_back();
  return parts;
}

}  // namespace

std::vector<double> parse_grid(const std::string& text, const std::string& field, Spacing spacing) {
  const bool log = spacing == Spacing::logarithmic;
  const std::string syntax = "expected LO:HI:N (N >= 1 points) or a comma-separated list";
  if (text.find(':') != std::string::npos) {
    const auto parts = split(text, ':');
    if (parts.size() != 3) throw InputError(field, "'" + text + "': " + syntax);
    const double lo = parse_number(parts[0], field), hi = parse_number(parts[1], field);
    const double n = parse_number(parts[2], field);
    if (n < 1 || n != std::floor(n) || n > 1e6)
      throw InputError(field,
                       "point count N must be an integer in [1, 1e6] (got " + parts[2] + ")");
    if (hi < lo) throw InputError(field, "HI must not be below LO in '" + text + "'");
    if (log && !(lo > 0)) throw InputError(field, "a logarithmic grid (--log, log:) needs LO > 0");
    return log ? log_grid(lo, hi, static_cast<int>(n)) : linear_grid(lo, hi, static_cast<int>(n));
  }
  std::vector<double> values;
  for (const auto& p : split(text, ',')) values.push_back(parse_number(p, field));
  if (values.empty()) throw InputError(field, "empty list: " + syntax);
  return values;
}

SetAxisSpec parse_set_axis(const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set", "'" + item +
                                  "': expected KEY=LO:HI:N, KEY=log:LO:HI:N or KEY=a,b,c, e.g. "
                                  "structure.thickness=0.001:0.01:10");
  SetAxisSpec spec;
  spec.key = item.substr(0, eq);
  const std::string field = "--set " + spec.key;
  if (!find_scene_value(spec.key))
    throw InputError(field, "not a numeric scene value; accepted: " + scene_value_keys() +
                                " (v0 and zeta are --v0 and --zeta)");
  spec.range = item.substr(eq + 1);
  constexpr std::string_view log_prefix = "log:";
  if (spec.range.starts_with(log_prefix)) {
    spec.log = true;
    spec.range.erase(0, log_prefix.size());
    if (spec.range.find(':') == std::string::npos)
      throw InputError(field, "'log:' takes a range LO:HI:N, got '" + spec.range + "'");
  }
  spec.values = parse_grid(spec.range, field, spacing_of(spec.log));
  return spec;
}

std::map<std::string, double, std::less<>> parse_parameters(const std::vector<std::string>& items) {
  std::map<std::string, double, std::less<>> out;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--param", "'" + item + "': expected NAME=VALUE, e.g. mu=0.3");
    const std::string name = item.substr(0, eq);
    const double value = parse_number(item.substr(eq + 1), "--param " + name);
    if (!out.emplace(name, value).second) throw InputError("--param " + name, "given twice");
  }
  return out;
}

}  // namespace ivv
