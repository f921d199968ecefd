// ivv check-law: a contact law (--force EXPR, or --law NAME) through the conformance checks
// (verification/conformance.h), with a verdict per check; --report DIR writes its HTML page.
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "app/cli_args.h"
#include "app/command.h"
#include "app/model_flags.h"
#include "oracles/expression_functions.h"
#include "reports/law_report.h"
#include "scene/input_error.h"
#include "verification/check_law_request.h"
#include "verification/conformance.h"

namespace ivv::app {
namespace {

struct CheckLawFlags {
  conformance::CheckLawAsk ask;  // the claims (the grid's axes are parsed from the strings below)
  bool no_monotone = false;
  std::optional<std::string> onset_force;  // --onset-force EXPR (expression laws)
  std::string v0_grid, zeta_grid, c_grid;
  bool json = false;
  std::string report_dir;
  std::string name;        // the law's name in the verdict and the report
  bool law_given = false;  // --law NAME was typed (a built-in law is checked by name)
};

// `--functions`: the published formulas an --expect-cor expression may call.
int list_functions() {
  for (const ExpressionFunction& f : oracles::expression_functions())
    std::cout << f.signature << "\t" << f.meaning << "\n";
  return 0;
}

int run_check_law(ModelFlags f, const CheckLawFlags& c, const std::string& command_line) {
  if (f.scene.empty()) f.scene = "paper";
  if (!f.force && !c.law_given && f.params.empty() && !f.hc_k && !f.hc_mu)
    throw InputError("--force",
                     "give the law to check: --force EXPR, or --law NAME (`ivv laws` lists them)");
  RequestOptions options = to_options(f);
  conformance::declare_onset_force(options, c.onset_force);
  const SimulationRequest req = to_check_law_request(load_scene(options.scene), options);
  conformance::CheckLawAsk ask = c.ask;
  ask.monotone = !c.no_monotone;
  if (!c.v0_grid.empty()) ask.velocities = parse_grid(c.v0_grid, "--v0");
  if (!c.zeta_grid.empty()) ask.zetas = parse_grid(c.zeta_grid, "--zeta");
  if (!c.c_grid.empty()) ask.dashpots = parse_grid(c.c_grid, "--c");
  const conformance::Grid grid = conformance::check_law_grid(req, ask);
  const conformance::Claims claims =
      conformance::check_law_claims(req, ask, oracles::expression_functions());
  if (!c.report_dir.empty()) reports::check_report_dir(c.report_dir);
  conformance::LawUnderTest law = conformance::registry_law(req);
  if (!c.name.empty()) law.name = c.name;
  const conformance::Report report = conformance::run_conformance(law, claims, grid);
  if (!c.report_dir.empty()) {
    const auto index = reports::write_law_report(report, c.report_dir, command_line);
    std::cerr << "ivv check-law: wrote " << index.string() << "\n";
  }
  if (c.json) {
    const nlohmann::json j = conformance::check_law_json(report, req, claims);
    std::cout << j.dump(2) << std::endl;
  } else {
    std::cout << report.full();
  }
  return report.passed() ? 0 : kExitFailure;
}

class CheckLaw final : public Command {
 public:
  explicit CheckLaw(CLI::App& app)
      : Command(app.add_subcommand(
            "check-law",
            "put a contact law (--force EXPR, or --law NAME) through the conformance checks")) {
    add_flags(cli());
  }

  int run(const Invocation& inv) override {
    if (functions_) return list_functions();
    check_.law_given = cli().count("--law") > 0;
    return run_check_law(flags_, check_, inv.command_line);
  }

 private:
  void add_flags(CLI::App& cmd);
  ModelFlags flags_;
  CheckLawFlags check_;
  bool functions_ = false;
};

void CheckLaw::add_flags(CLI::App& cmd) {
  add_model_flags(cmd, flags_, {.scene_required = false});
  cmd.add_option("--expect-cor", check_.ask.expect_cor,
                 "the COR the law is meant to deliver: an expression in v0, the scene's "
                 "constants and --param names");
  cmd.add_option("--onset-force", check_.onset_force,
                 "expression law: the force [N] the law intends at z = 0 on first loading (an "
                 "adhesive jump-in, e.g. '-Fad'); static.onset then checks F(0) against it");
  cmd.add_option("--cor-tolerance", check_.ask.cor_tolerance,
                 "allowed |e - expected| (default 1e-9: 10x the reference's error of e)");
  cmd.add_flag("--elastic-at-low-speed", check_.ask.elastic_at_low_speed,
               "claim e -> 1 as v0 -> 0 (checked)");
  cmd.add_flag("--no-monotone", check_.no_monotone,
               "do not claim that e falls with v0 and with damping");
  cmd.add_flag("--cor-increasing-in-v0", check_.ask.cor_increasing_in_v0,
               "claim e non-decreasing in v0 (adhesive laws: slow impacts captured), in place of "
               "the default claim that e falls with v0 (checked)");
  cmd.add_option("--captured-below", check_.ask.captured_below,
                 "claim: captured (e = 0) at every grid velocity below V [m/s], and without a "
                 "dashpot rebounding at every one at or above it (checked)");
  cmd.add_option("--v0", check_.v0_grid,
                 "velocity grid [m/s], LO:HI:N or a,b,c (default: 7 points over three decades "
                 "around the scene's v0)");
  cmd.add_option("--zeta", check_.zeta_grid,
                 "damping ratios of the series dashpot (default 0,0.1; rate-dependent laws: 0 "
                 "only)");
  cmd.add_flag("--json", check_.json, "print the verdict and every check as JSON");
  cmd.add_option("--report", check_.report_dir, "write DIR/index.html for this law");
  cmd.add_option("--c", check_.c_grid,
                 "dashpot coefficients c [N s/m] to check besides the zetas, LO:HI:N or a,b,c "
                 "(any scene; default: the scene's own dashpot, if it has one)");
  cmd.add_option("--name", check_.name, "the law's name in the verdict and the report");
  cmd.add_flag("--functions", functions_,
               "list the published formulas an --expect-cor expression may call, and exit");
}

}  // namespace

std::unique_ptr<Command> make_check_law(CLI::App& app) {
  return std::make_unique<CheckLaw>(app);
}

}  // namespace ivv::app
