// settle_captured (capture_end_state.h) by regime: captured without turning back, captured
// after turning back, rate-dependent law without a dashpot, free target, not captured; and the
// end state of real captured runs: `simulate --scene paper --v0 10 --zeta 2` reported the
// impulse, energy and times at the moment capture was declared (impulse 0.677 N s where the end
// state's is m* v0 = 5 N s, final energy 18.69 of 25 J), different for every integrator.
#include "solver/driver/capture_end_state.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "solver/consistency.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The settling is a few additions and products of O(1) numbers: round-off only.
constexpr double kRoundOff = 1e-14;

// A captured result as the driver leaves it (numbers at capture, invented for the arithmetic:
// synthetic, not a simulation).
ImpactResult at_capture() {
  ImpactResult r;
  r.status = ImpactStatus::captured;
  r.t_contact = 2e-3;
  r.t_alpha_max = 2e-3;
  r.rebound_velocity = 0.5;  // still approaching [m/s]
  r.alpha_max = 1e-3;
  r.z_perm = 2e-4;
  r.y_final = 7e-4;
  r.impulse = 0.2;
  r.impulse_compression = 0.2;
  r.energy.initial = 25.0;
  r.energy.final = 0.5 * 0.5 * 0.5 * 0.5;  // 1/2 m w_c^2 with m = 0.5
  r.energy.stored = 0.3;
  r.energy.plastic = 4.0;
  r.energy.viscous = 25.0 - 0.0625 - 0.3 - 4.0 - 1e-9;
  r.energy.residual = 1e-9;
  return r;
}

TEST(CaptureEndState, NeverTurnedBackEndsAtTheLimitOfBothInvariants) {
  Scene s = paper_scene();
  s.velocity = 10.0;
  ImpactResult r = at_capture();
  const double viscous_before = r.energy.viscous;
  settle_captured(r, s, {0.5, 1000.0, false});
  EXPECT_EQ(r.status, ImpactStatus::captured);
  EXPECT_EQ(r.t_contact, kInf);
  EXPECT_EQ(r.t_capture, 2e-3);
  EXPECT_EQ(r.t_alpha_max, kInf);
  EXPECT_EQ(r.e, 0.0);
  EXPECT_EQ(r.rebound_velocity, 0.0);
  EXPECT_NEAR(r.impulse, 0.5 * 10.0, kRoundOff);
  EXPECT_NEAR(r.impulse_compression, 0.5 * 10.0, kRoundOff);
  EXPECT_NEAR(r.y_final, 0.5 * 10.0 / 1000.0, kRoundOff);
  EXPECT_NEAR(r.alpha_max, 2e-4 + 5e-3, kRoundOff);
  EXPECT_EQ(r.energy.final, 0.0);
  EXPECT_EQ(r.energy.stored, 0.0);
  EXPECT_NEAR(r.energy.viscous, viscous_before + 0.0625 + 0.3, kRoundOff);
  EXPECT_NEAR(r.energy.residual, 1e-9, kRoundOff);  // the integration error, as measured
  EXPECT_NEAR(r.energy.initial - r.energy.plastic - r.energy.viscous, r.energy.residual,
              kRoundOff * 25);
  EXPECT_EQ(r.impactor_velocity_after, 0.0);  // half-space: the impactor comes to rest
  EXPECT_EQ(r.target_velocity_after, 0.0);
}

TEST(CaptureEndState, TurnedBackKeepsTheMeasuredMaximumDisplacement) {
  Scene s = paper_scene();
  s.velocity = 10.0;
  ImpactResult r = at_capture();
  settle_captured(r, s, {0.5, 1000.0, true});
  EXPECT_EQ(r.alpha_max, 1e-3);
  EXPECT_EQ(r.t_alpha_max, 2e-3);
  EXPECT_EQ(r.impulse_compression, 0.2);
  EXPECT_NEAR(r.impulse, 5.0, kRoundOff);
}

TEST(CaptureEndState, RateDependentLawDissipatesTheRestItself) {
  Scene s = paper_scene();
  s.velocity = 10.0;
  ImpactResult r = at_capture();
  r.energy.viscous = 0.0;
  const double plastic_before = r.energy.plastic;
  settle_captured(r, s, {0.5, kInf, true});
  EXPECT_EQ(r.energy.viscous, 0.0);
  EXPECT_NEAR(r.energy.plastic, plastic_before + 0.0625 + 0.3, kRoundOff);
  EXPECT_EQ(r.y_final, 0.0);
}

TEST(CaptureEndState, FreeTargetBothBodiesAtTheCommonVelocity) {
  Scene s = paper_scene();
  s.velocity = 10.0;
  s.target_radius = 0.01;
  s.target_mass = 1.5;
  ImpactResult r = at_capture();
  const double m_star = 0.5 * 1.5 / 2.0;
  settle_captured(r, s, {m_star, 1000.0, false});
  const double common = 0.5 * 10.0 / 2.0;  // m1 v0/(m1 + m2)
  EXPECT_NEAR(r.impactor_velocity_after, common, kRoundOff * 10);
  EXPECT_NEAR(r.target_velocity_after, common, kRoundOff * 10);
  EXPECT_NEAR(r.impulse, m_star * 10.0, kRoundOff * 10);
}

TEST(CaptureEndState, SeparatedResultUnchanged) {
  ImpactResult r = at_capture();
  r.status = ImpactStatus::separated;
  settle_captured(r, paper_scene(), {0.5, 1000.0, false});
  EXPECT_EQ(r.t_contact, 2e-3);
  EXPECT_EQ(r.impulse, 0.2);
  EXPECT_EQ(r.energy.final, 0.0625);
}

// That command (paper scene, v0 = 10 m/s, zeta = 2) through the library, with every integrator that
// runs a stiff scene in reasonable time. The end state is m* v0 exactly (a product), final energy
// 0, and the ledger closes to the consistency bound the run passed (consistency.h).
TEST(CapturedImpact, ReportsItsEndStateWithEveryIntegrator) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 10.0;
  req.scene.damping = Damping::ratio(2.0);
  for (IntegratorKind k : {IntegratorKind::rodas4, IntegratorKind::odeint_rosenbrock4,
                           IntegratorKind::gsl_msbdf, IntegratorKind::dop853}) {
    req.integrator = k;
    const ImpactResult r = simulate(req);
    ASSERT_EQ(r.status, ImpactStatus::captured) << to_string(k) << ": " << r.reason;
    EXPECT_EQ(r.impulse, 0.5 * 10.0) << to_string(k);
    EXPECT_EQ(r.energy.final, 0.0) << to_string(k);
    EXPECT_EQ(r.energy.stored, 0.0) << to_string(k);
    EXPECT_EQ(r.t_contact, kInf) << to_string(k);
    EXPECT_GT(r.t_capture, 0.0) << to_string(k);
    EXPECT_EQ(r.e_poisson, 0.0) << to_string(k);
    // the settling moves energy between entries and leaves the residual (the integration
    // error) within the bound the run's consistency check held it to
    EXPECT_LE(std::abs(r.energy.residual) / (0.5 * 10.0 * 10.0),
              accumulated_error_bound(r.steps, req.options))
        << to_string(k);
  }
}

}  // namespace
}  // namespace ivv
