// Section 5 of the report: speed against error.
//
//   * Work-precision diagrams (bench/work_precision.h): the relative error of e and of F_max
//     against the wall-clock time of one impact, per integrator, over a tolerance sweep, with
//     errors against the 50-digit reference; on the paper scene (v0 = 1 m/s, zeta = 0.1) and
//     on a stiff one (zeta = 10).
//   * The peers (bench/peers.h: GSL rk8pd with its stock driver, odeint's dense-output dopri5,
//     each with bisection after the step, as a competent user writes them) in the paper
//     study's plots, and a table per error level: ivv's best time, each peer's, the ratio.
//   * Convergence plots: the error of e of the fixed-step integrators (rk4, dp45 without error
//     control) against the step, with and without event location, with the fitted order.
//   * The hard cases: what each integrator achieved (status, e, steps, time) on a stiff
//     dashpot (zeta = 1000), a grazing (1e-6 m/s) and a fast (100 m/s) impact, a capture, and
//     Hunt-Crossley with mu v0 = 5; simulate() with each integrator's defaults.
// Timings are single-threaded wall clock on the machine described in `machine`; they are
// information, never pass/fail.
#pragma once

#include <string>
#include <vector>

#include "bench/speed_bench.h"
#include "bench/work_precision.h"
#include "reports/figure.h"
#include "solver/simulate.h"

namespace ivv::reports {

struct HardCaseCell {
  IntegratorKind integrator = IntegratorKind::odeint_dopri5;
  ImpactResult result;
  double seconds = 0.0;  // wall clock of the one run [s]
};

struct HardCaseRow {
  std::string name;                 // e.g. "stiff dashpot"
  std::string description;          // HTML: the scene and what makes it hard
  double reference_e = 0.0;         // an independent value of e where one exists (NaN otherwise)
  std::string reference_source;     // where reference_e comes from
  std::vector<HardCaseCell> cells;  // one per integrator
};

struct SpeedSection {
  std::vector<bench::WorkPrecisionStudy> studies;
  std::vector<bench::ConvergenceStudy> convergence;
  std::vector<HardCaseRow> hard_cases;
  std::vector<Figure> figures;
  bench::MachineInfo machine;
  // The peers (bench/peers.h) on the paper study's scene and tolerances, drawn in its plots,
  // and per error level ivv's best time against each peer's (bench::ratio_table).
  std::vector<bench::BenchPoint> peers;
  std::vector<bench::RatioRow> ratios;
};

// HTML table of SpeedSection::ratios: error level, ivv's best time and integrator, each
// peer's time and the ratio peer / ivv.
std::string ratio_table_html(const SpeedSection& section);

// Throws std::runtime_error if a reference run fails (see bench/work_precision.h).
SpeedSection speed_section(const SectionOptions& options);

}  // namespace ivv::reports
