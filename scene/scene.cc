#include "scene/scene.h"

#include <toml++/toml.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <utility>

#include "scene/input_error.h"

namespace ivv {
namespace {

// Accepted ranges. They are wide on purpose (docs/design.md §6 asks for masses from 1e-6 to 1e3 kg
// and velocities from 1e-6 to beyond 100 m/s); they exclude only the physically meaningless.
void require_positive_finite(std::string_view field, double v, const char* unit) {
  if (std::isfinite(v) && v > 0.0) return;  // no string built on the hot path
  require(false, field, std::string("a finite number > 0 ") + unit, v);
}

void require_poisson(std::string_view field, double nu) {
  require(std::isfinite(nu) && nu > -1.0 && nu < 0.5, field, "a Poisson's ratio in (-1, 0.5)", nu);
}

// The target: a half-space or a free sphere, elastic or rigid, with or without a yield strength.
void validate_target(const Scene& s) {
  const double E2 = s.target_youngs_modulus;
  require(E2 > 0.0 && !std::isnan(E2), "target.youngs_modulus",
          "a number > 0 Pa (inf: a rigid target)", E2);
  require_poisson("target.poisson_ratio", s.target_poisson_ratio);
  if (s.yield_strength) {
    require_positive_finite("target.yield_strength", *s.yield_strength, "Pa");
  }
  if (s.target_radius.has_value() != s.target_mass.has_value()) {
    throw InputError(s.target_radius ? "target.mass" : "target.radius",
                     "a free target sphere needs both radius and mass (neither: a half-space)");
  }
  if (s.target_radius) require_positive_finite("target.radius", *s.target_radius, "m");
  if (s.target_mass) require_positive_finite("target.mass", *s.target_mass, "kg");
  if (s.damping.kind == Damping::Kind::ratio && !s.yield_strength) {
    throw InputError("damping.zeta",
                     "a damping ratio is defined with K_y = 1.5 K_h sqrt(z_y) and needs "
                     "target.yield_strength; give damping.c [N s/m] (--c) instead");
  }
}

}  // namespace

const char* damping_field(Damping::Kind kind) {
  switch (kind) {
    case Damping::Kind::none:
      return "";
    case Damping::Kind::ratio:
      return "damping.zeta";
    case Damping::Kind::coefficient:
      return "damping.c";
    case Damping::Kind::zener_lambda:
      return "damping.lambda";
    case Damping::Kind::structure:
      return "structure";
  }
  return "";
}

void validate(const Scene& s) {
  require_positive_finite("impactor.mass", s.mass, "kg");
  require_positive_finite("impactor.radius", s.radius, "m");
  require_positive_finite("impactor.youngs_modulus", s.impactor_youngs_modulus, "Pa");
  require_poisson("impactor.poisson_ratio", s.impactor_poisson_ratio);
  validate_target(s);
  require_positive_finite("impact.velocity", s.velocity, "m/s");
  switch (s.damping.kind) {
    case Damping::Kind::none:
      break;
    case Damping::Kind::ratio:
      require_positive_finite("damping.zeta", s.damping.value, "(dimensionless)");
      break;
    case Damping::Kind::coefficient:
      require_positive_finite("damping.c", s.damping.value, "N s/m");
      break;
    case Damping::Kind::zener_lambda:
      require_positive_finite("damping.lambda", s.damping.value, "(dimensionless)");
      break;
    case Damping::Kind::structure:
      validate_structure(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio);
      break;
  }
  validate_derived(s);
}

namespace {
// The damping input of a scene and its Table 1 value (the paper's c = 11440 N s/m; zeta 0.1;
// lambda 0.2398, that c at 1 m/s; a structure by its c).
std::pair<double, double> damping_input(const Scene& s) {
  switch (s.damping.kind) {
    case Damping::Kind::ratio:
      return {s.damping.value, 0.1};
    case Damping::Kind::zener_lambda:
      return {s.damping.value, 0.2398};
    case Damping::Kind::structure:
      return {
          structure_dashpot(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio).c,
          11440.0};
    default:
      return {s.damping.value, 11440.0};
  }
}
}  // namespace

void validate_derived(const Scene& s) {
  const Scene ref = paper_scene();
  struct Input {
    const char* field;
    double value, reference;
  };
  const auto [damping_value, damping_ref] = damping_input(s);
  const std::array<Input, 8> inputs = {{
      {"impactor.mass", s.mass, ref.mass},
      {"impactor.radius", s.radius, ref.radius},
      {"impactor.youngs_modulus", s.impactor_youngs_modulus, ref.impactor_youngs_modulus},
      // a rigid target (inf) and an absent yield strength are never the culprit
      {"target.youngs_modulus",
       std::isfinite(s.target_youngs_modulus) ? s.target_youngs_modulus : ref.target_youngs_modulus,
       ref.target_youngs_modulus},
      {"target.yield_strength", s.yield_strength.value_or(*ref.yield_strength),
       *ref.yield_strength},
      {"impact.velocity", s.velocity, ref.velocity},
      {damping_field(s.damping.kind), damping_value, damping_ref},
      {"", 0.0, 1.0},
  }};
  // bit i of `depends` set: inputs[i] enters the quantity
  auto check = [&](const char* name, double value, unsigned depends) {
    if (std::isfinite(value) && value > 0.0) return;
    const Input* culprit = nullptr;
    double worst = -1.0;
    for (std::size_t i = 0; i + 1 < inputs.size(); ++i) {
      if (!(depends & (1u << i)) || !(inputs[i].value > 0)) continue;
      const double decades = std::abs(std::log10(inputs[i].value / inputs[i].reference));
      if (decades > worst) {
        worst = decades;
        culprit = &inputs[i];
      }
    }
    std::ostringstream os;
    os.precision(6);
    os << "gives " << name << " = " << value
       << ", not a representable positive number (double covers about 1e-308 to 1e308); "
          "bring the scene's values nearer physical scales";
    throw InputError(culprit ? culprit->field : "scene", os.str());
  };
  constexpr unsigned moduli = 0b1100, stiffness = moduli | 0b0010, yield = stiffness | 0b10000;
  constexpr unsigned dynamic = yield | 0b0001;
  const DerivedParameters p = derive(s);
  check("E*", p.E_star, moduli);
  check("K_h", p.K_h, stiffness);
  // a dashpot derived from lambda (m, K_h, v0) or from the structure (its own c) is checked
  // whether or not a yield strength exists
  if (s.damping.kind == Damping::Kind::zener_lambda)
    check("c", p.c, stiffness | 0b0001 | 0b100000 | 0b1000000);
  if (s.damping.kind == Damping::Kind::structure) check("c", p.c, 0b1000000);
  const bool yield_given = s.yield_strength.has_value();  // p.has_yield() is false for z_y = inf
  if (yield_given) {
    check("z_y", p.z_y, yield);
    check("K_y", p.K_y, yield);
    check("omega0", p.omega0, dynamic);
    check("v_y", p.v_yield, dynamic);
    if (p.has_dashpot()) {
      check("zeta", p.zeta, dynamic | 0b1000000);
      check("c", p.c, dynamic | 0b1000000);
    }
  }
  // the scales of every basis a law may use on this scene (scene/scene.h ScaleBasis)
  for (ScaleBasis basis : {ScaleBasis::hertz, ScaleBasis::yield}) {
    if (basis == ScaleBasis::yield && !yield_given) continue;
    const unsigned d = basis == ScaleBasis::yield ? dynamic : stiffness | 0b0001 | 0b100000;
    const unsigned sc = d | 0b100000;
    const Scales k = scales(s, p, basis);
    check("the time scale", k.time, d);
    check("the length scale", k.length, sc);
    check("the force scale", k.force, sc);
    check("the energy scale m v0^2", k.energy, sc);
    const double L15 = k.length * std::sqrt(k.length);  // L^1.5 without pow
    check("the spring energy scale K_h L^2.5", p.K_h * L15 * k.length, sc);
    check("the spring force scale K_h L^1.5 / F_scale", p.K_h * L15 / k.force, sc);
  }
}

DerivedParameters derive(const Scene& s) {
  DerivedParameters p;
  p.effective_radius =
      s.target_radius ? s.radius * *s.target_radius / (s.radius + *s.target_radius) : s.radius;
  p.effective_mass = s.target_mass ? s.mass * *s.target_mass / (s.mass + *s.target_mass) : s.mass;
  const double R = p.effective_radius, m = p.effective_mass;
  // a rigid target (E2 = inf) adds no compliance: (1 - nu2^2)/inf = 0
  const double compliance =
      (1.0 - s.impactor_poisson_ratio * s.impactor_poisson_ratio) / s.impactor_youngs_modulus +
      (1.0 - s.target_poisson_ratio * s.target_poisson_ratio) / s.target_youngs_modulus;
  p.E_star = 1.0 / compliance;                  // eq. 7
  p.K_h = 4.0 / 3.0 * std::sqrt(R) * p.E_star;  // eq. 6
  if (s.yield_strength) {
    const double Sy = *s.yield_strength;
    const double pi2 = std::numbers::pi * std::numbers::pi;
    p.z_y = 0.68 * Sy * Sy * pi2 * R / (p.E_star * p.E_star);  // eq. 11
    p.K_y = 1.5 * p.K_h * std::sqrt(p.z_y);                    // eq. 12
    p.omega0 = std::sqrt(p.K_y / m);                           // eq. 23
    p.v_yield = std::sqrt(4.0 * p.K_h * p.z_y * p.z_y * std::sqrt(p.z_y) / (5.0 * m));
  }
  const double critical = std::sqrt(m * p.K_y);  // 2 c zeta (NaN without a yield strength)
  switch (s.damping.kind) {
    case Damping::Kind::none:
      break;
    case Damping::Kind::ratio:  // validate() requires a yield strength for it
      p.zeta = s.damping.value;
      p.c = critical / (2.0 * p.zeta);
      break;
    case Damping::Kind::coefficient:
      p.c = s.damping.value;
      p.zeta = critical / (2.0 * p.c);
      break;
    case Damping::Kind::zener_lambda:
      p.c = dashpot_for_zener_lambda(m, p.K_h, s.velocity, s.damping.value);
      p.zeta = critical / (2.0 * p.c);
      break;
    case Damping::Kind::structure:
      p.c =
          structure_dashpot(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio).c;
      p.zeta = critical / (2.0 * p.c);
      break;
  }
  p.zener_lambda = zener_lambda(m, p.K_h, s.velocity, p.c);
  return p;
}

Scales scales(const Scene& s, const DerivedParameters& p, ScaleBasis basis) {
  const double m = p.effective_mass, v0 = s.velocity;
  double omega = 0.0;
  switch (basis) {
    case ScaleBasis::yield:
      if (!p.has_yield()) {
        throw InputError("target.yield_strength",
                         "missing: the yield-based scales (omega0 = sqrt(K_y/m)) need it");
      }
      omega = p.omega0;
      break;
    case ScaleBasis::hertz:
      omega = v0 / std::pow(5.0 * m * v0 * v0 / (4.0 * p.K_h), 0.4);  // v0/z_mH
      break;
  }
  Scales k;
  k.time = 1.0 / omega;
  k.length = v0 / omega;
  k.velocity = v0;
  k.force = m * v0 * omega;
  k.energy = m * v0 * v0;
  return k;
}

BodyVelocities body_velocities_after(const Scene& s, double w) {
  if (!s.target_mass) return {w, 0.0};
  const double m1 = s.mass, m2 = *s.target_mass;
  const double centre = m1 * s.velocity / (m1 + m2);  // unchanged by the contact
  return {centre + m2 / (m1 + m2) * w, centre - m1 / (m1 + m2) * w};
}

Scene paper_scene() {
  Scene s;
  s.name = "paper";
  s.mass = 0.5;
  s.radius = 0.010;
  s.impactor_youngs_modulus = 207e9;
  s.impactor_poisson_ratio = 0.3;
  s.target_youngs_modulus = 7.9e9;
  s.target_poisson_ratio = 0.3;
  s.yield_strength = 2.0 * 101e6;  // laminate: S_y = 2 S_u
  s.velocity = 1.0;
  return s;
}

namespace {

std::string join(const std::set<std::string>& names) {
  std::string list;
  for (const auto& a : names) list += (list.empty() ? "" : ", ") + a;
  return list;
}

void reject_unknown_keys(const toml::table& table, const std::string& prefix,
                         const std::set<std::string>& allowed) {
  for (const auto& [key, node] : table) {
    const std::string k(key.str());
    if (!allowed.count(k)) {
      throw InputError(prefix.empty() ? k : prefix + "." + k,
                       "unknown key; accepted keys here: " + join(allowed));
    }
  }
}

const toml::table& require_table(const toml::table& root, const std::string& name) {
  const toml::table* t = root[name].as_table();
  if (!t) throw InputError(name, "missing section [" + name + "]");
  return *t;
}

std::optional<double> number(const toml::table& t, const std::string& section,
                             const std::string& key) {
  const toml::node* n = t.get(key);
  if (!n) return std::nullopt;
  if (auto v = n->value<double>()) return v;
  throw InputError(section + "." + key, "must be a number");
}

double required_number(const toml::table& t, const std::string& section, const std::string& key) {
  auto v = number(t, section, key);
  if (!v) throw InputError(section + "." + key, "missing (required)");
  return *v;
}

void parse_target(const toml::table& tgt, Scene& s) {
  reject_unknown_keys(
      tgt, "target",
      {"youngs_modulus", "poisson_ratio", "yield_strength", "shear_strength", "radius", "mass"});
  // TOML's inf is a float like any other: +inf means a rigid target (validate() rejects -inf, nan)
  s.target_youngs_modulus = required_number(tgt, "target", "youngs_modulus");
  // a rigid target's Poisson's ratio plays no part (its compliance is zero): optional then
  const auto nu2 = number(tgt, "target", "poisson_ratio");
  if (!nu2 && !s.rigid_target()) {
    throw InputError("target.poisson_ratio", "missing (required unless youngs_modulus = inf)");
  }
  s.target_poisson_ratio = nu2.value_or(0.0);
  const auto yield = number(tgt, "target", "yield_strength");
  const auto shear = number(tgt, "target", "shear_strength");
  if (yield && shear) {
    throw InputError("target.shear_strength",
                     "give either yield_strength (S_y) or shear_strength (S_u, laminates: "
                     "S_y = 2 S_u), not both");
  }
  if (shear) {
    if (!std::isfinite(*shear) || *shear <= 0.0) {
      throw InputError("target.shear_strength", "must be a finite number > 0 Pa");
    }
    s.yield_strength = 2.0 * *shear;
  } else {
    s.yield_strength = yield;  // absent: only laws without yield (hertz, hunt-crossley) run
  }
  s.target_radius = number(tgt, "target", "radius");
  s.target_mass = number(tgt, "target", "mass");
}

// The scene's `name`: a string of 1 to kMaxSceneNameLength printable characters (it is printed
// and written into JSON sidecars and reports); absent: the file's stem. `name = 42` and names
// with control characters were accepted.
constexpr std::size_t kMaxSceneNameLength = 200;
std::string scene_name(const toml::table& root, const std::string& source_name) {
  const toml::node* node = root.get("name");
  if (!node) return std::filesystem::path(source_name).stem().string();
  const std::optional<std::string> name = node->value<std::string>();
  const auto control = [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return u < 0x20 || u == 0x7f;
  };
  if (!name || !node->is_string() || name->empty() || name->size() > kMaxSceneNameLength ||
      std::any_of(name->begin(), name->end(), control))
    throw InputError("name", "must be a string of 1 to " + std::to_string(kMaxSceneNameLength) +
                                 " characters without control characters");
  return *name;
}

void parse_damping(const toml::table& d, Scene& s) {
  reject_unknown_keys(d, "damping", {"zeta", "c", "lambda"});
  const auto zeta = number(d, "damping", "zeta");
  const auto c = number(d, "damping", "c");
  const auto lambda = number(d, "damping", "lambda");
  if ((zeta.has_value() + c.has_value() + lambda.has_value()) > 1)
    throw InputError("damping", "give one of zeta, c or lambda, not more");
  if (zeta) s.damping = Damping::ratio(*zeta);
  if (c) s.damping = Damping::coefficient(*c);
  if (lambda) s.damping = Damping::zener(*lambda);
}

// The finite plate's keys of [structure] (scene/structure.h): the lengths, edges, impact point
// and the four bending stiffnesses (all four or none). Ranges are checked by validate_structure.
void parse_finite_plate(const toml::table& t, Structure& st) {
  st.length_x = number(t, "structure", "length_x");
  st.length_y = number(t, "structure", "length_y");
  st.impact_x = number(t, "structure", "impact_x");
  st.impact_y = number(t, "structure", "impact_y");
  if (const toml::node* e = t.get("edges")) {
    const auto name = e->value<std::string>();
    if (name && *name == "clamped")
      throw InputError("structure.edges",
                       "\"clamped\" is not modelled yet; accepted: \"simply-supported\"");
    st.edges = name ? plate_edges_from_name(*name) : std::nullopt;
    if (!st.edges) throw InputError("structure.edges", "accepted: \"simply-supported\"");
  }
  const std::array<const char*, 4> names = {"D11", "D22", "D12", "D66"};
  std::array<std::optional<double>, 4> d;
  int given = 0;
  for (std::size_t i = 0; i < names.size(); ++i) {
    d[i] = number(t, "structure", names[i]);
    given += d[i].has_value();
  }
  if (given == 0) return;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (!d[i])
      throw InputError(std::string("structure.") + names[i],
                       "missing: D11, D22, D12 and D66 are given together (all four: a "
                       "specially orthotropic plate; none: isotropic from E and nu)");
  st.bending = OrthotropicBending{*d[0], *d[1], *d[2], *d[3]};
}

// [structure]: the keys a kind uses (the others are bad input, not ignored).
Structure parse_structure(const toml::table& t) {
  const toml::node* kind_node = t.get("kind");
  const auto kind_name = kind_node ? kind_node->value<std::string>() : std::nullopt;
  const auto kind = kind_name ? structure_kind_from_name(*kind_name) : std::nullopt;
  if (!kind) {
    throw InputError("structure.kind",
                     kind_node ? "unknown kind; accepted: \"plate\", \"bar\", \"plate+bar\""
                               : "missing; accepted: \"plate\", \"bar\", \"plate+bar\"");
  }
  std::set<std::string> keys = {"kind", "density", "youngs_modulus"};
  if (*kind != Structure::Kind::bar)
    keys.insert({"thickness", "bending_stiffness", "poisson_ratio", "length_x", "length_y", "edges",
                 "impact_x", "impact_y", "D11", "D22", "D12", "D66"});
  if (*kind != Structure::Kind::plate) keys.insert("area");
  for (const char* length : {"length_x", "length_y"})
    if (*kind == Structure::Kind::bar && t.contains(length))
      throw InputError(std::string("structure.") + length,
                       "not used by kind = \"bar\": the lengths make a plate finite "
                       "(kind = \"plate\")");
  for (const auto& [key, node] : t) {
    const std::string k(key.str());
    if (keys.count(k)) continue;
    static const std::set<std::string> known = {
        "thickness", "bending_stiffness", "poisson_ratio", "area", "length_x", "length_y", "edges",
        "impact_x",  "impact_y",          "D11",           "D22",  "D12",      "D66"};
    if (!known.count(k)) reject_unknown_keys(t, "structure", keys);
    throw InputError("structure." + k, "not used by kind = \"" + *kind_name +
                                           "\"; accepted keys for it: " + join(keys));
  }
  Structure st;
  st.kind = *kind;
  st.density = required_number(t, "structure", "density");
  if (st.has_plate()) st.thickness = required_number(t, "structure", "thickness");
  if (st.has_bar()) st.area = required_number(t, "structure", "area");
  st.bending_stiffness = number(t, "structure", "bending_stiffness");
  st.youngs_modulus = number(t, "structure", "youngs_modulus");
  st.poisson_ratio = number(t, "structure", "poisson_ratio");
  parse_finite_plate(t, st);
  return st;
}

}  // namespace

Scene parse_scene_toml(const std::string& text, const std::string& source_name) {
  toml::table root;
  try {
    root = toml::parse(text, source_name);
  } catch (const toml::parse_error& err) {
    std::ostringstream os;
    os << "TOML syntax error at line " << err.source().begin.line << ", column "
       << err.source().begin.column << ": " << err.description();
    throw InputError(source_name, os.str());
  }
  reject_unknown_keys(root, "", {"name", "impactor", "target", "damping", "structure", "impact"});

  Scene s;
  s.name = scene_name(root, source_name);

  const toml::table& imp = require_table(root, "impactor");
  reject_unknown_keys(imp, "impactor", {"mass", "radius", "youngs_modulus", "poisson_ratio"});
  s.mass = required_number(imp, "impactor", "mass");
  s.radius = required_number(imp, "impactor", "radius");
  s.impactor_youngs_modulus = required_number(imp, "impactor", "youngs_modulus");
  s.impactor_poisson_ratio = required_number(imp, "impactor", "poisson_ratio");

  parse_target(require_table(root, "target"), s);

  if (root.contains("structure") && root.contains("damping")) {
    throw InputError("structure",
                     "and [damping] both given: the dashpot comes either from the "
                     "struck structure ([structure]) or from [damping] (zeta, c or "
                     "lambda), not both");
  }
  if (const toml::table* d = root["damping"].as_table()) {
    parse_damping(*d, s);
  } else if (root.contains("damping")) {
    throw InputError("damping", "must be a table [damping] with zeta, c or lambda");
  }
  if (const toml::table* st = root["structure"].as_table()) {
    s.damping = Damping::from_structure(parse_structure(*st));
  } else if (root.contains("structure")) {
    throw InputError("structure",
                     "must be a table [structure] with kind = \"plate\", \"bar\" "
                     "or \"plate+bar\"");
  }

  const toml::table& impact = require_table(root, "impact");
  reject_unknown_keys(impact, "impact", {"velocity"});
  s.velocity = required_number(impact, "impact", "velocity");

  validate(s);
  return s;
}

Scene load_scene_file(const std::filesystem::path& path) {
  return parse_scene_toml(read_scene_text(path), path.string());
}

std::string read_scene_text(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("--scene", "'" + path.string() + "' is a directory, not a scene file");
  // opening a FIFO blocks until a writer comes, for ever if none does
  const std::filesystem::file_status st = std::filesystem::status(path, ec);
  if (std::filesystem::is_fifo(st) || std::filesystem::is_socket(st) ||
      std::filesystem::is_block_file(st))
    throw InputError("--scene", "'" + path.string() + "' is " +
                                    (std::filesystem::is_fifo(st)     ? "a FIFO"
                                     : std::filesystem::is_socket(st) ? "a socket"
                                                                      : "a block device") +
                                    ", not a scene file; give a regular TOML file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--scene", "cannot read scene file '" + path.string() + "'");
  std::string text(kMaxSceneFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw InputError("--scene", "cannot read scene file '" + path.string() + "'");
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxSceneFileBytes) {
    throw InputError("--scene", "'" + path.string() + "' is larger than " +
                                    std::to_string(kMaxSceneFileBytes) +
                                    " bytes: not a scene file");
  }
  return text;
}

Scene load_scene(const std::string& name_or_path) {
  if (name_or_path == "paper") return paper_scene();
  const bool bare_name = name_or_path.find('/') == std::string::npos &&
                         !name_or_path.ends_with(".toml") && !name_or_path.empty();
  if (!bare_name || std::filesystem::exists(name_or_path)) return load_scene_file(name_or_path);
  std::string searched;
  for (const auto& dir : data_directories()) {
    const auto file = dir / "scenes" / (name_or_path + ".toml");
    if (std::filesystem::is_regular_file(file)) return load_scene_file(file);
    searched += (searched.empty() ? "" : ", ") + file.parent_path().string();
  }
  throw InputError("--scene", "no scene file '" + name_or_path + "' and no shipped scene '" +
                                  name_or_path + ".toml' in " + searched +
                                  " (set IVV_DATA_DIR to the directory holding scenes/)");
}

}  // namespace ivv
