// ivv fit-hc: the Hunt-Crossley K and mu that reproduce a model's F_max and e (as the paper did).
#include <iomanip>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/command.h"
#include "app/model_flags.h"
#include "solver/fit_hunt_crossley.h"

namespace ivv::app {
namespace {

class FitHc final : public Command {
 public:
  explicit FitHc(CLI::App& app)
      : Command(app.add_subcommand(
            "fit-hc",
            "Hunt-Crossley K and mu reproducing a model's F_max and e (as the paper did)")) {
    add_model_flags(cli(), flags_, {.single_velocity_and_damping = true});
    cli().add_flag("--json", json_, "JSON {K, mu, e, F_max, t_contact_hc, t_contact_model}");
  }

  int run(const Invocation&) override {
    const SimulationRequest req = to_request(to_options(flags_));
    const HuntCrossleyFit fit = fit_hunt_crossley(req);
    if (json_) {
      std::cout << nlohmann::json{{"K", fit.K},
                                  {"mu", fit.mu},
                                  {"e", fit.e},
                                  {"F_max", fit.F_max},
                                  {"t_contact_hc", fit.t_contact_hc},
                                  {"t_contact_model", fit.t_contact_model},
                                  {"e_hc", fit.hc.e},
                                  {"F_max_hc", fit.hc.F_max},
                                  {"hc_runs", fit.evaluations}}
                       .dump(2)
                << std::endl;
      return 0;
    }
    std::cout << std::setprecision(8) << "Hunt-Crossley fitted to the " << to_string(req.law)
              << " model at v0 = " << req.scene.velocity << " m/s\n"
              << "  K  = " << fit.K << " N/m^1.5\n"
              << "  mu = " << fit.mu << " s/m   (mu v0 = " << fit.mu * req.scene.velocity << ")\n"
              << "  targets   e = " << fit.e << ", F_max = " << fit.F_max << " N\n"
              << "  HC gives  e = " << fit.hc.e << ", F_max = " << fit.hc.F_max << " N\n"
              << "  contact time: model " << fit.t_contact_model * 1e3 << " ms, Hunt-Crossley "
              << fit.t_contact_hc * 1e3 << " ms\n";
    return 0;
  }

 private:
  ModelFlags flags_;
  bool json_ = false;
};

}  // namespace

std::unique_ptr<Command> make_fit_hc(CLI::App& app) {
  return std::make_unique<FitHc>(app);
}

}  // namespace ivv::app
