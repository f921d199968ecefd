#include "solver/driver/capture_end_state.h"

#include <cmath>
#include <limits>

namespace ivv {

void settle_captured(ImpactResult& r, const Scene& scene, const CaptureInputs& in) {
  if (r.status != ImpactStatus::captured) return;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double v0 = scene.velocity;
  const double m = in.effective_mass;
  const bool dashpot = in.dashpot < inf;

  r.t_capture = r.t_contact;
  r.t_contact = inf;
  r.e = r.e_poisson = r.e_energetic = 0.0;
  r.rebound_velocity = 0.0;
  const BodyVelocities bodies = body_velocities_after(scene, 0.0);
  r.impactor_velocity_after = bodies.impactor;
  r.target_velocity_after = bodies.target;
  r.impulse = m * v0;
  r.y_final = dashpot ? m * v0 / in.dashpot : 0.0;
  if (!in.turned_back) {
    r.impulse_compression = m * v0;
    r.alpha_max = r.z_perm + r.y_final;
    r.t_alpha_max = inf;
  }
  // everything still recoverable at capture is dissipated; the residual is left as measured
  EnergyLedger& led = r.energy;
  const double remaining = led.final + led.stored;  // 1/2 m* w_c^2 + U(z_c)
  if (in.bound_in_well) {
    led.stored = remaining;  // the bound oscillation about z_f keeps it
  } else {
    (dashpot ? led.viscous : led.plastic) += remaining;
    led.stored = 0.0;
  }
  led.final = 0.0;
}

}  // namespace ivv
