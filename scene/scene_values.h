// The numeric values of a scene, by the dotted names of its TOML file (docs/design.md §5):
// "impactor.mass", "target.yield_strength", "structure.thickness", ... One table of key, unit
// and accessor, so that every front end that sets a scene value by name (`ivv sweep --set`,
// ivv.sweep(**axes)) names the same keys, in the same units, and reaches the same member of
// Scene. A value set here is checked as a scene file's value is: validate(scene) afterwards
// (scene/scene.h) names the key and its accepted range.
//
// What the table leaves out: the impact velocity and the dashpot (impact.velocity, damping.*),
// which have their own flags and grids (--v0, --zeta, --c, --lambda), and the non-numeric keys
// (name, structure.kind, structure.edges).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace ivv {

struct SceneValueInfo {
  std::string_view key;          // the dotted name of the scene file, e.g. "impactor.mass"
  std::string_view unit;         // SI unit, "-" for a dimensionless value
  std::string_view description;  // what it is, in a few words
};

// Every key, in the order of a scene file's sections (impactor, target, structure).
const std::vector<SceneValueInfo>& scene_values();

// The entry of `key`; nullptr for a key the table does not have.
const SceneValueInfo* find_scene_value(std::string_view key);

// Sets `key` of `scene` to `value` (no range check: validate() the scene afterwards). Throws
// InputError(key, ...) for an unknown key (listing the accepted ones) and for a key the scene
// has no place for: a [structure] value without a [structure], a plate's value on a bar
// (and the reverse), a finite plate's size or impact point on an infinite plate, D11..D66 on a
// plate whose bending stiffnesses the scene does not give.
void set_scene_value(Scene& scene, std::string_view key, double value);

// Leaves the optional value `key` out of `scene` (a yield strength, a free target's radius or
// mass, a structure's own D*, E, nu or impact point: the scene file without it). InputError(key)
// for a required value, an unknown key or one the scene has no place for.
void clear_scene_value(Scene& scene, std::string_view key);

// The value of `key` in `scene`; nullopt when the scene does not give it (an optional value
// left out, or a [structure] value without a [structure]). Throws InputError for an unknown key.
std::optional<double> scene_value(const Scene& scene, std::string_view key);

// "impactor.mass, impactor.radius, ...": the accepted keys, for messages.
std::string scene_value_keys();

}  // namespace ivv
