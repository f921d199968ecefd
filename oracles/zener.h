// Zener's sphere-on-plate impact for small lambda: the first-order energy loss, by quadrature of
// the undamped Hertz solution. No ODE integration.
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
#pragma once

namespace ivv::oracles {

// a = 2 integral_0^{sigma_m} sigma^3/sqrt(1 - (4/5) sigma^{5/2}) dsigma, by quadrature.
double zener_small_lambda_slope();
// (4/5) (5/4)^{8/5} B(8/5, 1/2), the same number in closed form.
double zener_small_lambda_slope_closed_form();
// The undamped Hertz contact time in tau = t v0/z*: 2 integral_0^{sigma_m} dsigma/sqrt(...)
// = (4/5) (5/4)^{2/5} B(2/5, 1/2) = 3.2145... (the lambda -> 0 limit of t_f v0/z*).
double zener_undamped_contact_time();

}  // namespace ivv::oracles
