// Undamped elastoplastic impact (paper eqs 8-10, no dashpot): closed form by energy, contact
// time by quadrature. Source: docs/design.md §2 "Undamped elastoplastic, closed form by energy";
// contact law of the paper (eqs 8-12), after Majeed, Yigit & Christoforou.
//
//   m z'' = -F(z, z_m),  z(0) = 0, z'(0) = v0, with
//   loading   F = K_h z^{3/2}                      (z <= z_y)          (eq 8)
//             F = K_y (z - z_y) + K_h z_y^{3/2}    (z_y <= z <= z_m)   (eq 9)
//   unloading F = K_h (z^{3/2} - z_m^{3/2}) + F_m  (z_f <= z <= z_m)   (eq 10)
//   K_y = 1.5 K_h sqrt(z_y)                                            (eq 12)
//
// Energy: E0 = m v0^2/2, E_y = (2/5) K_h z_y^{5/2} (Hertz work to z_y).
//   E0 <= E_y: Hertz, e = 1, z_m = (5 m v0^2/(4 K_h))^{2/5}.
//   E0 >  E_y: d = z_m - z_y solves (K_y/2) d^2 + K_h z_y^{3/2} d = E0 - E_y, taken as
//              d = 2 (E0 - E_y) / (F_y + sqrt(F_y^2 + 2 K_y (E0 - E_y))), F_y = K_h z_y^{3/2}
//              (no cancellation); F_m = K_y d + F_y;
//              z_f = (z_m^{3/2} - F_m/K_h)^{2/3}; with K_y = 1.5 K_h sqrt(z_y) this is exactly
//              z_f^{3/2} = d^2 (a + b/2)/(a + b)^2, a = sqrt(z_m), b = sqrt(z_y) (used: no
//              cancellation just above yield);
//              W_u = (2/5) K_h (z_m^{5/2} - z_f^{5/2}) - (K_h z_m^{3/2} - F_m)(z_m - z_f)
//                  = K_h A^3 (A - B)^2 (3t^3 + 6t^2 + 4t + 2)/5,  A = sqrt(z_m), B = sqrt(z_f),
//                    t = B/A, A - B = (F_m/K_h)/(A^2 + AB + B^2)   (no cancellation at high v0);
//              e = sqrt(W_u/E0);  W_p = (loading work) - W_u.
//
// Times: t = integral dz / v(z) with v from the energy integral of each leg.
//   elastic loading leg, 0 -> z_top (z_y, or z_m when elastic): substitution z = z_top - u^2
//     removes the 1/sqrt(z_top - z) singularity of the purely elastic case; just above yield
//     a second one, u = u_s sinh(sigma), resolves the near-singular layer of width
//     u_s = sqrt((E0 - E_y)/(K_h z_y^{3/2})); GSL QAGS.
//   plastic loading leg z_y -> z_m: harmonic motion about z_y - F_y/K_y, exactly
//     t = 2 sqrt(m/K_y) asin(sqrt(K_y d/(2 F_m))) (the quadrature of this leg in closed form).
//   unloading leg z_m -> z_f: z = z_m - u^2 again (v ~ u near z_m); GSL QAGS.
//   Elastic impact: t_f = 2 t_m (the unloading curve is the loading curve).
//
// Units: m [kg], K_h [N/m^1.5], z_y [m], v0 [m/s]; lengths [m], forces [N], energies [J],
// times [s].
#pragma once

#include "scene/scene.h"

namespace ivv::oracles {

struct ElastoplasticInput {
  double mass = 0.0;  // m [kg], > 0
  double K_h = 0.0;   // Hertz stiffness [N/m^1.5], > 0
  double z_y = 0.0;   // yield deformation [m], > 0 (K_y = 1.5 K_h sqrt(z_y))
  double v0 = 0.0;    // impact velocity [m/s], > 0
};

// The input for a scene (its dashpot, if any, is ignored: this oracle is undamped).
ElastoplasticInput elastoplastic_input(const Scene& scene, const DerivedParameters& p);

struct ElastoplasticImpact {
  bool yielded = false;         // E0 > E_y
  double v_yield = 0.0;         // sqrt(2 E_y/m) [m/s]
  double z_max = 0.0;           // z_m [m]
  double F_max = 0.0;           // F_m = F(z_m) [N]
  double z_perm = 0.0;          // z_f, where the unloading force vanishes [m]
  double e = 1.0;               // Newton COR [-]
  double energy_initial = 0.0;  // E0 [J]
  double energy_yield = 0.0;    // E_y [J]
  double W_u = 0.0;             // elastic energy given back in unloading, = E0 e^2 [J]
  double W_p = 0.0;             // hysteresis loss, loading work - W_u [J]
  double t_max = 0.0;           // time of maximum compression [s]
  double t_contact = 0.0;       // separation time t_f [s]
  double t_error = 0.0;         // sum of the GSL absolute error estimates of the quadratures [s]
};

// Throws ivv::InputError for a non-positive or non-finite input, std::runtime_error if a
// GSL quadrature fails to reach its tolerance (message names the leg and the GSL reason).
ElastoplasticImpact solve_undamped_elastoplastic(const ElastoplasticInput& in);

}  // namespace ivv::oracles
