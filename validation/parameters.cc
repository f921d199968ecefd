#include "validation/parameters.h"

#include <algorithm>
#include <limits>

#include "scene/input_error.h"

namespace ivv::validation {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct SceneParameter {
  const char* name;
  const char* unit;
};
constexpr SceneParameter kSceneParameters[] = {
    {"mass", "kg"},
    {"radius", "m"},
    {"impactor_youngs_modulus", "Pa"},
    {"target_youngs_modulus", "Pa"},
    {"yield_strength", "Pa"},
    {"c", "N s/m"},
    {"zeta", "-"},
};

const ParameterSpec* law_spec(const SimulationRequest& r, const std::string& name) {
  if (r.law == LawKind::expression) return nullptr;
  for (const auto& s : law_info(r.law).parameters)
    if (s.name == name) return &s;
  return nullptr;
}

std::string names_of(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& n : v) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// The scene's derived parameters, or InputError naming the parameter when the scene is invalid.
DerivedParameters derived_of(const Scene& scene) {
  validate(scene);
  return derive(scene);
}

}  // namespace

std::vector<std::string> fittable_parameters(const SimulationRequest& r) {
  std::vector<std::string> names;
  for (const auto& p : kSceneParameters) names.emplace_back(p.name);
  if (r.law == LawKind::expression) {
    for (const auto& [name, value] : r.parameters) names.push_back(name);
  } else {
    for (const auto& s : law_info(r.law).parameters) names.emplace_back(s.name);
  }
  return names;
}

ParameterInfo parameter_info(const SimulationRequest& r, const std::string& name) {
  for (const auto& p : kSceneParameters)
    if (name == p.name) return {p.name, p.unit, 0.0, kInf, true};
  if (const ParameterSpec* s = law_spec(r, name))
    return {name, std::string(s->unit), std::max(0.0, s->lower), s->upper, true};
  if (r.law == LawKind::expression && r.parameters.count(name)) return {name, "", 0.0, kInf, true};
  throw InputError("--fit", "unknown parameter '" + name + "' for this scene and law; fittable: " +
                                names_of(fittable_parameters(r)));
}

double parameter_value(const SimulationRequest& r, const std::string& name) {
  const Scene& s = r.scene;
  if (name == "mass") return s.mass;
  if (name == "radius") return s.radius;
  if (name == "impactor_youngs_modulus") return s.impactor_youngs_modulus;
  if (name == "target_youngs_modulus") return s.target_youngs_modulus;
  if (name == "yield_strength") {
    if (!s.yield_strength)
      throw InputError("--fit",
                       "yield_strength has no start value: the scene gives none "
                       "(set target.yield_strength)");
    return *s.yield_strength;
  }
  if (name == "c" || name == "zeta") {
    if (s.damping.kind == Damping::Kind::none)
      throw InputError("--fit", name +
                                    " has no start value: the scene has no dashpot (give it a "
                                    "[damping] with zeta or c to start from)");
    const DerivedParameters p = derived_of(s);
    return name == "c" ? p.c : p.zeta;
  }
  if (const ParameterSpec* spec = law_spec(r, name))
    return ivv::parameter_value(r.parameters, *spec, derived_of(s));
  if (auto it = r.parameters.find(name); it != r.parameters.end()) return it->second;
  parameter_info(r, name);  // throws naming the fittable parameters
  return 0.0;
}

void set_parameter(SimulationRequest& r, const std::string& name, double value) {
  Scene& s = r.scene;
  if (name == "mass")
    s.mass = value;
  else if (name == "radius")
    s.radius = value;
  else if (name == "impactor_youngs_modulus")
    s.impactor_youngs_modulus = value;
  else if (name == "target_youngs_modulus")
    s.target_youngs_modulus = value;
  else if (name == "yield_strength")
    s.yield_strength = value;
  else if (name == "c")
    s.damping = Damping::coefficient(value);
  else if (name == "zeta")
    s.damping = Damping::ratio(value);
  else
    r.parameters[name] = value;
}

void check_fit_names(const SimulationRequest& r, const std::vector<std::string>& names) {
  if (names.empty()) throw InputError("--fit", "name at least one parameter to fit");
  for (std::size_t i = 0; i < names.size(); ++i) {
    parameter_info(r, names[i]);
    if (std::find(names.begin(), names.begin() + static_cast<long>(i), names[i]) !=
        names.begin() + static_cast<long>(i))
      throw InputError("--fit", "parameter '" + names[i] + "' is named twice");
  }
  const bool c = std::find(names.begin(), names.end(), "c") != names.end();
  const bool zeta = std::find(names.begin(), names.end(), "zeta") != names.end();
  if (c && zeta)
    throw InputError("--fit", "c and zeta are the same dashpot (zeta = sqrt(m K_y)/(2c)); fit one");
}

}  // namespace ivv::validation
