// The impact near contact onset as a series: where the integrators start (eight of the fifteen
// steps of a dop853 run on the paper scene at 1e-8 were spent leaving the z^{3/2} onset).
//
// A law whose first loading is Hertzian, F = K z^{3/2} for 0 <= z <= z_end (the law declares it,
// law.h: hertzian_onset), gives a solution that is not smooth in t at onset: F ~ t^{3/2}, so the
// ninth derivative of the state an eighth-order method needs grows like t^{-15/2}, and an
// adaptive step leaves t = 0 in many small steps (8 of 15 for the paper scene at rtol 1e-8).
// The series below is exact in the limit and is used up to the tau where its truncation bound
// is below the integrator's tolerance, or to the end of the Hertzian onset (the yield) where
// that comes first; the integrator starts there (impact_driver.h: series_start).
//
// Equations, in the normalised variables of impact_system.h (tau = omega t, a and z in v0/omega,
// w = a' in v0, F_bar = F/(m v0 omega); kappa = K (v0/omega)^{3/2} / (m v0 omega) so that
// F_bar = kappa z^{3/2}; beta = 2 zeta = m omega / c, 0 without a dashpot):
//
//   a' = w,  w' = -F_bar,  z' = w - beta F_bar;   a(0) = z(0) = 0,  w(0) = 1.
//
// F_bar = kappa tau^{3/2} B(p, r), with B a power series in the two small numbers
//   p = beta kappa tau^{3/2}   (the dashpot's share of the compression rate)
//   r = kappa tau^{5/2}        (the impactor's loss of speed, J = (2/5) r + ...)
// B = 1 - (3/5) p - (6/35) r + (57/200) p^2 + (183/1400) p r + (33/2450) r^2 + ...
// and the state follows termwise (a term p^a r^b of F_bar is a power e = 3/2 + 3a/2 + 5b/2 of
// tau): J = int F_bar, w = 1 - J, a = tau - int J, z = a - beta J, Wa = int F_bar w = J - J^2/2,
// Wv = beta int F_bar^2. Exact rational coefficients to total degree kDegree = 5 are derived by
// Picard iteration in sympy by scripts/derive_onset_series.py, which writes
// onset_series_coefficients.h; the leading terms agree with z = v0 t - (4 K v0^{3/2}/(35 m))
// t^{7/2} without a dashpot (Hertz loading).
//
// Truncation bound. The first omitted terms are those of degree 6; their sum of |c_ab| is
// kErrorConstant = 0.01355, so the relative error of B (and of J, int J and Wv, integrals of
// terms that all grow with tau) is about kErrorConstant max(p, r)^6, the next degree adding a
// fraction max(p, r)/rho of it (the coefficients fall by rho ~ 2.6 per degree in p, ~25 in r).
// onset_series_reach() returns the tau where that bound equals a tolerance. Checked against the
// 50-digit integration from tau = 0 by onset_series_test and the case onset.series.
#pragma once

#include <array>
#include <optional>

namespace ivv {

struct OnsetSeriesState {
  double tau = 0;  // normalised time of the state
  double a = 0;    // impactor displacement [v0/omega]
  double w = 1;    // impactor velocity [v0]
  double z = 0;    // spring deformation [v0/omega]
  double J = 0;    // impulse int F_bar dtau [m v0]
  double Wa = 0;   // work of the contact force on the impactor [m v0^2]
  double Wv = 0;   // dashpot dissipation [m v0^2] (0 without a dashpot)
};

// The series at tau (>= 0) for F_bar = kappa z^{3/2} and beta = 2 zeta (0: no dashpot).
OnsetSeriesState onset_series_state(double kappa, double beta, double tau);

// The bound on the relative truncation error of the series at tau (see above).
double onset_series_error_bound(double kappa, double beta, double tau);

// The bound on the relative truncation error of Wv (B^2's first omitted degree, constant
// kDashpotWorkErrorConstant = 0.198: Wv only closes the energy ledger, where it is
// negligible at the reach, Wv = p r / 4 << 1).
double onset_series_dashpot_work_error_bound(double kappa, double beta, double tau);

// The largest tau at which onset_series_error_bound(kappa, beta, tau) <= tolerance.
double onset_series_reach(double kappa, double beta, double tolerance);

// The series' state where its z first equals z_target (> 0), when that tau is at most `reach`:
// Newton's method on z(tau) = z_target with dz/dtau = w - beta kappa z^{3/2} (the equations
// above), from the leading terms inverted, tau = z (1 + kappa z^{3/2} (2 beta/5 + 4 z/35)),
// whose error is second order in (p, r); until the step is within 4 ulps of tau, and then on
// the far side (z >= z_target). Three or four evaluations of the series where the reach is set
// by a tolerance of 1e-8 or tighter. nullopt past the reach, where z stops rising, or after
// kOnsetNewtonIterations.
inline constexpr int kOnsetNewtonIterations = 12;
std::optional<OnsetSeriesState> onset_series_at_z(double kappa, double beta, double z_target,
                                                  double reach);

}  // namespace ivv
