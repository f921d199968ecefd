// Post-run consistency check of one impact: the three restitution coefficients and the energy
// ledger must agree to within what the integrator's tolerance allows, or the run is a failure
// with a reason (docs/design.md §6: a solver that cannot meet its tolerance says so).
//
// Why these quantities. In the normalised variables of impact_system.h the state and its
// quadratures are O(1): w in [-1, 1], J = int F dtau in [0, 2], Wa = int F w dtau in [0, 1/2].
//   - Poisson against Newton: J + w is a linear invariant (J' = F = -w'), so e_P = e up to the
//     error in J and w.
//   - Energetic against Newton: e_E^2 = (Wa_c - Wa_f) / Wa_c and e^2 = w_f^2, while
//     1/2 w^2 + Wa is conserved by the exact flow but not by a Runge-Kutta method (it is
//     quadratic). |e_E^2 - e^2| is the error of that invariant over the restitution phase, in
//     units of 1/2 m v0^2, plus e^2 times its error over compression (through Wa_c).
//   - The energy ledger residual (closed-form hysteresis work from the integrated z_m) is the
//     same invariant over the whole impact.
// The derived threshold. Every accepted step of an adaptive integrator is held to a local
// error <= atol + rtol |x_i| per component, and |x_i| <= 1 for w and Wa (J <= 2), so one step
// moves an invariant above by at most kComponents (atol + 2 rtol); errors add over the steps
// (the contact dynamics is not expanding in these variables: the worst case is linear
// accumulation). kEstimatorSafety allows for the error estimators being asymptotic (the true
// local error can exceed the embedded estimate by a small factor). A fixed-step integrator
// (rk4) is held to the same rtol/atol: its default step is chosen to meet them.
// The restitution part is judged on the steps after maximum impactor displacement only, so
// a coarse unloading (a handful of steps) cannot hide behind a long well-resolved loading.
#pragma once

#include <string>
#include <string_view>

#include "solver/result.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {

// The measures of one finished impact, normalised (velocities in v0, energies in m v0^2).
struct ConsistencyMeasures {
  bool has_restitution = false;  // separated after a located maximum displacement
  double e = 0.0;                // Newton COR -w_f
  double e_poisson = 0.0;        // (J_f - J_c) / J_c
  double e_energetic_sq = 0.0;   // (Wa_c - Wa_f) / Wa_c, not square-rooted (may be < 0)
  double ledger_residual = 0.0;  // initial - final - stored - plastic - viscous [m v0^2]
  long steps = 0;                // accepted steps, whole impact
  long restitution_steps = 0;    // accepted steps after maximum impactor displacement
};

// Components whose local errors enter one invariant (w and Wa; J and w).
constexpr double kComponents = 2.0;
// True local error over the embedded estimate, at most (asymptotic estimators).
constexpr double kEstimatorSafety = 10.0;

// Bound on the accumulated error of an invariant after `steps` steps (units of m v0^2 or v0).
double accumulated_error_bound(long steps, const IntegratorOptions& opt);

// Empty when consistent; otherwise a reason naming what disagreed, by how much, the bound,
// and what to do.
std::string consistency_failure(const ConsistencyMeasures& m, const IntegratorOptions& opt,
                                std::string_view integrator);

// A result whose status says it succeeded (separated or captured) but which carries a number
// that is not finite (NaN; or +-inf, except t_contact and t_alpha_max, which are +inf exactly
// when a captured impact never ends or the impactor never turns back) becomes a failure whose
// reason names the field and `what` produced it (a Hunt-Crossley run at mu = 1e-200 printed
// e = NaN as a separated result). A failed result is left as it is. Returns true when it
// changed `r`.
bool fail_non_finite_outcome(ImpactResult& r, std::string_view what);

}  // namespace ivv
