// `ivv check-law` and the expression-law flags of `ivv simulate`, as a contact-law author
// meets them: verdicts and exit codes, the JSON contract, errors with a caret, the report.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include "app/cli_run.h"

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace {

namespace fs = std::filesystem;

using ivv::testing::CliRun;
using ivv::testing::ivv;

TEST(CheckLaw, HertzExpressionPassesOnThePaperScene) {
  const CliRun r = ivv("check-law --force 'K_h*z^1.5' --scene paper");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
}

TEST(CheckLaw, KelvinVoigtFailsAtOnsetWithExitOne) {
  const CliRun r = ivv("check-law --force 'k*z + c*zdot' --param k=4e6 --param c=11440");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("FAIL  static.onset"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("jumps at impact"), std::string::npos) << r.out;
}

TEST(CheckLaw, MalformedExpressionExitsTwoWithACaret) {
  const CliRun r = ivv("check-law --force 'K_h*z^(1.5'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("--force"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("    K_h*z^(1.5\n"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find('^'), std::string::npos) << r.err;
}

TEST(CheckLaw, UnknownVariableIsNamed) {
  const CliRun r = ivv("check-law --force 'K_h*z^1.5*(1 + mu*zdot)'");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown variable 'mu'"), std::string::npos) << r.err;
}

TEST(CheckLaw, JsonHasTheContractKeysAndTheClaimIsJudged) {
  // Hunt-Crossley with the Gonthier map at e = 0.5 (mu v0 = (1 - e^2)/e = 1.5) delivers 0.48774
  const CliRun r =
      ivv("check-law --force 'K_h*z^1.5*(1 + u/v0*zdot)' --param u=1.5 "
          "--expect-cor 0.5 --json");
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["verdict"], "fail");
  EXPECT_EQ(j["law"]["force"], "K_h*z^1.5*(1 + u/v0*zdot)");
  bool found = false;
  for (const auto& c : j["checks"]) {
    for (const char* key : {"id", "passed", "measured", "reference", "tolerance", "why", "detail"})
      EXPECT_TRUE(c.contains(key)) << key;
    if (c["id"] == "dynamic.expected_cor") {
      found = true;
      EXPECT_FALSE(c["passed"].get<bool>());
      // the exact Lambert-W COR for u0 = 1.5 is 0.4877413 (closed_forms/hunt_crossley.h)
      EXPECT_NEAR(c["measured"].get<double>(), 0.5 - 0.48774126, 1e-6);
    }
  }
  EXPECT_TRUE(found);
}

// A law with a fixed plastic loss (unloading to z_f = zmax/2 at every speed: e independent of
// v0) is not elastic at low speed; the claim must fail, and a Hertz law's must pass.
TEST(CheckLaw, ElasticAtLowSpeedIsJudged) {
  auto low_speed = [](const std::string& args) {
    const CliRun r = ivv("check-law " + args + " --elastic-at-low-speed --json");
    const auto j = nlohmann::json::parse(r.out);
    for (const auto& c : j["checks"])
      if (c["id"] == "dynamic.low_speed") return c;
    ADD_FAILURE() << "no dynamic.low_speed in " << r.out;
    return nlohmann::json{};
  };
  const auto plastic =
      low_speed("--force 'K_h*z^1.5' --unload 'K_h*(z^1.5 - (zmax/2)^1.5)' --scene paper");
  EXPECT_FALSE(plastic["passed"].get<bool>()) << plastic.dump();
  const auto hertz = low_speed("--force 'K_h*z^1.5' --scene paper");
  EXPECT_TRUE(hertz["passed"].get<bool>()) << hertz.dump();
}

TEST(CheckLaw, ReportWritesASelfContainedPage) {
  const fs::path dir =
      fs::temp_directory_path() / ("ivv_check_law_report_" + std::to_string(getpid()));
  const CliRun r = ivv("check-law --force 'K_h*z^1.5' --report " + dir.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir / "index.html");
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("static.onset"), std::string::npos);
  EXPECT_NE(html.find("<svg"), std::string::npos);
  // the command line as typed, quotes included (HTML-escaped; a browser shows ' and a copy of it
  // pastes back into a shell)
  EXPECT_NE(html.find("check-law --force &#39;K_h*z^1.5&#39; --report"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "results.json"));
  fs::remove_all(dir);
}

TEST(CheckLaw, SimulateWithTheSameEquationGivesTheBuiltInCor) {
  const CliRun builtin = ivv("simulate --scene paper --v0 1 --c 11440 --law hertz --json");
  const CliRun typed = ivv("simulate --scene paper --v0 1 --c 11440 --force 'K_h*z^1.5' --json");
  ASSERT_EQ(builtin.exit_code, 0) << builtin.err;
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  const double a = nlohmann::json::parse(builtin.out)["result"]["e"];
  const double b = nlohmann::json::parse(typed.out)["result"]["e"];
  // default rtol 1e-10 over N <= 1000 steps: global error <= 1e-7 in e for each
  EXPECT_NEAR(a, b, 1e-7);
  EXPECT_EQ(nlohmann::json::parse(typed.out)["request"]["law"], "expression");
}

TEST(CheckLaw, ForceAndLawTogetherAreBadInput) {
  const CliRun r = ivv("simulate --scene paper --law hertz --force 'K_h*z^1.5'");
  EXPECT_EQ(r.exit_code, 2);
}

TEST(CheckLaw, HcMuWithAnotherLawIsBadInput) {
  const CliRun r = ivv("simulate --scene paper --law hertz --hc-mu 0.3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--hc-mu"), std::string::npos) << r.err;
}

TEST(CheckLaw, ParameterOfALawThatHasNoneIsNamed) {
  const CliRun r = ivv("simulate --scene paper --law hertz --param mu=0.3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--param mu"), std::string::npos) << r.err;
}

// The README's two adhesive examples, as printed there, on the shipped scene glass-bead: a
// DMT-type law with its declared jump at onset (conservative: e = 1 at every v0) and a JKR-type
// hysteresis captured in its well below 5 mm/s; both PASS with exit 0.
TEST(CheckLaw, TheReadmesAdhesiveExamplesPassOnTheShippedGlassBead) {
  const CliRun dmt =
      ivv("check-law --scene glass-bead --force 'K_h*z^1.5 - Fad' --allow-tension "
          "--onset-force=-Fad --param Fad=3.1e-5 --v0 1e-4,1e-3,1e-2,1e-1,1 --no-monotone");
  EXPECT_EQ(dmt.exit_code, 0) << dmt.out << dmt.err;
  EXPECT_NE(dmt.out.find("law expression: PASS (12 of 12 checks passed"), std::string::npos)
      << dmt.out;
  EXPECT_NE(dmt.out.find("no dashpot  0.0001: 1, 0.001: 1, 0.01: 1, 0.1: 1, 1: 1"),
            std::string::npos)
      << dmt.out;
  const CliRun jkr =
      ivv("check-law --scene glass-bead --force 'K_h*z^1.5' "
          "--unload 'K_h*z^1.5 - Fad*(1 - z/zmax)' --allow-tension --param Fad=3.1e-5 "
          "--v0 1e-4,1e-3,1e-2,1e-1,1 --cor-increasing-in-v0 --captured-below 0.005");
  EXPECT_EQ(jkr.exit_code, 0) << jkr.out << jkr.err;
  EXPECT_NE(jkr.out.find("law expression: PASS (14 of 14 checks passed"), std::string::npos)
      << jkr.out;
  EXPECT_NE(jkr.out.find("0.0001: 0 (captured, e <= 0), 0.001: 0 (captured, e <= 0)"),
            std::string::npos)
      << jkr.out;
}

}  // namespace
