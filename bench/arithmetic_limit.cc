#include "bench/arithmetic_limit.h"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "scene/scene.h"
#include "solver/driver/impact_system.h"
#include "solver/laws/elastoplastic.h"
#include "solver/simulate.h"
#include "verification/work_precision.h"

namespace ivv::bench {
namespace {

using System = ImpactSystem<ElastoplasticLaw, true, double>;
using State = System::state_type;

// One pass through `states` on `sys`, each evaluation's input nudged by the last one's output
// (by 1e-300 of it: no change to the value, a dependency the compiler must honour).
double chained_pass(const System& sys, const std::vector<State>& states) {
  State f{};
  double sum = 0.0;
  for (const State& s : states) {
    State x = s;
    x[System::W] += 1e-300 * f[System::W];
    sys(x, f, 0.0);
    sum += f[System::W];
  }
  return sum;
}

// The trajectory of the paper impact as normalised states, split at maximum compression.
struct BranchStates {
  std::vector<State> loading, unloading;
  double z_max = 0.0;  // [m]
};

BranchStates paper_states(const Scene& scene, const Scales& k) {
  SimulationRequest req;
  req.scene = scene;
  req.law = LawKind::elastoplastic;
  req.model = ModelKind::full;
  req.integrator = IntegratorKind::dop853;
  req.options.rtol = req.options.atol = 1e-8;
  std::vector<TrajectoryPoint> trajectory;
  const ImpactResult r = simulate(req, &trajectory);
  BranchStates out;
  out.z_max = r.z_max;
  for (const TrajectoryPoint& p : trajectory) {
    State x{};
    x[System::A] = p.alpha / k.length;
    x[System::W] = p.alpha_dot / k.velocity;
    x[System::Z] = p.z / k.length;
    (p.t <= r.t_z_max ? out.loading : out.unloading).push_back(x);
  }
  return out;
}

}  // namespace

double rhs_nanoseconds(double min_seconds, int min_repeats) {
  Scene scene = paper_scene();
  scene.velocity = 1.0;
  scene.damping = Damping::ratio(0.1);
  const DerivedParameters p = derive(scene);
  const Scales k = scales(scene, p, ScaleBasis::yield);  // the elastoplastic law's scales
  // the system as simulate() sets it up (solver/simulate_impl.h, run_typed)
  System loading;
  loading.law = ElastoplasticLaw::make({}, p);
  loading.length = k.length;
  loading.velocity = k.velocity;
  loading.force_scale = k.force;
  loading.inverse_force_scale = 1.0 / k.force;
  loading.two_zeta = p.effective_mass / (k.time * p.c);
  const BranchStates states = paper_states(scene, k);
  System unloading = loading;
  law_begin_unloading(unloading.law, unloading.branch, states.z_max);
  const std::size_t n = states.loading.size() + states.unloading.size();
  if (n == 0) return std::numeric_limits<double>::quiet_NaN();
  double sink = 0.0;
  const double us = verification::median_microseconds(
      [&] {
        sink += chained_pass(loading, states.loading) + chained_pass(unloading, states.unloading);
      },
      min_seconds, min_repeats);
  return std::isfinite(sink) ? us * 1e3 / static_cast<double>(n)
                             : std::numeric_limits<double>::quiet_NaN();
}

std::optional<double> parse_callgrind_total(std::string_view output) {
  constexpr std::string_view key = "Collected : ";
  const std::size_t at = output.find(key);
  if (at == std::string_view::npos) return std::nullopt;
  double total = 0.0;
  bool digits = false;
  for (std::size_t i = at + key.size(); i < output.size(); ++i) {
    const char c = output[i];
    if (c < '0' || c > '9') break;
    total = total * 10 + (c - '0');
    digits = true;
  }
  return digits ? std::optional<double>(total) : std::nullopt;
}

namespace {

// callgrind's total for `command` (valgrind on an `ivv` child), or nullopt with *why.
std::optional<double> callgrind_total(const std::string& command, std::string* why) {
  std::FILE* pipe = ::popen((command + " 2>&1 >/dev/null").c_str(), "r");
  if (!pipe) {
    *why = "could not start valgrind";
    return std::nullopt;
  }
  std::string output;
  std::array<char, 4096> buffer;
  for (std::size_t got; (got = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0;)
    output.append(buffer.data(), got);
  const int status = ::pclose(pipe);
  const std::optional<double> total = parse_callgrind_total(output);
  if (status != 0 || !total) {
    *why = "`" + command + "` failed (is valgrind installed?): " + output.substr(0, 200);
    return std::nullopt;
  }
  return total;
}

}  // namespace

InstructionCount count_instructions(const CountRequest& req) {
  const std::string valgrind = "valgrind --tool=callgrind --callgrind-out-file=/dev/null ";
  const std::string toggle = "--collect-atstart=no '--toggle-collect=" + req.collect + "' ";
  const std::string sweep = "'" + req.ivv + "' " + req.command + " ";
  InstructionCount out{std::numeric_limits<double>::quiet_NaN(), ""};
  std::string why;
  if (req.simulate_only) {
    const std::string command = valgrind + toggle + sweep + req.args;
    if (const auto total = callgrind_total(command, &why)) {
      out.per_impact = *total / req.points;
      out.how = "callgrind, inside " + req.collect + ", over " + std::to_string(req.points) +
                " impacts: " + command;
    }
  } else {
    const std::string many = valgrind + sweep + req.args, one = valgrind + sweep + req.single;
    const auto total = callgrind_total(many, &why);
    const auto base = total ? callgrind_total(one, &why) : std::nullopt;
    if (total && base && req.points > 1) {
      out.per_impact = (*total - *base) / (req.points - 1);
      out.how = "callgrind, whole process, (" + many + ") - (one point), per point";
    }
  }
  if (std::isnan(out.per_impact)) out.how = "not measured: " + why;
  return out;
}

std::optional<ImpactCostModel> fit_impact_cost(std::span<const ImpactRun> runs) {
  if (runs.size() < 3) return std::nullopt;
  double mean_x = 0.0, mean_y = 0.0;
  for (const ImpactRun& r : runs) {
    mean_x += r.rhs_evaluations;
    mean_y += r.us;
  }
  mean_x /= static_cast<double>(runs.size());
  mean_y /= static_cast<double>(runs.size());
  double sxx = 0.0, sxy = 0.0;  // centred sums: no cancellation of large products
  for (const ImpactRun& r : runs) {
    sxx += (r.rhs_evaluations - mean_x) * (r.rhs_evaluations - mean_x);
    sxy += (r.rhs_evaluations - mean_x) * (r.us - mean_y);
  }
  if (!(sxx > 0.0)) return std::nullopt;  // one evaluation count: no slope
  const double slope = sxy / sxx;         // [us] per evaluation
  return ImpactCostModel{mean_y - slope * mean_x, slope * 1e3, static_cast<int>(runs.size())};
}

}  // namespace ivv::bench
