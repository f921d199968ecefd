#include "scene/scene_values.h"

#include <array>

#include "scene/input_error.h"

namespace ivv {
namespace {

using Get = std::optional<double> (*)(const Scene&);
using Set = void (*)(Scene&, double);
// Leaves an optional value out (nullptr: a required value).
using Clear = void (*)(Scene&);
// Why the scene has no place for the key (nullptr: it has).
using Unavailable = const char* (*)(const Scene&);

struct Entry {
  SceneValueInfo info;
  Get get;
  Set set;
  Unavailable unavailable;
  Clear clear = nullptr;
};

const char* always_available(const Scene&) {
  return nullptr;
}

const char* needs_structure(const Scene& s) {
  return s.damping.kind == Damping::Kind::structure
             ? nullptr
             : "the scene has no [structure] section whose value it could set";
}
const char* needs_plate(const Scene& s) {
  if (const char* why = needs_structure(s)) return why;
  return s.damping.structure.has_plate() ? nullptr : "not used by kind = \"bar\" (a plate's value)";
}
const char* needs_bar(const Scene& s) {
  if (const char* why = needs_structure(s)) return why;
  return s.damping.structure.has_bar() ? nullptr : "not used by kind = \"plate\" (a bar's value)";
}
const char* needs_finite_plate(const Scene& s) {
  if (const char* why = needs_plate(s)) return why;
  return s.damping.structure.finite_plate()
             ? nullptr
             : "the scene's plate is infinite: give length_x, length_y and edges in its "
               "[structure] to vary a finite plate's size or impact point";
}
const char* needs_orthotropic(const Scene& s) {
  if (const char* why = needs_plate(s)) return why;
  return s.damping.structure.bending
             ? nullptr
             : "the scene's plate is isotropic: give D11, D22, D12 and D66 in its [structure] "
               "to vary one of them";
}

Structure& st(Scene& s) {
  return s.damping.structure;
}
const Structure& st(const Scene& s) {
  return s.damping.structure;
}
std::optional<double> if_structure(const Scene& s, std::optional<double> v) {
  return s.damping.kind == Damping::Kind::structure ? v : std::nullopt;
}
std::optional<double> if_orthotropic(const Scene& s, double OrthotropicBending::*d) {
  if (s.damping.kind != Damping::Kind::structure || !st(s).bending) return std::nullopt;
  return (*st(s).bending).*d;
}

// clang-format off
const std::array<Entry, 24> kEntries = {{
    {{"impactor.mass", "kg", "impactor mass m1"},
     [](const Scene& s) -> std::optional<double> { return s.mass; },
     [](Scene& s, double v) { s.mass = v; }, always_available},
    {{"impactor.radius", "m", "impactor radius R1"},
     [](const Scene& s) -> std::optional<double> { return s.radius; },
     [](Scene& s, double v) { s.radius = v; }, always_available},
    {{"impactor.youngs_modulus", "Pa", "impactor Young's modulus E1"},
     [](const Scene& s) -> std::optional<double> { return s.impactor_youngs_modulus; },
     [](Scene& s, double v) { s.impactor_youngs_modulus = v; }, always_available},
    {{"impactor.poisson_ratio", "-", "impactor Poisson's ratio nu1"},
     [](const Scene& s) -> std::optional<double> { return s.impactor_poisson_ratio; },
     [](Scene& s, double v) { s.impactor_poisson_ratio = v; }, always_available},
    {{"target.youngs_modulus", "Pa", "target Young's modulus E2 (E22 of a laminate)"},
     [](const Scene& s) -> std::optional<double> { return s.target_youngs_modulus; },
     [](Scene& s, double v) { s.target_youngs_modulus = v; }, always_available},
    {{"target.poisson_ratio", "-", "target Poisson's ratio nu2"},
     [](const Scene& s) -> std::optional<double> { return s.target_poisson_ratio; },
     [](Scene& s, double v) { s.target_poisson_ratio = v; }, always_available},
    {{"target.yield_strength", "Pa", "yield strength S_y"},
     [](const Scene& s) { return s.yield_strength; },
     [](Scene& s, double v) { s.yield_strength = v; }, always_available,
     [](Scene& s) { s.yield_strength.reset(); }},
    {{"target.shear_strength", "Pa", "laminate shear strength S_u (S_y = 2 S_u)"},
     [](const Scene& s) -> std::optional<double> {
       if (!s.yield_strength) return std::nullopt;
       return *s.yield_strength / 2.0;
     },
     [](Scene& s, double v) { s.yield_strength = 2.0 * v; }, always_available,
     [](Scene& s) { s.yield_strength.reset(); }},
    {{"target.radius", "m", "radius R2 of a free target sphere"},
     [](const Scene& s) { return s.target_radius; },
     [](Scene& s, double v) { s.target_radius = v; }, always_available,
     [](Scene& s) { s.target_radius.reset(); }},
    {{"target.mass", "kg", "mass m2 of a free target sphere"},
     [](const Scene& s) { return s.target_mass; },
     [](Scene& s, double v) { s.target_mass = v; }, always_available,
     [](Scene& s) { s.target_mass.reset(); }},
    {{"structure.density", "kg/m^3", "structure density rho"},
     [](const Scene& s) { return if_structure(s, st(s).density); },
     [](Scene& s, double v) { st(s).density = v; }, needs_structure},
    {{"structure.thickness", "m", "plate thickness h"},
     [](const Scene& s) { return if_structure(s, st(s).thickness); },
     [](Scene& s, double v) { st(s).thickness = v; }, needs_plate},
    {{"structure.area", "m^2", "bar cross-section A"},
     [](const Scene& s) { return if_structure(s, st(s).area); },
     [](Scene& s, double v) { st(s).area = v; }, needs_bar},
    {{"structure.bending_stiffness", "N m", "plate bending stiffness D*"},
     [](const Scene& s) { return if_structure(s, st(s).bending_stiffness); },
     [](Scene& s, double v) { st(s).bending_stiffness = v; }, needs_plate,
     [](Scene& s) { st(s).bending_stiffness.reset(); }},
    {{"structure.youngs_modulus", "Pa", "structure Young's modulus E"},
     [](const Scene& s) { return if_structure(s, st(s).youngs_modulus); },
     [](Scene& s, double v) { st(s).youngs_modulus = v; }, needs_structure,
     [](Scene& s) { st(s).youngs_modulus.reset(); }},
    {{"structure.poisson_ratio", "-", "plate Poisson's ratio nu"},
     [](const Scene& s) { return if_structure(s, st(s).poisson_ratio); },
     [](Scene& s, double v) { st(s).poisson_ratio = v; }, needs_plate,
     [](Scene& s) { st(s).poisson_ratio.reset(); }},
    {{"structure.length_x", "m", "finite plate length a"},
     [](const Scene& s) { return if_structure(s, st(s).length_x); },
     [](Scene& s, double v) { st(s).length_x = v; }, needs_finite_plate},
    {{"structure.length_y", "m", "finite plate width b"},
     [](const Scene& s) { return if_structure(s, st(s).length_y); },
     [](Scene& s, double v) { st(s).length_y = v; }, needs_finite_plate},
    {{"structure.impact_x", "m", "impact point x0 on a finite plate"},
     [](const Scene& s) { return if_structure(s, st(s).impact_x); },
     [](Scene& s, double v) { st(s).impact_x = v; }, needs_finite_plate,
     [](Scene& s) { st(s).impact_x.reset(); }},
    {{"structure.impact_y", "m", "impact point y0 on a finite plate"},
     [](const Scene& s) { return if_structure(s, st(s).impact_y); },
     [](Scene& s, double v) { st(s).impact_y = v; }, needs_finite_plate,
     [](Scene& s) { st(s).impact_y.reset(); }},
    {{"structure.D11", "N m", "orthotropic bending stiffness D11"},
     [](const Scene& s) { return if_orthotropic(s, &OrthotropicBending::D11); },
     [](Scene& s, double v) { st(s).bending->D11 = v; }, needs_orthotropic},
    {{"structure.D22", "N m", "orthotropic bending stiffness D22"},
     [](const Scene& s) { return if_orthotropic(s, &OrthotropicBending::D22); },
     [](Scene& s, double v) { st(s).bending->D22 = v; }, needs_orthotropic},
    {{"structure.D12", "N m", "orthotropic bending stiffness D12"},
     [](const Scene& s) { return if_orthotropic(s, &OrthotropicBending::D12); },
     [](Scene& s, double v) { st(s).bending->D12 = v; }, needs_orthotropic},
    {{"structure.D66", "N m", "orthotropic bending stiffness D66"},
     [](const Scene& s) { return if_orthotropic(s, &OrthotropicBending::D66); },
     [](Scene& s, double v) { st(s).bending->D66 = v; }, needs_orthotropic},
}};
// clang-format on

const Entry* find_entry(std::string_view key) {
  for (const Entry& e : kEntries)
    if (e.info.key == key) return &e;
  return nullptr;
}

const Entry& entry(std::string_view key) {
  if (const Entry* e = find_entry(key)) return *e;
  std::string why = "not a numeric scene value; accepted: " + scene_value_keys();
  if (key == "impact.velocity" || key.starts_with("damping."))
    why += " (the impact velocity and the dashpot have their own flags: --v0, --zeta, --c)";
  throw InputError(std::string(key), why);
}

}  // namespace

const std::vector<SceneValueInfo>& scene_values() {
  static const std::vector<SceneValueInfo> infos = [] {
    std::vector<SceneValueInfo> v;
    for (const Entry& e : kEntries) v.push_back(e.info);
    return v;
  }();
  return infos;
}

const SceneValueInfo* find_scene_value(std::string_view key) {
  const Entry* e = find_entry(key);
  return e ? &e->info : nullptr;
}

void set_scene_value(Scene& scene, std::string_view key, double value) {
  const Entry& e = entry(key);
  if (const char* why = e.unavailable(scene)) throw InputError(std::string(key), why);
  e.set(scene, value);
}

void clear_scene_value(Scene& scene, std::string_view key) {
  const Entry& e = entry(key);
  if (!e.clear) throw InputError(std::string(key), "required: it cannot be left out");
  if (const char* why = e.unavailable(scene)) throw InputError(std::string(key), why);
  e.clear(scene);
}

std::optional<double> scene_value(const Scene& scene, std::string_view key) {
  return entry(key).get(scene);
}

std::string scene_value_keys() {
  std::string list;
  for (const Entry& e : kEntries) {
    if (!list.empty()) list += ", ";
    list += e.info.key;
  }
  return list;
}

}  // namespace ivv
