// Parameters of a contact law as the user gives them (`--param NAME=VALUE`), and the
// description each law publishes of the ones it accepts.
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <string>
#include <string_view>

namespace ivv {

struct DerivedParameters;

// Named values [SI units as the law's ParameterSpec says]; absent names take their defaults.
using LawParameters = std::map<std::string, double, std::less<>>;

// One parameter of a built-in law: what `--param`, the JSON and the report show.
struct ParameterSpec {
  std::string_view name;     // as typed after --param
  std::string_view unit;     // SI unit, e.g. "s/m"
  std::string_view meaning;  // one line, with the default when it comes from the scene
  double default_value = std::numeric_limits<double>::quiet_NaN();  // NaN: from_scene
  double lower = 0.0;  // accepted closed range [lower, upper]
  double upper = std::numeric_limits<double>::infinity();
  bool lower_open = false;                                   // (lower, upper] when true
  double (*from_scene)(const DerivedParameters&) = nullptr;  // default taken from the scene
};

// The value of the parameter in `given`, else its default (from the scene when the spec says).
double parameter_value(const LawParameters& given, const ParameterSpec& spec,
                       const DerivedParameters& p);

}  // namespace ivv
