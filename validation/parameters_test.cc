// Named parameters: every fittable name reads back what it sets, and bad names are bad input.
#include "validation/parameters.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"

namespace ivv::validation {
namespace {

SimulationRequest paper_request() {
  SimulationRequest r;
  r.scene = paper_scene();
  r.scene.damping = Damping::ratio(0.1);
  return r;
}

TEST(Parameters, EveryFittableNameReadsBackWhatItSets) {
  SimulationRequest r = paper_request();
  for (const auto& name : fittable_parameters(r)) {
    if (name == "zeta") continue;  // below: zeta and c are one dashpot
    const double v = parameter_value(r, name) * 1.25;
    set_parameter(r, name, v);
    EXPECT_DOUBLE_EQ(parameter_value(r, name), v) << name;
  }
  set_parameter(r, "zeta", 0.2);
  EXPECT_NEAR(parameter_value(r, "zeta"), 0.2, 1e-15);
}

TEST(Parameters, DashpotGivenAsRatioReadsAsCoefficient) {
  // paper scene: zeta = 0.1 <=> c = 11440 N s/m (docs/design.md §1, to the 4 digits given there)
  EXPECT_NEAR(parameter_value(paper_request(), "c"), 11440, 0.5e-3 * 11440);
}

TEST(Parameters, LawParametersTakeTheSceneDefault) {
  SimulationRequest r = paper_request();
  r.law = LawKind::hunt_crossley;
  const DerivedParameters p = derive(r.scene);
  EXPECT_DOUBLE_EQ(parameter_value(r, "K"), p.K_h);
}

TEST(Parameters, BadNamesAreBadInputNamingFit) {
  SimulationRequest r = paper_request();
  EXPECT_THROW(check_fit_names(r, {"mu"}), InputError);  // not a parameter of elastoplastic
  EXPECT_THROW(check_fit_names(r, {"c", "c"}), InputError);
  EXPECT_THROW(check_fit_names(r, {"c", "zeta"}), InputError);
  EXPECT_THROW(check_fit_names(r, {}), InputError);
  r.scene.damping = Damping::none();
  EXPECT_THROW(parameter_value(r, "c"), InputError);
  try {
    check_fit_names(r, {"nonsense"});
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--fit");
    EXPECT_NE(std::string(e.what()).find("yield_strength"), std::string::npos);
  }
}

}  // namespace
}  // namespace ivv::validation
