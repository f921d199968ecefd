// ivv sweep: COR and peak force over a v0 x zeta grid, to CSV with a JSON sidecar and a journal
// that --resume continues from; across MPI ranks under mpirun.
#include <signal.h>

#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>
#include <optional>

#include "app/cli_args.h"
#include "app/command.h"
#include "app/model_flags.h"
#include "app/mpi_sweep.h"
#include "app/progress.h"
#include "app/sweep_sidecar.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/sweep.h"

namespace ivv::app {
namespace {

// SIGINT/SIGTERM during a sweep: stop handing out work, finish the points in flight, keep the
// journal. A second signal ends the process at once (SA_RESETHAND); the journal survives it.
std::atomic<bool> g_sweep_stop{false};
std::atomic<int> g_sweep_signal{0};
extern "C" void on_sweep_signal(int sig) {
  g_sweep_signal = sig;
  g_sweep_stop = true;
}
void install_sweep_signal_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;
  sa.sa_flags = SA_RESETHAND;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
}

struct SweepFlags {
  std::string v0_grid, zeta_grid, out_path;
  bool log = false;
  bool resume = false;
  bool quiet = false;
  int threads = 0;
  bool zeta_given = false;
};

int run_sweep(const ModelFlags& f, const SweepFlags& sf, const std::string& command) {
  SweepRequest req;
  req.base = to_request(to_options(f));
  req.velocities = parse_grid(sf.v0_grid, "--v0", sf.log);
  if (sf.zeta_given)
    req.zetas = parse_grid(sf.zeta_grid, "--zeta", false);
  else if (req.base.scene.damping.kind != Damping::Kind::none)
    req.scene_dashpot = true;  // every point keeps the scene's own dashpot (c, lambda, structure)
  else
    throw InputError("--zeta",
                     "required: the scene has no dashpot of its own (LO:HI:N or a,b,c; 0 = no "
                     "dashpot)");
  req.threads = sf.threads;
  resolve_output_path(sf.out_path, "--out");  // a bad output path fails before the sweep runs
  validate(req);  // the one validation of a sweep, before any file is touched

  const nlohmann::json inputs = sweep_inputs_json(req, {sf.v0_grid, sf.log}, {sf.zeta_grid, false});
  install_sweep_signal_handlers();
  std::optional<mpi::World> world;
  if (mpi::launched_by_mpirun()) world.emplace();
  const bool writer = !world || world->rank() == 0;

  std::unique_ptr<SweepSink> sink;
  int start_code = 0;
  std::string start_error;
  if (writer) {
    try {
      SweepOutputOptions out{sf.out_path, sf.resume, inputs.dump()};
      out.sidecar = sidecar_path(sf.out_path);  // committed with the CSV, never without it
      sink = std::make_unique<SweepSink>(req, std::move(out));
    } catch (const InputError& e) {
      start_code = kExitBadInput;
      start_error = e.what();
    } catch (const std::exception& e) {
      start_code = kExitFailure;
      start_error = e.what();
    }
  }
  if (world) start_code = world->agree_on_start(start_code);
  if (start_code != 0) {
    if (writer) std::cerr << "ivv: error: " << start_error << "\n";
    return start_code;
  }
  if (writer && sink->resumed() > 0)
    std::cerr << "ivv sweep: resuming: " << sink->resumed() << " of " << sink->total()
              << " points read back from " << sink->journal_path().string() << "\n";
  if (writer && sink->damaged_rows() > 0)
    std::cerr << "ivv sweep: " << sink->damaged_rows()
              << " journal rows failed their checksum and are computed again\n";

  ProgressLine progress("ivv sweep", writer ? sink->resumed() : 0);
  SweepRunOptions run;
  run.stop = &g_sweep_stop;
  if (writer && !sf.quiet)
    run.progress = [&](std::size_t d, std::size_t t) { progress.update(d, t); };
  if (world) {
    const auto per_rank = mpi::run_sweep_ranks(*world, req, sink.get(), run);
    if (writer) {
      progress.finish();
      std::cerr << "ivv sweep: " << world->size() << " MPI ranks computed";
      for (std::size_t r = 0; r < per_rank.size(); ++r)
        std::cerr << (r ? ", " : " ") << per_rank[r];
      std::cerr << " points\n";
    }
    if (!writer) return 0;
  } else {
    run_sweep_points(req, *sink, run);
  }
  progress.finish();

  const bool complete =
      sink->finish_with_sidecar([&](const SweepCounts& counts, std::ostream& out) {
        out << sweep_sidecar_json(inputs, counts, sf.out_path, command).dump(2) << "\n";
      });
  if (!complete) {
    std::cerr << "ivv sweep: interrupted: " << sink->done() << " of " << sink->total()
              << " points done and kept in " << sink->journal_path().string()
              << ". Resume with:\n  "
              << (world ? "mpirun -np " + std::to_string(world->size()) + " ... " : "") << command
              << (command.find(" --resume") == std::string::npos ? " --resume" : "") << "\n";
    const int sig = g_sweep_signal.load();
    return 128 + (sig ? sig : SIGINT);
  }
  const SweepCounts& c = sink->counts();
  std::cerr << "ivv sweep: wrote " << sink->total() << " impacts to " << sf.out_path << " and "
            << sidecar_path(sf.out_path).string() << " (" << c.separated << " separated, "
            << c.captured << " captured, " << c.failed << " failed";
  if (c.failed) std::cerr << ": see the reason column";
  std::cerr << ")\n";
  return c.failed ? kExitFailure : 0;
}

class Sweep final : public Command {
 public:
  explicit Sweep(CLI::App& app)
      : Command(app.add_subcommand(
            "sweep",
            "COR and peak force over a v0 x zeta grid, to CSV (+ a JSON sidecar); runs across "
            "MPI ranks under mpirun")) {
    CLI::App& cmd = cli();
    add_model_flags(cmd, flags_, false);
    cmd.add_option("--v0", sf_.v0_grid, "velocities [m/s]: LO:HI:N or a,b,c")->required();
    cmd.add_flag("--log", sf_.log, "logarithmic spacing of the LO:HI:N velocity grid");
    cmd.add_option("--zeta", sf_.zeta_grid,
                   "damping ratios: LO:HI:N or a,b,c (0 = no dashpot); absent: the scene's own "
                   "dashpot at every point");
    cmd.add_option("--out", sf_.out_path, "output CSV (the sidecar goes beside it: NAME.json)")
        ->required();
    add_threads_option(cmd, sf_.threads, "worker threads per process (0 = all cores)");
    cmd.add_flag("--resume", sf_.resume,
                 "continue an interrupted sweep from its journal (OUT.journal)");
    cmd.add_flag("-q,--quiet", sf_.quiet, "no progress on stderr");
  }

  int run(const Invocation& inv) override {
    sf_.zeta_given = cli().count("--zeta") > 0;
    return run_sweep(flags_, sf_, inv.command_line);
  }

 private:
  ModelFlags flags_;
  SweepFlags sf_;
};

}  // namespace

std::unique_ptr<Command> make_sweep(CLI::App& app) {
  return std::make_unique<Sweep>(app);
}

}  // namespace ivv::app
