// Run failures: no silent wrong number, every failure named with a reason (and its code).
// One test per finding of an adversarial pass over every law and integrator; each fails
// without its fix.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>

#include "scene/input_error.h"
#include "solver/consistency.h"
#include "solver/driver/impact_driver.h"
#include "solver/simulate.h"
#include "solver/steppers/gsl_odeiv2.h"

namespace ivv {
namespace {

// dopri5, rosenbrock4 and msbdf declared "captured" (e = 0) at v0 = 1e16 m/s without a
// dashpot, where the closed form gives e = 6.5e-5. Round-off in the stored energy of the
// unloading branch (a difference of terms sqrt(z_m/z_y) ~ 1e8 times E0) drove the capture
// bound below 1e-9. Without a dashpot nothing dissipates after maximum compression: the run
// must separate, or fail with a reason, never be captured.
TEST(RunFailures, NoCaptureWithoutADashpot) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1e16;
  req.integrator = IntegratorKind::gsl_rk8pd;  // the eighth-order run is the reference
  const ImpactResult ref = simulate(req);
  ASSERT_TRUE(ref.separated()) << ref.reason;
  ASSERT_NEAR(ref.e, 6.5e-5,
              0.05e-5);  // the closed form's value as first reported, to its 2 digits
  for (IntegratorKind k : all_integrators()) {
    if (k == IntegratorKind::mp50 || k == IntegratorKind::rk4) continue;  // slow at this scale
    req.integrator = k;
    const ImpactResult r = simulate(req);
    EXPECT_NE(r.status, ImpactStatus::captured) << to_string(k);
    if (r.ok()) {
      // measured: the runs agree to 1.1e-5 relative (gsl-msbdf; the others 1e-7). 1e-4 is
      // far narrower than the "e = 0" of the bug and leaves msbdf a factor 10
      EXPECT_NEAR(r.e / ref.e, 1.0, 1e-4) << to_string(k);
    } else {
      EXPECT_FALSE(r.reason.empty()) << to_string(k);
    }
  }
}

// rk4 at its default step resolves the loading of this scene (m = 1000 kg,
// R = 0.1 um, v0 = 1000 m/s) but not the unloading, which is (z_m/z_y)^{1/4} ~ 300 times
// faster: e came out 8 % low with status "separated". The CORs disagree far beyond the
// tolerance: a failure with the reason.
TEST(RunFailures, CoarseRk4UnloadingIsAFailureWithAReason) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.mass = 1000.0;
  req.scene.radius = 1e-7;
  req.scene.velocity = 1000.0;
  req.integrator = IntegratorKind::rk4;
  const ImpactResult r = simulate(req);
  EXPECT_EQ(r.status, ImpactStatus::failed) << "e = " << r.e;
  EXPECT_EQ(r.failure, FailureKind::inconsistent) << to_string(r.failure);
  EXPECT_NE(r.reason.find("rk4"), std::string::npos) << r.reason;
  EXPECT_NE(r.reason.find("bound"), std::string::npos) << r.reason;
  // two adaptive integrators meet their tolerance here, pass the same check and agree
  // (rtol 1e-10 over ~100 steps: 1e-7 leaves a factor 10 over the accumulated bound)
  req.integrator = IntegratorKind::odeint_dopri5;
  const ImpactResult ok = simulate(req);
  req.integrator = IntegratorKind::gsl_rk8pd;
  const ImpactResult ok8 = simulate(req);
  ASSERT_TRUE(ok.separated()) << ok.reason;
  ASSERT_TRUE(ok8.separated()) << ok8.reason;
  EXPECT_NEAR(ok.e / ok8.e, 1.0, 1e-7);
  EXPECT_GT(std::abs(r.e / ok8.e - 1.0), 1e-3)
      << "rk4 was right after all: the test proves nothing";
}

TEST(RunFailures, ConsistencyCheckNamesWhatDisagreed) {
  IntegratorOptions opt;
  ConsistencyMeasures m;
  m.has_restitution = true;
  m.steps = 1000;
  m.restitution_steps = 5;
  m.e = 0.000549;
  m.e_poisson = 0.000549;
  m.e_energetic_sq = 0.000618 * 0.000618;  // the rk4 run that came out 8 % low
  EXPECT_NE(consistency_failure(m, opt, "rk4").find("energetic"), std::string::npos);
  m.e_energetic_sq = m.e * m.e;
  EXPECT_EQ(consistency_failure(m, opt, "rk4"), "");
  m.ledger_residual = 1e-3;
  EXPECT_NE(consistency_failure(m, opt, "rk4").find("ledger"), std::string::npos);
  m.ledger_residual = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(consistency_failure(m, opt, "rk4").find("ledger"), std::string::npos);
}

// Near the capture boundary the force reaches zero while the impactor still
// approaches at +1e-13 v0, within the integration error: that is capture (e = 0) with the
// bound, not a failure.
TEST(RunFailures, GrazingCaptureIsCapture) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 2.8923076923076927;
  req.scene.damping = Damping::ratio(0.7777777777777778);
  // the grazing path is the energy criterion's: the exact one (below) decides first here
  req.options.exact_capture = false;
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.ok()) << r.reason;
  if (r.status == ImpactStatus::captured) {
    EXPECT_EQ(r.e, 0.0);
    EXPECT_GT(r.e_bound, 0.0);
    EXPECT_LT(r.e_bound, accumulated_error_bound(r.steps, req.options) * (1 + 1e-12));
  } else {
    EXPECT_GE(r.e, 0.0);
  }
  // With the invariant region of ImpactSystem::capture_margin the same impact is a capture
  // with no rebound at all (e = 0 and e_bound = 0), decided before the creep.
  req.options.exact_capture = true;
  const ImpactResult exact = simulate(req);
  ASSERT_TRUE(exact.ok()) << exact.reason;
  EXPECT_EQ(exact.status, ImpactStatus::captured);
  EXPECT_EQ(exact.e, 0.0);
  EXPECT_EQ(exact.e_bound, 0.0);
  EXPECT_LE(exact.t_contact, r.t_contact);
}

// TOMS 748 out of iterations was never checked.
TEST(RunFailures, RootFinderOutOfIterationsFailsTheRun) {
  for (IntegratorKind k : {IntegratorKind::odeint_dopri5, IntegratorKind::gsl_rk8pd}) {
    SimulationRequest req;
    req.scene = paper_scene();
    req.integrator = k;
    req.options.locator.max_iterations = 1;
    const ImpactResult r = simulate(req);
    EXPECT_EQ(r.status, ImpactStatus::failed) << to_string(k);
    EXPECT_EQ(r.failure, FailureKind::event_location) << to_string(r.failure);
    EXPECT_NE(r.reason.find("TOMS 748"), std::string::npos) << r.reason;
  }
}

// A failed result always carries a reason (an unknown integrator returned {}).
TEST(RunFailures, FailedSimulationAlwaysHasAReason) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.integrator = static_cast<IntegratorKind>(99);
  const ImpactResult r = simulate(req);
  EXPECT_EQ(r.status, ImpactStatus::failed);
  EXPECT_EQ(r.failure, FailureKind::integrator);
  EXPECT_FALSE(r.reason.empty());
}

// The field of a bad option used to be cut from the message at its first space
// ("max_steps" for a flag spelled --max-steps).
TEST(RunFailures, InvalidOptionNamesItsFlagAndRange) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.options.max_steps = 0;
  try {
    validate(req);
    FAIL() << "max_steps = 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--max-steps");
  }
  req.options.max_steps = 10;
  req.options.rtol = 1.0;
  const auto why = req.options.invalid();
  ASSERT_TRUE(why.has_value());
  EXPECT_EQ(why->field, "--rtol");
  EXPECT_NE(why->message.find("[1e-15, 1e-2]"), std::string::npos) << why->message;
}

// --- Hermite refinement and GSL re-steps, on small stand-in systems -------------------------

// x' = 1 (what the stepper's derivative says) but the re-stepped states follow
// x = cbrt(t - 0.3): the cubic Hermite interpolant, fed wrong slopes, converges only
// linearly onto the crossing and cannot reach the ulp level in kMaxRefinements re-steps.
struct OneState {
  using value_type = double;
  using state_type = std::array<double, 1>;
  void operator()(const state_type&, state_type& d, double) const { d[0] = 1.0; }
};

struct CubeRootStepper {
  static constexpr std::string_view name = "stand-in";
  using state_type = OneState::state_type;
  double t0() const { return 0.0; }
  double t1() const { return 1.0; }
  state_type x0() const { return {std::cbrt(-0.3)}; }
  state_type x1() const { return {std::cbrt(0.7)}; }
  state_type f0() const { return {1.0}; }
  state_type f1() const { return {1.0}; }
  StepResult restep(const OneState&, double t, state_type& out) const {
    out[0] = std::cbrt(t - 0.3);
    return StepResult::success();
  }
};

TEST(RunFailures, UnconvergedHermiteRefinementIsNamed) {
  CubeRootStepper stepper;
  OneState sys;
  OneState::state_type xe{};
  auto value = [](EventKind, const OneState::state_type& x) { return x[0]; };
  const auto r = refine_on_restep(stepper, sys, EventKind::yield, Direction::rising, 0.5, xe, value,
                                  IntegratorOptions{});
  EXPECT_NE(r.failure.find("did not converge"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("yield"), std::string::npos) << r.failure;
}

// A stand-in system for the GSL steppers whose right-hand side can be poisoned (NaN) after
// a good step, so that only the re-step meets it.
struct Poisonable {
  using value_type = double;
  static constexpr std::size_t N = 2;
  using state_type = std::array<double, N>;
  bool poisoned = false;
  void operator()(const state_type& x, state_type& d, double) const {
    d[0] = x[1];
    d[1] = poisoned ? std::numeric_limits<double>::quiet_NaN() : -x[0];
  }
  template <class Matrix>
  void jacobian(const state_type&, Matrix& m) const {
    m(0, 0) = 0;
    m(0, 1) = 1;
    m(1, 0) = -1;
    m(1, 1) = 0;
  }
};

template <GslMethod Method>
void expect_restep_failure_reported() {
  Poisonable sys;
  GslStepper<Poisonable, Method> stepper{IntegratorOptions{}};
  stepper.start(sys, 0.0, {0.0, 1.0});
  ASSERT_TRUE(stepper.step(sys).ok);
  sys.poisoned = true;
  Poisonable::state_type out{};
  const StepResult r = stepper.restep(sys, 0.5 * (stepper.t0() + stepper.t1()), out);
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("re-stepping"), std::string::npos) << r.reason;
}

TEST(RunFailures, GslRk8pdRestepFailureIsReported) {
  expect_restep_failure_reported<GslMethod::rk8pd>();
}
TEST(RunFailures, GslMsbdfRestepFailureIsReported) {
  expect_restep_failure_reported<GslMethod::msbdf>();
}

}  // namespace
}  // namespace ivv

namespace ivv {
namespace {

// The limits of a run are codes, not only words: max_steps and tau_max, for an integrator
// written here and one from a library (the driver owns both limits).
TEST(RunFailures, StepAndTimeLimitsCarryTheirCodes) {
  for (IntegratorKind k : {IntegratorKind::dop853, IntegratorKind::odeint_dopri5}) {
    SimulationRequest req;
    req.scene = paper_scene();
    req.integrator = k;
    req.options.max_steps = 3;
    const ImpactResult steps = simulate(req);
    EXPECT_EQ(steps.failure, FailureKind::step_limit) << to_string(k) << ": " << steps.reason;
    EXPECT_TRUE(is_integrator_failure(steps.failure));
    req.options.max_steps = 1'000'000;
    req.options.tau_max = 1e-3;
    const ImpactResult time = simulate(req);
    EXPECT_EQ(time.failure, FailureKind::time_limit) << to_string(k) << ": " << time.reason;
  }
  EXPECT_FALSE(is_integrator_failure(FailureKind::law_domain));
  EXPECT_EQ(to_string(FailureKind::step_limit), "step_limit");
}

}  // namespace
}  // namespace ivv
