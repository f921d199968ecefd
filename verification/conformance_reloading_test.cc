// The reloading checks (verification/conformance_reloading.cc): laws that dissipate or retrace on
// reloading pass; a law whose reloading is softer than its unloading creates energy over a
// cycle below z_m and fails static.reloading, and only that check of the static ones.
#include <gtest/gtest.h>

#include <string>

#include "verification/conformance.h"
#include "verification/conformance_internal.h"

namespace ivv::conformance {
namespace {

const Check& check(const Report& r, const std::string& id) {
  for (const Check& c : r.checks)
    if (c.id == id) return c;
  throw std::runtime_error("no check " + id + " in the report:\n" + r.full());
}

// One velocity, no dashpot: the reloading checks do not depend on the grid beyond its largest v0.
Grid one_point() {
  Grid g = default_grid(paper_scene());
  g.velocities = {0.3};
  g.zetas = {0.0};
  return g;
}

Report conformance_of(const SimulationRequest& req) {
  return run_conformance(registry_law(req), {}, one_point());
}

// The static checks alone (no impact run): those at zdot = 0 and the reloading ones, at v = 0.3.
Report static_checks_of(const SimulationRequest& req) {
  Report r;
  const LawUnderTest law = registry_law(req);
  detail::static_checks(law, paper_scene(), 0.3, 2.0 * detail::hertz_scales(paper_scene(), 0.3).z,
                        r);
  detail::reloading_checks(law, paper_scene(), 0.3, r);
  return r;
}

TEST(Reloading, TheElastoplasticLawRetracesItsUnloadingCurveAndLoadsOnBeyondZm) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::elastoplastic;
  const Report r = conformance_of(req);
  const Check& cycle = check(r, "static.reloading");
  EXPECT_TRUE(cycle.passed) << cycle.line();
  EXPECT_EQ(cycle.measured, 0.0) << cycle.line();  // the same branch both ways: no rate term
  EXPECT_EQ(cycle.unit, "F_ref z_ref");
  EXPECT_TRUE(check(r, "static.reloading_beyond").passed) << r.full();
}

// Kelvin-Voigt's dashpot term c zdot pushes more on reloading (zdot > 0) than on unloading:
// the cycle dissipates 2 c v (z_m - z1) > 0, never creates energy.
TEST(Reloading, ARateTermThatDissipatesPasses) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "K_h*z^1.5 + c*zdot*sqrt(z/z_y)";
  req.parameters = {{"c", 1000.0}};
  const Report r = static_checks_of(req);
  const Check& cycle = check(r, "static.reloading");
  EXPECT_TRUE(cycle.passed) << cycle.line();
  EXPECT_LT(cycle.measured, 0.0) << cycle.line();  // returned < put in: dissipated
}

// Hertz on loading and unloading (zdot < 0), but reloading below z_m (zdot > 0) softer by
// mu zdot (1 - z/zmax) (no jump at z_m, where the factor is 1): a cycle z_m -> z1 -> z_m
// returns more work than it takes. At zdot = 0 the law is Hertz throughout, so the checks at
// zdot = 0 (unloading below loading, the switch at z_m) cannot see it.
TEST(Reloading, AReloadingCurveBelowTheUnloadingCurveCreatesEnergyAndFails) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "K_h*z^1.5";
  req.expression.unload = "K_h*z^1.5*(1 - mu*max(zdot, 0)*(1 - z/zmax))";
  req.parameters = {{"mu", 1.0}};  // [s/m]: 30 % softer at zdot = 0.3 m/s, far from z_m
  const Report r = static_checks_of(req);
  const Check& cycle = check(r, "static.reloading");
  EXPECT_FALSE(cycle.passed) << cycle.line();
  // the energy created: int mu v (1 - z/z_m) K_h z^{3/2} dz over (z1, z_m) is a few per cent of
  // F_ref z_ref at v = 0.3 m/s (measured 0.19); 1e-3 is far above the tolerance (1e-10) and
  // far below that
  EXPECT_GT(cycle.measured, 1e-3) << cycle.line();
  EXPECT_NE(cycle.detail.find("creates energy"), std::string::npos) << cycle.detail;
  ASSERT_TRUE(cycle.value && cycle.reference_value);
  EXPECT_LT(*cycle.value, *cycle.reference_value);  // put in on reloading < returned
  EXPECT_FALSE(r.passed());
  // the failure is the reloading's: the checks at zdot = 0 pass
  for (const char* id : {"static.onset", "static.unloading_switch", "static.unloading_below",
                         "static.reloading_beyond"})
    EXPECT_TRUE(check(r, id).passed) << check(r, id).line();
}

}  // namespace
}  // namespace ivv::conformance
