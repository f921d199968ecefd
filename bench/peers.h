// Peer baselines: the same impact written as a competent user would with stock libraries,
// measured in the same run as ivv (`ivv bench`, the report's speed section).
//
// The problem (both peers): the elastoplastic law of paper eqs 8-10 with a dashpot, in the
// normalised variables of solver/impact_system.h (a' = w, w' = -F, z' = w - 2 zeta F, state
// (a, w, z), no quadratures), the kink at z = z_y left to the integrator's error control. Two
// events, as a user would code them: maximum compression z' = 0 (switch to the unloading curve,
// record z_m and F_max = F(z_m)) and separation F = 0 (e = -w, t_f). Each event is noticed only
// after a step (a sign change of the event function between two outputs), then bisected to
// |dt| <= 1e-13 (1 + t) in normalised time.
//
//   gsl-rk8pd-driver   GSL odeiv2 rk8pd behind its stock driver (gsl_odeiv2_driver_apply)
//                      called for output intervals of 0.05 in tau (about 80 per contact); an
//                      event is bisected by re-integrating from the last output before it to
//                      each midpoint with the driver (reset in between).
//   odeint-dopri5-dense  Boost.Odeint's dense-output dopri5 (make_dense_output, stepped with
//                      do_step, the state observed after each step); an event is bisected on
//                      the dense output (calc_state), then the stepper restarts there.
// They share nothing with ivv's drivers, laws or event locator; the scene's derived parameters
// come from ivv::derive (so both solve the same problem).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace ivv::bench {

struct PeerResult {
  bool ok = false;
  std::string reason;      // why not, when !ok
  double e = 0.0;          // Newton COR
  double F_max = 0.0;      // [N]
  double t_contact = 0.0;  // [s]
  long rhs_evaluations = 0;
};

enum class Peer { gsl_rk8pd_driver, odeint_dopri5_dense };
std::string to_string(Peer p);
inline constexpr Peer kPeers[] = {Peer::gsl_rk8pd_driver, Peer::odeint_dopri5_dense};

// One impact of `scene` (which must have a dashpot, and separate) at rtol = atol = tol.
PeerResult run_peer(Peer peer, const Scene& scene, double tol);

}  // namespace ivv::bench
