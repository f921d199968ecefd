// The calibration file: calibrate -> file -> predict for every kind of dashpot and for an
// expression law, and the hand-edited files predict must refuse (a covariance that is not one).
#include "validation/calibration_file.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "validation/parameters.h"
#include "validation/prediction.h"
#include "validation/synthetic.h"

namespace ivv::validation {
namespace {

SimulationRequest paper_with(Damping damping) {
  SimulationRequest r;
  r.scene = paper_scene();
  r.scene.damping = damping;
  r.auto_integrator = true;
  return r;
}

// A plate under the paper's impactor: c = 8 sqrt(rho h D) from the target's E and nu, about
// 13700 N s/m at h = 40 mm (zeta ~ 0.08: a rebound to fit).
Damping plate() {
  Structure st;
  st.kind = Structure::Kind::plate;
  st.density = 1580;
  st.thickness = 0.04;
  return Damping::from_structure(st);
}

// Fits S_y (or the expression's k) to 5 synthetic impacts of `truth` from a start 20 % off,
// writes the file, reads it back and predicts from both: the two must agree to the last bit
// (the file describes the same model), and the prediction must be finite.
void expect_round_trip(const SimulationRequest& truth, const std::string& name) {
  SCOPED_TRACE(name);
  const MeasuredData data = synthetic_data(
      truth,
      {.velocities = log_velocities(0.4, 4, 5), .u_e = 0.01, .seed = 3, .description = name});
  CalibrationProblem problem{truth, data};
  set_parameter(problem.request, name, 1.2 * parameter_value(truth, name));
  CalibrationOptions o;
  o.fit = {name};
  o.profile = false;
  const CalibrationResult r = calibrate(problem, o);
  ASSERT_TRUE(r.ok) << r.failure;
  const nlohmann::json file = calibration_json(problem, r);
  EXPECT_EQ(file["determined"], 1);
  EXPECT_TRUE(file["notes"].is_array());
  const CalibratedModel direct = calibrated_model(problem, r);
  const CalibratedModel read =
      read_calibration(nlohmann::json::parse(calibration_json(problem, r).dump()), "mem");
  EXPECT_EQ(read.law, direct.law);
  PredictionOptions p;
  p.samples = 100;
  const Prediction a = predict(direct, {0.5, 2.0}, p), b = predict(read, {0.5, 2.0}, p);
  ASSERT_TRUE(a.ok() && b.ok());
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_TRUE(std::isfinite(b.points[k].e_nominal));
    EXPECT_EQ(a.points[k].e_nominal, b.points[k].e_nominal);
    EXPECT_EQ(a.points[k].e_lo, b.points[k].e_lo);
    EXPECT_EQ(a.points[k].e_hi, b.points[k].e_hi);
  }
}

TEST(CalibrationFile, RoundTripsWithoutADashpot) {
  expect_round_trip(paper_with(Damping::none()), "yield_strength");
}
TEST(CalibrationFile, RoundTripsADampingRatio) {
  expect_round_trip(paper_with(Damping::ratio(0.1)), "yield_strength");
}
TEST(CalibrationFile, RoundTripsADashpotCoefficient) {
  expect_round_trip(paper_with(Damping::coefficient(11440)), "yield_strength");
}
TEST(CalibrationFile, RoundTripsAZenerLambda) {
  expect_round_trip(paper_with(Damping::zener(0.3)), "yield_strength");
}
TEST(CalibrationFile, RoundTripsAStructureDashpot) {
  expect_round_trip(paper_with(plate()), "yield_strength");
}
TEST(CalibrationFile, RoundTripsAnExpressionLaw) {
  SimulationRequest r = paper_with(Damping::coefficient(11440));
  r.law = LawKind::expression;
  r.expression.force = "k*K_h*z^1.5";
  r.parameters["k"] = 1.0;
  expect_round_trip(r, "k");
}

// A hand-made calibration of two parameters (the writer's own output), for editing.
nlohmann::json two_parameter_file() {
  CalibrationProblem problem{paper_with(Damping::coefficient(11440)), {}};
  problem.data.source = "mem";
  CalibrationResult r;
  r.law = "elastoplastic";
  r.ok = true;
  for (const auto& [name, value] :
       {std::pair<std::string, double>{"c", 11000}, {"yield_strength", 2e8}}) {
    ParameterEstimate p;
    p.name = name;
    p.value = p.start = value;
    p.standard_error = 0.05 * value;
    r.parameters.push_back(p);
  }
  r.covariance = {{std::pow(550.0, 2), 0.5 * 550 * 1e7}, {0.5 * 550 * 1e7, 1e14}};
  r.correlation = {{1, 0.5}, {0.5, 1}};
  r.sigma[0] = 0.01;
  return calibration_json(problem, r);
}

// The InputError's message reading `j` ("" when it is accepted).
std::string refusal(const nlohmann::json& j) {
  try {
    read_calibration(j, "cal.json");
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--calibration");
    return e.what();
  }
  return "";
}

TEST(CalibrationFile, ACovarianceThatIsNotOneIsBadInput) {
  const nlohmann::json good = two_parameter_file();
  EXPECT_EQ(refusal(good), "");
  nlohmann::json j = good;
  j["covariance"][1][1] = -1e14;  // a negative variance
  EXPECT_NE(refusal(j).find("covariance[1][1] (yield_strength, yield_strength)"), std::string::npos)
      << refusal(j);
  j = good;
  j["covariance"][0][1] = j["covariance"][1][0] = 157 * 550 * 1e7;  // correlation 157
  EXPECT_NE(refusal(j).find("correlation of 157"), std::string::npos) << refusal(j);
  j = good;
  j["covariance"][0][1] = 0.4 * 550 * 1e7;  // asymmetric
  EXPECT_NE(refusal(j).find("symmetric"), std::string::npos) << refusal(j);
  j = good;
  j["fit"][1]["name"] = "c";  // duplicate
  EXPECT_NE(refusal(j).find("fit[1] names 'c' again"), std::string::npos) << refusal(j);
  j = good;
  j["fit"][1]["identifiable"] = false;  // held at its start, yet a covariance to draw from
  EXPECT_NE(refusal(j).find("identifiable: false"), std::string::npos) << refusal(j);
  j = good;
  j["fit"][1]["name"] = "nonsense";
  EXPECT_NE(refusal(j).find("not a parameter"), std::string::npos) << refusal(j);
}

// Three correlations each within [-1, 1] whose matrix has a negative eigenvalue.
TEST(CalibrationFile, ACovarianceThatIsNotPositiveSemiDefiniteIsBadInput) {
  nlohmann::json j = two_parameter_file();
  j["fit"].push_back(j["fit"][0]);
  j["fit"][2]["name"] = "mass";
  j["fit"][2]["value"] = j["fit"][2]["start"] = 0.5;
  j["covariance"] = {{1, 0.9, -0.9}, {0.9, 1, 0.9}, {-0.9, 0.9, 1}};
  EXPECT_NE(refusal(j).find("not positive semi-definite"), std::string::npos) << refusal(j);
}

// The law of an edited file is its law_kind: the name printed follows it.
TEST(CalibrationFile, TheLawIsTheLawKind) {
  nlohmann::json j = two_parameter_file();
  j["law_kind"] = "linearized";
  EXPECT_EQ(read_calibration(j, "cal.json").law, "linearized");
  j["law_kind"] = "nonsense";
  EXPECT_NE(refusal(j).find("law_kind"), std::string::npos) << refusal(j);
}

// A scene field out of range is named as the file's, not as a command-line flag.
TEST(CalibrationFile, ASceneFieldIsNamedInTheFile) {
  nlohmann::json j = two_parameter_file();
  j["scene"]["mass"] = -1;
  const std::string why = refusal(j);
  EXPECT_NE(why.find("cal.json: scene."), std::string::npos) << why;
  EXPECT_NE(why.find("mass"), std::string::npos) << why;
}

// A malformed expression in the file is named as the file's field, not as --force.
TEST(CalibrationFile, AnExpressionFieldIsNamedInTheFile) {
  nlohmann::json j = two_parameter_file();
  j["law_kind"] = "expression";
  j["expression"]["force"] = "K_h*z^(1.5";
  const std::string why = refusal(j);
  EXPECT_NE(why.find("expression.force"), std::string::npos) << why;
  EXPECT_EQ(why.find("--force"), std::string::npos) << why;
}

}  // namespace
}  // namespace ivv::validation
