// Speed against error: work-precision and convergence-order measurements.
//
// What is measured
//   * Work-precision (measure_work_precision): for each double-precision integrator and each
//     tolerance, the wall-clock time of one impact [s] (std::chrono::steady_clock, single
//     thread) and the relative errors of the Newton COR e, the peak force F_max and the contact
//     time t_f against the 50-digit reference (IntegratorKind::mp50, run once per study on the
//     same request). The "tolerance" of a point is rtol (= atol, normalised state) for the
//     adaptive integrators and the fixed step dt in normalised time tau = omega0 t for rk4.
//   * Convergence order (measure_convergence): the errors of e and of the contact time t_f of
//     a fixed-step integrator (rk4, or dp45 with its error control off) against the exact
//     closed form of the linearized model (closed_forms::solve_linear_model, paper eqs 19-25), and
//     the least-squares slope of log(error) on log(dt). Measured on the paper scene at 1 m/s
//     (see work_precision_test.cc for the step ranges):
//       rk4, events located, zeta = 0.1: e order 4 (the method's order)
//       rk4, events located, no dashpot: t_f order 3.98; e order 4.98, because e is then
//                                 an amplitude and RK4's amplitude error on an undamped
//                                 oscillator is |R(i theta)| - 1 = -theta^6/144 per step,
//                                 O(h^5) globally (with damping the O(h^5) local amplitude
//                                 error returns and so does order 4)
//       dp45 fixed, located:      e order 4.97
//       either, events at step ends only: e order 2.1 (z_m taken at the first step end past
//                                 dz/dt = 0 is short by O(h^2)), t_f order 1.1 (separation
//                                 declared up to one step late)
//
// Why the timing is a median of repeats
//   One impact takes microseconds to milliseconds; a single run is at the mercy of the cache,
//   frequency scaling and other processes. Each point is repeated until both
//   min_seconds_per_point and min_repeats are reached and the median of the per-run times is
//   kept: it is insensitive to the occasional preempted run. Timings are never pass/fail (no
//   test asserts on them). On a shared or noisy machine quote ratios between integrators
//   measured in one study (one run of the program), not absolute times across runs, and
//   report the MachineInfo with them.
//
// Error conventions
//   Relative error |x - x_ref| / |x_ref| (absolute |x - x_ref| when x_ref = 0, e.g. e of a
//   captured impact). An error of exactly 0 (the double result rounds to the reference) is
//   floored at kErrorFloor = 1e-17 so that log-log plots work; 1e-17 is below the
//   double-precision unit round-off 1.1e-16, so a floored value is never mistaken for a
//   measured one.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "solver/result.h"
#include "solver/simulate.h"

namespace ivv::verification {

// Errors of exactly zero are reported as this value (see "Error conventions" above).
inline constexpr double kErrorFloor = 1e-17;

// Median wall-clock time of one call of f() [us] (std::chrono::steady_clock, this thread): f
// runs at least min_repeats times and until min_seconds have passed (see "Why the timing is a
// median of repeats" above). Used by the peers' measurement and by `ivv bench`.
template <class F>
double median_microseconds(F&& f, double min_seconds, int min_repeats) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> us;
  const auto start = Clock::now();
  do {
    const auto t0 = Clock::now();
    f();
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count());
  } while (static_cast<int>(us.size()) < min_repeats ||
           std::chrono::duration<double>(Clock::now() - start).count() < min_seconds);
  std::sort(us.begin(), us.end());
  const std::size_t n = us.size();
  return n % 2 ? us[n / 2] : 0.5 * (us[n / 2 - 1] + us[n / 2]);
}

// Where a timing was taken: timings mean nothing without it.
struct MachineInfo {
  std::string cpu_model;   // "model name" of /proc/cpuinfo ("unknown" if unreadable)
  int logical_cores = 0;   // std::thread::hardware_concurrency() (0 if unknown)
  std::string compiler;    // compiler name and __VERSION__
  std::string build_type;  // CMake build type the library was compiled with
  // the machine code the hot loop runs (solver/steppers/machine_code.h): "x86-64-v3 (AVX2, FMA)"
  // or "x86-64 baseline"
  std::string machine_code;
};
MachineInfo describe_machine();

struct WorkPrecisionPoint {
  double tolerance = 0.0;           // rtol (= atol) for adaptive integrators; dt in tau for rk4
  double seconds_per_impact = 0.0;  // median wall-clock time of one impact [s]
  double error_e = 0.0;             // relative error of e vs the mp50 reference [-]
  double error_F_max = 0.0;         // relative error of F_max vs the reference [-]
  double error_t_contact = 0.0;     // relative error of t_f vs the reference [-]
  long steps = 0;                   // accepted steps of one impact
  long rhs_evaluations = 0;         // right-hand-side evaluations of one impact
  int repeats = 0;                  // number of timed runs behind the median
  bool ok = false;  // false: the run failed or ended in another status than the reference;
                    // then `reason` says why and the three errors are NaN
  std::string reason;
};

struct WorkPrecisionSeries {
  IntegratorKind integrator = IntegratorKind::odeint_dopri5;
  std::vector<WorkPrecisionPoint> points;  // one per tolerance, in the order given
};

struct WorkPrecisionOptions {
  // Every double-precision integrator of the table (all but the reference).
  std::vector<IntegratorKind> integrators = production_integrators();
  // rtol (= atol) of the adaptive integrators, 1e-4 ... 1e-13.
  std::vector<double> rtols = {1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13};
  // Fixed steps in tau for rk4 (its error ~ dt^4 spans about the same range as rtols).
  std::vector<double> rk4_steps = {1e-1, 5e-2, 2e-2, 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4};
  double min_seconds_per_point = 0.05;  // total timed wall-clock per point [s]
  int min_repeats = 3;                  // at least this many timed runs per point
  // Called after each point with (points done, points in total); may be empty.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

struct WorkPrecisionStudy {
  std::string label;
  SimulationRequest base;  // the request every point varies (integrator and tolerance only)
  ImpactResult reference;  // the mp50 run of `base`
  std::vector<WorkPrecisionSeries> series;  // one per WorkPrecisionOptions::integrators
  MachineInfo machine;
};

// Runs the mp50 reference once, then every (integrator, tolerance) point of `options`.
// Each point copies `base` and changes only the integrator and its rtol/atol (or dt for rk4).
// Throws ivv::InputError for an invalid base request and std::runtime_error if the reference
// itself fails (without it no error can be measured). A failing point is kept, with ok=false.
WorkPrecisionStudy measure_work_precision(const std::string& label, const SimulationRequest& base,
                                          const WorkPrecisionOptions& options);

// Where a fixed-step run finds its events: on the step's interpolant (located), or only at
// the end of the step that crossed them (options.locate_events = false).
enum class EventLocation { located, at_step_ends };

// Order of convergence of a fixed-step integrator, measured on a closed form.
struct ConvergenceStudy {
  IntegratorKind integrator = IntegratorKind::rk4;
  bool events_located = true;
  std::vector<double> steps;             // dt in tau, as given
  std::vector<double> errors_e;          // |e - gamma| / gamma, floored at kErrorFloor
  std::vector<double> errors_t_contact;  // |t_f - t_exact| / t_exact, floored likewise
  double fitted_order = 0.0;             // least-squares slope of log(errors_e) on log(dt)
  double fitted_order_t_contact = 0.0;   // the same for errors_t_contact
};

// Runs `base` with integrator `kind` (rk4, or dp45 with fixed_step) at each fixed step dt of
// `dts` (normalised time), with options.locate_events = locate_events, and compares e and t_f
// with the closed form of the linearized model, with or without a dashpot
// (closed_forms::solve_linear_model, paper eqs 22-25). Preconditions (std::invalid_argument
// otherwise): base.law is LawKind::linearized, the closed form rebounds (no capture), kind is
// an integrator with a fixed-step mode, at least two distinct dts. Throws std::runtime_error naming
// dt if a run fails.
ConvergenceStudy measure_convergence(const SimulationRequest& base, IntegratorKind kind,
                                     std::vector<double> dts, EventLocation events);

// Observed order of an integrator of the table with a fixed-step mode
// (IntegratorTraits::fixed_step_mode), on the closed form of the linearized model (paper eqs
// 22-25; closed_forms::solve_linear_model): run at each fixed step dt of `settings` (normalised
// time) with error control off and events located; the order is the least-squares slope of
// log(error of e) on log(dt). Points whose error is below `error_floor` (round-off
// territory) are left out of the fit and marked so. std::invalid_argument for an integrator
// without a fixed-step mode or a base request that is not the linearized law with a rebound.
struct OrderStudy {
  IntegratorKind integrator = IntegratorKind::rk4;
  std::vector<double> settings;  // dt (fixed step) or rtol (adaptive), as run
  std::vector<double> steps;     // accepted steps of each run
  std::vector<double> errors_e;  // |e - e_exact| / e_exact, floored at kErrorFloor
  std::vector<bool> fitted;      // whether each point entered the fit
  double observed_order = 0.0;
};
OrderStudy measure_order(const SimulationRequest& base, IntegratorKind kind,
                         const std::vector<double>& settings, double error_floor);

}  // namespace ivv::verification
