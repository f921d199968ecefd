// The least time an impact with a dashpot still needs before it can end, for an explicit
// stepper held by stability to tiny steps (the stiff dashpot, zeta >> 1): a lower bound that
// lets the driver fail at once, by name, when the step budget cannot reach it, instead of
// taking max_steps steps to find out (a JKR-type law on a 100 um glass bead with c = 1e-6 N s/m
// at v0 = 1 cm/s: dp45 took 2e6 steps of tau ~ 4e-6 to tau = 7 of the ~3900 it needs).
//
// In normalised variables (impact_system.h) the dashpot's invariant is w + y/(2 zeta) = const
// (w' = -F_bar, y' = 2 zeta F_bar): the impactor slows only as fast as the dashpot moves, and
// y = a - z moves by at most w_max dtau + z (a' = w <= w_max; z >= 0 in contact). Every way the
// impact can end on the unloading branch needs w down to a floor w_end:
//   separation (F = 0 clamped, or z = 0 with tension)          w < 0
//   capture by energy (capture.h, criterion 2)                 |w| < capture_cor
//   capture in the well (criterion 4: 1/2 w^2 + S(z) < 0)      |w| < sqrt(2 W), W = pull-off work
// so the impact cannot end before
//   dtau_min = (2 zeta (w - w_end) - z) / w_max,   w_end = max(capture_cor, sqrt(2 W)).
// w_max bounds |w| for the rest of the contact: with a dashpot the energy on the unloading
// branch, 1/2 w^2 + S(z) (S the separation work, S >= -W), never rises, so
// w_max^2 = w^2 + 2 max(U(z), S(z) + W) (U the recoverable energy, law.h: stored_energy).
// Not applicable (nullopt): first loading (the energy argument needs the unloading branch), no
// dashpot, and a law with an unloading slope floor (capture.h criterion 1 can end the impact at
// any time). A grazing capture (criterion 3) ends an impact early only where the integration
// error has exceeded the remaining force; the bound does not count it.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include "solver/laws/law.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {

// dtau_min above, at state x of an unloading step; nullopt where the bound does not apply.
template <class System>
std::optional<double> least_remaining_time(const System& sys, const typename System::state_type& x,
                                           const IntegratorOptions& opt) {
  if constexpr (!System::has_dashpot) {
    return std::nullopt;
  } else {
    if (sys.branch.phase != Phase::unloading) return std::nullopt;
    if (unloading_slope_floor(sys.law, sys.branch)) return std::nullopt;
    const double w = static_cast<double>(x[System::W]);
    const double z = static_cast<double>(sys.z(x));
    double reach2 = 2.0 * static_cast<double>(sys.recoverable_energy(x));
    if (const std::optional<double> E = sys.separation_energy(x))  // 1/2 w^2 + S(z)
      reach2 = std::max(reach2, 2.0 * (*E + sys.pull_off_work));
    const double w_max = std::sqrt(std::max(reach2, w * w));
    const double w_end = std::max(opt.capture_cor, std::sqrt(2.0 * sys.pull_off_work));
    if (!(w_max > 0) || !(w > w_end)) return std::nullopt;
    return std::max(0.0, (sys.two_zeta * (w - w_end) - z) / w_max);
  }
}

// How many times the steps left the projected steps (dtau_min / h, h the present step) must
// exceed before the driver gives up. A run that would finish within its budget is stopped only
// if its later steps are on average more than kStallMargin times the present one: an explicit
// step held by stability is h ~ B/|lambda|, lambda ~ 2 zeta dF/dz on the unloading branch
// (normalised), so it grows only as far as the spring's slope falls between the present z and
// the end of contact, and dtau_min undercounts the time left (w_max bounds the speed for the
// whole rest): on the paper scene at zeta = 300 (Hertz, dop853) the run needs tau = 10129 where
// the projection said 791 more, 0.36 of the steps it then took. No bound on the slope's fall
// holds for every law, so 10 is a stated safety factor, not a derivation. Measured
// (dashpot_stall_test.cc, ItCannotFireOnARunThatFinishesWithinItsBudget): Hertz and
// elastoplastic at zeta = 30 and 300 and the JKR bead at c = 1e-4 N s/m, dop853 and dp45, given
// exactly the steps they take, finish; they finish with a factor 1 as well, so on them 10 leaves
// at least tenfold room. What a wrong factor costs: too small, a run an explicit stepper could
// have finished fails by name (FailureKind::step_limit, naming the implicit integrators, which
// finish it), never a wrong number; too large, a run whose projection lies between 1 and
// kStallMargin times the steps left runs on to max_steps before failing (the JKR bead at
// c = 1e-6 N s/m: 2e6 steps, minutes, instead of milliseconds).
inline constexpr double kStallMargin = 10.0;

}  // namespace ivv
