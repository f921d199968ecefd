// Dop853 in lanes and the scalar dop853 step, both compiled here for AVX2 + FMA where the build
// compiles the FMA copy (dop853_lanes_run.h).
//
// The rules of dop853_fma.cc: everything included from outside ivv comes first, compiled as
// usual; then ivv's headers under `#pragma GCC target("avx2,fma")`, with every template
// instantiated on types of this unit only (LocalLaw, Avx2Lanes: internal linkage), so no AVX2
// code stands in for baseline code of the same name (cpu_clone_symbols_lanes checks the object).
// The entry points come after the region, baseline code that checks the CPU before it calls in.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <concepts>
#include <cstddef>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "solver/steppers/fma_copy.h"      // IVV_FMA_COPY, a macro only
#include "solver/steppers/machine_code.h"  // cpu_has_fma_clone(), defined in baseline code

#if IVV_FMA_COPY
#pragma GCC push_options
#pragma GCC target("avx2,fma")
#elif defined(__GNUC__)
// Four lanes are 32-byte vectors, passed between this unit's own functions (internal linkage):
// without AVX GCC notes that their ABI differs from an AVX caller's, which no caller here is.
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

#include "solver/driver/impact_system.h"
#include "solver/laws/elastoplastic.h"
#include "solver/steppers/avx2_lanes.h"
#include "solver/steppers/dop853.h"
#include "solver/steppers/dop853_lanes.h"
#include "solver/steppers/dop853_lanes_run.h"

namespace ivv {
namespace {

// The law as a type of this unit: every template instantiated on it has internal linkage.
struct LocalLaw : ElastoplasticLaw {
  LocalLaw() = default;
  explicit LocalLaw(const ElastoplasticLaw& law) : ElastoplasticLaw(law) {}
};
using System = ImpactSystem<LocalLaw, true>;
using Lanes = Dop853Lanes<System, Avx2Lanes>;

System local_system(const PaperLaneSystem& s) {
  System sys;
  sys.law = LocalLaw(s.law);
  sys.branch = s.branch;
  sys.tension = s.tension;
  sys.length = s.length;
  sys.velocity = s.velocity;
  sys.force_scale = s.force_scale;
  sys.inverse_force_scale = s.inverse_force_scale;
  sys.two_zeta = s.two_zeta;
  sys.pull_off_work = s.pull_off_work;
  return sys;
}

constexpr std::array<double, 3> kDenseThetas = {0.25, 0.5, 0.75};

// The report of a stepper that exposes t0, t1, x0, x1, f1 and steps for lane/impact `i`.
template <class Get>
void fill_report(LaneRunReport& r, const System& sys, Get&& get) {
  r.t0 = get.t0();
  r.t1 = get.t1();
  r.x0 = get.x0();
  r.x1 = get.x1();
  r.f1 = get.f1();
  r.steps = get.steps();
  r.rhs_evaluations = sys.rhs_evaluations;
}

[[gnu::flatten]] LaneRunReport run_scalar(const LaneStart& lane, const IntegratorOptions& options,
                                          const LaneRunOptions& run) {
  System sys = local_system(lane.system);
  sys.rhs_evaluations = 0;
  Dop853Stepper<System> stepper(options);
  stepper.start(sys, lane.tau, lane.x);
  stepper.propose_step(lane.h);
  LaneRunReport r;
  r.t1_each.reserve(static_cast<std::size_t>(run.steps));
  for (int s = 0; s < run.steps; ++s) {
    r.result = stepper.step(sys);
    r.t1_each.push_back(stepper.t1());
    if (!r.result.ok) break;
  }
  fill_report(r, sys, stepper);
  if (run.dense_samples) {
    for (std::size_t q = 0; q < kDenseThetas.size(); ++q)
      stepper.interpolate(sys, r.t0 + kDenseThetas[q] * (r.t1 - r.t0), r.dense[q]);
  }
  return r;
}

// Lane i of `lanes` seen through the scalar stepper's accessors.
struct LaneView {
  const Lanes& lanes;
  std::size_t i;
  double t0() const { return lanes.t0(i); }
  double t1() const { return lanes.t1(i); }
  System::state_type x0() const { return lanes.x0(i); }
  System::state_type x1() const { return lanes.x1(i); }
  System::state_type f1() const { return lanes.f1(i); }
  long steps() const { return lanes.steps(i); }
};

void report_lane(LaneRunReport& r, const System& sys, const Lanes& lanes, std::size_t i,
                 const LaneRunOptions& run) {
  fill_report(r, sys, LaneView{lanes, i});
  r.error_norm = lanes.last_error_norm(i);
  r.h_next = lanes.h(i);
  if (run.dense_samples) {
    for (std::size_t q = 0; q < kDenseThetas.size(); ++q)
      lanes.interpolate(i, r.t0 + kDenseThetas[q] * (r.t1 - r.t0), r.dense[q]);
  }
}

// run.steps calls of Dop853Lanes::step(); a lane that fails is reported and stopped.
[[gnu::always_inline]] inline void run_lockstep(Lanes& lanes,
                                                const std::array<System, kDop853Lanes>& systems,
                                                const LaneRunOptions& run, LanesRunReport& out) {
  std::array<bool, kDop853Lanes> reported{};
  for (int s = 0; s < run.steps; ++s) {
    const std::array<StepResult, kDop853Lanes> results = lanes.step();
    for (std::size_t i = 0; i < kDop853Lanes; ++i) {
      LaneRunReport& r = out.lanes[i];
      if (reported[i]) continue;
      r.result = results[i];
      r.t1_each.push_back(lanes.t1(i));
      if (r.result.ok) continue;
      // stopped at its failure: reported now (a stopped lane's numbers are not kept)
      report_lane(r, systems[i], lanes, i, {.steps = run.steps, .dense_samples = false});
      reported[i] = true;
      lanes.stop(i);
    }
  }
  for (std::size_t i = 0; i < kDop853Lanes; ++i)
    if (!reported[i]) report_lane(out.lanes[i], systems[i], lanes, i, run);
}

// Dop853Lanes::attempt() until every lane has taken run.steps steps or failed: each lane is
// reported when it is done and then stopped (it idles while the others finish).
[[gnu::always_inline]] inline void run_free(Lanes& lanes,
                                            const std::array<System, kDop853Lanes>& systems,
                                            const LaneRunOptions& run, LanesRunReport& out) {
  std::size_t left = kDop853Lanes;
  std::array<bool, kDop853Lanes> reported{};
  for (std::size_t i = 0; i < kDop853Lanes; ++i) {
    if (run.steps > 0) continue;
    report_lane(out.lanes[i], systems[i], lanes, i, run);
    reported[i] = true;
    --left;
  }
  while (left > 0) {
    const std::array<LaneAttempt, kDop853Lanes> attempts = lanes.attempt();
    for (std::size_t i = 0; i < kDop853Lanes; ++i) {
      const LaneAttempt::Kind kind = attempts[i].kind;
      if (reported[i] || (kind != LaneAttempt::Kind::accepted && kind != LaneAttempt::Kind::failed))
        continue;
      LaneRunReport& r = out.lanes[i];
      r.result = lanes.step_result(i);
      r.t1_each.push_back(lanes.t1(i));
      if (r.result.ok && lanes.steps(i) < run.steps) continue;
      LaneRunOptions at_end = run;
      at_end.dense_samples = run.dense_samples && r.result.ok;
      report_lane(r, systems[i], lanes, i, at_end);
      reported[i] = true;
      lanes.stop(i);
      --left;
    }
  }
}

[[gnu::flatten]] LanesRunReport run_lanes(const std::array<LaneStart, kDop853Lanes>& starts,
                                          const IntegratorOptions& options,
                                          const LaneRunOptions& run) {
  std::array<System, kDop853Lanes> systems;
  Lanes lanes(options);
  LanesRunReport out;
  for (std::size_t i = 0; i < kDop853Lanes; ++i) {
    systems[i] = local_system(starts[i].system);
    systems[i].rhs_evaluations = 0;
    lanes.start(i, systems[i], starts[i].tau, starts[i].x);
    lanes.propose_step(i, starts[i].h);
    out.lanes[i].t1_each.reserve(static_cast<std::size_t>(run.steps));
  }
  if (run.schedule == LaneSchedule::lockstep)
    run_lockstep(lanes, systems, run, out);
  else
    run_free(lanes, systems, run, out);
  out.useful_attempts = lanes.counts().useful_attempts;
  out.lane_attempts = lanes.counts().lane_attempts;
  return out;
}

}  // namespace
}  // namespace ivv

#if IVV_FMA_COPY
#pragma GCC pop_options
#endif

namespace ivv {

bool dop853_lanes_runnable() {
  return !IVV_FMA_COPY || cpu_has_fma_clone();
}

LanesRunReport dop853_run_lanes(const std::array<LaneStart, kDop853Lanes>& lanes,
                                const IntegratorOptions& options, const LaneRunOptions& run) {
  if (!dop853_lanes_runnable())
    throw std::logic_error("dop853-lanes: compiled for AVX2 + FMA, which this CPU lacks");
  return run_lanes(lanes, options, run);
}

LaneRunReport dop853_run_scalar(const LaneStart& lane, const IntegratorOptions& options,
                                const LaneRunOptions& run) {
  if (!dop853_lanes_runnable())
    throw std::logic_error("dop853-lanes: compiled for AVX2 + FMA, which this CPU lacks");
  return run_scalar(lane, options, run);
}

}  // namespace ivv
