// The stiff-dashpot bound of dashpot_stall.h through simulate(): an explicit stepper that cannot
// reach the end of a dashpot-controlled impact fails at once, by name, and an implicit one
// decides it; an explicit stepper that can finish is not stopped.
#include "solver/driver/dashpot_stall.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv {
namespace {

// A 100 um glass bead (R = 50 um, E = 48 GPa, nu = 0.2, rho = 2800 kg/m^3) on glass, with a
// JKR-type unloading K_h z^{3/2} - F_ad (1 - z/z_max) (F_ad = 3.1e-5 N) and a dashpot of
// c = 1e-6 N s/m: zeta ~ 2000, the spring-dashpot relaxation on the unloading branch (slope
// F_ad/z_max ~ 3e6 N/m at z_max = 1.2e-11 m, v0 = 1 cm/s) far faster than the impactor, which
// the dashpot slows over m/c = 1.5 ms.
SimulationRequest jkr_bead(double v0, IntegratorKind k) {
  SimulationRequest req;
  req.scene.name = "glass-bead";
  req.scene.radius = 50e-6;
  req.scene.mass = 2800.0 * 4.0 / 3.0 * std::numbers::pi * std::pow(50e-6, 3);
  req.scene.impactor_youngs_modulus = req.scene.target_youngs_modulus = 48e9;
  req.scene.impactor_poisson_ratio = req.scene.target_poisson_ratio = 0.2;
  req.scene.velocity = v0;
  req.scene.damping = Damping::coefficient(1e-6);
  req.law = LawKind::expression;
  req.expression = {"K_h*z^1.5", "K_h*z^1.5 - Fad*(1 - z/zmax)", true};
  req.parameters = {{"Fad", 3.1e-5}};
  req.integrator = k;
  req.model = ModelKind::full;
  return req;
}

// Before the bound, dp45 took 2e6 steps (and, with the well's quadrature halving to its depth
// limit, 9 ms each) to stop at tau = 7 of the ~3900 the dashpot needs.
TEST(DashpotStall, AnExplicitStepperFailsAtOnceWhereOnlyAnImplicitOneCanFinish) {
  for (double v0 : {1e-2, 1.0})
    for (IntegratorKind k : {IntegratorKind::dp45, IntegratorKind::dop853,
                             IntegratorKind::odeint_dopri5, IntegratorKind::gsl_rk8pd}) {
      const ImpactResult r = simulate(jkr_bead(v0, k));
      EXPECT_EQ(r.failure, FailureKind::step_limit) << to_string(k) << " v0 = " << v0;
      EXPECT_LT(r.steps, 10'000) << to_string(k) << ": stopped only at " << r.steps;
      EXPECT_NE(r.reason.find("needs an implicit integrator"), std::string::npos) << r.reason;
    }
  for (IntegratorKind k : {IntegratorKind::rodas4, IntegratorKind::odeint_rosenbrock4}) {
    const ImpactResult r = simulate(jkr_bead(1e-2, k));
    EXPECT_EQ(r.status, ImpactStatus::captured) << to_string(k) << ": " << r.reason;
    EXPECT_LT(r.steps, 10'000) << to_string(k);
  }
}

// The paper scene's Hertz law at zeta = 300: dop853 needs ~4e4 steps, held by stability, and
// captures; the bound (a lower bound on the time left) does not stop it.
TEST(DashpotStall, AnExplicitStepperThatCanFinishIsNotStopped) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = Damping::ratio(300);
  req.law = LawKind::hertz;
  req.integrator = IntegratorKind::dop853;
  req.model = ModelKind::full;
  const ImpactResult r = simulate(req);
  EXPECT_EQ(r.status, ImpactStatus::captured) << r.reason;
  EXPECT_GT(r.steps, 10'000);  // the stability-held regime the bound watches
}

// The margin kStallMargin holds: runs an explicit stepper finishes, held by stability to a stiff
// dashpot, given a budget of exactly the steps they take (max_steps = N: at every check the steps
// left are the steps the run really needs), still finish with the same e. The stop fires only
// where the projection exceeds 10 times the steps left, so it did not fire: on these runs the
// projection at the present step stays below 10 times the steps really needed.
TEST(DashpotStall, ItCannotFireOnARunThatFinishesWithinItsBudget) {
  struct Finishing {
    std::string what;
    SimulationRequest req;
  };
  std::vector<Finishing> runs;
  for (double zeta : {30.0, 300.0})
    for (LawKind law : {LawKind::hertz, LawKind::elastoplastic}) {
      SimulationRequest req;
      req.scene = paper_scene();
      req.scene.velocity = 1.0;
      req.scene.damping = Damping::ratio(zeta);
      req.law = law;
      req.model = ModelKind::full;
      runs.push_back({std::string(to_string(law)) + " zeta = " + std::to_string(zeta), req});
    }
  SimulationRequest bead = jkr_bead(1e-2, IntegratorKind::dp45);
  bead.scene.damping = Damping::coefficient(1e-4);  // zeta ~ 20: explicit steppers finish
  runs.push_back({"JKR bead c = 1e-4", bead});
  for (Finishing& f : runs)
    for (IntegratorKind k : {IntegratorKind::dop853, IntegratorKind::dp45}) {
      f.req.integrator = k;
      f.req.options.max_steps = 2'000'000;
      const ImpactResult free = simulate(f.req);
      ASSERT_TRUE(free.ok()) << f.what << " " << to_string(k) << ": " << free.reason;
      ASSERT_GT(free.steps, 1000) << f.what << ": not the stability-held regime the stop watches";
      f.req.options.max_steps = free.steps;
      const ImpactResult tight = simulate(f.req);
      EXPECT_TRUE(tight.ok()) << f.what << " " << to_string(k) << ": " << tight.reason;
      EXPECT_EQ(tight.e, free.e) << f.what << " " << to_string(k);
    }
}

}  // namespace
}  // namespace ivv
