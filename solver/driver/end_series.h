// The impact near an elastic separation as a series: the onset series (onset_series.h) run
// backwards in time from the end of contact.
//
// Where the unloading branch is Hertzian to its end (F_bar = kappa z^{3/2}, z_perm = 0: Hertz,
// and the elastoplastic law unloading from z_m <= z_y), the solution is not smooth at the
// separation tau_f: F ~ (tau_f - tau)^{3/2}, so w and z carry a (tau_f - tau)^{5/2} term and an
// eighth-order step near tau_f has an error ~ h^{5/2} whether it ends short of tau_f, at it or
// past it. Measured (dop853, rtol 1e-8, paper scene, v0 = 0.1 m/s, zeta = 0): the steps shrink
// geometrically from h = 0.47 at tau_f - 0.39 to h = 5e-4 at tau_f - 2e-4, with a rejection
// every other step (13 of 23 steps and 10 rejections of the impact are in its last 0.39 of tau),
// then two retakes (impact_driver.h, retake_to_separation): 448 right-hand sides against 147
// for a plastic impact.
//
// Time reversal. With s = tau_f - tau and W = -w, the equations a' = w, w' = -F_bar,
// z' = w - beta F_bar (beta = 2 zeta) become dW/ds = -F_bar, dz/ds = W + beta F_bar, z(0) = 0,
// W(0) = W_f = -w_f > 0: the onset problem with the dashpot's sign turned (beta -> -beta) and
// the initial speed W_f. Scaling z and W by W_f gives the onset's unit speed with
// kappa -> kappa sqrt(W_f). So with S = onset_series_state(kappa sqrt(W_f), -beta, s):
//   z(tau) = W_f S.z,   w(tau) = -W_f S.w,
// and what the last s of contact adds to the quadratures and the displacement:
//   J(tau_f) - J(tau) = W_f S.J,          Wa(tau_f) - Wa(tau) = -W_f^2 S.Wa,
//   Wv(tau_f) - Wv(tau) = -W_f^2 S.Wv,    a(tau_f) - a(tau) = -W_f S.a.
// The series in p = -beta kappa' s^{3/2} and r = kappa' s^{5/2} converges for either sign of p;
// its truncation bound (onset_series.h) holds with |p|: the omitted terms are at most
// kErrorConstant max(|p|, r)^6.
//
// Matching. Given (z, w) at the end of an accepted step, the unknowns (s, W_f) solve
// W_f S.z(s) = z, -W_f S.w(s) = w. From W_f = -w, s = z/W_f, a fixed-point iteration: W_f from
// the w equation, then a Newton step of s on the z equation (dS.z/ds = S.w + beta kappa'
// S.z^{3/2}). Near the reach of the series the corrections are O(max(|p|, r)) of the last, so
// the iteration contracts fast; it is run until s and W_f move by a few ulps.
//
// Defined in end_series.cc, out of line: the AVX2 + FMA copy of the dop853 run
// (solver/steppers/dop853_fma.cc) includes this header, and an inline function of shared types
// compiled there would be one name with two codes (cpu_clone_symbols).
#pragma once

#include <optional>

#include "solver/driver/onset_series.h"

namespace ivv {

// The remaining contact from a state on a Hertzian unloading branch (header).
struct EndSeriesMatch {
  double s = 0;         // tau_f - tau, the time left until separation
  double W = 0;         // -w_f, the rebound speed at separation [v0]
  double kappa = 0;     // kappa sqrt(W_f), the series' stiffness for unit speed
  OnsetSeriesState at;  // the series at s (units of W_f, reversed time)
};

// Iterations of the match before it is declared unconverged (then no series is used).
inline constexpr int kEndSeriesIterations = 40;

// The match of (z, w) (normalised, z > 0, w < 0) on F_bar = kappa z^{3/2} with beta = 2 zeta,
// when the series' truncation bound at the matched s is at most `tolerance`; nullopt when the
// state is not within the series' reach or the iteration does not converge.
std::optional<EndSeriesMatch> match_end_series(double kappa, double beta, double z, double w,
                                               double tolerance);

// The time left until separation predicted from (z, w) by the same reversal, at the first
// estimate W_f = -w, s = z / W_f, and the reach of the series there (onset_series_reach with
// |beta|): where a step must end for the next state to be matched. nullopt unless z > 0, w < 0.
struct EndSeriesTarget {
  double s = 0;      // predicted tau_f - tau
  double reach = 0;  // the largest tau_f - tau where the series is accurate to the tolerance
};
std::optional<EndSeriesTarget> end_series_target(double kappa, double beta, double z, double w,
                                                 double tolerance);

}  // namespace ivv
