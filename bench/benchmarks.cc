#include "bench/benchmarks.h"

#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/plate/plate_impact.h"
#include "solver/simulate.h"
#include "solver/steppers/dop853_lanes_run.h"

namespace ivv::bench {
namespace {

// docs/design.md §1: with c = 11440 N s/m the paper scene has zeta ~ 0.1.
constexpr double kPaperDashpot = 11440.0;  // [N s/m]
constexpr double kPaperVelocity = 1.0;     // [m/s]
constexpr double kStiffZeta = 1000.0;      // docs/design.md §6: the stiff end of the damping range

SimulationRequest paper_request(IntegratorKind kind, Damping damping) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = kPaperVelocity;
  req.scene.damping = damping;
  req.law = LawKind::elastoplastic;
  req.integrator = kind;
  return req;
}

void one_impact(benchmark::State& state, const SimulationRequest& req) {
  ImpactResult r;
  for (auto _ : state) {
    r = simulate(req);
    benchmark::DoNotOptimize(r);
    if (!r.ok()) {
      state.SkipWithError(("impact failed: " + r.reason).c_str());
      break;
    }
  }
  state.counters["rhs_evals"] = static_cast<double>(r.rhs_evaluations);
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["e"] = r.e;
}

// One finite-plate impact (solver/plate/plate_impact.h) of a shipped scene, at a fixed cut-off
// or (truncation_tol > 0) with the cut-off chosen for it, all its runs timed.
void one_plate_impact(benchmark::State& state, const Scene& scene, LawKind law,
                      const PlateImpactOptions& opt) {
  PlateImpactResult r;
  for (auto _ : state) {
    r = simulate_plate_impact(scene, law, {}, opt);
    benchmark::DoNotOptimize(r);
    if (!r.ok) {
      state.SkipWithError(("plate impact failed: " + r.reason).c_str());
      break;
    }
  }
  state.counters["modes"] = static_cast<double>(r.mode_count);
  state.counters["steps"] = static_cast<double>(r.steps);
  state.counters["e"] = r.e;
}

void register_plate() {
  const std::pair<const char*, LawKind> scenes[] = {
      {"steel-ball-on-finite-steel-plate", LawKind::hertz},
      {"drop-weight-coupon", LawKind::elastoplastic}};
  for (const auto& [name, law] : scenes) {
    const Scene scene = load_scene(name);
    for (double cutoff : {20.0, 40.0, 50.0, 80.0}) {
      PlateImpactOptions opt;
      opt.cutoff = cutoff;
      opt.rtol = 1e-8;
      opt.atol = 1e-10;
      benchmark::RegisterBenchmark(
          ("plate/" + std::string(name) + "/cutoff=" + std::to_string(static_cast<int>(cutoff)))
              .c_str(),
          one_plate_impact, scene, law, opt)
          ->Unit(benchmark::kMillisecond);
    }
    PlateImpactOptions chosen;
    chosen.cutoff = kPlateFirstCutoff;
    chosen.truncation_tol = kPlateTruncationTol;
    chosen.rtol = 1e-8;
    chosen.atol = 1e-10;
    benchmark::RegisterBenchmark(("plate/" + std::string(name) + "/truncation-tol=1e-6").c_str(),
                                 one_plate_impact, scene, law, chosen)
        ->Unit(benchmark::kMillisecond);
  }
}

// Four states of the paper impact (Table 1, 1 m/s, zeta 0.1, dop853 at rtol 1e-8), one a lane,
// read off its trajectory (four samples a step, so a step is four sample spacings): halfway to
// yield (Hertz loading), halfway from yield to maximum compression (plastic loading), and a
// third and two thirds of the way from maximum compression to separation (unloading).
std::array<LaneStart, kDop853Lanes> paper_impact_lanes() {
  constexpr double v0 = 1.0, zeta = 0.1;
  SimulationRequest req = paper_request(IntegratorKind::dop853, Damping::ratio(zeta));
  req.options.rtol = req.options.atol = 1e-8;
  std::vector<TrajectoryPoint> path;
  const ImpactResult r = simulate(req, &path);
  if (!r.ok() || path.size() < 8) throw std::runtime_error("paper impact failed: " + r.reason);
  double t_yield = 0, t_z_max = 0;
  for (const ImpactEvent& ev : r.events) {
    if (ev.kind == EventKind::yield) t_yield = ev.t;
    if (ev.kind == EventKind::max_compression) t_z_max = ev.t;
  }
  const double z_y = derive(req.scene).z_y;
  using Branch = LanePlace::Branch;
  const std::array<std::pair<double, Branch>, kDop853Lanes> at = {{
      {0.5 * t_yield, Branch::hertz_loading},
      {0.5 * (t_yield + t_z_max), Branch::plastic_loading},
      {t_z_max + (r.t_contact - t_z_max) / 3, Branch::plastic_unloading},
      {t_z_max + 2 * (r.t_contact - t_z_max) / 3, Branch::plastic_unloading},
  }};
  std::array<LaneStart, kDop853Lanes> lanes;
  for (std::size_t i = 0; i < kDop853Lanes; ++i) {
    std::size_t k = 0;
    while (k + 2 < path.size() && path[k].t < at[i].first) ++k;
    LanePlace place;
    place.branch = at[i].second;
    place.z_over_z_y = path[k].z / z_y;
    place.z_max_over_z_y = r.z_max / z_y;
    place.w = path[k].alpha_dot / v0;
    place.h = 4 * (path[k + 1].tau - path[k].tau);
    lanes[i] = paper_lane(v0, zeta, place);
  }
  return lanes;
}

// Steps per lane a benchmark iteration takes from the paper states: the whole impact takes 9
// (150 right-hand sides at rtol 1e-8), so three stay near the states' branches, as the driver's
// steps between two events do. The lanes' start (a scalar right-hand side each) is spread over
// them.
constexpr int kLaneSteps = 3;

// The four paper lanes, kLaneSteps dop853 steps each: in AVX2 lanes (in lockstep, a call of
// Dop853Lanes::step a step, or free, each lane beginning its next step as soon as its last is
// complete) or four scalar dop853 steppers of the same unit, one after another. Counters per
// lane-step: the time (lane_step), and for the lanes their use (useful attempts / computed).
enum class LaneStepping { avx2_lockstep, avx2_free, scalar };
void paper_lanes(benchmark::State& state, LaneStepping stepping) {
  const bool in_lanes = stepping != LaneStepping::scalar;
  if (!dop853_lanes_runnable()) {
    state.SkipWithError("dop853 in lanes: this CPU has no AVX2 and FMA");
    return;
  }
  const std::array<LaneStart, kDop853Lanes> starts = paper_impact_lanes();
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;
  const LaneRunOptions run{.steps = kLaneSteps,
                           .dense_samples = false,
                           .schedule = stepping == LaneStepping::avx2_free
                                           ? LaneSchedule::free
                                           : LaneSchedule::lockstep};
  double use = 1;
  long steps = 0;
  for (auto _ : state) {
    if (in_lanes) {
      const LanesRunReport r = dop853_run_lanes(starts, opt, run);
      benchmark::DoNotOptimize(r);
      use = static_cast<double>(r.useful_attempts) / static_cast<double>(r.lane_attempts);
      steps = 0;
      for (const LaneRunReport& lane : r.lanes) steps += lane.steps;
    } else {
      steps = 0;
      for (const LaneStart& lane : starts) {
        const LaneRunReport r = dop853_run_scalar(lane, opt, run);
        benchmark::DoNotOptimize(r);
        steps += r.steps;
      }
    }
  }
  if (steps != static_cast<long>(kDop853Lanes) * kLaneSteps) {
    state.SkipWithError("a paper lane failed to take its steps");
    return;
  }
  state.counters["lane_step"] =
      benchmark::Counter(static_cast<double>(steps), benchmark::Counter::kIsIterationInvariantRate |
                                                         benchmark::Counter::kInvert);
  if (in_lanes) state.counters["lane_use"] = use;
}

void register_all() {
  register_plate();
  // the SIMD-lanes lever: 4 paper states a dop853 step each, in AVX2 lanes against 4 scalar steps
  benchmark::RegisterBenchmark("lanes/dop853/avx2-lockstep", paper_lanes,
                               LaneStepping::avx2_lockstep)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("lanes/dop853/avx2-free", paper_lanes, LaneStepping::avx2_free)
      ->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark("lanes/dop853/scalar", paper_lanes, LaneStepping::scalar)
      ->Unit(benchmark::kMicrosecond);
  for (IntegratorKind k : production_integrators()) {
    const SimulationRequest req = paper_request(k, Damping::coefficient(kPaperDashpot));
    benchmark::RegisterBenchmark(("paper/default/" + std::string(to_string(k))).c_str(), one_impact,
                                 req)
        ->Unit(benchmark::kMicrosecond);
  }
  // 1e-6, and 1e-8: the tolerance of the paper-scene speed target (|de|/e <= 1e-8)
  for (const char* tol : {"1e-6", "1e-8"}) {
    for (IntegratorKind k : production_integrators()) {
      if (traits(k).fixed_step) continue;  // no tolerance to set
      SimulationRequest req = paper_request(k, Damping::coefficient(kPaperDashpot));
      req.options.rtol = req.options.atol = std::stod(tol);
      benchmark::RegisterBenchmark(
          ("paper/rtol=" + std::string(tol) + "/" + std::string(to_string(k))).c_str(), one_impact,
          req)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  for (IntegratorKind k : production_integrators()) {
    if (!traits(k).implicit) continue;
    const SimulationRequest req = paper_request(k, Damping::ratio(kStiffZeta));
    benchmark::RegisterBenchmark(("stiff/" + std::string(to_string(k))).c_str(), one_impact, req)
        ->Unit(benchmark::kMicrosecond);
  }
  const SimulationRequest ref =
      paper_request(IntegratorKind::mp50, Damping::coefficient(kPaperDashpot));
  benchmark::RegisterBenchmark("reference/mp50", one_impact, ref)
      ->Unit(benchmark::kMillisecond)
      ->Iterations(1);
}

}  // namespace

void validate_benchmark_arguments(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const std::size_t eq = arg.find('=');
    if (arg.rfind("--benchmark_", 0) != 0 || eq == std::string::npos) continue;
    const std::string flag = arg.substr(0, eq), value = arg.substr(eq + 1);
    if (flag == "--benchmark_min_time") {
      // a number of seconds ("0.5", "0.5s") or of iterations ("100x")
      std::string number = value;
      if (!number.empty() && (number.back() == 's' || number.back() == 'x')) number.pop_back();
      char* end = nullptr;
      const double v = std::strtod(number.c_str(), &end);
      if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(v) ||
          !(v > 0) || v > 3600)
        throw InputError(flag,
                         "must be a number of seconds in (0, 3600] (e.g. 0.5s) or of "
                         "iterations (e.g. 100x), got '" +
                             value + "'");
    } else if (flag == "--benchmark_repetitions") {
      char* end = nullptr;
      const long n = std::strtol(value.c_str(), &end, 10);
      if (value.empty() || end != value.c_str() + value.size() || n < 1 || n > 1000)
        throw InputError(flag, "must be an integer in [1, 1000], got '" + value + "'");
    } else if (flag == "--benchmark_out") {
      resolve_output_path(value, flag);  // a regular file or a new path in an existing directory
    }
  }
}

int run_benchmarks(int argc, char** argv) {
  validate_benchmark_arguments(argc, argv);  // before Google Benchmark sees them
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace ivv::bench
