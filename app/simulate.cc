// ivv simulate: one impact, as a summary or as one JSON object (docs/design.md §5).
#include <iomanip>
#include <iostream>

#include "app/command.h"
#include "app/model_flags.h"
#include "reports/impact_json.h"
#include "reports/impact_text.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/plate/plate_run.h"

namespace ivv::app {
namespace {

void write_trajectory(const std::string& path, const std::vector<TrajectoryPoint>& trajectory) {
  write_file_atomically(
      path,
      [&](std::ostream& out) {
        out << "t,alpha,alpha_dot,y,z,F,tau,alpha_bar,F_bar\n" << std::setprecision(12);
        for (const auto& p : trajectory)
          out << p.t << ',' << p.alpha << ',' << p.alpha_dot << ',' << p.y << ',' << p.z << ','
              << p.force << ',' << p.tau << ',' << p.alpha_bar << ',' << p.force_bar << '\n';
      },
      "--trajectory");
}

class Simulate final : public Command {
 public:
  explicit Simulate(CLI::App& app)
      : Command(app.add_subcommand("simulate",
                                   "run one impact and print COR, peak force, contact time")) {
    add_model_flags(cli(), flags_, {.single_velocity_and_damping = true});
    cli().add_flag("--json", json_, "print one JSON object on stdout instead of the summary");
    cli().add_option("--trajectory", trajectory_,
                     "write t, alpha, alpha_dot, y, z, F, tau, alpha_bar, F_bar to this CSV");
  }

  int run(const Invocation&) override {
    const RequestOptions options = to_options(flags_);
    if (has_finite_plate(load_scene(options.scene))) return run_plate(options);
    SimulationRequest req = to_request(options);
    // given but empty is an error (resolve_output_path says so), not "no trajectory"
    if (trajectory_) resolve_output_path(*trajectory_, "--trajectory");
    std::vector<TrajectoryPoint> samples;
    const SimulationRun run = run_simulation(std::move(req), trajectory_ ? &samples : nullptr);
    const ImpactResult& r = run.result;
    if (r.failure == FailureKind::law_domain) throw InputError("--law", r.reason);
    if (trajectory_ && r.ok()) write_trajectory(*trajectory_, samples);
    if (json_)
      std::cout << simulation_json(run).dump(2) << std::endl;
    else
      std::cout << impact_summary(run);
    if (!r.ok()) {
      if (json_) std::cerr << "ivv simulate: " << r.reason << "\n";
      return kExitFailure;
    }
    return 0;
  }

 private:
  // A finite plate: its modes, no dashpot (solver/plate/plate_impact.h).
  int run_plate(const RequestOptions& options) const {
    if (trajectory_)
      throw InputError("--trajectory",
                       "not written for a finite plate yet (its state is the "
                       "impactor and every kept mode)");
    const PlateRun run = run_plate_simulation(options);
    if (json_)
      std::cout << plate_simulation_json(run).dump(2) << std::endl;
    else
      std::cout << plate_impact_summary(run);
    if (!run.result.ok) {
      if (json_) std::cerr << "ivv simulate: " << run.result.reason << "\n";
      return kExitFailure;
    }
    return 0;
  }

  ModelFlags flags_;
  bool json_ = false;
  std::optional<std::string> trajectory_;
};

}  // namespace

std::unique_ptr<Command> make_simulate(CLI::App& app) {
  return std::make_unique<Simulate>(app);
}

}  // namespace ivv::app
