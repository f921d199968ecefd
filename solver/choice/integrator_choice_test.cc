// --integrator auto chooses by estimated cost (solver/choice/integrator_choice.h): on heavily
// damped scenes (where a stiffness ratio chose rodas4 at 2-10x dop853's time) the choice must be
// the candidate that does less work, judged by running both. Work is counted in accepted steps,
// which is deterministic: the two candidates cost the same per step (kMicrosecondsPerStepExplicit
// == kMicrosecondsPerStepImplicit, measured), so the fewer steps is the faster run.
#include "solver/choice/integrator_choice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "solver/format.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

SimulationRequest paper_request(double v0, double zeta, double rtol) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = v0;
  req.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  req.law = LawKind::elastoplastic;
  req.model = ModelKind::full;
  req.options.rtol = req.options.atol = rtol;
  return req;
}

long steps_with(SimulationRequest req, IntegratorKind k) {
  req.integrator = k;
  req.auto_integrator = false;
  const ImpactResult r = simulate(req);
  EXPECT_TRUE(r.ok()) << to_string(k) << ": " << r.reason;
  return r.steps;
}

struct DampedScene {
  double v0, zeta;
};

class CheaperChoice : public ::testing::TestWithParam<DampedScene> {};

TEST_P(CheaperChoice, ChosenIntegratorTakesFewerStepsThanTheOther) {
  static_assert(kMicrosecondsPerStepExplicit == kMicrosecondsPerStepImplicit,
                "steps compare the costs only while a step costs the same in both");
  const SimulationRequest req = paper_request(GetParam().v0, GetParam().zeta, 1e-8);
  const IntegratorKind chosen = choose_integrator(req).integrator;
  const IntegratorKind other =
      chosen == IntegratorKind::dop853 ? IntegratorKind::rodas4 : IntegratorKind::dop853;
  const long chosen_steps = steps_with(req, chosen);
  const long other_steps = steps_with(req, other);
  EXPECT_LT(chosen_steps, other_steps)
      << "v0 = " << GetParam().v0 << " m/s, zeta = " << GetParam().zeta << ": chose "
      << to_string(chosen) << " (" << chosen_steps << " steps) over " << to_string(other) << " ("
      << other_steps << " steps)";
}

// v0 = 5 m/s, zeta 8-16 (capture at the start of unloading: dop853, ~14 against ~50
// steps), v0 = 1 m/s, zeta 8-16 (dop853 140 against rodas4 306 at zeta 8, 347 against 270 at
// zeta 16); v0 = 0.3, zeta 16 (252 against 325) and zeta = 100 (thousands against ~180)
INSTANTIATE_TEST_SUITE_P(DampedPaperScenes, CheaperChoice,
                         ::testing::Values(DampedScene{5.0, 8.0}, DampedScene{5.0, 16.0},
                                           DampedScene{1.0, 8.0}, DampedScene{1.0, 16.0},
                                           DampedScene{0.3, 16.0}, DampedScene{1.0, 100.0},
                                           DampedScene{1.0, 0.1}));

// capture.h criterion 1 at the estimated z_m as the cost model states it: the elastoplastic
// unloading slope at the permanent set, 1.5 K_h sqrt(z_f), overdamped, K_f m >= 4 c^2, z_f > 0.
bool written_early_capture(const DerivedParameters& p, double z_m) {
  if (!p.has_yield() || !(z_m > p.z_y)) return false;
  const double s = z_m * std::sqrt(z_m) - p.z_y * std::sqrt(p.z_y) - p.K_y / p.K_h * (z_m - p.z_y);
  const double z_f = s > 0 ? std::cbrt(s * s) : 0.0;
  return z_f > 0 && 1.5 * p.K_h * std::sqrt(z_f) * p.effective_mass >= 4.0 * p.c * p.c;
}

// The cost model decides early capture without the cube root where the answer is clear, and by
// the written form near the boundary: the same decision on a grid of v0 x zeta and at points
// approaching each v0's boundary in zeta (found by bisection to adjacent doubles) from both sides,
// from 1e-6 down to a few ulps away.
TEST(IntegratorChoice, EarlyCaptureWithoutTheCubeRootIsTheWrittenDecision) {
  int boundaries = 0;
  for (double v0 : {0.05, 0.3, 1.0, 5.0, 20.0}) {
    auto decisions = [v0](double zeta) {
      Scene s = paper_scene();
      s.velocity = v0;
      s.damping = Damping::ratio(zeta);
      const DerivedParameters p = derive(s);
      const IntegratorCosts k = estimate_integrator_costs(s, p, LawKind::elastoplastic, 1e-8);
      return std::pair{k.early_capture, written_early_capture(p, k.z_max)};
    };
    for (double zeta = 1e-3; zeta < 1e3; zeta *= 1.07) {
      const auto [model, written] = decisions(zeta);
      EXPECT_EQ(model, written) << "v0 " << v0 << " zeta " << zeta;
      if (written == decisions(zeta * 1.07).second) continue;
      double lo = zeta, hi = zeta * 1.07;  // a boundary between: bisected to adjacent doubles
      while (std::nextafter(lo, hi) < hi) {
        const double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo && mid < hi)) break;
        (decisions(mid).second == decisions(lo).second ? lo : hi) = mid;
      }
      ++boundaries;
      for (double d = 1e-6; d > 1e-17; d /= 10)
        for (double z : {hi * (1 + d), lo * (1 - d), hi, lo}) {
          const auto [near_model, near_written] = decisions(z);
          EXPECT_EQ(near_model, near_written) << "v0 " << v0 << " zeta " << z << " (boundary)";
        }
    }
  }
  EXPECT_GE(boundaries, 3);  // the boundary lies inside the range at most of these v0
}

TEST(IntegratorChoice, HeavilyDampedFastImpactIsExplicit) {
  for (double zeta : {8.0, 16.0})
    EXPECT_EQ(choose_integrator(paper_request(5.0, zeta, 1e-8)).integrator, IntegratorKind::dop853)
        << "zeta " << zeta;
}

TEST(IntegratorChoice, ReasonsStateBothCostsAndTheWinner) {
  const IntegratorChoice c = choose_integrator(paper_request(1.0, 16.0, 1e-8));
  std::string all;
  for (const std::string& why : c.reasons) all += why + "\n";
  EXPECT_NE(all.find("dop853 " + fmt(c.costs.steps_explicit, 3) + " steps"), std::string::npos)
      << all;
  EXPECT_NE(all.find("rodas4 " + fmt(c.costs.steps_implicit, 3) + " steps"), std::string::npos)
      << all;
  EXPECT_NE(all.find("is the cheaper"), std::string::npos) << all;
}

TEST(IntegratorChoice, ScenesWithoutDashpotOrYieldStrength) {
  SimulationRequest none = paper_request(1.0, 0.0, 1e-8);
  const IntegratorChoice c = choose_integrator(none);
  EXPECT_EQ(c.integrator, IntegratorKind::dop853);
  EXPECT_EQ(c.costs.steps_explicit, kAccuracyStepsExplicit);

  SimulationRequest hertz = paper_request(1.0, 0.0, 1e-8);
  hertz.scene.yield_strength.reset();
  hertz.law = LawKind::hertz;
  for (double c_dashpot : {1.0, 1e6}) {
    hertz.scene.damping = Damping::coefficient(c_dashpot);
    const IntegratorChoice h = choose_integrator(hertz);
    EXPECT_TRUE(std::isfinite(h.costs.us_explicit) && std::isfinite(h.costs.us_implicit));
    for (const std::string& why : h.reasons) EXPECT_EQ(why.find("nan"), std::string::npos) << why;
  }
}

// `--integrator auto` on a scene without a yield strength computed its stiffness ratio from
// NaN (zeta, z_y), called it "not stiff", and dop853 ran out of steps where rodas4 succeeds
// (chung-ooi-2-aluminium, hertz, c = 1 N s/m).
TEST(IntegratorChoice, WithoutYieldStrengthMeasuresStiffness) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.yield_strength.reset();
  req.scene.damping = Damping::coefficient(1.0);
  req.law = LawKind::hertz;
  const DerivedParameters p = derive(req.scene);
  const double S = stiffness_ratio(req.scene, p);
  ASSERT_TRUE(std::isfinite(S));
  EXPECT_GT(S, 100.0);  // c = 1 N s/m: the dashpot relaxes far faster than loading
  EXPECT_EQ(auto_integrator(req, p), IntegratorKind::rodas4);
  req.auto_integrator = true;
  const ImpactResult r = simulate(req);
  EXPECT_TRUE(r.ok()) << r.reason;
  const IntegratorChoice c = choose_integrator(req);
  for (const std::string& why : c.reasons) EXPECT_EQ(why.find("nan"), std::string::npos) << why;
}

}  // namespace
}  // namespace ivv
