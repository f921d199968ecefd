// The scene file (docs/design.md §5, TOML): parsing, with every unknown key rejected and every
// bad value one InputError naming the field; loading by path or by a shipped scene's name.
#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "scene/data_dir.h"
#include "scene/input_error.h"
#include "scene/scene.h"
#include "scene/structure.h"

namespace ivv {

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

// The finite plate's keys of [structure] (scene/structure.h): the lengths, edges, impact point,
// the four bending stiffnesses (all four or none) and what the impact does with the modes above
// its cut-off (dropped_modes). Ranges are checked by validate_structure.
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
  if (const toml::node* dm = t.get("dropped_modes")) {
    const auto name = dm->value<std::string>();
    st.dropped_modes = name ? dropped_modes_from_name(*name) : std::nullopt;
    if (!st.dropped_modes)
      throw InputError("structure.dropped_modes", std::string("accepted: ") + kDroppedModesNames);
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
                 "impact_x", "impact_y", "D11", "D22", "D12", "D66", "dropped_modes"});
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
        "thickness", "bending_stiffness", "poisson_ratio", "area", "length_x", "length_y",
        "edges",     "impact_x",          "impact_y",      "D11",  "D22",      "D12",
        "D66",       "dropped_modes"};
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
