#include "scene/scene_json.h"

#include <cmath>
#include <limits>
#include <optional>

#include "scene/input_error.h"

namespace ivv {
namespace {

using nlohmann::json;

json optional_json(const std::optional<double>& v) {
  return v ? json(*v) : json(nullptr);
}

// The inputs of the scene. Every member is named by a structured binding, so that a member
// added to Scene, Damping or Structure stops compilation here until it is written (and read
// back in scene_from_json): the two scene writers this one replaced had drifted apart that way.
json inputs_json(const Scene& s) {
  const auto& [name, mass, radius, E1, nu1, E2, nu2, yield_strength, target_radius, target_mass,
               damping, velocity] = s;
  const auto& [kind, value, structure] = damping;
  const bool has_value = kind != Damping::Kind::none && kind != Damping::Kind::structure;
  return {
      {"name", name},
      {"mass", mass},
      {"radius", radius},
      {"impactor_youngs_modulus", E1},
      {"impactor_poisson_ratio", nu1},
      {"target_youngs_modulus", finite_or_null(E2)},
      {"target_poisson_ratio", nu2},
      {"rigid_target", s.rigid_target()},
      {"target_radius", optional_json(target_radius)},
      {"target_mass", optional_json(target_mass)},
      {"yield_strength", optional_json(yield_strength)},
      {"v0", velocity},
      {"damping",
       {{"kind", damping_kind_name(kind)}, {"value", has_value ? json(value) : json(nullptr)}}},
      {"structure", kind == Damping::Kind::structure ? structure_json(s) : json(nullptr)},
  };
}

// Readers of one field; InputError(prefix + name, ...) when it is missing or mistyped.
const json& field(const json& j, const std::string& name, const std::string& prefix) {
  if (!j.is_object() || !j.contains(name)) throw InputError(prefix + name, "missing");
  return j.at(name);
}
double number(const json& j, const std::string& name, const std::string& prefix) {
  const json& v = field(j, name, prefix);
  if (!v.is_number()) throw InputError(prefix + name, "must be a number, got " + v.dump());
  return v.get<double>();
}
std::optional<double> optional_number(const json& j, const std::string& name,
                                      const std::string& prefix) {
  if (!j.is_object() || !j.contains(name) || j.at(name).is_null()) return std::nullopt;
  return number(j, name, prefix);
}
std::string text(const json& j, const std::string& name, const std::string& prefix) {
  const json& v = field(j, name, prefix);
  if (!v.is_string()) throw InputError(prefix + name, "must be a string, got " + v.dump());
  return v.get<std::string>();
}

// A finite plate's keys (absent or null: an infinite plate, as in files written before them).
void finite_plate_from_json(const json& j, const std::string& prefix, Structure& st) {
  st.length_x = optional_number(j, "length_x", prefix);
  st.length_y = optional_number(j, "length_y", prefix);
  st.impact_x = optional_number(j, "impact_x", prefix);
  st.impact_y = optional_number(j, "impact_y", prefix);
  if (j.contains("edges") && !j.at("edges").is_null()) {
    const auto edges = plate_edges_from_name(text(j, "edges", prefix));
    if (!edges) throw InputError(prefix + "edges", "must be \"simply-supported\"");
    st.edges = *edges;
  }
  if (j.contains("dropped_modes") && !j.at("dropped_modes").is_null()) {
    const auto dropped = dropped_modes_from_name(text(j, "dropped_modes", prefix));
    if (!dropped)
      throw InputError(prefix + "dropped_modes", std::string("accepted: ") + kDroppedModesNames);
    st.dropped_modes = *dropped;
  }
  if (j.contains("orthotropic_bending") && !j.at("orthotropic_bending").is_null()) {
    const json& d = j.at("orthotropic_bending");
    const std::string in = prefix + "orthotropic_bending.";
    st.bending = OrthotropicBending{number(d, "D11", in), number(d, "D22", in),
                                    number(d, "D12", in), number(d, "D66", in)};
  }
}

Structure structure_from_json(const json& j, const std::string& prefix) {
  Structure st;
  const std::string kind = text(j, "kind", prefix);
  const auto k = structure_kind_from_name(kind);
  if (!k) throw InputError(prefix + "kind", "must be \"plate\", \"bar\" or \"plate+bar\"");
  st.kind = *k;
  st.density = number(j, "density", prefix);
  if (st.has_plate()) st.thickness = number(j, "thickness", prefix);
  if (st.has_bar()) st.area = number(j, "area", prefix);
  const json& given = field(j, "bending_stiffness_given", prefix);
  if (!given.is_boolean()) throw InputError(prefix + "bending_stiffness_given", "must be a bool");
  if (st.has_plate() && given.get<bool>())
    st.bending_stiffness = number(j, "bending_stiffness", prefix);
  st.youngs_modulus = optional_number(j, "youngs_modulus", prefix);
  st.poisson_ratio = optional_number(j, "poisson_ratio", prefix);
  finite_plate_from_json(j, prefix, st);
  return st;
}

Damping damping_from_json(const json& j, const std::string& prefix) {
  const json& d = field(j, "damping", prefix);
  const std::string kind = text(d, "kind", prefix + "damping.");
  if (kind == "none") return Damping::none();
  if (kind == "structure")
    return Damping::from_structure(
        structure_from_json(field(j, "structure", prefix), prefix + "structure."));
  const double value = number(d, "value", prefix + "damping.");
  if (kind == "ratio") return Damping::ratio(value);
  if (kind == "coefficient") return Damping::coefficient(value);
  if (kind == "zener_lambda") return Damping::zener(value);
  throw InputError(
      prefix + "damping.kind",
      "must be none, ratio, coefficient, zener_lambda or structure, got '" + kind + "'");
}

}  // namespace

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

const char* damping_kind_name(Damping::Kind kind) {
  switch (kind) {
    case Damping::Kind::none:
      return "none";
    case Damping::Kind::ratio:
      return "ratio";
    case Damping::Kind::coefficient:
      return "coefficient";
    case Damping::Kind::zener_lambda:
      return "zener_lambda";
    case Damping::Kind::structure:
      return "structure";
  }
  return "none";
}

json scene_json(const Scene& s, const DerivedParameters& p) {
  json j = inputs_json(s);
  // yield-related values are null without a yield strength, the dashpot's without a dashpot
  j.update({
      {"effective_radius", p.effective_radius},
      {"effective_mass", p.effective_mass},
      {"E_star", p.E_star},
      {"K_h", p.K_h},
      {"z_y", finite_or_null(p.z_y)},
      {"K_y", finite_or_null(p.K_y)},
      {"omega0", finite_or_null(p.omega0)},
      {"zeta", finite_or_null(p.zeta)},
      {"c", finite_or_null(p.c)},
      {"v_yield", finite_or_null(p.v_yield)},
      // Zener's lambda = m*^{3/5} K_h^{2/5} v0^{1/5}/c (scene/structure.h): null without a dashpot
      {"zener_lambda", p.has_dashpot() ? json(p.zener_lambda) : json(nullptr)},
      {"dashpot_source",
       s.damping.kind == Damping::Kind::none ? "none" : damping_field(s.damping.kind)},
  });
  return j;
}

json scene_json(const Scene& s) {
  return scene_json(s, derive(s));
}

json structure_json(const Scene& s) {
  if (s.damping.kind != Damping::Kind::structure) return nullptr;
  const auto& [kind, density, thickness, area, bending_stiffness, youngs_modulus, poisson_ratio,
               length_x, length_y, edges, impact_x, impact_y, bending, dropped_modes] =
      s.damping.structure;
  const Structure& st = s.damping.structure;
  const StructureDashpot d = structure_dashpot(st, s.target_youngs_modulus, s.target_poisson_ratio);
  return {
      {"kind", std::string(structure_kind_name(kind))},
      {"density", density},
      {"thickness", st.has_plate() ? json(thickness) : json(nullptr)},
      {"area", st.has_bar() ? json(area) : json(nullptr)},
      {"youngs_modulus", optional_json(youngs_modulus)},
      {"poisson_ratio", optional_json(poisson_ratio)},
      {"bending_stiffness", finite_or_null(d.bending_stiffness)},
      {"bending_stiffness_given", bending_stiffness.has_value()},
      {"c_plate", finite_or_null(d.c_plate)},
      {"c_bar", finite_or_null(d.c_bar)},
      {"c", finite_or_null(d.c)},
      {"formula", structure_formula(st)},
      // a finite plate (null for an infinite one): its size, edges, impact point, D's
      {"length_x", optional_json(length_x)},
      {"length_y", optional_json(length_y)},
      {"edges", edges ? json(std::string(plate_edges_name(*edges))) : json(nullptr)},
      {"impact_x", optional_json(impact_x)},
      {"impact_y", optional_json(impact_y)},
      {"orthotropic_bending", bending ? json{{"D11", bending->D11},
                                             {"D22", bending->D22},
                                             {"D12", bending->D12},
                                             {"D66", bending->D66}}
                                      : json(nullptr)},
      // what the impact does with the modes above the cut-off (null: the static compliance)
      {"dropped_modes",
       dropped_modes ? json(std::string(dropped_modes_name(*dropped_modes))) : json(nullptr)},
  };
}

Scene scene_from_json(const json& j, const std::string& prefix) {
  if (!j.is_object()) throw InputError(prefix.empty() ? "scene" : prefix, "must be an object");
  Scene s;
  s.name = text(j, "name", prefix);
  s.mass = number(j, "mass", prefix);
  s.radius = number(j, "radius", prefix);
  s.impactor_youngs_modulus = number(j, "impactor_youngs_modulus", prefix);
  s.impactor_poisson_ratio = number(j, "impactor_poisson_ratio", prefix);
  field(j, "target_youngs_modulus", prefix);  // null is a rigid target, absent is an error
  s.target_youngs_modulus = optional_number(j, "target_youngs_modulus", prefix)
                                .value_or(std::numeric_limits<double>::infinity());
  s.target_poisson_ratio = number(j, "target_poisson_ratio", prefix);
  s.yield_strength = optional_number(j, "yield_strength", prefix);
  s.target_radius = optional_number(j, "target_radius", prefix);
  s.target_mass = optional_number(j, "target_mass", prefix);
  s.velocity = j.contains("v0") || !j.contains("velocity") ? number(j, "v0", prefix)
                                                           : number(j, "velocity", prefix);
  s.damping = damping_from_json(j, prefix);
  validate(s);
  return s;
}

}  // namespace ivv
