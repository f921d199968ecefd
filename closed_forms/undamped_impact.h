// The undamped impact in closed form (docs/design.md §2), fast enough to be a model route of
// `--model auto` (solver/choice/model_choice.h, routes 1 and 2), SI units throughout.
//
//   Hertz:          z_m = (5 m v0^2/(4 K_h))^{2/5}, F_max = K_h z_m^{3/2},
//                   t_f = (4/5) B(2/5, 1/2) z_m/v0, e = 1.
//   Elastoplastic:  by energy, E0 = m v0^2/2, E_y = (2/5) K_h z_y^{5/2}; E0 <= E_y is Hertz;
//                   otherwise d = z_m - z_y solves (K_y/2) d^2 + K_h z_y^{3/2} d = E0 - E_y,
//                   F_m = K_y d + K_h z_y^{3/2}, z_f = (z_m^{3/2} - F_m/K_h)^{2/3}, e =
//                   sqrt(W_u/E0) with W_u the unloading work; contact time in closed form on the
//                   loading legs (elastic: incomplete beta, t = (z_H/v0)(2/5) B(u_y; 2/5, 1/2), u_y
//                   = (z_y/z_H)^{5/2}; plastic: harmonic, 2 sqrt(m/K_y) asin(sqrt(K_y d/(2 F_m))))
//                   and by Gauss-Legendre quadrature on the unloading leg after z = z_m - s^2,
//                   which removes the 1/sqrt endpoint singularity (error estimated by 20 against
//                   30 nodes; adaptive Gauss-Kronrod when that estimate exceeds tol/10).
//
// These are the routes' own implementation. oracles/undamped_elastoplastic.h and
// oracles/hertz.h compute the same quantities independently (GSL QAGS, ~3-14 us per impact)
// and check these in the autochoice cases.
#pragma once

#include <limits>
#include <optional>

namespace ivv::closed_forms {

struct UndampedImpact {
  bool yielded = false;
  double z_max = 0.0, F_max = 0.0, z_perm = 0.0, e = 1.0;
  double E0 = 0.0, W_p = 0.0;                                   // [J]
  double t_max = std::numeric_limits<double>::quiet_NaN();      // [s] (NaN: not computed)
  double t_contact = std::numeric_limits<double>::quiet_NaN();  // [s] (NaN: not computed)
  double t_error = 0.0;                                         // quadrature error estimate [s]
};

// The Hertz impact of mass m [kg] at v0 [m/s] on stiffness K_h [N/m^1.5], with its times.
UndampedImpact undamped_hertz(double m, double K_h, double v0);

// Asks undamped_elastoplastic for t_max and t_contact too, the unloading quadrature to `rtol`
// relative.
struct TimesQuadrature {
  double rtol = 1e-10;
};

// The undamped elastoplastic impact (yield deformation z_y [m]); its times only when asked
// (`times`). Below yield: undamped_hertz().
UndampedImpact undamped_elastoplastic(double m, double K_h, double z_y, double v0,
                                      std::optional<TimesQuadrature> times = std::nullopt);

// Hertz's maximum deformation (5 m v0^2/(4 K_h))^{2/5} [m].
double hertz_z_max(double m, double K_h, double v0);

}  // namespace ivv::closed_forms
