// ivv sweep: COR and peak force over a v0 x zeta grid (x the scene values of --set), to CSV with
// a JSON sidecar and a journal that --resume continues from, or to standard output (--out -);
// across MPI ranks under mpirun.
#include <signal.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

#include "app/cli_args.h"
#include "app/command.h"
#include "app/model_flags.h"
#include "app/mpi_sweep.h"
#include "app/progress.h"
#include "app/sweep_sidecar.h"
#include "scene/input_error.h"
#include "scene/scene_values.h"
#include "solver/atomic_file.h"
#include "solver/sweep/sweep.h"

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
  std::vector<std::string> sets;  // --set KEY=RANGE, in the order given
  bool log = false;
  bool resume = false;
  bool quiet = false;
  int threads = 0;
  bool zeta_given = false;
  bool to_stdout() const { return out_path == "-"; }
};

// The request and the sidecar's description of its inputs, from the flags; throws InputError.
struct ParsedSweep {
  SweepRequest request;
  nlohmann::json inputs;
};
ParsedSweep parse_sweep(const ModelFlags& f, const SweepFlags& sf) {
  ParsedSweep p;
  SweepRequest& req = p.request;
  req.base = to_sweep_base(to_options(f));
  req.velocities = parse_grid(sf.v0_grid, "--v0", spacing_of(sf.log));
  if (sf.zeta_given)
    req.zetas = parse_grid(sf.zeta_grid, "--zeta");
  else if (req.base.scene.damping.kind != Damping::Kind::none)
    req.scene_dashpot = true;  // every point keeps the scene's own dashpot (c, lambda, structure)
  else
    throw InputError("--zeta",
                     "required: the scene has no dashpot of its own (LO:HI:N or a,b,c; 0 = no "
                     "dashpot)");
  std::vector<GridSpec> axis_specs;
  for (const std::string& item : sf.sets) {
    SetAxisSpec spec = parse_set_axis(item);
    req.axes.push_back({spec.key, std::move(spec.values)});
    axis_specs.push_back({spec.range, spec.log});
  }
  req.threads = sf.threads;
  // a bad output path fails before the sweep runs
  if (!sf.to_stdout()) resolve_output_path(sf.out_path, "--out");
  validate(req);  // the one validation of a sweep, before any file is touched
  p.inputs = sweep_inputs_json(req, {sf.v0_grid, sf.log}, {sf.zeta_grid, false}, axis_specs);
  return p;
}

// The sink of the writing rank: the CSV with its journal and sidecar, or standard output.
// Returns 0, or the exit code of the error it printed.
int open_sink(const SweepRequest& req, const SweepFlags& sf, const nlohmann::json& inputs,
              std::unique_ptr<SweepSink>& sink) {
  try {
    SweepOutputOptions out{sf.out_path, sf.resume, inputs.dump()};
    if (sf.to_stdout()) {
      // a reader that stops reading (`| head`) is an EPIPE on the next write, not a SIGPIPE
      std::signal(SIGPIPE, SIG_IGN);
      out.csv = "standard output";
      out.stream = stdout;
    } else {
      out.sidecar = sidecar_path(sf.out_path);  // committed with the CSV, never without it
    }
    sink = std::make_unique<SweepSink>(req, std::move(out));
    return 0;
  } catch (const InputError& e) {
    std::cerr << "ivv: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::cerr << "ivv: error: " << e.what() << "\n";
    return kExitFailure;
  }
}

// " in 0.27 s, 3.0 us an impact" for the points this run computed (a resumed sweep's read-back
// points took no time) since `started`: what a sweep of millions of points costs a point.
std::string sweep_time_text(const SweepSink& sink, std::chrono::steady_clock::time_point started) {
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::size_t computed = sink.total() - sink.resumed();
  std::ostringstream os;
  os << std::setprecision(3) << " in " << seconds << " s";
  if (computed > 0) os << ", " << 1e6 * seconds / static_cast<double>(computed) << " us an impact";
  if (computed > 0 && sink.resumed() > 0) os << " over the " << computed << " computed in this run";
  return os.str();
}

// The end of a sweep: the CSV and its sidecar committed (or the stream flushed), and what
// happened said on stderr, with the time since `started`. Returns the exit code.
int finish_sweep(SweepSink& sink, const SweepFlags& sf, const nlohmann::json& inputs,
                 const std::string& command, const std::optional<mpi::World>& world,
                 std::chrono::steady_clock::time_point started) {
  const bool complete = sink.finish_with_sidecar([&](const SweepCounts& counts, std::ostream& out) {
    out << sweep_sidecar_json(inputs, counts, sf.out_path, command).dump(2) << "\n";
  });
  if (sink.output_error() == EPIPE) {  // the reader had what it wanted: not a failure of ivv
    if (!sf.quiet)
      std::cerr << "ivv sweep: the reader closed standard output after " << sink.written() << " of "
                << sink.total() << " rows; stopped\n";
    return 0;
  }
  if (sink.output_error() != 0) {
    std::cerr << "ivv: error: cannot write standard output: " << std::strerror(sink.output_error())
              << "\n";
    return kExitFailure;
  }
  if (!complete) {
    const int sig = g_sweep_signal.load();
    if (sf.to_stdout()) {
      std::cerr << "ivv sweep: interrupted: " << sink.written() << " of " << sink.total()
                << " rows written to standard output (a sweep to standard output keeps no "
                   "journal: rerun it, or use --out FILE to be able to resume)\n";
      return 128 + (sig ? sig : SIGINT);
    }
    std::cerr << "ivv sweep: interrupted: " << sink.done() << " of " << sink.total()
              << " points done and kept in " << sink.journal_path().string() << ". Resume with:\n  "
              << (world ? "mpirun -np " + std::to_string(world->size()) + " ... " : "") << command
              << (command.find(" --resume") == std::string::npos ? " --resume" : "") << "\n";
    return 128 + (sig ? sig : SIGINT);
  }
  const SweepCounts& c = sink.counts();
  std::cerr << "ivv sweep: wrote " << sink.total() << " impacts to "
            << (sf.to_stdout() ? std::string("standard output")
                               : sf.out_path + " and " + sidecar_path(sf.out_path).string())
            << " (" << c.separated << " separated, " << c.captured << " captured, " << c.failed
            << " failed";
  if (c.failed) std::cerr << ": see the reason column";
  std::cerr << ")" << sweep_time_text(sink, started) << "\n";
  return c.failed ? kExitFailure : 0;
}

int run_sweep(const ModelFlags& f, const SweepFlags& sf, const std::string& command) {
  const ParsedSweep parsed = parse_sweep(f, sf);
  const SweepRequest& req = parsed.request;
  install_sweep_signal_handlers();
  std::optional<mpi::World> world;
  if (mpi::launched_by_mpirun()) world.emplace();
  const bool writer = !world || world->rank() == 0;

  std::unique_ptr<SweepSink> sink;
  int start_code = writer ? open_sink(req, sf, parsed.inputs, sink) : 0;
  if (world) start_code = world->agree_on_start(start_code);
  if (start_code != 0) return start_code;
  if (writer && sink->resumed() > 0)
    std::cerr << "ivv sweep: resuming: " << sink->resumed() << " of " << sink->total()
              << " points read back from " << sink->journal_path().string() << "\n";
  if (writer && sink->damaged_rows() > 0)
    std::cerr << "ivv sweep: " << sink->damaged_rows()
              << " journal rows failed their checksum and are computed again\n";

  const auto started = std::chrono::steady_clock::now();
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
  return finish_sweep(*sink, sf, parsed.inputs, command, world, started);
}

// The CSV's columns and the --set keys, each with its unit (from the tables of the library).
std::string help_footer() {
  std::string keys;
  for (const SceneValueInfo& v : scene_values()) {
    keys += keys.empty() ? "" : ", ";
    keys += std::string(v.key) + " [" + std::string(v.unit) + "]";
  }
  std::string columns = sweep_csv_columns_text({SceneAxis{"KEY", {}}});
  columns.replace(columns.find("KEY"), 3, "KEY of each --set [its unit]");
  return "CSV columns (units; '-' dimensionless or a count): " + columns +
         "\nRows: row-major over v0, zeta, then each --set axis in order (the last fastest); "
         "LO:HI:N grids hold the decimals typed (0.1:1:10 gives 0.1, 0.2, ..., 1).\n"
         "Scene values for --set: " +
         keys + "\n";
}

class Sweep final : public Command {
 public:
  explicit Sweep(CLI::App& app)
      : Command(app.add_subcommand(
            "sweep",
            "COR and peak force over a v0 x zeta grid (x any scene values: --set), to CSV (+ a "
            "JSON sidecar) or to standard output; runs across MPI ranks under mpirun")) {
    CLI::App& cmd = cli();
    add_model_flags(cmd, flags_, {});
    cmd.add_option("--v0", sf_.v0_grid, "velocities [m/s]: LO:HI:N or a,b,c")->required();
    cmd.add_flag("--log", sf_.log, "logarithmic spacing of the LO:HI:N velocity grid");
    cmd.add_option("--zeta", sf_.zeta_grid,
                   "damping ratios: LO:HI:N or a,b,c (0 = no dashpot); absent: the scene's own "
                   "dashpot at every point");
    cmd.add_option("--set", sf_.sets,
                   "KEY=LO:HI:N, KEY=log:LO:HI:N or KEY=a,b,c: sweep the scene value KEY too "
                   "(repeatable; e.g. structure.thickness=0.001:0.01:10); one CSV column each, "
                   "named KEY, in KEY's unit (listed below)");
    cmd.add_option("--out", sf_.out_path,
                   "output CSV (the sidecar goes beside it: NAME.json); '-': the rows to standard "
                   "output in grid order as they complete (no sidecar, no journal, so no "
                   "--resume)")
        ->required();
    add_threads_option(cmd, sf_.threads, "worker threads per process (0 = all cores)");
    cmd.add_flag("--resume", sf_.resume,
                 "continue an interrupted sweep from its journal (OUT.journal)");
    cmd.add_flag("-q,--quiet", sf_.quiet, "no progress on stderr");
    cmd.footer(help_footer());
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
