// Calibration: recovery, unidentifiable parameters, estimated noise, failures.
#include "validation/calibration.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"
#include "validation/synthetic.h"

namespace ivv::validation {
namespace {

CalibrationOptions fitting(std::vector<std::string> names) {
  CalibrationOptions o;
  o.fit = std::move(names);
  return o;
}

SimulationRequest paper(double zeta) {
  SimulationRequest r;
  r.scene = paper_scene();
  if (zeta > 0) r.scene.damping = Damping::ratio(zeta);
  r.auto_integrator = true;
  return r;
}

// Noise-free data: the fit returns the generating S_y from a start 30 % off. The data carry
// the generator's error (<= 3e-10 in e) and the fit's runs theirs (<= 1e-5 u_e = 1e-7); both
// move the estimate by at most sqrt(n) (1e-7 / u_e) = 4.5e-5 standard errors (the bound of
// the recovery case, verification/cases_validation.cc): 1e-3 SE leaves a factor 20.
TEST(Calibration, RecoversYieldStrengthFromNoiseFreeData) {
  const SimulationRequest truth = paper(0.0);
  const MeasuredData data = synthetic_data(truth, {.velocities = log_velocities(0.5, 5, 20),
                                                   .u_e = 0.01,
                                                   .noise = false,
                                                   .seed = 1,
                                                   .description = "test"});
  CalibrationProblem problem{truth, data};
  set_parameter(problem.request, "yield_strength", 1.3 * *truth.scene.yield_strength);
  const CalibrationResult r = calibrate(problem, fitting({"yield_strength"}));
  ASSERT_TRUE(r.ok) << r.failure;
  const ParameterEstimate* sy = r.find("yield_strength");
  ASSERT_TRUE(sy && sy->identifiable);
  EXPECT_LT(std::abs(sy->value - *truth.scene.yield_strength) / sy->standard_error, 1e-3)
      << r.brief();
  EXPECT_LT(r.chi2, 1e-6);
  ASSERT_TRUE(r.p_value.has_value());
}

// Data all below yield (paper scene: v_y ~ 0.2 m/s, docs/design.md §3 "0.1 m/s is elastic") cannot
// determine S_y: named unidentifiable, no number; c is still determined.
TEST(Calibration, YieldStrengthFromElasticDataIsUnidentifiable) {
  SimulationRequest truth = paper(0.1);
  truth.scene.damping = Damping::coefficient(parameter_value(truth, "c"));
  const MeasuredData data = synthetic_data(truth, {.velocities = log_velocities(0.01, 0.1, 12),
                                                   .u_e = 0.005,
                                                   .seed = 3,
                                                   .description = "test"});
  const CalibrationResult r = calibrate({truth, data}, fitting({"c", "yield_strength"}));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_FALSE(r.find("yield_strength")->identifiable) << r.brief();
  EXPECT_TRUE(std::isnan(r.find("yield_strength")->value));
  EXPECT_TRUE(r.find("c")->identifiable) << r.brief();
  EXPECT_FALSE(r.unidentifiable.empty());
}

SimulationRequest hunt_crossley(double mu) {
  SimulationRequest r;
  r.scene = paper_scene();
  r.law = LawKind::hunt_crossley;
  r.parameters["mu"] = mu;
  r.auto_integrator = true;
  return r;
}

// Hunt-Crossley's e depends on mu v0 alone (docs/design.md §2: independent of K): K's column of the
// Jacobian is exactly zero. K is named unidentifiable; mu keeps the estimate and standard error
// it has when fitted alone (the zero column must not turn 0/0 into NaN for mu). Tolerance: the
// two fits reach the same minimum of the same chi^2 in mu; 1e-6 relative is the fit's
// convergence (parameter_tolerance 1e-10) with room for the central differences.
TEST(Calibration, AParameterWithoutEffectLeavesTheOthersDetermined) {
  const SimulationRequest truth = hunt_crossley(1.5);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.3, 3, 10), .u_e = 0.005, .seed = 11, .description = "test"});
  CalibrationProblem problem{hunt_crossley(0.5), data};
  const CalibrationResult alone = calibrate(problem, fitting({"mu"}));
  const CalibrationResult both = calibrate(problem, fitting({"mu", "K"}));
  ASSERT_TRUE(alone.ok && both.ok) << alone.failure << both.failure;
  const ParameterEstimate* mu = both.find("mu");
  ASSERT_TRUE(mu->identifiable) << both.brief();
  EXPECT_FALSE(both.find("K")->identifiable) << both.brief();
  EXPECT_NEAR(mu->value / alone.find("mu")->value, 1.0, 1e-6);
  EXPECT_NEAR(mu->standard_error / alone.find("mu")->standard_error, 1.0, 1e-6);
  EXPECT_EQ(both.determined, 1);
  EXPECT_EQ(both.dof, alone.dof);
  EXPECT_GT(both.covariance[0][0], 0.0);
  EXPECT_EQ(both.covariance[1][1], 0.0);
}

// The Hertz law ignores the yield strength: c stays determined beside it.
TEST(Calibration, DampingOfAHertzLawIsDeterminedBesideAYieldStrengthWithoutEffect) {
  SimulationRequest truth = paper(0.0);
  truth.law = LawKind::hertz;
  truth.scene.damping = Damping::coefficient(11440);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.3, 3, 8), .u_e = 0.01, .seed = 5, .description = "test"});
  SimulationRequest start = truth;
  start.scene.damping = Damping::coefficient(8000);
  const CalibrationResult r = calibrate({start, data}, fitting({"c", "yield_strength"}));
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_TRUE(r.find("c")->identifiable) << r.brief();
  EXPECT_FALSE(r.find("yield_strength")->identifiable) << r.brief();
  EXPECT_LT(std::abs(r.find("c")->value - 11440) / r.find("c")->standard_error, 4.0) << r.brief();
  EXPECT_EQ(r.determined, 1);
}

// Two points and two parameters leave no residual to estimate the noise from: the noise is
// undefined, and so is every interval; the fit says so instead of a zero-width interval.
TEST(Calibration, EstimatedNoiseWithoutDegreesOfFreedomIsNoInterval) {
  const SimulationRequest truth = paper(0.1);
  const MeasuredData data = synthetic_data(truth, {.velocities = {0.3, 3.0},
                                                   .u_e = 0.01,
                                                   .state_uncertainty = false,
                                                   .seed = 2,
                                                   .description = "test"});
  const CalibrationResult r = calibrate({truth, data}, fitting({"c", "yield_strength"}));
  EXPECT_FALSE(r.ok) << r.brief();
  EXPECT_NE(r.failure.find("undefined"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("yield_strength = "), std::string::npos) << r.failure;
}

// With u_e stated, 0 dof still give intervals (from the stated noise) but no chi^2 test, and
// the text does not claim the noise was estimated.
TEST(Calibration, StatedNoiseWithoutDegreesOfFreedomSaysSo) {
  const SimulationRequest truth = paper(0.1);
  const MeasuredData data = synthetic_data(
      truth, {.velocities = {0.3, 3.0}, .u_e = 0.01, .seed = 2, .description = "test"});
  const CalibrationResult r = calibrate({truth, data}, fitting({"c", "yield_strength"}));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_EQ(r.dof, 0);
  EXPECT_FALSE(r.p_value.has_value());
  EXPECT_EQ(r.brief().find("estimated from the residuals"), std::string::npos) << r.brief();
  EXPECT_NE(r.brief().find("no degrees of freedom"), std::string::npos) << r.brief();
  EXPECT_GT(r.find("c")->standard_error, 0.0);
}

// A fit stopped by the iteration limit (Ceres NO_CONVERGENCE) is a failure with the reason,
// never an estimate: here the scan was asked for, so there is no second start to try.
TEST(Calibration, AFitThatDidNotConvergeIsNoEstimate) {
  const SimulationRequest truth = paper(0.0);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.5, 5, 8), .u_e = 0.01, .seed = 1, .description = "test"});
  CalibrationProblem problem{truth, data};
  set_parameter(problem.request, "yield_strength", 5 * *truth.scene.yield_strength);
  CalibrationOptions o = fitting({"yield_strength"});
  o.scan = true;
  o.max_iterations = 1;
  const CalibrationResult r = calibrate(problem, o);
  EXPECT_FALSE(r.ok) << r.brief();
  EXPECT_NE(r.failure.find("NO_CONVERGENCE"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("no estimate"), std::string::npos) << r.failure;
}

// Without --scan, a fit that does not converge from the given start is started again from the
// coarse scan and says so; its result is the converged one. The data: Hertz with a dashpot,
// fitted by the elastoplastic law from the paper's S_y, where the elastic data leave S_y free
// to run off upwards (Ceres stops at its iteration limit); the scan's best start converges.
TEST(Calibration, AFitThatDidNotConvergeStartsAgainFromTheScan) {
  SimulationRequest truth = paper(0.0);
  truth.law = LawKind::hertz;
  truth.scene.damping = Damping::coefficient(11440);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.3, 5, 25), .u_e = 0.01, .seed = 26, .description = "test"});
  SimulationRequest start = truth;
  start.law = LawKind::elastoplastic;
  CalibrationOptions o = fitting({"c", "yield_strength"});
  o.profile = false;
  const CalibrationResult r = calibrate({start, data}, o);
  ASSERT_FALSE(r.notes.empty()) << r.brief() << r.failure;
  EXPECT_NE(r.notes[0].find("coarse scan"), std::string::npos) << r.brief() << r.solver_report;
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_NE(r.solver_report.find("Termination: CONVERGENCE"), std::string::npos) << r.solver_report;
}

// With a t_contact column, a start at which impacts are captured (t_contact = inf) is no
// residual Ceres can use: the fit moves to the scan's start and says so, instead of failing at
// once (it did, with Ceres' residual-block dump in the log).
TEST(Calibration, ACapturedStartMovesToTheScan) {
  SimulationRequest truth = paper(0.0);
  truth.scene.damping = Damping::coefficient(11440);
  const std::vector<double> v0 = log_velocities(0.3, 5, 8);
  MeasuredData data;
  data.source = "test";
  data.has_quantity = {true, false, true};
  data.has_uncertainty = {true, false, true};
  const auto runs = run_model_points(truth, {}, {}, v0, 1);
  for (std::size_t i = 0; i < v0.size(); ++i) {
    Measurement m;
    m.v0 = v0[i];
    m.value[0] = runs[i].result.e;
    m.uncertainty[0] = 0.01;
    m.value[2] = runs[i].result.t_contact;
    m.uncertainty[2] = 0.01 * runs[i].result.t_contact;
    m.line = static_cast<int>(i) + 2;
    data.points.push_back(m);
  }
  SimulationRequest start = truth;
  start.scene.damping = Damping::coefficient(300);  // zeta ~ 4: every impact captured
  CalibrationOptions o = fitting({"c"});
  o.profile = false;
  const CalibrationResult r = calibrate({start, data}, o);
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes[0].find("coarse scan"), std::string::npos) << r.notes[0];
  // noise-free data of the same model: c comes back to its convergence and the runs' error;
  // 1e-3 relative is 0.05 of its standard error (~230 N s/m with these u)
  EXPECT_NEAR(r.find("c")->value, 11440, 1e-3 * 11440) << r.brief();
}

// A dashpot fitted on a scene without one starts from a coarse scan over Zener's lambda and
// reaches the generating c (within 4 standard errors: a 6e-5 chance for a correct interval).
TEST(Calibration, ADashpotWithoutAStartIsStartedFromAScan) {
  SimulationRequest truth = paper(0.0);
  truth.scene.damping = Damping::coefficient(11440);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.3, 4, 8), .u_e = 0.01, .seed = 4, .description = "test"});
  CalibrationOptions o = fitting({"yield_strength", "c"});
  o.profile = false;
  const CalibrationResult r = calibrate({paper(0.0), data}, o);
  ASSERT_TRUE(r.ok) << r.failure;
  ASSERT_FALSE(r.notes.empty());
  EXPECT_NE(r.notes[0].find("coarse scan over lambda"), std::string::npos) << r.notes[0];
  const ParameterEstimate* c = r.find("c");
  EXPECT_LT(std::abs(c->value - 11440) / c->standard_error, 4.0) << r.brief();
}

TEST(Calibration, WithoutStatedUncertaintyTheNoiseIsEstimated) {
  const SimulationRequest truth = paper(0.1);
  SyntheticSpec spec{.velocities = log_velocities(0.5, 5, 25),
                     .u_e = 0.01,
                     .state_uncertainty = false,
                     .seed = 7,
                     .description = "test"};
  const CalibrationResult r =
      calibrate({truth, synthetic_data(truth, spec)}, fitting({"yield_strength"}));
  ASSERT_TRUE(r.ok) << r.failure;
  EXPECT_FALSE(r.p_value.has_value());
  ASSERT_EQ(r.estimated_noise.size(), 1u);
  // sigma^2 = chi2-like sum / (n - p): chi2/dof == 1 by construction up to the one re-fit
  EXPECT_NEAR(r.chi2_per_dof(), 1.0, 0.05);
}

TEST(Calibration, BadOptionsAreBadInput) {
  const SimulationRequest truth = paper(0.0);
  const MeasuredData data = synthetic_data(truth, {.velocities = log_velocities(0.5, 5, 5),
                                                   .u_e = 0.01,
                                                   .noise = false,
                                                   .seed = 1,
                                                   .description = "test"});
  EXPECT_THROW(calibrate({truth, data}, fitting({"nonsense"})), InputError);
  CalibrationOptions o = fitting({"yield_strength"});
  o.bounds["yield_strength"] = {1e9, 2e9};  // start 2.02e8 outside
  EXPECT_THROW(calibrate({truth, data}, o), InputError);
  o.bounds.clear();
  o.bounds["c"] = {1, 2};  // not fitted
  EXPECT_THROW(calibrate({truth, data}, o), InputError);
}

}  // namespace
}  // namespace ivv::validation
