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
// Capture needs dissipation: without it the unloading branch is conservative, the rebound speed
// is sqrt(2 U(z_m)) > 0, and criteria 1 and 2 are not asked (a bound below capture_cor there
// would be round-off in U, not physics).
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "solver/consistency.h"
#include "solver/integrator_options.h"

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

// Criteria 1 then 2 after an unloading step ending at x; nullopt for a conservative system.
template <class System>
std::optional<double> capture_after_step(const System& sys, const typename System::state_type& x,
                                         long steps, const IntegratorOptions& opt) {
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
