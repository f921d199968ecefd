// The conformance checks on a finite plate through the C++ API and the GoogleTest front end: a
// C++ law of a user struck against the plate's modes, every check run on the plate or skipped
// with its reason.
#include <gtest/gtest.h>

#include <string>

#include "scene/input_error.h"
#include "solver/laws/hertz.h"
#include "solver/plate/steel_ball_on_plate.h"
#include "verification/conformance.h"
#include "verification/conformance_gtest.h"
#include "verification/conformance_plate_law.h"

namespace ivv::conformance {
namespace {

// The 5 mm steel ball (4.168 g) on the 200 x 200 x 2 mm simply supported steel plate
// (reference_data/scenes/steel-ball-on-finite-steel-plate.toml).
Scene ball_on_finite_plate() {
  Scene s = steel_ball_on_plate(0.2, 0.2, 0.002);
  s.name = "steel-ball-on-finite-steel-plate";
  return s;
}

LawUnderTest cxx_hertz() {
  return law_under_test_on_plate<HertzLaw>("hertz", "F = K_h z^{3/2}",
                                           [](const Scene& s) { return HertzLaw{derive(s).K_h}; });
}

Grid plate_grid() {
  Grid g = default_grid(ball_on_finite_plate());
  g.velocities = {0.3, 1.0};
  return g;
}

TEST(ConformanceOnAPlate, TheDefaultGridHasNoDashpotAndADashpotIsBadInput) {
  const Grid g = default_grid(ball_on_finite_plate());
  EXPECT_EQ(g.zetas, std::vector<double>{0.0});
  EXPECT_TRUE(g.dashpots.empty());
  Grid damped = plate_grid();
  damped.dashpots = {100.0};
  EXPECT_THROW(run_conformance(cxx_hertz(), {}, damped), InputError);
}

// Hertz on the plate: e < 1 (the plate keeps vibration energy), every COR point is the plate's
// final e, and the plate's checks ran.
TEST(ConformanceOnAPlate, ACxxLawIsStruckAgainstThePlate) {
  const Report r = run_conformance(cxx_hertz(), {}, plate_grid());
  EXPECT_TRUE(r.passed()) << r.full();
  ASSERT_EQ(r.cor.size(), 2u);
  for (const CorPoint& c : r.cor) {
    EXPECT_TRUE(c.finite_plate);
    EXPECT_EQ(c.damping_label(), "finite plate");
    ASSERT_TRUE(c.e);
    EXPECT_LT(*c.e, 0.5);  // Zener's problem on this plate: e = 0.19 at 1 m/s
  }
  for (const char* id : {"dynamic.energy", "dynamic.impulse", "dynamic.integrators"})
    EXPECT_NE(r.find(id), nullptr) << id;
  ASSERT_NE(r.find_skipped("dynamic.monotone_v0"), nullptr);
  EXPECT_NE(r.find_skipped("dynamic.monotone_v0")->why.find("plate"), std::string::npos);
}

// A COR claimed on the plate is judged on the final e, within the claim's tolerance plus the
// plate's estimated truncation error: e = 0.19234 at 1 m/s (the infinite plate's, the shipped
// scene's note) is met to 1e-4, a claim of 0.3 is missed.
TEST(ConformanceOnAPlate, AClaimIsJudgedOnTheFinalCor) {
  Grid g = plate_grid();
  g.velocities = {1.0};
  Claims claims;
  claims.expected_cor = [](double) { return 0.19234; };
  claims.expected_cor_text = "0.19234";
  claims.cor_tolerance = 1e-4;
  claims.cor_tolerance_reason = "the claim's five digits";
  EXPECT_TRUE(run_conformance(cxx_hertz(), claims, g).find("dynamic.expected_cor")->passed);
  claims.expected_cor = [](double) { return 0.3; };
  const Report missed = run_conformance(cxx_hertz(), claims, g);
  EXPECT_FALSE(missed.find("dynamic.expected_cor")->passed);
  EXPECT_NEAR(missed.find("dynamic.expected_cor")->measured, 0.3 - 0.19234, 1e-4);
}

// The suite a downstream project instantiates, on the plate.
testing::Subject hertz_on_a_plate() {
  return {cxx_hertz(), {}, plate_grid()};
}
IVV_CONFORMANCE_SUITE(HertzOnAFinitePlate, hertz_on_a_plate);

}  // namespace
}  // namespace ivv::conformance
