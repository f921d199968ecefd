// Parsing of the command line's values: numbers, counts, "LO:HI:N" ranges and "a,b,c" lists.
// Every numeric flag goes through these, so an empty value, trailing junk, a non-finite
// number or an integer out of range is one InputError naming the flag (exit 2).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ivv {

// The whole of `text` as one finite double (std::stod syntax, no leading or trailing junk).
double parse_number(const std::string& text, const std::string& field);

// The whole of `text` as an integer in [lo, hi] (decimal digits, optional sign).
long parse_count(const std::string& text, const std::string& field, long lo, long hi);

// How a range LO:HI:N is spaced (--log, or a `log:` prefix, asks for logarithmic).
enum class Spacing { linear, logarithmic };
inline Spacing spacing_of(bool log_flag) {
  return log_flag ? Spacing::logarithmic : Spacing::linear;
}

// "LO:HI:N" (n points, inclusive, spaced as `spacing`) or a comma-separated list (taken as
// given). Throws InputError naming `field` with the accepted syntax.
std::vector<double> parse_grid(const std::string& text, const std::string& field,
                               Spacing spacing = Spacing::linear);

// One `--set KEY=RANGE` of `ivv sweep`: a scene value (scene/scene_values.h) varied over RANGE,
// "LO:HI:N" (linear, decimal: solver/sweep/sweep_grid.h), "log:LO:HI:N" (logarithmic) or "a,b,c".
struct SetAxisSpec {
  std::string key;    // e.g. "structure.thickness"
  std::string range;  // as typed, without "log:"
  bool log = false;
  std::vector<double> values;
};
// Throws InputError("--set", ...) for an item without KEY=, InputError("--set KEY", ...) for an
// unknown key (listing the accepted ones) or a bad range.
SetAxisSpec parse_set_axis(const std::string& item);

// "NAME=VALUE" items of --param into a map; throws InputError("--param", ...) for a malformed
// item, a value that is not a finite number, or a name given twice.
std::map<std::string, double, std::less<>> parse_parameters(const std::vector<std::string>& items);

}  // namespace ivv
