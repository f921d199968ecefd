// Regression tests of issue 21 ("no wrong number, second pass"): one test per finding, named
// after what it guards; each fails without its fix. (Item 1, the end state of a captured
// impact, is in capture_end_state_test.cc and the case conservation.captured-end-state.)
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/input_error.h"
#include "solver/consistency.h"
#include "solver/integrator_choice.h"
#include "solver/laws/expression.h"
#include "solver/model_choice.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

std::shared_ptr<const CompiledExpressions> compile(const std::string& force,
                                                   const LawParameters& params = {}) {
  const Scene s = paper_scene();
  return std::make_shared<const CompiledExpressions>(ExpressionLawSpec{force, "", false}, params, s,
                                                     derive(s));
}

// Item 2: `simulate --law hunt-crossley --hc-mu 1e-200` (model auto) printed "separated,
// e = -nan": the Lambert-W route's Newton polish divided by an underflowed slope.
TEST(Issue21, NoNaNBesideASuccessStatus) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::hunt_crossley;
  req.parameters = {{"mu", 1e-200}};
  req.model = ModelKind::automatic;
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.separated()) << r.reason;
  // e = 1 - (2/3) mu v0 to round-off: exactly elastic at mu v0 = 1e-200
  EXPECT_EQ(r.e, 1.0);
}

// Item 2, the guard behind every route: a success status beside a NaN becomes a named failure.
TEST(Issue21, NonFiniteOutcomeIsANamedFailure) {
  ImpactResult r;
  r.status = ImpactStatus::separated;
  r.e = std::nan("");
  EXPECT_TRUE(fail_non_finite_outcome(r, "test"));
  EXPECT_EQ(r.status, ImpactStatus::failed);
  EXPECT_NE(r.reason.find("its e is not a finite number"), std::string::npos) << r.reason;
  ImpactResult captured;
  captured.status = ImpactStatus::captured;
  captured.t_contact = captured.t_alpha_max = INFINITY;  // the contact never ends: allowed
  EXPECT_FALSE(fail_non_finite_outcome(captured, "test"));
  ImpactResult separated;
  separated.status = ImpactStatus::separated;
  separated.t_contact = INFINITY;  // a separated impact has a finite contact time
  EXPECT_TRUE(fail_non_finite_outcome(separated, "test"));
}

// Item 4: `--force 'K_h*z^1.5 + 100'` is conservative (e = 1 exactly: contact ends at z = 0,
// where the force drops to 0), but the continuation below z = 0 started at F(0) = 100 N and
// pushed on: e = 1.0006352 and negative plastic work, at any rtol.
TEST(Issue21, ForceNotVanishingAtZeroEndsContactThereWithoutGainingEnergy) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::expression;
  req.expression.force = "K_h*z^1.5 + 100";
  req.integrator = IntegratorKind::dop853;
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.separated()) << r.reason;
  // the run's own error bound (consistency.h, the bound its ledger passed); the bug was 6e-4
  const double bound = accumulated_error_bound(r.steps, req.options);
  EXPECT_NEAR(r.e, 1.0, bound);
  EXPECT_LE(r.e, 1.0 + bound);
  EXPECT_NEAR(r.events.back().z, 0.0, 1e-9 * r.z_max);  // separation at z = 0
}

// Item 5: "K_h*z^1,5" (a decimal comma) was muParser's comma operator, a constant 5 N force.
TEST(Issue21, DecimalCommaIsBadInputWithTheCaret) {
  try {
    compile("K_h*z^1,5");
    FAIL() << "accepted a decimal comma";
  } catch (const ExpressionError& e) {
    EXPECT_EQ(e.field(), "--force");
    EXPECT_EQ(e.position(), 7);
    EXPECT_NE(std::string(e.what()).find("write decimals with '.'"), std::string::npos);
  }
  EXPECT_NO_THROW(compile("max(K_h*z^1.5, 0)"));  // a comma between arguments is fine
}

// Item 5: `--param _pi=1` silently redefined pi.
TEST(Issue21, ParameterMayNotRedefineABuiltIn) {
  EXPECT_THROW(compile("K_h*z^1.5", {{"_pi", 1.0}}), InputError);
  EXPECT_THROW(compile("K_h*z^1.5", {{"_e", 1.0}}), InputError);
  EXPECT_THROW(compile("K_h*z^1.5", {{"sqrt", 1.0}}), InputError);
}

// Item 14: 1e400 was reported as an "unknown variable".
TEST(Issue21, OutOfRangeNumberIsNamedAsSuch) {
  try {
    compile("1e400*z");
    FAIL() << "accepted 1e400";
  } catch (const ExpressionError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the range of double"), std::string::npos)
        << e.what();
  }
}

// Item 6: `--integrator auto` on a scene without a yield strength computed its stiffness
// ratio from NaN (zeta, z_y), called it "not stiff", and dop853 ran out of steps where rodas4
// succeeds (chung-ooi-2-aluminium, hertz, c = 1 N s/m).
TEST(Issue21, IntegratorAutoWithoutYieldStrengthMeasuresStiffness) {
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

double relative(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

// Item 7: just above yield the closed-form route put t_F_max and t_f 1.3e-8 and 6.7e-9 off
// mp50 at v0 = 0.13085169358677584 m/s (growing as v0 -> v_y) while stating rtol/10: its two
// loading legs are each ill-conditioned there, their sum is not. Held against mp50 at the
// issue's velocity and closer to v_y; the statement is the route's estimated error.
TEST(Issue21, ClosedFormTimesJustAboveYieldMeetTheirStatement) {
  SimulationRequest req;
  req.scene = paper_scene();
  const double v_y = derive(req.scene).v_yield;
  for (double v0 : {0.13085169358677584, v_y * (1 + 1e-9), v_y * (1 + 1e-13)}) {
    if (!(v0 > v_y)) continue;
    req.scene.velocity = v0;
    req.model = ModelKind::automatic;
    const ValidatedRequest v(req);
    const ModelRun run = simulate_model(v);
    ASSERT_TRUE(run.result.separated()) << run.result.reason;
    ASSERT_EQ(run.result.route, "closed-form-elastoplastic");
    SimulationRequest ref_req = req;
    ref_req.model = ModelKind::full;
    ref_req.integrator = IntegratorKind::mp50;
    const ImpactResult ref = simulate(ref_req);
    ASSERT_TRUE(ref.separated()) << ref.reason;
    // the contact-time statement of the route: rtol/10 (model_choice.h, route 1)
    const double stated = req.options.rtol / 10;
    EXPECT_LE(relative(run.result.t_F_max, ref.t_F_max), stated) << "v0 = " << v0;
    EXPECT_LE(relative(run.result.t_contact, ref.t_contact), stated) << "v0 = " << v0;
    EXPECT_LE(relative(run.result.t_contact, ref.t_contact), run.choice.estimated_error)
        << "v0 = " << v0;
  }
}

// Item 7: rk4 stated dt^4 = 1e-12 while F_max erred by 1.2e-10 to 3.9e-10 (v0 = 10 m/s,
// zeta = 0.05). Its statement is now the onset term h^{5/2}; measured against mp50 here.
TEST(Issue21, Rk4MeetsItsStatedError) {
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
