// Where an error-controlled integration starts (impact_driver.h: series_start): from the onset
// series, at the yield itself when the series reaches it (the yield fired at the series'
// state), else inside the Hertzian onset with the yield located by the integrator. Either way
// the run agrees with the 50-digit integrator, which never uses the series.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "solver/driver/event_locator.h"
#include "solver/driver/onset_series.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

constexpr double kRtol = 1e-8;
// dop853's stated error of e in units of v0 (solver/choice/integrator_choice.h: 200 rtol), as
// separation_step_test.cc.
constexpr double kStatedError = 200 * kRtol;
// The yield time: from the series, whose truncation bound there is at most rtol (relative, on
// the impulse and the displacement, onset_series.h), or located by the integrator on a step
// whose local error is held to rtol, the yield being the first event (no error carried in);
// the 50-digit run locates its yield to its own far tighter tolerance, and each root is
// resolved to a few ulps.
constexpr double kYieldTimeError = kRtol;  // relative

// (integrator_choice_test.cc builds the same request without the integrator: the solver's tests
// share no helper header, and six lines are not worth one)
SimulationRequest request(double v0, double zeta, IntegratorKind integrator) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = v0;
  req.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  req.law = LawKind::elastoplastic;
  req.model = ModelKind::full;
  req.integrator = integrator;
  req.options.rtol = req.options.atol = kRtol;
  return req;
}

std::optional<ImpactEvent> yield_of(const ImpactResult& r) {
  for (const ImpactEvent& ev : r.events)
    if (ev.kind == EventKind::yield) return ev;
  return std::nullopt;
}

struct TracedRun {
  ImpactResult result;
  std::vector<TrajectoryPoint> trajectory;
};

TracedRun run_dop853(double v0, double zeta) {
  TracedRun run;
  run.result = simulate(request(v0, zeta, IntegratorKind::dop853), &run.trajectory);
  return run;
}

// The samples on the series come first, four of them (samples_per_step) up to where the
// integration starts: the fifth trajectory point (after onset) is that start.
double integration_start(const TracedRun& run) {
  return run.trajectory.at(4).t;
}

void expect_as_the_reference(const TracedRun& run, double v0, double zeta) {
  const ImpactResult ref = simulate(request(v0, zeta, IntegratorKind::mp50));
  ASSERT_TRUE(ref.separated()) << ref.reason;
  ASSERT_TRUE(run.result.separated()) << run.result.reason;
  EXPECT_NEAR(run.result.e, ref.e, kStatedError) << "v0 = " << v0 << ", zeta = " << zeta;
  const std::optional<ImpactEvent> y = yield_of(run.result), y_ref = yield_of(ref);
  ASSERT_TRUE(y && y_ref);
  EXPECT_NEAR(y->t, y_ref->t, kYieldTimeError * y_ref->t) << "v0 = " << v0 << ", zeta = " << zeta;
  // maximum compression, reached from the yield in closed form where the series reached it
  // (linear_phase.h), else by the integrator: the state's error there is the series' or the
  // steps', within the stated error of e
  EXPECT_NEAR(run.result.t_z_max, ref.t_z_max, kStatedError * ref.t_z_max);
  EXPECT_NEAR(run.result.z_max, ref.z_max, kStatedError * ref.z_max);
  EXPECT_NEAR(run.result.F_max, ref.F_max, kStatedError * ref.F_max);
}

// The paper impact (v0 = 1 m/s, zeta = 0.1): the series' bound at the yield is ~1e-11, so the
// run starts at the yield, which is fired there, on the spring's far side of z_y; region II
// is then crossed in closed form, and the stepper starts at maximum compression.
TEST(OnsetStart, TheSeriesCarriesThePaperImpactToTheYield) {
  const TracedRun run = run_dop853(1.0, 0.1);
  const std::optional<ImpactEvent> y = yield_of(run.result);
  ASSERT_TRUE(y);
  EXPECT_DOUBLE_EQ(integration_start(run), y->t);
  EXPECT_DOUBLE_EQ(run.trajectory.at(8).t, run.result.t_z_max);  // four closed-form samples
  const double z_y = derive(paper_scene()).z_y;
  EXPECT_GE(y->z, z_y * (1 - 1e-15));  // the rounding of z back into metres
  EXPECT_NEAR(y->z, z_y, 1e-14 * z_y);
  expect_as_the_reference(run, 1.0, 0.1);
}

// Across the plastic range, with and without a dashpot, the run that starts at the yield agrees
// with the 50-digit one.
TEST(OnsetStart, FromTheYieldAsTheReferenceAcrossThePlasticRange) {
  for (double v0 : {2.0, 5.0, 10.0})
    for (double zeta : {0.0, 0.3}) {
      const TracedRun run = run_dop853(v0, zeta);
      const std::optional<ImpactEvent> y = yield_of(run.result);
      ASSERT_TRUE(y) << "v0 = " << v0 << ", zeta = " << zeta;
      EXPECT_DOUBLE_EQ(integration_start(run), y->t) << "v0 = " << v0 << ", zeta = " << zeta;
      expect_as_the_reference(run, v0, zeta);
    }
}

// Nearer the yield velocity (v_y = 0.131 m/s) the impactor has lost more of its speed by z_y:
// at 0.3 m/s the series' bound there is above rtol, and just above v_y far above it. The
// integration then starts inside the onset (at most half of z_y) and the integrator locates
// the yield; the run is as accurate.
TEST(OnsetStart, AYieldPastTheSeriesReachIsLocatedByTheIntegrator) {
  // (a dashpot of zeta = 0.3 keeps z below z_y at 0.135 m/s)
  for (const auto& [v0, zeta] : {std::pair{0.135, 0.0}, {0.3, 0.0}, {0.3, 0.3}}) {
    const TracedRun run = run_dop853(v0, zeta);
    const std::optional<ImpactEvent> y = yield_of(run.result);
    ASSERT_TRUE(y) << "v0 = " << v0 << ", zeta = " << zeta;
    EXPECT_LT(integration_start(run), y->t) << "v0 = " << v0 << ", zeta = " << zeta;
    expect_as_the_reference(run, v0, zeta);
  }
}

// onset_series_at_z, the root the start above is found by: the series' z there is on the far
// side of the target and within the 4 ulps Newton's step is resolved to (a few more for the
// rounding of z itself), at the time the bracketing root finder of the events finds on the same
// z(tau); past the reach there is no answer.
constexpr double kUlp = std::numeric_limits<double>::epsilon();
TEST(OnsetSeriesAtZ, FarSideOfTheTargetAtTheBracketedRoot) {
  for (double kappa : {0.3, 1.0, 4.0})
    for (double beta : {0.0, 0.2, 2.0})
      for (double fraction : {0.2, 0.6, 0.9}) {
        const double reach = onset_series_reach(kappa, beta, kRtol);
        const double target = fraction * reach;
        const std::optional<OnsetSeriesState> S = onset_series_at_z(kappa, beta, target, reach);
        ASSERT_TRUE(S) << kappa << " " << beta << " " << fraction;
        EXPECT_GE(S->z, target);
        EXPECT_LE(S->z - target, 16 * kUlp * target);
        auto g = [&](double tau) { return onset_series_state(kappa, beta, tau).z - target; };
        const double bracketed =
            solve_crossing(g, target, reach, g(target), g(reach), Direction::rising);
        EXPECT_NEAR(S->tau, bracketed, 16 * kUlp * bracketed);
      }
}
TEST(OnsetSeriesAtZ, NoAnswerPastTheReach) {
  const double reach = onset_series_reach(1.0, 0.2, kRtol);
  EXPECT_FALSE(onset_series_at_z(1.0, 0.2, reach, reach));  // z < tau: its root is past it
  EXPECT_FALSE(onset_series_at_z(1.0, 0.2, 2 * reach, reach));
}

}  // namespace
}  // namespace ivv
