// Every integrator on a problem with a known solution: the linearized law without a dashpot.
//
// In tau = omega0 t the loading phase is z'' + z = 0 (K_y normalises to 1): z = sin tau, so
// maximum compression is at tau = pi/2 with z_m = v0/omega0 (eq. 19) and F_max = K_y z_m.
// Unloading is harmonic about z_f with frequency 1/gamma (eq. 25) from rest at z_m:
// z - z_f = (z_m - z_f) cos((tau - pi/2)/gamma), so separation (z = z_f) comes a quarter
// period later, at tau = pi/2 (1 + gamma), with rebound velocity -(z_m - z_f)/gamma = -gamma z_m
// (normalised), i.e. e = gamma (eq. 20).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "solver/choice/integrator_accuracy.h"
#include "solver/choice/model_choice.h"
#include "solver/simulate.h"
#include "solver/steppers/dp45_dense_probe.h"

namespace ivv {
namespace {

struct Exact {
  double e, t_contact, z_max, F_max;
};

Exact linearized_undamped(const Scene& s) {
  const DerivedParameters p = derive(s);
  const double z_m = s.velocity * std::sqrt(s.mass / p.K_y);
  const double z_f = z_m * std::pow(1 - p.K_y / (p.K_h * std::sqrt(z_m)), 2.0 / 3.0);
  const double gamma = std::sqrt(1 - z_f / z_m);
  return {gamma, std::numbers::pi / 2 * (1 + gamma) / p.omega0, z_m, p.K_y * z_m};
}

// Default settings: adaptive rtol 1e-10 and rk4 h = 1e-3 give global errors ~1e-9 on this
// smooth piecewise-harmonic problem; 1e-7 leaves a factor 100 for error accumulation over
// the two phases and event location (the requirement: every integrator within 1e-6 relative
// at its default settings).
constexpr double kDefaultSettingsTolerance = 1e-7;

class EveryIntegrator : public ::testing::TestWithParam<IntegratorKind> {};

TEST_P(EveryIntegrator, LinearizedUndampedMatchesClosedForm) {
  for (double v0 : {1.0, 5.0}) {
    SimulationRequest req;
    req.scene = paper_scene();
    req.scene.velocity = v0;
    req.law = LawKind::linearized;
    req.integrator = GetParam();
    const ImpactResult r = simulate(req);
    ASSERT_EQ(r.status, ImpactStatus::separated) << r.reason;
    const Exact x = linearized_undamped(req.scene);
    EXPECT_NEAR(r.e / x.e, 1.0, kDefaultSettingsTolerance) << "v0 = " << v0;
    EXPECT_NEAR(r.t_contact / x.t_contact, 1.0, kDefaultSettingsTolerance) << "v0 = " << v0;
    EXPECT_NEAR(r.z_max / x.z_max, 1.0, kDefaultSettingsTolerance) << "v0 = " << v0;
    EXPECT_NEAR(r.F_max / x.F_max, 1.0, kDefaultSettingsTolerance) << "v0 = " << v0;
    // without a dashpot, dz/dt = 0 and dalpha/dt = 0 are the same event
    EXPECT_EQ(r.t_z_max, r.t_alpha_max);
  }
}

TEST_P(EveryIntegrator, EventsComeInPhysicalOrderWithDamping) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.damping = Damping::coefficient(11440.0);
  req.integrator = GetParam();
  const ImpactResult r = simulate(req);
  ASSERT_EQ(r.status, ImpactStatus::separated) << r.reason;
  std::vector<EventKind> kinds;
  for (const auto& ev : r.events) kinds.push_back(ev.kind);
  const std::vector<EventKind> expected = {EventKind::onset, EventKind::yield,
                                           EventKind::max_compression, EventKind::max_displacement,
                                           EventKind::separation};
  EXPECT_EQ(kinds, expected);
  EXPECT_LT(r.t_z_max, r.t_alpha_max);  // paper: alpha_c after z_m when damped
  EXPECT_LT(r.z_max, r.alpha_max);
}

INSTANTIATE_TEST_SUITE_P(All, EveryIntegrator, ::testing::ValuesIn(all_integrators()),
                         [](const auto& info) {
                           std::string n(to_string(info.param));
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

// What each integrator's tolerance delivers is stated (integrator_accuracy.h: gsl-msbdf once
// reached 4e-7 at rtol 1e-10 unannounced);
// the statement is re-measured here against the 50-digit reference.
TEST_P(EveryIntegrator, DeliversTheStatedAccuracyOnThePaperScene) {
  for (bool damped : {true, false}) {
    SimulationRequest req;
    req.scene = paper_scene();
    if (damped) req.scene.damping = Damping::ratio(0.1);
    SimulationRequest ref = req;
    ref.integrator = IntegratorKind::mp50;
    req.integrator = GetParam();
    const ImpactResult r = simulate(req), x = simulate(ref);
    ASSERT_TRUE(r.separated() && x.separated()) << r.reason << x.reason;
    EXPECT_LE(std::abs(r.e / x.e - 1.0), measured_relative_error(GetParam()))
        << (damped ? "zeta 0.1" : "no dashpot");
  }
}

TEST(Rk4, RefusesAStepOutsideItsStabilityRegion) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.damping = Damping::ratio(1000.0);
  req.integrator = IntegratorKind::rk4;
  req.options.dt = 0.05;  // h lambda ~ 2 zeta k h >> 2.8 once the spring stiffens
  const ImpactResult r = simulate(req);
  EXPECT_EQ(r.status, ImpactStatus::failed);
  // Which check fires first depends on where the stiffness appears: the step's own stability
  // test at its start state, or (the spring stiffening within the first step) the event
  // refinement, whose re-steps of different lengths then disagree. Either is a named refusal.
  const bool stability = r.failure == FailureKind::unstable_step &&
                         r.reason.find("stability region") != std::string::npos;
  const bool refinement =
      r.failure == FailureKind::event_refinement && r.reason.find("too large") != std::string::npos;
  EXPECT_TRUE(stability || refinement) << to_string(r.failure) << ": " << r.reason;
}

TEST(Dp45, DenseOutputIsFourthOrder) {
  // x' = x on one step of size h: a fourth-order continuous extension has mid-step error
  // C h^5 (1 + a h + O(h^2)), so the observed order p(h) = log2(err(2h)/err(h)) is
  // 5 + O(h): its distance from 5 must halve with each halving of h (0.6 allows the O(h^2)
  // term). An interpolant of any other order would approach that order instead, and the
  // distance from 5 would not shrink.
  const std::array<double, 4> h = {0.4, 0.2, 0.1, 0.05};
  std::array<double, 3> distance{};
  for (std::size_t i = 0; i + 1 < h.size(); ++i) {
    const double p = std::log2(dp45_midpoint_error_exponential(h[i]) /
                               dp45_midpoint_error_exponential(h[i + 1]));
    distance[i] = std::abs(p - 5.0);
  }
  EXPECT_LE(distance[1], 0.6 * distance[0]) << distance[0] << " " << distance[1];
  EXPECT_LE(distance[2], 0.6 * distance[1]) << distance[1] << " " << distance[2];
}

double relative(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

// rk4 stated dt^4 = 1e-12 while F_max erred by 1.2e-10 to 3.9e-10 (v0 = 10 m/s, zeta = 0.05).
// Its statement is now the onset term h^{5/2}; measured against mp50 here.
TEST(Rk4, MeetsItsStatedError) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 10.0;
  req.scene.damping = Damping::ratio(0.05);
  req.integrator = IntegratorKind::rk4;
  req.model = ModelKind::automatic;
  const ValidatedRequest v(req);
  const ModelRun run = simulate_model(v);
  ASSERT_TRUE(run.result.separated()) << run.result.reason;
  ASSERT_EQ(run.result.integrator, "rk4");
  SimulationRequest ref_req = req;
  ref_req.model = ModelKind::full;
  ref_req.integrator = IntegratorKind::mp50;
  const ImpactResult ref = simulate(ref_req);
  ASSERT_TRUE(ref.separated()) << ref.reason;
  const double stated = run.choice.estimated_error;
  EXPECT_LE(relative(run.result.F_max, ref.F_max), stated);
  EXPECT_LE(relative(run.result.z_max, ref.z_max), stated);
  EXPECT_LE(std::abs(run.result.e - ref.e), stated);  // e in units of v0
}

}  // namespace
}  // namespace ivv
