// Capture: the impactor never rebounds (Newton COR e = 0). Three criteria, each a small unit the
// driver (impact_driver.h) asks; each returns the bound e_bound on the true COR, e in
// [0, e_bound] (units of v0), or nullopt when it does not decide capture.
//
// 1. Exact, after an unloading step (dashpot, law with an unloading slope floor, law.h): the
//    state is inside the forward-invariant region {u > 0, w >= s1 u} of
//    ImpactSystem::capture_margin by more than the accumulated error bound of consistency.h.
//    There the impactor keeps approaching for ever: e = 0 exactly, e_bound = 0, and the creep
//    towards the permanent set z_f is not integrated. Off with IntegratorOptions::exact_capture.
// 2. By energy, after an unloading step, for any dissipative system: the rebound the remaining
//    energy could still produce, sqrt(w^2 + 2 U) (U stored in the spring, normalised by m v0^2),
//    is below capture_cor: e_bound = max(that rebound, capture_cor), the threshold standing in
//    where round-off makes the remaining energy read as zero.
// 3. Grazing, at F = 0 with the impactor still approaching (w > 0) with a dashpot: in the exact
//    solution the force is still (barely) positive and the integration error has exceeded it.
//    When w is within the accumulated error bound, the impact is on the capture boundary:
//    e_bound = that bound. Beyond it the driver reports a failure, never a negative COR.
// 4. In an attractive well, after an unloading step, for a law that allows tension and states
//    its separation work (law.h; ImpactSystem::separation_energy): the impactor could reach
//    separation (z = 0) only with 1/2 w_sep^2 <= E = 1/2 w^2 + S(z). When E < -(the
//    accumulated error bound + the quadrature's allowance), it never separates: e = 0 exactly,
//    e_bound = 0 (dashpot or none). Without a dashpot E is conserved on the unloading branch,
//    so the well decides at the first unloading step; with one, E only falls.
// 5. Turned back in the well, no dashpot: E within that allowance of zero (criterion 4 cannot
//    decide), and the impactor is moving inwards again on the unloading branch (w > 0 after its
//    maximum displacement; without a dashpot z = alpha, so z rises: the spring would reload). It
//    failed to reach separation once and its energy is conserved: captured, e_bound =
//    sqrt(2 max(E + allowance, 0)), the rebound the uncertainty in E could still hide.
// "After an unloading step" includes the event that puts the law on its unloading branch
// (maximum compression): each criterion is a property of one state on that branch, and the driver
// asks them there first (impact_driver.h, capture_at_unloading), so an impact already inside the
// region at z_m is not carried one step further.
// Capture needs dissipation or a well: without either the unloading branch is conservative, the
// rebound speed is sqrt(2 U(z_m)) > 0, and criteria 1 and 2 are not asked (a bound below
// capture_cor there would be round-off in U, not physics).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "solver/consistency.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {

// Criterion 1: e_bound = 0 when the state x (after `steps` accepted steps) is inside the
// invariant region by more than the accumulated error bound.
template <class System>
std::optional<double> exact_capture(const System& sys, const typename System::state_type& x,
                                    long steps, const IntegratorOptions& opt) {
  const std::optional<double> margin = sys.capture_margin(x);
  if (opt.exact_capture && margin && *margin > accumulated_error_bound(steps, opt)) return 0.0;
  return std::nullopt;
}

// Criterion 2: e_bound = max(sqrt(w^2 + 2 U), capture_cor) when sqrt(w^2 + 2 U) < capture_cor.
template <class System>
std::optional<double> energy_capture(const System& sys, const typename System::state_type& x,
                                     const IntegratorOptions& opt) {
  using T = typename System::value_type;
  using std::sqrt;
  const T bound2 = 2 * sys.recoverable_energy(x);
  if (!(bound2 < T(opt.capture_cor) * T(opt.capture_cor))) return std::nullopt;
  return std::max(static_cast<double>(sqrt(bound2 > 0 ? bound2 : T(0))), opt.capture_cor);
}

// Relative allowance for the quadrature of the separation work (the expression law's adaptive
// Gauss-Kronrod is asked for 1e-12; 1e-9 of the energies involved leaves a factor 1000).
inline constexpr double kSeparationWorkAllowance = 1e-9;

// Criteria 4 and 5: the attractive well. e_bound (0 for criterion 4), or nullopt.
template <class System>
std::optional<double> well_capture(const System& sys, const typename System::state_type& x,
                                   long steps, const IntegratorOptions& opt) {
  const std::optional<double> E = sys.separation_energy(x);
  if (!E) return std::nullopt;
  const double w = static_cast<double>(x[System::W]);
  const double allowance = accumulated_error_bound(steps, opt) +
                           kSeparationWorkAllowance * (0.5 * w * w + sys.pull_off_work + 1.0);
  if (*E < -allowance) return 0.0;
  if (!System::has_dashpot && w > allowance) return std::sqrt(2.0 * std::max(*E + allowance, 0.0));
  return std::nullopt;
}

// Criteria 4 and 5, then 1 and 2, after an unloading step ending at x; nullopt for a
// conservative system without a well.
template <class System>
std::optional<double> capture_after_step(const System& sys, const typename System::state_type& x,
                                         long steps, const IntegratorOptions& opt) {
  if (opt.exact_capture)
    if (const auto well = well_capture(sys, x, steps, opt)) return well;
  if constexpr (System::has_dashpot || System::rate_dependent) {  // something dissipates
    if (const auto exact = exact_capture(sys, x, steps, opt)) return exact;
    return energy_capture(sys, x, opt);
  } else {
    return std::nullopt;
  }
}

// Criterion 3: the force reached zero at approach speed w > 0 (units of v0) after `steps`
// accepted steps; e_bound = the accumulated error bound when a dashpot is present and w is
// within it.
std::optional<double> grazing_capture(bool has_dashpot, double w, long steps,
                                      const IntegratorOptions& opt);

}  // namespace ivv
