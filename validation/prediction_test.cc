// Prediction band (Monte Carlo over the fitted distribution) and the V&V 20 comparison.
#include "validation/prediction.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/input_error.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"
#include "validation/synthetic.h"

namespace ivv::validation {
namespace {

SimulationRequest undamped_paper() {
  SimulationRequest r;
  r.scene = paper_scene();
  r.auto_integrator = true;
  return r;
}

// S_y fitted to 15 noisy impacts (u_e = 0.01) of the undamped paper scene (closed form).
struct Fitted {
  CalibrationProblem problem;
  CalibrationResult result;
};
const Fitted& fitted() {
  static const Fitted f = [] {
    const SimulationRequest truth = undamped_paper();
    Fitted x{{truth, synthetic_data(truth, {.velocities = log_velocities(0.5, 5, 15),
                                            .u_e = 0.01,
                                            .seed = 21,
                                            .description = "prediction test"})},
             {}};
    CalibrationOptions o;
    o.fit = {"yield_strength"};
    x.result = calibrate(x.problem, o);
    return x;
  }();
  return f;
}

TEST(Prediction, CalibrationFileRoundTrips) {
  const Fitted& f = fitted();
  ASSERT_TRUE(f.result.ok) << f.result.failure;
  const CalibratedModel a = calibrated_model(f.problem, f.result);
  const CalibratedModel b = read_calibration(calibration_json(f.problem, f.result), "mem");
  EXPECT_EQ(a.values, b.values);
  EXPECT_EQ(a.covariance, b.covariance);
  EXPECT_EQ(*b.request.scene.yield_strength, a.values[0]);
  EXPECT_THROW(read_calibration(nlohmann::json::object(), "mem"), InputError);
}

// One parameter: the band's standard deviation is |de/dS_y| SE to first order. Tolerance: the
// Monte Carlo error of a standard deviation from N = 4000 draws is 1/sqrt(2N) = 1.1 % (4.5 %
// at 4 sigma), and the curvature of e(S_y) over +-2 SE (SE/S_y ~ 1e-2) adds < 1 %: 6 %.
TEST(Prediction, BandMatchesLinearPropagationForOneParameter) {
  const Fitted& f = fitted();
  const CalibratedModel m = calibrated_model(f.problem, f.result);
  PredictionOptions o;
  o.samples = 4000;
  o.seed = 5;
  const std::vector<double> v{0.7, 2.0, 4.0};
  const Prediction p = predict(m, v, o);
  ASSERT_TRUE(p.ok());
  const double sy = m.values[0], se = f.result.parameters[0].standard_error, h = 1e-4 * sy;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const double up = run_model_points(m.request, {"yield_strength"}, std::vector{sy + h},
                                       std::vector{v[k]}, 1)[0]
                          .result.e;
    const double dn = run_model_points(m.request, {"yield_strength"}, std::vector{sy - h},
                                       std::vector{v[k]}, 1)[0]
                          .result.e;
    const double linear = std::abs(up - dn) / (2 * h) * se;
    EXPECT_NEAR(p.points[k].u_input / linear, 1.0, 0.06) << "v0 = " << v[k];
    EXPECT_LT(p.points[k].e_lo, p.points[k].e_nominal);
    EXPECT_GT(p.points[k].e_hi, p.points[k].e_nominal);
  }
}

TEST(Prediction, SeededBandIsIndependentOfThreadCount) {
  const CalibratedModel m = calibrated_model(fitted().problem, fitted().result);
  PredictionOptions one;
  one.samples = 200;
  one.threads = 1;
  PredictionOptions two = one;
  two.threads = 2;
  const auto a = predict(m, {1.0, 3.0}, one), b = predict(m, {1.0, 3.0}, two);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(a.points[k].e_lo, b.points[k].e_lo);
    EXPECT_EQ(a.points[k].u_input, b.points[k].u_input);
  }
  PredictionOptions bad;
  bad.samples = 10;
  EXPECT_THROW(predict(m, {1.0}, bad), InputError);
}

// Held-back data from the generating model: |E| > 2 u_val at ~5 % of points (0 or 1 of 10);
// data from a target twice as strong: every point exceeds (e shifts by ~0.1 >> u_val ~ 0.01).
TEST(Prediction, ValidationComparisonFlagsOnlyAWrongModel) {
  const CalibratedModel m = calibrated_model(fitted().problem, fitted().result);
  PredictionOptions o;
  o.samples = 500;
  const auto v = log_velocities(0.6, 4.5, 10);
  const MeasuredData same = synthetic_data(
      undamped_paper(), {.velocities = v, .u_e = 0.01, .seed = 99, .description = "held back"});
  const ValidationComparison ok = compare_with_data(m, same, o);
  EXPECT_LE(ok.exceeding, 2) << ok.summary();
  SimulationRequest other = undamped_paper();
  set_parameter(other, "yield_strength", 2 * *other.scene.yield_strength);
  const ValidationComparison bad = compare_with_data(
      m, synthetic_data(other, {.velocities = v, .u_e = 0.01, .seed = 98, .description = "other"}),
      o);
  EXPECT_EQ(bad.exceeding, 10) << bad.summary();
  for (const auto& p : bad.points)
    EXPECT_NEAR(p.u_val, std::sqrt(p.u_num * p.u_num + p.u_input * p.u_input + p.u_D * p.u_D),
                1e-15);
}

}  // namespace
}  // namespace ivv::validation
