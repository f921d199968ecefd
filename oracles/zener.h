// Zener's sphere-on-plate impact: the first-order energy loss at small lambda, by quadrature of
// the undamped Hertz solution; and e(lambda) at any lambda, by a Taylor-series solution in 50
// digits that shares nothing with the solver's steppers (below).
//
// Model (C. Zener, "The intrinsic inelasticity of large plates", Phys. Rev. 59 (1941) 669-673;
// docs/design.md §1): Hertz spring K_h z^{3/2} in series with the dashpot c of the plate; in
// sigma = z/z*, z* = (m v0^2/K_h)^{2/5}, tau = t v0/z*, lambda = m^{3/5} K_h^{2/5} v0^{1/5}/c:
//     sigma'' + lambda (sigma^{3/2})' + sigma^{3/2} = 0,  sigma(0) = 0, sigma'(0) = 1.
//
// Derivation of the small-lambda slope. The dashpot dissipates W = integral F^2/c dt. To first
// order in lambda the force is that of the undamped Hertz impact, F = K_h z*^{3/2} sigma0^{3/2}
// with sigma0'' = -sigma0^{3/2}, so
//     W = (K_h^2 z*^3/c) (z*/v0) integral sigma0^3 dtau
// and, with e^2 = 1 - W/E0, E0 = m v0^2/2, 1 - e = W/(2 E0) + O(lambda^2):
//     W/(2 E0) = K_h^2 z*^4 / (c m v0^3) I = lambda I,   I = integral_contact sigma0^3 dtau,
// since K_h^2 z*^4/(m v0^3) = m^{3/5} K_h^{2/5} v0^{1/5}. Hence 1 - e = a lambda + O(lambda^2),
// a = I. The undamped energy integral sigma0'^2/2 + (2/5) sigma0^{5/2} = 1/2 gives
// dtau = dsigma / sqrt(1 - (4/5) sigma^{5/2}) and a symmetric contact, so
//     a = 2 integral_0^{sigma_m} sigma^3 / sqrt(1 - (4/5) sigma^{5/2}) dsigma,
//     sigma_m = (5/4)^{2/5},
// evaluated here by tanh-sinh quadrature (Boost.Math; the inverse square-root singularity at
// sigma_m is integrable and handled by the rule's endpoint clustering). Substituting
// sigma = sigma_m w^{2/5} gives the closed form a = (4/5) (5/4)^{8/5} B(8/5, 1/2) = 1.7301...,
// which checks the quadrature (zener_test.cc).
//
// e(lambda) at any lambda: a Taylor-series solution. The force is that of the spring,
// F = K_h z^{3/2} (in Zener's units sigma^{3/2}); the dashpot in series carries the same force,
// so the sphere's velocity is u = alpha'/v0 = sigma' + lambda sigma^{3/2}, and the first-order
// system is sigma' = u - lambda sigma^{3/2}, u' = -sigma^{3/2}, sigma(0) = 0, u(0) = 1. Contact
// ends when the force is zero, i.e. when sigma returns to 0 (u < 0 there: u falls while
// sigma > 0, so sigma' <= u < 0 once u < 0 and the end comes in finite time), and e = -u then.
// (The same second-order equation with the force sigma^{3/2} + lambda (sigma^{3/2})' and its
// end at that force's zero is the Kuwabara-Kono law on the sphere's displacement, a different
// problem, whose e is larger.)
// The fractional power is singular at both ends of the contact (sigma = 0). With r = sqrt(sigma)
// and a new time s, d tau = 2 r ds, the system becomes polynomial:
//     dr/ds = u - lambda r^3,   du/ds = -2 r^4,   d tau/ds = 2 r,   r(0) = 0, u(0) = 1, tau(0) = 0,
// analytic through the start, the maximum compression (dr/ds = 0) and the end (r = 0 with
// dr/ds = u = -e != 0). It is integrated by the Taylor-series method: the series of r, u, tau
// about the current point to order N by the recurrences of Cauchy products (r^2, r^3, r^4),
// the step h from the last two coefficients (Jorba and Zou, Experimental Math. 14 (2005) 99,
// eq. 11: h = min_j (eps/|c_j|)^{1/j}, j = N-1, N), so each step's truncation error is about
// eps; events (maximum compression: dr/ds = 0; end: r = 0) are roots of the step's polynomial,
// found by safeguarded Newton iteration. In boost::multiprecision::cpp_bin_float_50 at
// eps = 1e-40 (N = 30). Stated error: the difference between that run and one at eps = 1e-30,
// plus one unit of double rounding of a number of order 1 (2.2e-16). zener_test.cc checks
// lambda = 0 (e = 1, the Hertz contact time and peak force in closed form), the small-lambda
// slope above, and three lambda against a second implementation of the method (mpmath's
// odefun, its own series and step control, 30 digits).
#pragma once

namespace ivv::oracles {

// One impact of Zener's problem in his units (z* = (m v0^2/K_h)^{2/5}, time z*/v0, force
// K_h z*^{3/2}).
struct ZenerImpact {
  double lambda = 0.0;        // [-], >= 0
  double e = 0.0;             // Newton COR -u at the end of contact [-]
  double contact_time = 0.0;  // tau_f = t_f v0/z* [-]
  double peak_force = 0.0;    // max sigma^{3/2} = F_max/(K_h z*^{3/2}) [-]
  double error = 0.0;         // stated error of e, contact_time and peak_force (see above) [-]
  long steps = 0;             // Taylor steps of the 50-digit run
};

// e(lambda) and the contact's time and peak force, by the 50-digit Taylor-series solution.
// Throws std::invalid_argument for lambda < 0 or not finite.
ZenerImpact zener_impact(double lambda);

// a = 2 integral_0^{sigma_m} sigma^3/sqrt(1 - (4/5) sigma^{5/2}) dsigma, by quadrature.
double zener_small_lambda_slope();
// (4/5) (5/4)^{8/5} B(8/5, 1/2), the same number in closed form.
double zener_small_lambda_slope_closed_form();
// The undamped Hertz contact time in tau = t v0/z*: 2 integral_0^{sigma_m} dsigma/sqrt(...)
// = (4/5) (5/4)^{2/5} B(2/5, 1/2) = 3.2145... (the lambda -> 0 limit of t_f v0/z*).
double zener_undamped_contact_time();

}  // namespace ivv::oracles
