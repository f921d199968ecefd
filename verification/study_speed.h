// Studies behind the report's speed-against-error section (see verification/study.h), the
// parts of it that are measurements rather than timings:
//
//   * fixed_step_convergence_study(): the error of e of rk4 and dp45 (error control off) against
//     the fixed step, with events located on the interpolant and noticed only at step ends
//     (measure_convergence), on the linearized law, Table 1 scene, v0 = 1 m/s,
//     zeta = 0.1, against its closed form (paper eqs 22-25). Steps in normalised time tau:
//     rk4 0.2 ... 0.00625, dp45 0.1 ... 0.0125 (the coarsest already asymptotic, the finest
//     above round-off). Judged by convergence.rk4.events-at-step-ends and
//     convergence.dp45.events-at-step-ends.
//   * hard_case_study(): every double-precision integrator at its defaults (rtol = atol =
//     1e-10; rk4 dt = 1e-3 in tau) on the hard scenes of docs/design.md §6 (a stiff dashpot, a
//     grazing and a fast impact, a capture, Hunt-Crossley with mu v0 = 5), with an independent e
//     where one exists. Judged by stability.hard-cases.named-or-within-tolerance. The wall time of
//     each run is recorded as information only: it is measured while other cases may run on other
//     threads, and nothing is ever judged on it.
//   * work_precision_study(quick): the work-precision diagrams (measure_work_precision)
//     on the Table 1 scene at v0 = 1 m/s, zeta = 0.1 and on a stiff dashpot (zeta = 10), every
//     double-precision integrator over rtol = atol 1e-4 ... 1e-13 (rk4: dt 0.1 ... 1e-4 in tau),
//     errors against the mp50 reference; and the peers (verification/peers.h) on the paper scene
//     with the ratio table. The errors are judged by convergence.work-precision (each point's error
//     of e within the accumulated tolerance bound of solver/consistency.h); the times are
//     information only (medians of repeated single-threaded runs, taken while other cases may run).
//     quick = true: rtol 1e-4, 1e-7, 1e-10, one timed run per point, reference at 1e-20 (the
//     report's test mode); the cases read the full study.
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"
#include "verification/peers.h"
#include "verification/work_precision.h"

namespace ivv::verification {

struct FixedStepConvergenceStudy {
  SimulationRequest base;  // linearized law, Table 1 scene, 1 m/s, zeta = 0.1
  // rk4 located, rk4 at step ends, dp45 located, dp45 at step ends
  std::vector<ConvergenceStudy> runs;
  // The run of integrator `k` (rk4 or dp45) with or without event location.
  const ConvergenceStudy& of(IntegratorKind k, EventLocation events) const;
};
const FixedStepConvergenceStudy& fixed_step_convergence_study();

struct HardCaseCell {
  IntegratorKind integrator = IntegratorKind::odeint_dopri5;
  ImpactResult result;
  double seconds = 0.0;  // wall clock of the one run [s]: information only
};

struct HardCaseRow {
  std::string name;                 // e.g. "stiff dashpot"
  std::string description;          // plain text: the scene and what makes it hard
  double reference_e = 0.0;         // an independent value of e (NaN: none in closed form)
  std::string reference_source;     // where reference_e comes from
  std::vector<HardCaseCell> cells;  // one per production integrator
};
const std::vector<HardCaseRow>& hard_case_study();

struct WorkPrecisionStudies {
  std::vector<WorkPrecisionStudy> studies;  // "paper" (zeta = 0.1), then "stiff" (10)
  std::vector<std::string> ids;             // "paper", "stiff"
  // The peers on the paper study's scene and tolerances, and per error level ivv's best time
  // against each peer's (ratio_table): timings, information only.
  std::vector<SpeedPoint> peers;
  std::vector<RatioRow> ratios;
  MachineInfo machine;
};
const WorkPrecisionStudies& work_precision_study(bool quick = false);

}  // namespace ivv::verification
