// The end state of a captured impact (no rebound): what the impact comes to as t -> inf,
// computed from conservation laws, not sampled when capture was declared.
//
// Model (paper eqs 1-4; docs/design.md §1): m* alpha'' = -F, c y' = F, z = alpha - y. Capture: the
// impactor never turns back (e = 0, exactly or within ImpactResult::e_bound); the spring
// relaxes towards its permanent set z_f along the unloading curve while the relative velocity
// alpha' decays to 0. Two invariants of the exact flow give the limit in closed form:
//   momentum   m* alpha' + int F dt = m* v0      ->  impulse(inf) = m* v0            [N s]
//   dashpot    m* alpha' + c y      = m* v0      ->  y(inf) = m* v0 / c              [m]
// (y(0) = 0, alpha'(0) = v0), so alpha(inf) = z_f + m* v0/c, the maximum impactor
// displacement when the impactor never turned back. The two bodies end at the common
// velocity m* v0/m2 (Johnson, Contact Mechanics, 1985, §11.1; Scene::body_velocities_after with
// relative velocity 0; 0 for a half-space). Energy: on the unloading curve the spring is
// elastic, so d/dt(1/2 m* alpha'^2 + U(z)) = -F (alpha' - z') = -F^2/c: everything still
// recoverable at capture, 1/2 m* w_c^2 + U(z_c), ends in the dashpot (in the law's own damping
// for a rate-dependent law without one). Final kinetic energy 0, stored energy 0 (U(z_f) = 0);
// the ledger residual (integration error) is unchanged. All three CORs are 0; with no maximum
// impactor displacement the compression phase lasts for ever (compression impulse m* v0).
// The contact never ends: t_contact = +inf (and t_alpha_max = +inf when alpha' > 0 for ever);
// the time at which capture was established is kept as ImpactResult::t_capture, an "at
// capture" number that depends on the integrator and its tolerance.
#pragma once

#include "scene/scene.h"
#include "solver/result.h"

namespace ivv {

// What settle_captured needs besides the result at capture.
struct CaptureInputs {
  double effective_mass = 0.0;  // m* [kg]
  double dashpot = 0.0;         // c [N s/m]; +inf without a dashpot
  bool turned_back = false;     // the impactor reached alpha' = 0 before capture
  // Captured in an attractive well with nothing to dissipate (no dashpot, a rate-independent
  // law): the energy still recoverable at capture stays in the contact as a bound oscillation
  // (ledger: stored), instead of ending in a dashpot.
  bool bound_in_well = false;
};

// Rewrites a captured result `r` (its numbers at the moment capture was declared: t_contact,
// rebound_velocity w_c, energy.stored U(z_c), energy.viscous, energy.plastic) into the end
// state above. A result that is not captured is returned unchanged.
void settle_captured(ImpactResult& r, const Scene& scene, const CaptureInputs& in);

}  // namespace ivv
