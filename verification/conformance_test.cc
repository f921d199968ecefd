// The conformance checks themselves: a sound law passes, and each defect is caught by the
// check meant for it (a broken stiffness, unloading above loading, a jump at onset, an unmet
// claim). The downstream GoogleTest suite is instantiated here too, for the Hertz law.
#include "verification/conformance.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/input_error.h"
#include "solver/laws/hertz.h"
#include "verification/conformance_gtest.h"
#include "verification/conformance_law.h"

namespace ivv::conformance {
namespace {

// A small, fast grid: three velocities over three decades, with and without a dashpot.
Grid small_grid() {
  Grid g = default_grid(paper_scene());
  g.velocities = {0.01, 0.3, 10.0};
  return g;
}

const Check& check(const Report& r, const std::string& id) {
  for (const Check& c : r.checks)
    if (c.id == id) return c;
  throw std::runtime_error("no check " + id + " in the report:\n" + r.full());
}

LawUnderTest hertz() {
  return law_under_test<HertzLaw>("hertz", "F = K_h z^{3/2}",
                                  [](const Scene& s) { return HertzLaw{derive(s).K_h}; });
}

TEST(Conformance, TheHertzLawPassesEveryCheck) {
  Claims claims;
  claims.elastic_at_low_speed = true;
  claims.expected_cor = [](double) { return 1.0; };
  claims.expected_cor_text = "1";
  const Report r = run_conformance(hertz(), claims, small_grid());
  EXPECT_TRUE(r.passed()) << r.full();
  // autodiff and the 50-digit reference were both used for this templated law
  EXPECT_NO_THROW(check(r, "static.stiffness"));
  EXPECT_NE(check(r, "dynamic.integrators").detail.find("mp50"), std::string::npos);
  EXPECT_NEAR(check(r, "dynamic.expected_cor").measured, 0.0, 1e-7);
}

// A claimed COR of 0/0 passed "at no separated run"; sqrt(-1) the same.
TEST(Conformance, ClaimThatIsNotAFiniteCorIsBadInput) {
  for (double bad : {std::nan(""), 1.5, -0.1}) {
    Claims claims;
    claims.expected_cor = [bad](double) { return bad; };
    claims.expected_cor_text = "bad";
    try {
      run_conformance(hertz(), claims, small_grid());
      ADD_FAILURE() << "accepted the claim " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "--expect-cor");
    }
  }
}

// A scene without a yield strength has no damping ratio; its default grid
// is undamped instead of failing on damping.zeta.
TEST(Conformance, DefaultGridOfASceneWithoutYieldIsUndamped) {
  Scene s = paper_scene();
  s.yield_strength.reset();
  EXPECT_EQ(default_grid(s).zetas, std::vector<double>{0.0});
  EXPECT_EQ(default_grid(paper_scene()).zetas, (std::vector<double>{0.0, 0.1}));
}

// Hertz with a stiffness 1 % off: only the autodiff comparison can see it.
struct WrongStiffness : HertzLaw {
  template <class T>
  T stiffness(const Branch<T>& b, const T& z, const T& v) const {
    return 1.01 * HertzLaw::stiffness(b, z, v);
  }
};

TEST(Conformance, AWrongStiffnessIsCaughtByAutomaticDifferentiation) {
  const auto law = law_under_test<WrongStiffness>(
      "wrong-stiffness", "Hertz, stiffness 1% high",
      [](const Scene& s) { return WrongStiffness{{derive(s).K_h}}; });
  const Report r = run_conformance(law, {}, small_grid());
  const Check& c = check(r, "static.stiffness");
  EXPECT_FALSE(c.passed);
  EXPECT_GT(c.measured, 1e-3);  // 1 % of a stiffness of order k_ref
}

// An unloading curve above loading: F_unload = 1.1 F_load, which creates energy.
struct EnergyCreating : HertzLaw {
  template <class T>
  T force(const Branch<T>& b, const T& z, const T& v) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::force(b, z, v);
  }
  template <class T>
  T stiffness(const Branch<T>& b, const T& z, const T& v) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::stiffness(b, z, v);
  }
  template <class T>
  T stored_energy(const Branch<T>& b, const T& z) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::stored_energy(b, z);
  }
};

TEST(Conformance, UnloadingAboveLoadingIsCaught) {
  const auto law = law_under_test<EnergyCreating>(
      "energy-creating", "Hertz loading, unloading 10% higher",
      [](const Scene& s) { return EnergyCreating{{derive(s).K_h}}; });
  const Report r = run_conformance(law, {}, small_grid());
  EXPECT_FALSE(check(r, "static.unloading_below").passed);
  EXPECT_FALSE(check(r, "static.unloading_switch").passed);  // it jumps at z_m too
  EXPECT_FALSE(check(r, "dynamic.cor_range").passed);        // e = sqrt(1.1) > 1
  EXPECT_FALSE(r.passed());
}

TEST(Conformance, KelvinVoigtFailsAtOnsetWithTheReason) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "k*z + c*zdot";
  req.parameters = {{"k", 4e6}, {"c", 11440.0}};
  const Report r = run_conformance(registry_law(req), {}, small_grid());
  const Check& onset = check(r, "static.onset");
  EXPECT_FALSE(onset.passed);
  EXPECT_NE(onset.detail.find("jumps at impact"), std::string::npos) << onset.detail;
  EXPECT_FALSE(r.passed());
  // an expression law cannot run in 50 digits: its checks say what they used instead
  EXPECT_NE(check(r, "dynamic.integrators").detail.find("dp45 at rtol 1e-13"), std::string::npos);
  bool stiffness_na = false;
  for (const auto& [id, why] : r.skipped) stiffness_na |= id == "static.stiffness";
  EXPECT_TRUE(stiffness_na);
}

TEST(Conformance, AnUnmetCorClaimReportsTheMiss) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::hertz;
  Claims claims;
  claims.expected_cor = [](double) { return 0.9; };  // Hertz is elastic: e = 1
  claims.expected_cor_text = "0.9";
  const Report r = run_conformance(registry_law(req), claims, small_grid());
  const Check& c = check(r, "dynamic.expected_cor");
  EXPECT_FALSE(c.passed);
  EXPECT_NEAR(c.measured, 0.1, 1e-7);
  EXPECT_NE(c.detail.find("over"), std::string::npos) << c.detail;
}

TEST(Conformance, JsonCarriesTheVerdictAndEveryCheck) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::elastoplastic;
  const Report r = run_conformance(registry_law(req), {}, small_grid());
  const auto j = to_json(r);
  EXPECT_EQ(j["verdict"], r.passed() ? "pass" : "fail");
  ASSERT_EQ(j["checks"].size(), r.checks.size());
  for (const auto& c : j["checks"])
    for (const char* key : {"id", "passed", "measured", "reference", "tolerance", "why", "detail"})
      EXPECT_TRUE(c.contains(key)) << key;
}

TEST(Conformance, AnUndeclaredJumpIsLocatedWithItsOneSidedValues) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "z < z1 ? K_h*z^1.5 : 1.5*K_h*z^1.5";
  req.parameters = {{"z1", 2e-4}};
  const Report r = run_conformance(registry_law(req), {}, small_grid());
  const Check& c = check(r, "static.continuity");
  EXPECT_FALSE(c.passed);
  EXPECT_FALSE(r.passed());
  EXPECT_NE(c.detail.find("z = 0.0002 m"), std::string::npos) << c.detail;
  const double F = derive(paper_scene()).K_h * std::pow(2e-4, 1.5);
  ASSERT_TRUE(c.value && c.reference_value);
  EXPECT_NEAR(*c.reference_value, F, 1e-12 * F);  // F(z1-)
  EXPECT_NEAR(*c.value, 1.5 * F, 1e-12 * F);      // F(z1+)
  // the same law without the jump passes the scan, and says what the scan cannot see
  req.expression.force = "K_h*z^1.5";
  const Report smooth = run_conformance(registry_law(req), {}, small_grid());
  EXPECT_TRUE(check(smooth, "static.continuity").passed);
  EXPECT_NE(check(smooth, "static.continuity").detail.find("pulse narrower than"),
            std::string::npos);
}

TEST(Conformance, CapturedRunsAreComparedOnTheirBoundNotOnAContactTime) {
  // Walton-Braun: e = sqrt(k1/k2) = 0.5; at zeta = 1 and 10 every run is captured
  const double k1 = derive(paper_scene()).K_y;
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "k1*z";
  req.expression.unload = "k2*(z - zmax*(1 - k1/k2))";
  req.parameters = {{"k1", k1}, {"k2", 4 * k1}};
  Grid grid = small_grid();
  grid.zetas = {0.0, 0.1, 1.0, 10.0};
  Claims claims;
  claims.expected_cor = [](double) { return 0.5; };
  claims.expected_cor_text = "0.5";
  const Report r = run_conformance(registry_law(req), claims, grid);
  EXPECT_TRUE(r.passed()) << r.full();
  EXPECT_NE(check(r, "dynamic.integrators").detail.find("captured"), std::string::npos);
  int captured = 0;
  for (const CorPoint& p : r.cor) captured += p.status == "captured";
  EXPECT_GT(captured, 0);
}

TEST(Conformance, TheResultReportsUnitsBoundsAndSkippedChecks) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "k*z + c*zdot";
  req.parameters = {{"k", 4e6}, {"c", 11440.0}};
  const Report r = run_conformance(registry_law(req), {}, small_grid());
  const Check& onset = check(r, "static.onset");
  EXPECT_EQ(onset.unit, "F_ref");
  EXPECT_EQ(onset.si_unit, "N");
  ASSERT_TRUE(onset.value);
  EXPECT_NEAR(*onset.value, 11440.0 * 10.0, 1e-6);  // F(0) = c v at the grid's largest v0
  EXPECT_NE(onset.measured_text().find(" N)"), std::string::npos) << onset.measured_text();
  EXPECT_EQ(check(r, "static.attractive").bound, Bound::at_least);
  EXPECT_EQ(check(r, "static.attractive").tolerance_text().substr(0, 2), ">=");
  ASSERT_NE(r.find_skipped("dynamic.expected_cor"), nullptr);
  EXPECT_NE(r.full().find("SKIP  dynamic.expected_cor"), std::string::npos);
  EXPECT_NE(r.brief().find("skipped"), std::string::npos);
  const auto j = to_json(r);
  EXPECT_EQ(j["skipped"].size(), r.skipped.size());
  EXPECT_EQ(j["brief"], r.brief());
  // the plots: e(v0) with the e = 1 line, and the force-deformation loops
  const auto plots = r.plots();
  ASSERT_EQ(plots.size(), 2u);
  bool elastic_line = false;
  for (const auto& s : plots[0].series) elastic_line |= s.label.rfind("e = 1", 0) == 0;
  EXPECT_TRUE(elastic_line);
  EXPECT_TRUE(plots[0].margins);
  EXPECT_FALSE(plots[1].series.empty());
}

TEST(Conformance, AnElasticSceneWithADashpotCoefficientGetsItsOwnDamping) {
  // no yield strength: zeta is not defined; the scene's c is the damped grid point
  Scene s = paper_scene();
  s.yield_strength.reset();
  s.damping = Damping::coefficient(500.0);
  const Grid g = default_grid(s);
  EXPECT_EQ(g.zetas, std::vector<double>{0.0});
  EXPECT_EQ(g.dashpots, std::vector<double>{500.0});
  SimulationRequest req;
  req.scene = s;
  req.law = LawKind::hertz;
  Grid small = g;
  small.velocities = {0.01, 0.3, 10.0};
  const Report r = run_conformance(registry_law(req), {}, small);
  EXPECT_TRUE(r.passed()) << r.full();
  bool damped = false;
  for (const CorPoint& p : r.cor) damped |= p.c == 500.0 && p.damping_label() == "c = 500 N s/m";
  EXPECT_TRUE(damped);
}

// The suite a downstream project instantiates, here for the Hertz law.
testing::Subject hertz_subject() {
  Claims claims;
  claims.elastic_at_low_speed = true;
  return {hertz(), claims, small_grid()};
}
IVV_CONFORMANCE_SUITE(HertzConformance, hertz_subject);

}  // namespace
}  // namespace ivv::conformance
