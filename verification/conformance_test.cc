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

// Issue 21 item 3: a claimed COR of 0/0 passed "at no separated run"; sqrt(-1) the same.
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

// Issue 21 item 14: a scene without a yield strength has no damping ratio; its default grid
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
  for (const auto& [id, why] : r.not_applicable) stiffness_na |= id == "static.stiffness";
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

// The suite a downstream project instantiates, here for the Hertz law.
testing::Subject hertz_subject() {
  Claims claims;
  claims.elastic_at_low_speed = true;
  return {hertz(), claims, small_grid()};
}
IVV_CONFORMANCE_SUITE(HertzConformance, hertz_subject);

}  // namespace
}  // namespace ivv::conformance
