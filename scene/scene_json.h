// The one JSON form of a scene, written by every JSON that carries one (`ivv simulate --json`,
// `ivv scene show --json`, a sweep's sidecar, a calibration file) and read back by those that
// need the scene again (`ivv predict --calibration`).
//
// scene_json() writes every input of the scene (SI units) and its derived parameters:
//   inputs   name, mass, radius, impactor_youngs_modulus, impactor_poisson_ratio,
//            target_youngs_modulus (null: rigid), target_poisson_ratio, rigid_target,
//            target_radius, target_mass, yield_strength (null when absent), v0,
//            damping {kind: none | ratio | coefficient | zener_lambda | structure,
//                     value: zeta, c [N s/m] or lambda (null for none and structure)},
//            structure (null without one; below)
//   derived  effective_radius, effective_mass, E_star, K_h, z_y, K_y, omega0, zeta, c,
//            v_yield (null where undefined: no yield strength, no dashpot), zener_lambda,
//            dashpot_source ("none", "damping.zeta", "damping.c", "damping.lambda",
//            "structure")
// structure_json(): kind ("plate", "bar", "plate+bar"), density, thickness (null for a bar),
// area (null for a plate), youngs_modulus and poisson_ratio (null: the target's),
// bending_stiffness (the D used) with bending_stiffness_given (true: it is the input D*),
// c_plate, c_bar, c (null where an element is absent), formula.
//
// scene_from_json() reads the inputs back (derived values are ignored) and validates the scene:
// scene_from_json(scene_json(s)) describes the same impact as s. A missing or mistyped field is
// InputError(prefix + field name, ...); a scene that fails validate() keeps validate()'s field
// (the caller says where the JSON came from). Calibration files written before this form gave
// the velocity as "velocity": it is read when "v0" is absent.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"

namespace ivv {

// JSON has no infinity or NaN: an absent or undefined value is null (every writer's rule).
nlohmann::json finite_or_null(double v);

nlohmann::json scene_json(const Scene& scene, const DerivedParameters& p);
nlohmann::json scene_json(const Scene& scene);  // derive()s the scene (valid) itself
// The [structure] of a scene: its inputs, each element's dashpot, the series c, the formula;
// null without one.
nlohmann::json structure_json(const Scene& scene);

// `prefix` is prepended to the field names in messages, e.g. "cal.json: scene.".
Scene scene_from_json(const nlohmann::json& j, const std::string& prefix);

// "none", "ratio", "coefficient", "zener_lambda", "structure": the damping kinds as written.
const char* damping_kind_name(Damping::Kind kind);

}  // namespace ivv
