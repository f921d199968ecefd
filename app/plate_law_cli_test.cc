// Contact laws on a finite plate from the command line: an expression law through `simulate` and
// `sweep`, `check-law --scene PLATE` with its text, JSON and report, and the reloading check.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/cli_run.h"

namespace {

namespace fs = std::filesystem;

using ivv::testing::CliRun;
using ivv::testing::ivv;

constexpr const char* kPlate = "--scene steel-ball-on-finite-steel-plate";

fs::path scratch(const std::string& name) {
  return fs::temp_directory_path() / ("ivv_plate_law_cli_" + std::to_string(getpid()) + name);
}

const nlohmann::json* find_check(const nlohmann::json& j, const std::string& id) {
  for (const auto& c : j["checks"])
    if (c["id"] == id) return &c;
  return nullptr;
}

// The same Hertz law typed as an expression: the same plate, modes and e as --law hertz, to the
// integration error of the two normalisations (N rtol over ~150 steps, far below 1e-7).
TEST(PlateLawCli, SimulateRunsAnExpressionLawOnTheFinitePlate) {
  const CliRun typed = ivv(std::string("simulate ") + kPlate + " --force 'K_h*z^1.5' --json");
  const CliRun builtin = ivv(std::string("simulate ") + kPlate + " --law hertz --json");
  ASSERT_EQ(typed.exit_code, 0) << typed.err;
  ASSERT_EQ(builtin.exit_code, 0) << builtin.err;
  const auto t = nlohmann::json::parse(typed.out), b = nlohmann::json::parse(builtin.out);
  EXPECT_EQ(t["law"], "expression");
  EXPECT_EQ(t["law_details"]["force"], "K_h*z^1.5");
  EXPECT_EQ(t["result"]["mode_count"], b["result"]["mode_count"]);
  EXPECT_NEAR(t["result"]["e"].get<double>(), b["result"]["e"].get<double>(), 1e-7);
  const CliRun text = ivv(std::string("simulate ") + kPlate + " --force 'K_h*z^1.5'");
  EXPECT_NE(text.out.find("law expression F = K_h*z^1.5"), std::string::npos) << text.out;
}

TEST(PlateLawCli, WhatThePlateDoesNotModelIsBadInputNamingTheFlag) {
  const CliRun rate = ivv(std::string("simulate ") + kPlate + " --force 'K_h*z^1.5 + 10*zdot'");
  EXPECT_EQ(rate.exit_code, 2);
  EXPECT_NE(rate.err.find("--force"), std::string::npos) << rate.err;
  EXPECT_NE(rate.err.find("zdot"), std::string::npos) << rate.err;
  const CliRun tension =
      ivv(std::string("simulate ") + kPlate + " --force 'K_h*z^1.5' --allow-tension");
  EXPECT_EQ(tension.exit_code, 2);
  EXPECT_NE(tension.err.find("--allow-tension"), std::string::npos) << tension.err;
}

TEST(PlateLawCli, SweepRunsAnExpressionLawOnTheFinitePlate) {
  const fs::path csv = scratch("sweep.csv");
  const CliRun r = ivv(std::string("sweep ") + kPlate +
                       " --force 'K_h*z^1.5' --v0 0.5,1 -q --out " + csv.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(csv);
  std::string line, all;
  int rows = 0;
  while (std::getline(in, line)) all += line + "\n", ++rows;
  EXPECT_EQ(rows, 3) << all;  // header and two velocities
  EXPECT_NE(all.find("finite-plate"), std::string::npos) << all;
  fs::remove(csv);
  fs::remove(fs::path(csv.string() + ".json"));
}

// The law's battery on the plate: every check runs on the plate or is skipped with its reason.
TEST(PlateLawCli, CheckLawOnAFinitePlatePassesASoundLaw) {
  const CliRun r = ivv(std::string("check-law ") + kPlate + " --force 'K_h*z^1.5' --v0 0.5,1");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  for (const char* line :
       {"pass  dynamic.energy", "pass  dynamic.impulse", "pass  dynamic.integrators",
        "pass  static.reloading", "SKIP  dynamic.cor_definitions", "SKIP  dynamic.monotone_v0"})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
  EXPECT_NE(r.out.find("finite plate"), std::string::npos) << r.out;
  const fs::path dir = scratch("report");
  const CliRun j = ivv(std::string("check-law ") + kPlate + " --law hertz --v0 1 --json --report " +
                       dir.string());
  ASSERT_EQ(j.exit_code, 0) << j.out << j.err;
  const auto json = nlohmann::json::parse(j.out);
  EXPECT_EQ(json["verdict"], "pass");
  ASSERT_NE(find_check(json, "dynamic.energy"), nullptr);
  EXPECT_NE((*find_check(json, "dynamic.energy"))["detail"].get<std::string>().find("plate"),
            std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "index.html"));
  fs::remove_all(dir);
}

// A law whose unloading curve lies above its loading curve below z_m (continuous at z_m): a cycle
// creates energy, and static.unloading_below fails. On the plate its runs are sound (the ledger
// closes with the law's own W_p < 0, the impulse and the steppers agree): the FAIL is the law's.
TEST(PlateLawCli, CheckLawOnAFinitePlateBlamesABrokenLawNotThePlate) {
  const CliRun r =
      ivv(std::string("check-law ") + kPlate +
          " --force 'K_h*z^1.5' --unload 'K_h*z^1.5*(1.1 - 0.1*z/zmax)' --v0 1 --json");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  const auto json = nlohmann::json::parse(r.out);
  EXPECT_EQ(json["verdict"], "fail");
  EXPECT_FALSE((*find_check(json, "static.unloading_below"))["passed"].get<bool>());
  for (const char* id : {"dynamic.energy", "dynamic.impulse", "dynamic.integrators"})
    EXPECT_TRUE((*find_check(json, id))["passed"].get<bool>()) << id << "\n" << r.out;
  // a rate-dependent law: the static checks run, the plate's are skipped with the reason
  const CliRun hc = ivv(std::string("check-law ") + kPlate + " --law hunt-crossley --hc-mu 0.1");
  EXPECT_NE(hc.out.find("SKIP  dynamic.energy"), std::string::npos) << hc.out << hc.err;
  EXPECT_NE(hc.out.find("rate-dependent"), std::string::npos) << hc.out;
}

// Reloading softer than unloading (zdot > 0 on the unloading branch) creates energy over a
// cycle below z_m: static.reloading fails, on any scene.
TEST(PlateLawCli, CheckLawFailsALawThatCreatesEnergyOnReloading) {
  const CliRun r =
      ivv("check-law --scene paper --force 'K_h*z^1.5' "
          "--unload 'K_h*z^1.5*(1 - mu*max(zdot, 0)*(1 - z/zmax))' --param mu=1 --v0 0.3");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.out.find("FAIL  static.reloading "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("creates energy"), std::string::npos) << r.out;
}

}  // namespace
