// How far a measured time is from the arithmetic it has to do: the two figures `ivv bench` prints
// beside each per-impact and map target.
//
// - The limit: the right-hand-side evaluations an impact needs times the measured cost of one
//   evaluation (rhs_nanoseconds). An integrator that did nothing but evaluate the equations
//   would take that long; the rest of the measured time is the stepper's stage arithmetic, the
//   error control, the event location, the driver and the output.
// - Instructions per impact, counted, not estimated: callgrind (valgrind) runs a child `ivv
//   sweep` and prints the instructions it collected. This machine's kernel gives no hardware
//   counter to perf_event_open (`perf stat -e instructions:u` reports "not supported"), so the
//   count comes from callgrind's simulated CPU: exact for the instructions executed, blind to
//   their cost. Without valgrind on the PATH the figure is "not measured", with the reason.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace ivv::bench {

// The cost of one right-hand-side evaluation of the paper scene's system (elastoplastic law,
// series dashpot, zeta = 0.1, v0 = 1 m/s: the system of the map's integrated points) [ns]: the
// median over repeated passes through the states of that impact's trajectory, on its loading
// and its unloading branch, each evaluation fed by the one before (as a Runge-Kutta stage is by
// the last), so the figure is the evaluation's latency, not the throughput of independent ones.
double rhs_nanoseconds(double min_seconds, int min_repeats);

struct InstructionCount {
  double per_impact;  // NaN when not measured
  std::string how;    // the command that counted it, or why it was not counted
};

// The total of "Collected : N" in valgrind --tool=callgrind's output; nullopt when absent.
std::optional<double> parse_callgrind_total(std::string_view output);

// What to count: `ivv COMMAND ARGS`, by default `ivv sweep -q --threads 1 ARGS` (ARGS must then
// write its rows to standard output: --out -).
struct CountRequest {
  std::string ivv;     // the executable's path
  std::string args;    // the sweep's arguments
  int points = 1;      // the impacts ARGS runs
  std::string single;  // one point of the same kind (whole-process counts only)
  // true: callgrind collects inside `collect` alone (--toggle-collect on it) and the count is
  // divided by `points`; false: the whole process is counted, once for `args` and once for
  // `single`, and the difference divided by points - 1 (start-up, the scene and the file set-up
  // cancel; the CSV rows and the journal stay in).
  bool simulate_only = true;
  // The subcommand, and the functions callgrind collects inside when simulate_only (a
  // --toggle-collect pattern): a sweep's simulate_batch() by default (its points computed a
  // batch at a time, the paper's law with a dashpot four at a time in SIMD lanes:
  // solver/simulate_batch.h); a finite plate's `simulate` and ivv::simulate_plate_impact* (every
  // run of its truncation rule) for the bench's plate rows.
  std::string command = "sweep -q --threads 1";
  std::string collect = "ivv::simulate_batch*";
};

// Instructions per impact as `request` says, counted by callgrind in a child process.
InstructionCount count_instructions(const CountRequest& request);

// One integrator's impact time split into what grows with its right-hand-side evaluations and
// what does not, from its runs of one impact at several tolerances in one bench run: the least-
// squares line time = fixed + per_rhs x evaluations. `fixed` is what an impact pays whatever its
// step count (validation, set-up, locating its events on the dense output, the result); per_rhs
// covers an evaluation with its share of the stage arithmetic and the step control (a dop853
// step is 12 evaluations). The limit above counts the evaluations alone, so the two together
// say which part of the distance to it is where.
struct ImpactCostModel {
  double fixed_us = 0.0;    // [us] the intercept
  double per_rhs_ns = 0.0;  // [ns] the slope
  int runs = 0;             // the runs fitted
};
struct ImpactRun {
  double rhs_evaluations = 0.0;
  double us = 0.0;  // median time of one impact [us]
};
// nullopt with fewer than three runs or fewer than two distinct evaluation counts (no line).
std::optional<ImpactCostModel> fit_impact_cost(std::span<const ImpactRun> runs);

}  // namespace ivv::bench
