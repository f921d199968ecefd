// A loading segment whose force is linear in the spring's deformation, with the series dashpot,
// in closed form: the elastic-plastic region of the elastoplastic law from the yield to maximum
// compression (paper eq. 9, F = K_y (z - z_y) + K_h z_y^{3/2}).
//
// In the normalised variables of impact_system.h (tau = omega t, w = impactor velocity, u =
// F_bar the normalised force, k the segment's normalised stiffness dF_bar/dz, beta = 2 zeta):
//   w' = -u,   u' = k z' = k (w - beta u)
// is linear in X = (w, u): X' = M X with M = [[0, -1], [k, -k beta]], whose characteristic
// polynomial is lambda^2 + k beta lambda + k. With s = k beta / 2 and Delta = s^2 - k,
//   exp(M tau) = exp(-s tau) [C(tau) I + S(tau) (M + s I)],
// C = cos(nu tau), S = sin(nu tau)/nu with nu = sqrt(-Delta) (Delta < 0), C = cosh(mu tau),
// S = sinh(mu tau)/mu with mu = sqrt(Delta) (Delta > 0), C = 1, S = tau (Delta = 0): the
// Cayley-Hamilton form of the exponential of a 2 x 2 matrix. Maximum compression is the first
// zero of g = w - beta u = u'/k, where the force is largest: with g0 = g(0) > 0 and
// h0 = (1, -beta) (M + s I) X0, C g0 + S h0 = 0, so
//   Delta < 0:  nu tau = atan2(nu g0, -h0),
//   Delta > 0:  mu tau = atanh(mu g0 / (-h0)),
//   Delta = 0:  tau = g0 / (-h0),
// each continuous in Delta through its limit (tau -> g0/(-h0) as nu, mu -> 0), so the formulas
// hold near critical damping without a case of their own. Overdamped, exp(-s tau) cosh(mu tau)
// and exp(-s tau) sinh(mu tau) are written with exp(-(s - mu) tau), s - mu = k/(s + mu), and
// expm1, so that neither overflows nor cancels.
//
// The rest of the state follows from (w, u) by the equations' own identities (no quadrature):
// J - J0 = w0 - w (J' = u = -w'), Wa - Wa0 = (w0^2 - w^2)/2 (Wa' = u w = -w w'),
// z - z0 = (u - u0)/k, a - a0 = (z - z0) + beta (J - J0) (a' - z' = beta u), and
// Wv - Wv0 = (Wa - Wa0) - (u^2 - u0^2)/(2k) (the work on the impactor less the spring's).
#pragma once

#include <optional>

namespace ivv {

// (w, u) at time tau after (w0, u0) on the linear segment of stiffness k with beta (header).
struct LinearPhasePoint {
  double tau = 0;  // normalised time since the segment's start
  double w = 0;    // impactor velocity [v0]
  double u = 0;    // normalised force F_bar
};

// The point tau after (w0, u0) (tau >= 0, k > 0, beta >= 0).
LinearPhasePoint linear_phase_at(double k, double beta, double w0, double u0, double tau);

// Maximum compression: the first zero of w - beta u after (w0, u0). nullopt unless k > 0,
// beta >= 0 and the spring is still being compressed at the start (w0 - beta u0 > 0), or where
// the closed form meets no zero in floating point (an overdamped case at the edge of the
// formula's range): the caller then integrates.
std::optional<LinearPhasePoint> linear_phase_max_compression(double k, double beta, double w0,
                                                             double u0);

}  // namespace ivv
