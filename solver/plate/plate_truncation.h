// The mode cut-off chosen for a stated truncation tolerance in e (the rule of plate_impact.h),
// shared by the built-in laws (plate_impact.cc) and any C++ or expression law
// (plate_law_impact.h), so the two cannot drift apart.
//
// run_at(c) runs the impact with the cut-off c (multiples of omega_s) and returns its result;
// modes_at(c) is the mode count that cut-off keeps. Two cut-offs c' = c/2 and c give
//   est = kTruncationSafety * |e(c) - e(c')| / ((c/c')^p - 1),
// p = truncation_order(opt.dropped) (the static compliance's when opt.dropped is empty), and while
// est > tol the cut-off grows by max(1.25, 1.2 (est/tol)^(1/p)).
// A cut-off that would keep more than opt.max_modes modes is refused (InputError "structure",
// naming the count); more than kMaxCutoffRefinements refinements is a failed run naming the
// last estimate.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "scene/input_error.h"
#include "solver/format.h"
#include "solver/plate/plate_impact.h"

namespace ivv {

// Throws InputError("structure") when `modes` > opt.max_modes (`estimate`: the error with the
// fewer modes of the last run, NaN before any).
inline void require_plate_mode_count(std::size_t modes, const PlateImpactOptions& opt,
                                     double cutoff, double estimate) {
  if (modes <= opt.max_modes) return;
  const std::string with_fewer =
      std::isnan(estimate) ? "" : "; the error with fewer is estimated " + fmt(estimate, 3);
  throw InputError("structure", "the truncation tolerance " + fmt(opt.truncation_tol, 3) +
                                    " in e needs about " + std::to_string(modes) +
                                    " modes (cut-off " + fmt(cutoff, 4) + with_fewer +
                                    "), more than the limit of " + std::to_string(opt.max_modes) +
                                    ": the plate is large against the contact, so the infinite "
                                    "plate (remove length_x, length_y) may be the model wanted");
}

template <class RunAt, class ModesAt>
PlateImpactResult run_to_truncation_tolerance(const PlateImpactOptions& opt, RunAt run_at,
                                              ModesAt modes_at) {
  require_plate_mode_count(modes_at(opt.cutoff), opt, opt.cutoff,
                           std::numeric_limits<double>::quiet_NaN());
  const double p = truncation_order(opt.dropped.value_or(DroppedModes::static_compliance));
  double c_prev = 0.5 * opt.cutoff, c = opt.cutoff;
  PlateImpactResult coarse = run_at(c_prev);
  if (!coarse.ok) return coarse;
  int runs = 1;
  for (int refinement = 0;; ++refinement) {
    PlateImpactResult fine = run_at(c);
    fine.cutoff_runs = ++runs;
    if (!fine.ok) return fine;
    const double est =
        kTruncationSafety * std::abs(fine.e - coarse.e) / (std::pow(c / c_prev, p) - 1.0);
    fine.truncation_error = est;
    fine.cutoff_coarser = c_prev;
    fine.e_coarser = coarse.e;
    if (est <= opt.truncation_tol) return fine;
    if (refinement == kMaxCutoffRefinements) {
      fine.ok = false;
      fine.reason = "the truncation estimate " + fmt(est, 3) + " at cut-off " + fmt(c, 4) +
                    " is still above the tolerance " + fmt(opt.truncation_tol, 3) + " after " +
                    std::to_string(kMaxCutoffRefinements) + " refinements";
      return fine;
    }
    const double grow = std::max(1.25, 1.2 * std::pow(est / opt.truncation_tol, 1.0 / p));
    require_plate_mode_count(modes_at(c * grow), opt, c * grow, est);
    c_prev = c;
    c *= grow;
    coarse = std::move(fine);
  }
}

}  // namespace ivv
