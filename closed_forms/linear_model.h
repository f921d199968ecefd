// Linearized (piecewise-linear) visco-elastoplastic impact model: closed-form solution.
//
// Source: the paper in /work/shared/paper, eqs 15-25 (docs/design.md §1 "linearized", §2 "Linear
// model, closed form"). A sphere of mass m meets a spring in series with a dashpot c:
//
//   m alpha'' = -F,   c y' = F,   z = alpha - y,   alpha(0) = y(0) = 0, alpha'(0) = z'(0) = v0.
//
// Contact law (history = maximum spring deformation z_m):
//   loading   (z' > 0):  F = K_y z                                             (eq 15)
//   unloading (after z' = 0 at t_m):  F = (K_y/gamma^2)(z - z_f)              (eq 16)
//   z_f = z_m (1 - K_y/(K_h sqrt(z_m)))^{2/3},  gamma^2 = 1 - z_f/z_m          (eqs 17, 18)
// The law is undefined when z_m < (K_y/K_h)^2 (= 2.25 z_y when K_y = 1.5 K_h sqrt(z_y)):
// solve_linear_model throws LinearizedLawUndefined there, never returns NaN.
//
// Eliminating alpha and y gives one equation per phase for the spring deformation:
//   loading:   z'' + 2 zeta omega0 z' + omega0^2 z = 0,     omega0 = sqrt(K_y/m),
//              zeta = sqrt(m K_y)/(2c)                                          (eqs 22, 23)
//   unloading: w = z - z_f, w'' + 2 zeta1 omega1 w' + omega1^2 w = 0,
//              omega1 = omega0/gamma, zeta1 = zeta/gamma, w(t_m) = gamma^2 z_m, w'(t_m) = 0
//                                                                                (eqs 24, 25)
// Underdamped unloading (zeta1 < 1), with phi1 = atan2(sqrt(1 - zeta1^2), zeta1) and
// omega_d1 = omega1 sqrt(1 - zeta1^2), s = t - t_m:
//   w(s) = gamma^2 z_m e^{-zeta1 omega1 s} sin(omega_d1 s + phi1)/sin(phi1)
//   separation (F = 0, w = 0):        s_f = (pi - phi1)/omega_d1
//   rebound velocity:                 e = gamma^2 z_m omega1 e^{-zeta1 omega1 s_f} / v0
//   maximum impactor displacement:    alpha' = w' + 2 zeta1 omega1 w = 0 at s_c = (pi - 2
//   phi1)/omega_d1
// zeta1 >= 1 (critically or over-damped unloading) never reaches w = 0: the spring relaxes to
// z_f only asymptotically and the impactor comes to rest: capture, e = 0, t_contact = inf.
//
// The dashpot displacement follows from momentum, not from a quadrature:
//   integral_0^t F dt = m (v0 - alpha'(t))  =>  y(t) = (m/c)(v0 - alpha'(t)),
//   alpha' = z' + F/c,  m/c = 2 zeta/omega0.
//
// Energy ledger (docs/design.md §1): (1/2) m v0^2 = (1/2) m alpha'_f^2 + W_p + W_v with
//   W_p = closed loop integral F dz = (1/2) K_y z_m^2 (1 - gamma^2)   (loading triangle minus
//         the unloading triangle (1/2)(K_y/gamma^2)(gamma^2 z_m)^2),
//   W_v = integral F^2/c dt, by exact integration of the exponential-trigonometric solution
//         for underdamped phases; for critically/over-damped phases by the exact identities
//         of the phase equation (see linear_model.cc), which hold in every regime.
//
// Units: SI throughout (kg, m, s, N, J). Time origin at first contact.
#pragma once

#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace ivv::closed_forms {

// Inputs of one impact of the linearized model.
struct LinearModelInput {
  double mass = 0.0;  // m [kg], > 0
  double K_h = 0.0;   // Hertz stiffness [N/m^1.5], > 0 (used only for z_f, eq 17)
  double K_y = 0.0;   // loading stiffness [N/m], > 0
  double zeta = 0.0;  // loading damping ratio sqrt(m K_y)/(2c) [-], >= 0; 0 = no dashpot
  double v0 = 0.0;    // impact velocity [m/s], > 0
};

// zeta of eq 23 for a dashpot c [N s/m]; c = +inf gives 0.
double damping_ratio(double mass, double K_y, double c);

// The input for a scene: v0 from the scene; m* (the effective mass), K_h, K_y, zeta from its
// derived parameters.
LinearModelInput linear_model_input(const Scene& scene, const DerivedParameters& p);

// Thrown when the linearized law has no meaning: z_m < (K_y/K_h)^2 makes eq 17 take a
// fractional power of a negative number.
class LinearizedLawUndefined : public std::domain_error {
 public:
  LinearizedLawUndefined(double z_max, double z_min);
  double z_max() const { return z_max_; }  // z_m reached by the loading phase [m]
  double z_min() const { return z_min_; }  // (K_y/K_h)^2 = 2.25 z_y [m]

 private:
  double z_max_;
  double z_min_;
};

// Closed-form outcome of one impact. Times from first contact.
struct LinearImpact {
  // loading phase
  double t_max = 0.0;               // t_m, time of maximum spring deformation and force [s]
  double z_max = 0.0;               // z_m [m]
  double F_max = 0.0;               // K_y z_m [N]
  double alpha_dot_at_t_max = 0.0;  // impactor velocity at t_m, F_max/c [m/s]
  // unloading law
  double z_perm = 0.0;        // z_f, permanent spring set [m]
  double gamma = 0.0;         // plastic loss factor (eq 18) [-]
  double zeta_unload = 0.0;   // zeta1 = zeta/gamma [-]
  double omega_unload = 0.0;  // omega1 = omega0/gamma [rad/s]
  // outcome
  bool captured = false;     // zeta1 >= 1: no separation, F -> 0 only as t -> inf
  double t_contact = 0.0;    // separation time t_f [s]; +inf when captured
  double e = 0.0;            // Newton COR -alpha'(t_f)/v0 [-]; 0 when captured
  double alpha_max = 0.0;    // alpha_c, maximum impactor displacement [m] (limit when captured)
  double t_alpha_max = 0.0;  // t_c [s]; +inf when captured
  double y_final = 0.0;      // dashpot displacement at separation (limit when captured) [m]
  double impulse = 0.0;      // integral F dt over the contact [N s]
  // energy ledger [J]
  double energy_initial = 0.0;  // (1/2) m v0^2
  double energy_final = 0.0;    // (1/2) m alpha'_f^2
  double W_p = 0.0;             // spring hysteresis, closed loop integral F dz
  double W_v = 0.0;             // dashpot, integral F^2/c dt
};

// Throws ivv::InputError for a non-positive or non-finite input (zeta may be 0),
// LinearizedLawUndefined when z_m < (K_y/K_h)^2.
LinearImpact solve_linear_model(const LinearModelInput& in);
// The question as a predicate: does the loading phase reach z_m >= (K_y/K_h)^2, where the
// unloading law (eq 17) is defined? Throws ivv::InputError as solve_linear_model does.
bool linearized_law_defined(const LinearModelInput& in);

// The state of the closed-form solution at time t >= 0.
// After separation F = 0: alpha' and y stay constant and z = alpha - y (free flight).
// While captured, the unloading solution holds for every t > t_m.
struct LinearState {
  enum class Phase { loading, unloading, separated };
  Phase phase = Phase::loading;
  double z = 0.0;          // spring deformation [m]
  double z_dot = 0.0;      // [m/s]
  double y = 0.0;          // dashpot displacement [m]
  double alpha = 0.0;      // impactor displacement [m]
  double alpha_dot = 0.0;  // [m/s]
  double F = 0.0;          // contact force [N]
};

// Same preconditions and exceptions as solve_linear_model; t must be >= 0 and finite.
LinearState linear_model_state(const LinearModelInput& in, double t);
// As above, reusing an already computed solution of the same input.
LinearState linear_model_state(const LinearModelInput& in, const LinearImpact& solution, double t);

// Undamped special cases (zeta = 0).
// Eq 19: z_m = alpha_c = v0 sqrt(m/K_y) [m].
double undamped_linear_z_max(double mass, double K_y, double v0);
// Eq 20: gamma^2 = 1 - [1 - (K_y/K_h)(K_y/(m v0^2))^{1/4}]^{2/3}; e = gamma when undamped.
// Computed as -expm1((2/3) log1p(-q)) to keep digits at high velocity (q -> 0).
// Throws LinearizedLawUndefined when q = (K_y/K_h)(K_y/(m v0^2))^{1/4} > 1.
double linear_gamma_squared_eq20(double mass, double K_h, double K_y, double v0);
// Eq 21, the high-velocity limit of eq 20 (first binomial term): (2/3) q.
// The next term makes eq 20 = (2/3) q (1 + q/6 + ...), so eq21/eq20 - 1 = -q/6 + O(q^2).
double linear_gamma_squared_eq21(double mass, double K_h, double K_y, double v0);

// Kelvin-Voigt (spring and dashpot in parallel, tension allowed), docs/design.md §3:
// e = exp(-pi zeta / sqrt(1 - zeta^2)) for 0 <= zeta < 1; for zeta >= 1 the deformation never
// returns to zero, and the function returns 0 (capture).
double linear_spring_dashpot_cor(double zeta);

}  // namespace ivv::closed_forms
