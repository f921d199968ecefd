// The impact every peer solves (verification/peers.h), written once as a user of a stock ODE
// library would write it: the elastoplastic law of paper eqs 8-10 with a dashpot, in the
// normalised variables of paper eq. 26 (tau = omega0 t; state (a, w, z) = (alpha, alpha', z)
// omega0/v0; a' = w, w' = -F, z' = w - 2 zeta F with F = F/(m v0 omega0)), the kink at z = z_y
// left to the integrator's error control. Two events: maximum compression z' = 0 (falls through
// zero; switch to the unloading curve, record z_m and F_max = F(z_m)) and separation F = 0
// (falls through zero; e = -w, t_f). Shares nothing with ivv's laws, drivers or event locator;
// the scene's derived parameters come from ivv::derive, so that every peer and ivv solve the
// same problem. Internal to the peers (peers.cc, peers_sundials.cc).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

#include "verification/peers.h"

namespace ivv::verification::peer_detail {

using State = std::array<double, 3>;      // a, w, z (normalised)
inline constexpr double kTauLimit = 1e3;  // no paper-scene contact lasts this long (in tau)

struct Problem {
  double L, Fs, K_h, z_y, K_y, two_zeta;  // length [m] and force [N] scales, the law, 2 zeta
  bool unloading = false;
  double z_m = 0.0;  // [m]
  mutable long evals = 0;

  // F / Fs at the normalised spring deformation zbar, on the current branch.
  double force(double zbar) const {
    const double z = zbar * L;
    double F;
    if (!unloading) {
      F = z <= z_y ? K_h * z * std::sqrt(z) : K_y * (z - z_y) + K_h * z_y * std::sqrt(z_y);
    } else if (z_m > z_y) {
      F = K_h * (z * std::sqrt(std::max(z, 0.0)) - z_m * std::sqrt(z_m) + z_y * std::sqrt(z_y)) +
          K_y * (z_m - z_y);
    } else {
      F = K_h * z * std::sqrt(std::max(z, 0.0));
    }
    return F / Fs;
  }
  // d(F/Fs)/d(zbar) on the current branch (the Jacobian a user gives an implicit method).
  double stiffness(double zbar) const {
    const double z = zbar * L;
    const double dF = !unloading && z > z_y ? K_y : 1.5 * K_h * std::sqrt(std::max(z, 0.0));
    return dF * L / Fs;
  }
  void operator()(const State& x, State& d, double) const {
    ++evals;
    const double F = force(x[2]);
    d[0] = x[1];
    d[1] = -F;
    d[2] = x[1] - two_zeta * F;
  }
  // event of the current phase: z' on loading (falls through 0), F on unloading
  double event(const State& x) const {
    const double F = force(x[2]);
    return unloading ? F : x[1] - two_zeta * F;
  }
  // At maximum compression (state x): record F_max and z_m, switch to unloading.
  double switch_to_unloading(const State& x) {
    const double F_max = force(x[2]);
    z_m = x[2] * L;
    unloading = true;
    return F_max;
  }
};

Problem make_problem(const Scene& scene);

// The result at separation (state x at tau), F_max normalised.
PeerResult finish(const Problem& pb, const Scene& scene, const State& x, double tau, double F_max);

// The SUNDIALS peers (peers_sundials.cc). CVODE's two linear multistep families: Adams-Moulton
// (non-stiff) and BDF (stiff).
enum class CvodeMethod { adams, bdf };
PeerResult cvode_peer(const Scene& scene, double tol, CvodeMethod method);
PeerResult arkode_erk_peer(const Scene& scene, double tol);

}  // namespace ivv::verification::peer_detail
