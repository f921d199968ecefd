// `ivv calibrate` and `ivv predict` as an analyst meets them: every kind of scene and law goes
// through calibrate -> file -> predict, outputs are checked before the fit, a parameter the data
// did not determine is said aloud.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_run.h"

namespace {

namespace fs = std::filesystem;

using ivv::testing::CliRun;
using ivv::testing::ivv;

fs::path scratch(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("ivv_calibrate_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

// Six impacts of the paper-damped scene (reference_data/calibration_example.csv, synthetic).
fs::path data_file() {
  const fs::path p = scratch("data.csv");
  std::ofstream(p) << "# SYNTHETIC: rows of reference_data/calibration_example.csv\n"
                      "v0,e,u_e\n0.3,0.677508,0.01\n0.55302,0.567320,0.01\n"
                      "1.0,0.447,0.01\n1.9,0.37,0.01\n3.1,0.316,0.01\n4.5,0.282,0.01\n";
  return p;
}

// The paper scene (Table 1) with `damping` as its [damping] section.
std::string paper_with(const std::string& name, const std::string& damping) {
  const fs::path p = scratch(name + ".toml");
  std::ofstream(p) << "[impactor]\nmass = 0.5\nradius = 0.010\nyoungs_modulus = 207e9\n"
                      "poisson_ratio = 0.3\n[target]\nyoungs_modulus = 7.9e9\n"
                      "poisson_ratio = 0.3\nyield_strength = 202e6\n[damping]\n"
                   << damping << "\n[impact]\nvelocity = 1.0\n";
  return p.string();
}

// calibrate with `args` writing cal.json, then predict from it: both exit 0.
void expect_calibrate_then_predict(const std::string& args) {
  SCOPED_TRACE(args);
  const fs::path cal = scratch("cal.json");
  fs::remove(cal);
  const CliRun c = ivv("calibrate --data " + data_file().string() + " --no-profile --out " +
                       cal.string() + " " + args);
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  const CliRun p = ivv("predict --calibration " + cal.string() + " --v0 0.5,2 --samples 100");
  ASSERT_EQ(p.exit_code, 0) << p.out << p.err;
  EXPECT_NE(p.out.find("95 % band"), std::string::npos) << p.out;
}

TEST(CalibrateCli, EveryDashpotKindRoundTripsThroughPredict) {
  expect_calibrate_then_predict("--scene paper --fit yield_strength");
  expect_calibrate_then_predict("--scene paper-damped --fit yield_strength");
  expect_calibrate_then_predict("--scene " + paper_with("zeta", "zeta = 0.1") +
                                " --fit yield_strength");
  expect_calibrate_then_predict("--scene " + paper_with("lambda", "lambda = 0.3") +
                                " --fit yield_strength");
  expect_calibrate_then_predict("--scene paper-on-laminate-plate --fit yield_strength");
}

TEST(CalibrateCli, AnExpressionLawRoundTripsThroughPredict) {
  expect_calibrate_then_predict("--scene paper-damped --force 'k*K_h*z^1.5' --param k=1 --fit k");
}

// --out that cannot be written is refused before the fit (nothing printed, exit 2), and a
// --report directory is not created for a run that fails.
TEST(CalibrateCli, OutputPathsAreCheckedBeforeTheFit) {
  const std::string fit = "calibrate --scene paper-damped --fit c --data " + data_file().string();
  const fs::path fifo = scratch("fifo");
  fs::remove(fifo);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  for (const std::string& out :
       {scratch("").string(), fifo.string(), scratch("missing/cal.json").string()}) {
    const CliRun r = ivv(fit + " --out " + out);
    EXPECT_EQ(r.exit_code, 2) << out << ": " << r.err;
    EXPECT_EQ(r.out, "") << out;  // no fit was run
    EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
  }
  const fs::path report = scratch("new-report");
  fs::remove_all(report);
  CliRun r = ivv("calibrate --scene paper-damped --fit c --data /nonexistent.csv --report " +
                 report.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_FALSE(fs::exists(report));
  const fs::path two = scratch("two.csv");  // no u_e, 2 points, 2 parameters: exit 1
  std::ofstream(two) << "v0,e\n0.3,0.6665\n3,0.3207\n";
  r = ivv("calibrate --scene paper-damped --fit c,yield_strength --data " + two.string() +
          " --report " + report.string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("undefined"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(report));
}

// Hunt-Crossley's e does not depend on K: mu is fitted with its uncertainty, K is named, and
// predict says aloud that it holds K at its start.
TEST(CalibrateCli, AParameterWithoutEffectIsNamedAndPredictSaysItHoldsIt) {
  const fs::path cal = scratch("hc.json");
  const CliRun c = ivv("calibrate --scene paper --law hunt-crossley --param mu=0.5 --data " +
                       data_file().string() + " --fit mu,K --no-profile --out " + cal.string());
  ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
  EXPECT_NE(c.out.find("K [N/m^1.5] = UNIDENTIFIABLE"), std::string::npos) << c.out;
  EXPECT_EQ(c.out.find("mu [s/m] = UNIDENTIFIABLE"), std::string::npos) << c.out;
  const auto j = nlohmann::json::parse(std::ifstream(cal));
  EXPECT_TRUE(j["fit"][0]["identifiable"].get<bool>());
  EXPECT_GT(j["covariance"][0][0].get<double>(), 0.0);
  const CliRun p = ivv("predict --calibration " + cal.string() + " --v0 0.5,2 --samples 100");
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_NE(p.err.find("warning: K was not determined"), std::string::npos) << p.err;
}

}  // namespace
