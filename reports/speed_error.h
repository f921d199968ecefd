// Section 6 of the report: speed against error.
//
//   * Work-precision diagrams (verification/work_precision.h): the relative error of e and of
//     F_max against the wall-clock time of one impact, per integrator, over a tolerance sweep,
//     with errors against the 50-digit reference; on the paper scene (v0 = 1 m/s, zeta = 0.1)
//     and on a stiff one (zeta = 10). A benchmark: labelled "Timing, information only".
//   * The peers (verification/peers.h: GSL rk8pd with its stock driver and odeint's
//     dense-output dopri5, each with bisection after the step, as a competent user writes
//     them; SUNDIALS CVODE Adams and BDF and ARKODE ERK with their own root finding, set up as
//     their guides advise) in the paper study's plots, and a table per error level: ivv's best
//     time, each peer's, the ratio, and how each peer is set up. Timing, information only.
//   * Convergence plots: the error of e of the fixed-step integrators (rk4, dp45 without error
//     control) against the step, with and without event location, with the fitted order, from
//     verification::fixed_step_convergence_study() (the cases convergence.*.events-at-step-ends
//     judge the same runs).
//   * The hard cases: what each integrator achieved (status, e, steps) on a stiff dashpot
//     (zeta = 1000), a grazing (1e-6 m/s) and a fast (100 m/s) impact, a capture, and
//     Hunt-Crossley with mu v0 = 5, from verification::hard_case_study() (judged by
//     stability.hard-cases.named-or-within-tolerance); the wall time of each run is shown as
//     information.
// Timings are single-threaded wall clock on the machine described in `machine`; they are
// information, never pass/fail.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"
#include "solver/simulate.h"
#include "verification/peers.h"
#include "verification/study_speed.h"
#include "verification/work_precision.h"

namespace ivv::reports {

struct SpeedSection {
  std::vector<verification::WorkPrecisionStudy> studies;
  std::vector<verification::ConvergenceStudy> convergence;  // rk4, dp45 x events located or not
  std::vector<verification::HardCaseRow> hard_cases;
  std::vector<Figure> figures;
  verification::MachineInfo machine;
  // The peers (verification/peers.h) on the paper study's scene and tolerances, drawn in its
  // plots, and per error level ivv's best time against each peer's (verification::ratio_table).
  std::vector<verification::SpeedPoint> peers;
  std::vector<verification::RatioRow> ratios;
};

// HTML table of SpeedSection::ratios: error level, ivv's best time and integrator, each
// peer's time and the ratio peer / ivv; then how each peer is set up (verification::setup).
std::string ratio_table_html(const SpeedSection& section);

// Throws std::runtime_error if a reference run fails (see verification/work_precision.h), and
// verification::StudyError if a study it draws failed.
SpeedSection speed_section(const SectionOptions& options);

}  // namespace ivv::reports
