// `ivv bench`: speed against error for every integrator and law, with the peers measured in
// the same run and the speed targets printed beside the measured figures.
//
// Scenes: the paper scene (Table 1) at v0 in {0.1, 1, 5} m/s and zeta in {0, 0.1}, and a stiff
// scene (v0 = 1 m/s, zeta = 100: the dashpot time scale 1/(2 zeta) in tau is 200 times shorter
// than the loading). Laws: hertz, elastoplastic, linearized (not at 0.1 m/s, where it is
// undefined, nor on the stiff scene), hunt-crossley with mu v0 = 1 (no dashpot: on the zeta = 0
// scenes only).
// Integrators: every production integrator of the table on the paper scenes; on the stiff
// scene the implicit ones and dop853 (the other explicit ones take milliseconds there for
// nothing). Each point: rtol = atol = the swept tolerance (rk4: its fixed step dt in tau,
// reported in the rtol field), errors of e, F_max, t_f relative to the reference, the median
// wall-clock time per impact over repeated single-threaded runs, RHS evaluations.
//
// Reference: mp50 (the 50-digit integration; reference_tolerance 1e-26, or 1e-20 with --quick,
// which still resolves errors >= 1e-16) on the paper scenes. On the stiff scene mp50 takes
// minutes (its explicit steps are stability-limited), so the reference there is dop853 at
// rtol = atol = 1e-13, whose stability-limited steps keep it far below its tolerance (it agrees
// with odeint-rosenbrock4 at 1e-13 to ~5e-11 in F_max): stated in the JSON as reference.
// The stiff scene is a capture (e = 0): err_e is then the absolute error of e.
//
// Peers (verification/peers.h, every one set up as stated there and in the JSON's
// peer_setups): GSL rk8pd behind its driver, odeint's dense dopri5, SUNDIALS CVODE Adams and
// BDF and ARKODE ERK with their own root finding, on the paper scene at v0 = 1 m/s, zeta = 0.1.
//
// The targets against the peers, the large map and the auto choice, measured in the same run: the
// paper scene at |de|/e <= 1e-8 (time, and ivv's time over odeint's and over the faster CVODE's at
// that level); the 300 x 300 map (v0 0.1-10 m/s log x zeta 0-1, rtol = atol = 1e-8, --model auto,
// --integrator auto) through SweepSink with its journal and CSV, wall clock on one and two threads
// (--quick: 150 x 150, scaled); --integrator auto against the fastest fixed integrator on every
// point of a grid with the heavily damped scenes (auto_grid in the JSON); the linearized closed
// form.
//
// Beside each per-impact target and the large map: the arithmetic limit (the RHS evaluations the
// run needed x the measured cost of one) and the instructions per impact counted by callgrind in
// a child `ivv sweep` (bench/arithmetic_limit.h), so the distance to the limit is a number.
//
// Timings are never pass/fail; quote ratios measured in one run, with `machine`.
#pragma once

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "verification/peers.h"
#include "verification/work_precision.h"

namespace ivv::bench {

// The measurements are the verification layer's (the report draws the same ones); bench only
// runs them over its grid, times them and states the targets.
using verification::kPeers;
using verification::MachineInfo;
using verification::Peer;
using verification::RatioRow;
using verification::SpeedPoint;

struct BenchTarget {
  std::string group;   // what it measures: per-impact, peers, map, auto-choice, calibration, plate
  std::string name;    // what the target says
  double bound = 0.0;  // the target [us] (or [s] for the map)
  std::string unit;
  double measured = 0.0;  // NaN when not measured
  bool met = false;
  double ratio = 0.0;  // measured / bound (> 1: missed by this factor)
  std::string how;     // what was measured, and why a miss happens if it does
  // The arithmetic limit (bench/arithmetic_limit.h), for the per-impact and map targets; NaN
  // where not stated:
  double instructions = std::numeric_limits<double>::quiet_NaN();  // per impact, counted
  std::string instructions_how;  // the command that counted them, or why they were not
  double limit = std::numeric_limits<double>::quiet_NaN();  // RHS evaluations x one's cost [unit]
  std::string limit_how;                                    // the evaluations and the cost of one
};

struct BenchOptions {
  bool quick = false;
  // The ivv executable, for the instruction counts (callgrind runs it as a child); empty: not
  // counted.
  std::string ivv_executable = {};
};

// One point of the --integrator auto grid: auto's time against the fastest fixed
// integrator's on the same request (elastoplastic, --model full, rtol = atol = 1e-8).
struct AutoPoint {
  double v0 = 0.0, zeta = 0.0;  // [m/s], [-]
  std::string auto_integrator;  // what auto chose
  double auto_us = 0.0;         // median [us]
  std::string best_integrator;  // the fastest fixed integrator that succeeded
  double best_us = 0.0;         // median [us]
  double ratio = 0.0;           // auto_us / best_us
};

struct BenchReport {
  MachineInfo machine;
  std::vector<SpeedPoint> points;
  std::vector<SpeedPoint> peers;  // integrator = the peer's name, law elastoplastic
  std::vector<AutoPoint> auto_grid;
  std::vector<BenchTarget> targets;
  double seconds = 0.0;  // wall clock of the whole run
};

// Runs everything; `progress` (may be empty) gets one line per stage.
BenchReport run_bench(const BenchOptions& options,
                      const std::function<void(const std::string&)>& progress);

std::string to_json(const BenchReport& report);  // the shape of `ivv bench --json`
std::string to_text(const BenchReport& report);  // the summary `ivv bench` prints

}  // namespace ivv::bench
