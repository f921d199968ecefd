// The 5 mm steel ball of the shipped plate scenes (4.168 g, R = 5 mm, 207 GPa, nu = 0.3) at
// 1 m/s on an a x b x h simply supported steel plate (207 GPa, nu = 0.3, 7960 kg/m^3): the
// scene of reference_data/scenes/steel-ball-on-finite-steel-plate.toml with a = b = 0.2 m,
// h = 2 mm. One definition for the tests of every layer that strike such a plate.
#pragma once

#include <optional>

#include "scene/scene.h"

namespace ivv {

// The ball at 1 m/s striking `structure` (its dashpot, or its modes when finite); yield [Pa] the
// target's yield strength (none: an elastic target).
inline Scene steel_ball_on(const Structure& structure, std::optional<double> yield = std::nullopt) {
  Scene s;
  s.mass = 0.004168;
  s.radius = 0.005;
  s.impactor_youngs_modulus = 207e9;
  s.impactor_poisson_ratio = 0.3;
  s.target_youngs_modulus = 207e9;
  s.target_poisson_ratio = 0.3;
  s.yield_strength = yield;
  s.velocity = 1.0;
  s.damping = Damping::from_structure(structure);
  return s;
}

// a, b, h [m]; yield [Pa] the target's yield strength (none: an elastic target).
inline Scene steel_ball_on_plate(double a, double b, double h,
                                 std::optional<double> yield = std::nullopt) {
  Structure st;
  st.kind = Structure::Kind::plate;
  st.thickness = h;
  st.density = 7960.0;
  st.length_x = a;
  st.length_y = b;
  st.edges = PlateEdges::simply_supported;
  return steel_ball_on(st, yield);
}

}  // namespace ivv
