// The command line as a user meets it: exit codes, the JSON contract, files, bad input.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include "app/cli_run.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

namespace {

namespace fs = std::filesystem;

using ivv::testing::CliRun;
using ivv::testing::ivv;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("ivv_cli_" + std::to_string(getpid()));
  fs::create_directories(dir);
  return dir / name;
}

TEST(Cli, SimulateJsonHasTheContractKeys) {
  const CliRun r = ivv("simulate --scene paper --v0 1 --c 11440 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);  // exactly one JSON object
  for (const char* key : {"e", "F_max", "t_contact", "z_max", "alpha_max", "z_perm", "separated"})
    EXPECT_TRUE(j["result"].contains(key)) << key;
  for (const char* key : {"initial", "final", "plastic", "viscous", "residual"})
    EXPECT_TRUE(j["result"]["energy"].contains(key)) << key;
  for (const char* key : {"E_star", "K_h", "z_y", "K_y", "zeta", "c", "v_yield"})
    EXPECT_TRUE(j["scene"].contains(key)) << key;
  EXPECT_TRUE(j["result"]["separated"].get<bool>());
  EXPECT_GT(j["result"]["e"].get<double>(), 0.0);
  EXPECT_LT(j["result"]["e"].get<double>(), 1.0);
}

TEST(Cli, SummaryIsReadable) {
  const CliRun r = ivv("simulate --scene paper --v0 5 --zeta 0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("COR"), std::string::npos);
  EXPECT_NE(r.out.find("F_max"), std::string::npos);
}

// The loader never looks for ivv's libraries in the directory it is run from: with CMake's build
// RPATH ("/usr/lib/x86_64-linux-gnu/openmpi/lib:", whose empty entry is that directory) a file
// named libgsl.so.27 there was loaded in place of Debian's, and ivv died before main ("file too
// short", exit 127).
TEST(Cli, LoadsNoLibraryFromTheDirectoryItRunsIn) {
  const fs::path dir = scratch("stray-libraries");
  fs::create_directories(dir);
  std::ofstream(dir / "libgsl.so.27") << "not a library\n";
  const std::string cmd =
      "cd '" + dir.string() + "' && '" + std::string(IVV_BINARY) + "' --help >/dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  fs::remove_all(dir);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

TEST(Cli, IntegratorsListsOnePerLine) {
  const CliRun r = ivv("integrators");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_EQ(
      r.out,
      "odeint-dopri5\nodeint-rosenbrock4\nrk4\ndp45\ndop853\ngsl-rk8pd\ngsl-msbdf\nrodas4\nmp50\n");
}

TEST(Cli, IntegratorsVerboseShowsTheTraits) {
  const CliRun r = ivv("integrators -v");
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("dop853\torder 8, explicit, dense output, adaptive"), std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("mp50\torder 8, explicit, Hermite interpolant, adaptive, reference"),
            std::string::npos);
}

TEST(Cli, AutoIntegratorSaysWhatItChoseAndWhy) {
  const CliRun r = ivv("simulate --scene paper --v0 1 --zeta 100 --integrator auto --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model_choice"]["integrator"], "rodas4");
  EXPECT_EQ(j["model_choice"]["route"], "integrated");  // a dashpot: no exact closed form
  EXPECT_EQ(j["model_choice"]["law"], "elastoplastic (full model, integrated)");
  EXPECT_GE(j["model_choice"]["reasons"].size(), 2u);
  EXPECT_GT(j["model_choice"]["estimated_error"].get<double>(), 0.0);
}

// --model auto (the default): no dashpot on the elastoplastic law is the closed form by
// energy, with no integration, and it agrees with the integrated full model.
TEST(Cli, ModelAutoTakesTheClosedFormWithoutADashpot) {
  const CliRun a = ivv("simulate --scene paper --v0 1 --no-dashpot --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  const auto ja = nlohmann::json::parse(a.out);
  EXPECT_EQ(ja["model_choice"]["route"], "closed-form-elastoplastic");
  EXPECT_EQ(ja["model_choice"]["integrator"], "none");
  EXPECT_EQ(ja["result"]["steps"], 0);
  const CliRun f = ivv(
      "simulate --scene paper --v0 1 --no-dashpot --model full --integrator dop853 --rtol 1e-12 "
      "--json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto jf = nlohmann::json::parse(f.out);
  // the integrated e at rtol 1e-12 is within 1e-9 (N rtol over < 1000 steps) of the exact one
  EXPECT_NEAR(ja["result"]["e"].get<double>(), jf["result"]["e"].get<double>(), 1e-9);
  EXPECT_NEAR(ja["result"]["F_max"].get<double>() / jf["result"]["F_max"].get<double>(), 1.0, 1e-9);
}

TEST(Cli, BenchRejectsUnknownFlags) {
  const CliRun r = ivv("bench --fast");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fast"), std::string::npos) << r.err;
}

TEST(Cli, BenchQuickJsonHasPointsPeersAndTargets) {
  const CliRun r = ivv("bench --quick --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"machine", "points", "peers", "targets"})
    EXPECT_TRUE(j.contains(key)) << key;
  ASSERT_FALSE(j["points"].empty());
  for (const char* key : {"integrator", "law", "scene", "rtol", "err_e", "err_F", "err_t",
                          "us_per_impact", "rhs_evals"})
    EXPECT_TRUE(j["points"][0].contains(key)) << key;
  // five peers (GSL, odeint, CVODE Adams and BDF, ARKODE ERK), each at the same tolerances,
  // each with its setup stated
  std::set<std::string> peers;
  for (const auto& p : j["peers"]) peers.insert(p["integrator"].get<std::string>());
  for (const char* name : {"gsl-rk8pd-driver", "odeint-dopri5-dense", "sundials-cvode-adams",
                           "sundials-cvode-bdf", "sundials-arkode-erk"}) {
    EXPECT_EQ(peers.count(name), 1u) << name;
    EXPECT_TRUE(j["peer_setups"].contains(name)) << name;
  }
  EXPECT_EQ(peers.size(), 5u);
  EXPECT_EQ(j["peers"].size() % 5, 0u);
  for (const auto& t : j["targets"]) EXPECT_TRUE(t.contains("status"));
  // every target says what it measures (its group) and carries its measured value (a number,
  // or null only when not measured); the groups of the speed targets are all there
  std::set<std::string> groups;
  for (const auto& t : j["targets"]) {
    for (const char* key : {"group", "target", "bound", "unit", "measured", "status", "how"})
      EXPECT_TRUE(t.contains(key)) << t["target"] << ": " << key;
    groups.insert(t["group"].get<std::string>());
  }
  for (const char* g : {"per-impact", "peers", "map", "auto-choice", "calibration"})
    EXPECT_EQ(groups.count(g), 1u) << g;
  ASSERT_FALSE(j["auto_grid"].empty());
  EXPECT_TRUE(j["auto_grid"][0].contains("best_integrator"));
}

// A rigid target without a yield strength and the Hertz law: the Hertz closed form (docs/design.md
// §2) z_m = (5 m v0^2/(4 K_h))^{2/5}, t_f = 2.9432752 z_m/v0, e = 1, with E* = E1/(1 - nu1^2).
TEST(Cli, RigidTargetHertzGivesClosedForm) {
  const CliRun r = ivv("simulate --scene chung-ooi-2-aluminium --law hertz --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double m = j["scene"]["mass"], v0 = j["scene"]["v0"];
  const double E_star = 70e9 / (1 - 0.33 * 0.33);
  EXPECT_NEAR(j["scene"]["E_star"].get<double>() / E_star, 1.0, 1e-15);
  EXPECT_TRUE(j["scene"]["rigid_target"].get<bool>());
  EXPECT_TRUE(j["scene"]["K_y"].is_null());
  const double K_h = 4.0 / 3.0 * std::sqrt(0.1) * E_star;
  const double z_m = std::pow(5 * m * v0 * v0 / (4 * K_h), 0.4);
  // default rtol 1e-10 per step, ~170 steps: 1e-7 (tolerances.h)
  EXPECT_NEAR(j["result"]["z_max"].get<double>() / z_m, 1.0, 1e-7);
  EXPECT_NEAR(j["result"]["t_contact"].get<double>() / (2.9432752 * z_m / v0), 1.0, 1e-7);
  EXPECT_NEAR(j["result"]["e"].get<double>(), 1.0, 1e-7);
  EXPECT_EQ(j["result"]["bodies"]["target_velocity_after"].get<double>(), 0.0);
}

TEST(Cli, SceneShowPrintsDerivedParameters) {
  const CliRun r = ivv("scene show --scene paper");
  ASSERT_EQ(r.exit_code, 0);
  for (const char* s : {"E*", "K_h", "z_y", "K_y", "omega0", "v_y"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

TEST(Cli, SceneShowNamesAFinitePlatesRegime) {
  const CliRun r = ivv("scene show --scene drop-weight-coupon");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("regime       plate-dynamics"), std::string::npos) << r.out;
  const CliRun j = ivv("scene show --json --scene steel-ball-on-finite-steel-plate");
  ASSERT_EQ(j.exit_code, 0) << j.err;
  const auto json = nlohmann::json::parse(j.out);
  EXPECT_EQ(json["regime"]["regime"], "infinite-plate");
  EXPECT_EQ(json["regime"]["law"], "hertz");  // the scene has no yield strength
  EXPECT_LT(json["regime"]["mass_ratio"].get<double>(), 0.23);
}

TEST(Cli, TrajectoryCsvIsWritten) {
  const fs::path csv = scratch("traj.csv");
  const CliRun r =
      ivv("simulate --json --scene paper --v0 1 --zeta 0.1 --trajectory " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const int steps = nlohmann::json::parse(r.out)["result"]["steps"].get<int>();
  std::ifstream in(csv);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header, "t,alpha,alpha_dot,y,z,F,tau,alpha_bar,F_bar");
  // from onset (t = 0) on, in time order, four samples per step (the steps that start past
  // onset, from the series, have series samples on (0, t0], and a segment crossed in closed
  // form has its own)
  int rows = 0;
  double last_t = -1;
  for (std::string line; std::getline(in, line);) {
    const double t = std::stod(line.substr(0, line.find(',')));
    if (rows == 0) {
      EXPECT_EQ(t, 0.0);
    }
    EXPECT_GT(t, last_t) << line;
    last_t = t;
    ++rows;
  }
  EXPECT_GE(rows, 1 + 4 * steps);
}

TEST(Cli, SweepWritesTheGrid) {
  const fs::path csv = scratch("grid.csv");
  const CliRun r =
      ivv("sweep --scene paper --v0 0.5:5:4 --log --zeta 0,0.1,0.3 --out " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(csv);
  int rows = 0;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 1 + 4 * 3);
  // the summary says what it wrote, how long it took and what an impact cost
  EXPECT_NE(r.err.find("wrote 12 impacts to"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" s, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" us an impact\n"), std::string::npos) << r.err;
}

// Bad input: exit 2, one message naming the field, no output file.
struct Bad {
  const char* label;
  std::string args;
  std::string must_mention;
};

class CliBadInput : public ::testing::TestWithParam<Bad> {};

TEST_P(CliBadInput, ExitsTwoNamingTheField) {
  const CliRun r = ivv(GetParam().args);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(GetParam().must_mention), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CliBadInput,
    ::testing::Values(
        Bad{"negative_v0", "simulate --scene paper --v0 -1", "--v0"},
        Bad{"nan_v0", "simulate --scene paper --v0 nan", "--v0"},
        Bad{"unknown_law", "simulate --scene paper --law plastic", "valid names: hertz"},
        Bad{"unknown_integrator", "simulate --scene paper --integrator euler",
            "valid names: odeint-dopri5"},
        Bad{"missing_scene_file", "simulate --scene /no/such.toml", "cannot read"},
        Bad{"linearized_outside_domain", "simulate --scene paper --v0 0.1 --law linearized",
            "2.25 z_y"},
        Bad{"hc_with_dashpot", "simulate --scene paper --law hunt-crossley --zeta 0.1", "--zeta"},
        Bad{"negative_hc_mu", "simulate --scene paper --law hunt-crossley --hc-mu -1", "--hc-mu"},
        Bad{"bad_rtol", "simulate --scene paper --rtol 2", "--rtol"},
        Bad{"zeta_and_c", "simulate --scene paper --zeta 0.1 --c 100", "excludes"},
        Bad{"bad_grid", "sweep --scene paper --v0 1:2 --zeta 0.1 --out /tmp/ivv_never.csv", "--v0"},
        // accepted silently or ended as an internal error (exit 1) before
        Bad{"empty_v0", "simulate --scene paper --v0 ''", "--v0"},
        Bad{"v0_with_junk", "simulate --scene paper --v0 1x", "--v0"},
        Bad{"max_steps_past_long", "simulate --scene paper --max-steps 99999999999999999999",
            "--max-steps"},
        Bad{"max_steps_not_integer", "simulate --scene paper --max-steps 1e30", "--max-steps"},
        Bad{"hc_mu_without_hc_law", "simulate --scene paper --hc-mu 0.1", "--hc-mu"},
        Bad{"hc_k_without_hc_law", "simulate --scene paper --law hertz --hc-k 1e9", "--hc-k"},
        Bad{"huge_v0", "simulate --scene paper --v0 1e300", "--v0"},
        Bad{"scene_is_a_directory", "simulate --scene /tmp", "is a directory"},
        Bad{"scene_without_bound", "simulate --scene /dev/zero", "larger than"},
        Bad{"trajectory_to_a_device", "simulate --scene paper --trajectory /dev/null",
            "--trajectory"},
        Bad{"trajectory_empty", "simulate --scene paper --trajectory ''", "--trajectory"},
        Bad{"sweep_out_directory", "sweep --scene paper --v0 1 --zeta 0.1 --out /tmp", "--out"},
        Bad{"verify_out_device_checked_first", "verify --filter 'trend.*' --out /dev/full",
            "--out"},
        Bad{"elastoplastic_without_yield", "simulate --scene chung-ooi-2-aluminium",
            "target.yield_strength: required by the elastoplastic law"},
        Bad{"linearized_without_yield",
            "simulate --scene chung-ooi-2-aluminium --law linearized --json",
            "target.yield_strength: required by the linearized law"},
        Bad{"zeta_without_yield", "simulate --scene chung-ooi-2-aluminium --law hertz --zeta 0.1",
            "--zeta"},
        Bad{"unknown_shipped_scene", "simulate --scene no-such-scene", "--scene"},
        Bad{"sweep_zeta_without_yield",
            "sweep --scene chung-ooi-2-aluminium --law hertz --v0 0.1:1:2 --zeta 0,0.1 --out "
            "/tmp/ivv_never.csv",
            "--zeta"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(Cli, BadSweepLeavesNoFile) {
  const fs::path csv = scratch("never.csv");
  fs::remove(csv);
  const CliRun r = ivv("sweep --scene paper --v0 1:5:3 --zeta 0.1,-1 --out " + csv.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--zeta"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(csv));
}

TEST(Cli, BadSceneFileNamesTheField) {
  const fs::path scene = scratch("bad.toml");
  std::ofstream(scene) << "[impactor]\nmass = 0.5\nradius = 0.01\nyoungs_modulus = 207e9\n"
                          "poisson_ratio = 0.5\n[target]\nyoungs_modulus = 7.9e9\n"
                          "poisson_ratio = 0.3\nyield_strength = 2e8\n[impact]\nvelocity = 1\n";
  const CliRun r = ivv("simulate --scene " + scene.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("impactor.poisson_ratio"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("(-1, 0.5)"), std::string::npos) << r.err;
}

// A [structure] scene: simulate --json carries each element's dashpot, the series c and
// Zener's lambda under "scene".
TEST(Cli, StructureSceneReportsItsDashpotAndLambda) {
  const CliRun r = ivv("simulate --scene steel-ball-on-steel-plate --law hertz --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto scene = nlohmann::json::parse(r.out)["scene"];
  EXPECT_EQ(scene["dashpot_source"], "structure");
  EXPECT_EQ(scene["structure"]["kind"], "plate");
  EXPECT_NEAR(scene["structure"]["c_plate"].get<double>(), 393.0795, 1e-3);  // README value
  EXPECT_TRUE(scene["structure"]["c_bar"].is_null());
  EXPECT_EQ(scene["c"], scene["structure"]["c"]);
  EXPECT_NEAR(scene["zener_lambda"].get<double>(), 0.97635, 1e-5);
}

// [structure] and [damping] together: exit 2, a message naming both, no output file.
TEST(Cli, StructureAndDampingTogetherIsBadInput) {
  const fs::path scene = scratch("both.toml");
  std::ofstream(scene) << "[impactor]\nmass = 0.5\nradius = 0.01\nyoungs_modulus = 207e9\n"
                          "poisson_ratio = 0.3\n[target]\nyoungs_modulus = 7.9e9\n"
                          "poisson_ratio = 0.3\nyield_strength = 2e8\n[damping]\nzeta = 0.1\n"
                          "[structure]\nkind = \"plate\"\nthickness = 0.01\ndensity = 1580\n"
                          "[impact]\nvelocity = 1\n";
  const fs::path traj = scratch("both-traj.csv");
  fs::remove(traj);
  const CliRun r = ivv("simulate --scene " + scene.string() + " --trajectory " + traj.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("structure"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[damping]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(traj));
}

TEST(Cli, EveryShippedSceneFileRuns) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(IVV_SCENES_DIR)) {
    if (entry.path().extension() != ".toml") continue;
    ++scenes;
    // a scene without a yield strength is elastic: it runs with a law without yield
    const CliRun show = ivv("scene show --json --scene " + entry.path().string());
    ASSERT_EQ(show.exit_code, 0) << entry.path() << ": " << show.err;
    const bool elastic = nlohmann::json::parse(show.out)["yield_strength"].is_null();
    const CliRun r =
        ivv("simulate --json --scene " + entry.path().string() + (elastic ? " --law hertz" : ""));
    EXPECT_EQ(r.exit_code, 0) << entry.path() << ": " << r.err;
  }
  EXPECT_GE(scenes, 6);
}

// Shipped scenes by name: from the source tree, and from $IVV_DATA_DIR (as after install).
TEST(Cli, ShippedSceneByNameAndFromDataDir) {
  EXPECT_EQ(ivv("scene show --scene chung-ooi-2-magnesium").exit_code, 0);
  const fs::path dir = scratch("data");
  fs::create_directories(dir / "scenes");
  fs::copy_file(fs::path(IVV_SCENES_DIR) / "chung-ooi-2-magnesium.toml",
                dir / "scenes" / "only-in-data-dir.toml", fs::copy_options::overwrite_existing);
  EXPECT_NE(ivv("scene show --scene only-in-data-dir").exit_code, 0);
  setenv("IVV_DATA_DIR", dir.c_str(), 1);
  const CliRun r = ivv("scene show --scene only-in-data-dir");
  unsetenv("IVV_DATA_DIR");
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

TEST(Cli, SceneShowSaysRigidTargetAndEffectiveBody) {
  const CliRun rigid = ivv("scene show --scene chung-ooi-2-aluminium");
  ASSERT_EQ(rigid.exit_code, 0) << rigid.err;
  EXPECT_NE(rigid.out.find("rigid target"), std::string::npos) << rigid.out;
  EXPECT_NE(rigid.out.find("no yield strength"), std::string::npos) << rigid.out;
  const CliRun pair = ivv("scene show --scene chung-ooi-1-glass");
  ASSERT_EQ(pair.exit_code, 0) << pair.err;
  for (const char* s : {"R*     = 0.005 m", "m*", "free sphere"})
    EXPECT_NE(pair.out.find(s), std::string::npos) << s << " in " << pair.out;
}

// Two identical spheres, e = 1: they exchange velocities (target frame); momentum m1 v0 is
// conserved to rounding and the printed summary gives both bodies.
TEST(Cli, TwoSpheresGiveBothBodyVelocities) {
  const CliRun r = ivv("simulate --scene chung-ooi-1-glass --law hertz --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  const double m1 = j["scene"]["mass"], m2 = j["scene"]["target_mass"], v0 = j["scene"]["v0"];
  const double v1 = j["result"]["bodies"]["impactor_velocity_after"];
  const double v2 = j["result"]["bodies"]["target_velocity_after"];
  EXPECT_NEAR(m1 * v1 + m2 * v2, m1 * v0, 4e-16 * m1 * v0);
  // e = 1 to the default rtol 1e-10 per step over ~170 steps (1e-7, as the analytic cases)
  EXPECT_NEAR(v1, 0.0, 1e-7 * v0);
  EXPECT_NEAR(v2, v0, 1e-7 * v0);
  EXPECT_NEAR(j["scene"]["effective_mass"].get<double>(), m1 / 2, 1e-16);
  const CliRun text = ivv("simulate --scene chung-ooi-1-glass --law hertz");
  EXPECT_NE(text.out.find("after impact impactor"), std::string::npos) << text.out;
}

TEST(Cli, FitHcReproducesTheTargets) {
  const CliRun r = ivv("fit-hc --scene paper --v0 1 --c 11440 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  // the fit solves e to ~1e-10 (bracket) and F_max exactly by scaling: 1e-8 either way
  EXPECT_NEAR(j["e_hc"].get<double>() / j["e"].get<double>(), 1.0, 1e-8);
  EXPECT_NEAR(j["F_max_hc"].get<double>() / j["F_max"].get<double>(), 1.0, 1e-8);
  EXPECT_GT(j["t_contact_hc"].get<double>(), j["t_contact_model"].get<double>());
}

TEST(Cli, VerifyWritesResultsAndRejectsAnUnmatchedFilter) {
  const fs::path json = scratch("results.json");
  const CliRun r = ivv("verify --filter 'trend.paper.fig9*' --out " + json.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(json);
  const auto j = nlohmann::json::parse(in);
  ASSERT_EQ(j["cases"].size(), 1u);
  for (const char* key :
       {"id", "title", "tier", "passed", "measured", "reference", "tolerance", "reason"})
    EXPECT_TRUE(j["cases"][0].contains(key)) << key;
  EXPECT_EQ(ivv("verify --filter 'no.such.case*' --out " + json.string()).exit_code, 2);
}

// --trajectory naming a symlink replaced the link by a regular file, its target left stale.
TEST(Cli, OutputThroughASymlinkReachesItsTarget) {
  const fs::path target = scratch("target.csv"), link = scratch("link.csv");
  fs::remove(target);
  fs::remove(link);
  std::ofstream(target) << "old\n";
  fs::create_symlink(target, link);
  const CliRun r = ivv("simulate --scene paper --trajectory " + link.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(link)));
  std::ifstream in(target);
  std::string header;
  std::getline(in, header);
  EXPECT_EQ(header.rfind("t,alpha", 0), 0u) << header;
}

// fit-hc at an elastic impact (e = 1) failed to bracket mu; mu = 0 is the answer.
TEST(Cli, FitHcAtAnElasticImpactGivesZeroMu) {
  const CliRun r = ivv("fit-hc --scene paper --v0 0.05 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["mu"].get<double>(), 0.0);
  // Hertz with K fitted to F_max: the same curve, so K = K_h to the run's accuracy (1e-8 as
  // in FitHcReproducesTheTargets)
  EXPECT_NEAR(j["F_max_hc"].get<double>() / j["F_max"].get<double>(), 1.0, 1e-8);
}

// Without a dashpot no run is ever "captured" (at v0 = 1e16 m/s these three integrators said
// e = 0, captured, where the closed form gives 6.5e-5).
TEST(Cli, NoCaptureWithoutADashpot) {
  for (const char* k : {"odeint-dopri5", "odeint-rosenbrock4", "gsl-msbdf"}) {
    const CliRun r =
        ivv(std::string("simulate --scene paper --no-dashpot --v0 1e16 --json --integrator ") + k);
    ASSERT_EQ(r.exit_code, 0) << k << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["result"]["status"], "separated") << k;
  }
}

TEST(Cli, IntegratorFailureExitsOneWithReason) {
  const CliRun r = ivv("simulate --scene paper --zeta 1000 --integrator rk4 --max-steps 1000");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("implicit integrator"), std::string::npos) << r.out;
}

// A failed run prints null for the outcome, never a plausible e = 0.
TEST(Cli, FailedRunPrintsNullOutcome) {
  const CliRun r =
      ivv("simulate --scene paper --zeta 1000 --integrator rk4 --max-steps 1000 --json");
  EXPECT_EQ(r.exit_code, 1);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["result"]["status"], "failed");
  for (const char* key : {"e", "e_poisson", "e_energetic", "F_max", "t_contact", "z_perm"})
    EXPECT_TRUE(j["result"][key].is_null()) << key << " = " << j["result"][key];
  EXPECT_TRUE(j["result"]["energy"]["residual"].is_null());
  EXPECT_TRUE(j["result"]["energy"]["plastic_integrated"].is_boolean());  // a flag, not a number
  EXPECT_FALSE(j["result"]["reason"].get<std::string>().empty());
  EXPECT_GT(j["result"]["steps"].get<long>(), 0);
}

// The captured impact (paper scene, v0 = 10 m/s, zeta = 2) reports its end state, impulse
// m v0 = 5 N s and final energy 0, with every integrator that runs the scene (rk4's fixed
// step is not for a stiff dashpot) and with --integrator auto.
TEST(Cli, CapturedImpactJsonReportsTheEndStateWithEveryIntegrator) {
  for (const char* k : {"auto", "dop853", "rodas4", "odeint-rosenbrock4", "gsl-msbdf", "gsl-rk8pd",
                        "odeint-dopri5", "dp45", "mp50"}) {
    const CliRun r =
        ivv(std::string("simulate --scene paper --v0 10 --zeta 2 --json --integrator ") + k);
    ASSERT_EQ(r.exit_code, 0) << k << ": " << r.err;
    const auto j = nlohmann::json::parse(r.out)["result"];
    EXPECT_EQ(j["status"], "captured") << k;
    EXPECT_NEAR(j["impulse"].get<double>(), 5.0, 5.0 * 1e-15) << k;  // m v0: a product
    EXPECT_EQ(j["energy"]["final"].get<double>(), 0.0) << k;
    EXPECT_EQ(j["energy"]["stored"].get<double>(), 0.0) << k;
    EXPECT_TRUE(j["t_contact"].is_null()) << k;  // the contact never ends
    EXPECT_GT(j["t_capture"].get<double>(), 0.0) << k;
  }
}

// Each command gave a wrong number with exit 0 (e = -nan beside "separated", a NaN claim
// passed, a decimal comma read as a 5 N force) or ran the whole sweep before failing; now a
// correct number, or bad input (exit 2) before any work.
TEST(Cli, CommandsGiveANumberOrBadInput) {
  const CliRun hc = ivv("simulate --scene paper --v0 1 --law hunt-crossley --hc-mu 1e-200 --json");
  ASSERT_EQ(hc.exit_code, 0) << hc.err;
  EXPECT_EQ(nlohmann::json::parse(hc.out)["result"]["e"].get<double>(), 1.0);
  for (const char* bad :
       {"simulate --scene paper --force 'K_h*z^1,5'",
        "simulate --scene paper --force 'K_h*z^1.5' --param _pi=1",
        "check-law --force 'K_h*z^1.5' --v0 1 --zeta 0 --expect-cor '0/0'",
        "check-law --force 'K_h*z^1.5' --v0 1 --zeta 0 --expect-cor 'sqrt(-1)'",
        "bench --gbench --benchmark_repetitions=-5", "bench --gbench --benchmark_min_time=nan",
        "bench --gbench --benchmark_out=/nonexistent/x.json"}) {
    const CliRun r = ivv(bad);
    EXPECT_EQ(r.exit_code, 2) << bad << "\n" << r.err;
  }
  // stdout is a pipe here (popen): refused before the sweep runs, and nothing left in /dev
  const CliRun out = ivv("sweep --scene paper --v0 1:2:3 --zeta 0 --out /dev/stdout");
  EXPECT_EQ(out.exit_code, 2) << out.err;
  EXPECT_FALSE(std::filesystem::exists("/dev/stdout.journal"));
}

// Each message names what the user gave and the exit code says whose fault it was (1: the
// computation failed; 2: the input is bad).
TEST(Cli, MessagesNameWhatTheUserGave) {
  // NaN reached inside contact is a failed computation (exit 1, the reason printed) ...
  const CliRun inside =
      ivv("simulate --scene paper --v0 1 --force 'z < 1e-5 ? K_h*z^1.5 : sqrt(-1)'");
  EXPECT_EQ(inside.exit_code, 1) << inside.err;
  EXPECT_NE(inside.out.find("--force evaluated to -nan"), std::string::npos) << inside.out;
  // ... NaN at contact onset is a law no impact can run (exit 2)
  const CliRun onset = ivv("simulate --scene paper --v0 1 --force 'sqrt(-1) + K_h*z^1.5'");
  EXPECT_EQ(onset.exit_code, 2) << onset.err;
  // fit-hc fits Hunt-Crossley to an expression law like to any other law
  const CliRun fit = ivv("fit-hc --scene paper --v0 1 --force 'K_h*z^1.5*(1 + 0.3*zdot)' --json");
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NEAR(nlohmann::json::parse(fit.out)["mu"].get<double>(), 0.3, 1e-6);  // it is HC
  const CliRun captured = ivv("fit-hc --scene paper --v0 10 --zeta 2");
  EXPECT_EQ(captured.exit_code, 1);
  EXPECT_EQ(captured.err.find(") :"), std::string::npos) << captured.err;
  // zeta = 0 is refused, and the message says how to ask for no dashpot
  const CliRun zero = ivv("simulate --scene paper --zeta 0");
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--zeta"), std::string::npos) << zero.err;
  EXPECT_NE(zero.err.find("--no-dashpot"), std::string::npos) << zero.err;
  const CliRun syntax = ivv("simulate --scene paper --force 'z++'");
  EXPECT_EQ(syntax.exit_code, 2);
  EXPECT_NE(syntax.err.find("syntax error"), std::string::npos) << syntax.err;
  for (const char* cmd :
       {"sweep --scene paper --v0 1 --zeta 0 --threads '' --out /tmp/ivv_never.csv",
        "verify --filter 'analytic.*' --threads -1 --out /tmp/ivv_never.json",
        "report --threads 2x --out /tmp/ivv_never_report"}) {
    const CliRun r = ivv(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists("/tmp/ivv_never.csv"));
  }
}

// A finite plate runs its modes: final e, e_first, the contacts, F_max and the mode count in the
// JSON and the text; a dashpot flag on it is bad input (exit 2) naming the flag.
TEST(Cli, FinitePlateSimulateReportsContactsAndModes) {
  const CliRun r = ivv("simulate --scene drop-weight-coupon --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "finite-plate");
  const auto& res = j["result"];
  for (const char* key : {"e", "e_first", "F_max", "t_contact", "contacts", "contact_count",
                          "mode_count", "residual_compliance", "energy"})
    EXPECT_TRUE(res.contains(key)) << key;
  EXPECT_GT(res["e"].get<double>(), 0.5);  // a rebound, not the infinite plate's capture
  EXPECT_GT(res["F_max"].get<double>(), 1000.0);
  EXPECT_GE(res["contact_count"].get<int>(), 1);
  const CliRun text = ivv("simulate --scene steel-ball-on-finite-steel-plate --law hertz");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  for (const char* word : {"e_first", "contacts", "modes", "F_max"})
    EXPECT_NE(text.out.find(word), std::string::npos) << word << "\n" << text.out;
  const CliRun bad = ivv("simulate --scene drop-weight-coupon --zeta 0.1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--zeta"), std::string::npos) << bad.err;
}

// [structure] dropped_modes reaches `simulate`: its JSON names it in the truncation block (the
// static compliance when the scene says nothing) with the order the truncation rule took; a name it
// does not know is bad input (exit 2) naming the field and the accepted names.
TEST(Cli, FinitePlateDroppedModesFromTheScene) {
  const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                     ("ivv_dropped_" + std::to_string(getpid()) + ".toml");
  auto write = [&](const std::string& dropped) {
    std::ofstream out(file);
    out << "[impactor]\nmass = 0.004168\nradius = 0.005\nyoungs_modulus = 207e9\n"
           "poisson_ratio = 0.3\n[target]\nyoungs_modulus = 207e9\npoisson_ratio = 0.3\n"
           "[structure]\nkind = \"plate\"\nthickness = 0.001\ndensity = 7960\n"
           "length_x = 0.05\nlength_y = 0.04\nedges = \"simply-supported\"\n"
        << dropped << "[impact]\nvelocity = 1.0\n";
  };
  write("dropped_modes = \"oscillator\"\n");
  const CliRun osc = ivv("simulate --scene " + file.string() + " --law hertz --json");
  ASSERT_EQ(osc.exit_code, 0) << osc.err;
  EXPECT_EQ(nlohmann::json::parse(osc.out)["truncation"]["dropped_modes"], "oscillator");
  EXPECT_EQ(nlohmann::json::parse(osc.out)["truncation"]["order"], 4.0);  // the rule's order
  write("");
  const CliRun plain = ivv("simulate --scene " + file.string() + " --law hertz --json");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(nlohmann::json::parse(plain.out)["truncation"]["dropped_modes"], "static-compliance");
  EXPECT_EQ(nlohmann::json::parse(plain.out)["truncation"]["order"], 3.0);
  // without --rtol/--atol a finite plate integrates at the plate's own defaults, 1e-8 and 1e-10
  // (kPlateSimulateRtol, kPlateSimulateAtol of solver/plate/plate_impact.h)
  EXPECT_EQ(nlohmann::json::parse(plain.out)["options"]["rtol"], 1e-8);
  EXPECT_EQ(nlohmann::json::parse(plain.out)["options"]["atol"], 1e-10);
  write("dropped_modes = \"modal\"\n");
  const CliRun bad = ivv("simulate --scene " + file.string() + " --law hertz --json");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(bad.out.empty()) << bad.out;
  for (const char* word :
       {"structure.dropped_modes", "static-compliance", "oscillator", "truncated"})
    EXPECT_NE(bad.err.find(word), std::string::npos) << word << ": " << bad.err;
  std::filesystem::remove(file);
}

// --integrator on a finite plate names its stepper (the exponential one by default), and the JSON
// says which ran. The two steppers on the same modes at the default rtol 1e-10 per step: e within
// 1e-7 (N rtol over the coupon's ~1000 steps; measured equal to 10 digits). A sweep runs only the
// default: any other name is bad input there, not ignored.
TEST(Cli, FinitePlateIntegratorNamesItsStepper) {
  const CliRun a = ivv("simulate --scene drop-weight-coupon --json");
  const CliRun b = ivv("simulate --scene drop-weight-coupon --integrator dop853 --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const auto ja = nlohmann::json::parse(a.out), jb = nlohmann::json::parse(b.out);
  EXPECT_EQ(ja["options"]["stepper"], "exponential");
  EXPECT_EQ(jb["options"]["stepper"], "dop853");
  EXPECT_NEAR(ja["result"]["e"].get<double>(), jb["result"]["e"].get<double>(), 1e-7);
  const CliRun rigid_name = ivv("simulate --scene drop-weight-coupon --integrator rodas4");
  EXPECT_EQ(rigid_name.exit_code, 2);
  EXPECT_NE(rigid_name.err.find("--integrator"), std::string::npos) << rigid_name.err;
  const CliRun sweep =
      ivv("sweep --scene drop-weight-coupon --v0 1,2 --integrator dop853 -q --out /dev/null");
  EXPECT_EQ(sweep.exit_code, 2);
  EXPECT_NE(sweep.err.find("--integrator"), std::string::npos) << sweep.err;
}

}  // namespace
