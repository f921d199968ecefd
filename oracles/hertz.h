// Undamped Hertz impact: closed form (docs/design.md §2 "Hertz, undamped"; Johnson, Contact
// Mechanics, 1985, §11.1; paper eq 5).
//
//   m z'' = -K_h z^{3/2},  z(0) = 0, z'(0) = v0.
// Energy: (1/2) m v0^2 = (2/5) K_h z_m^{5/2}  =>  z_m = (5 m v0^2 / (4 K_h))^{2/5}.
// Time: t_m = integral_0^{z_m} dz / (v0 sqrt(1 - (z/z_m)^{5/2}))
//           = (z_m/v0) integral_0^1 dx / sqrt(1 - x^{5/2})          (x = z/z_m)
//           = (z_m/v0) (2/5) B(2/5, 1/2)                          (u = x^{5/2})
// and by symmetry of the elastic rebound t_f = 2 t_m = (4/5) B(2/5, 1/2) z_m/v0
// = 2.94327... z_m/v0, e = 1.
//
// Units: m [kg], K_h [N/m^1.5], v0 [m/s]; lengths [m], times [s], force [N].
#pragma once

namespace ivv::oracles {

struct HertzImpact {
  double z_max = 0.0;      // z_m [m]
  double F_max = 0.0;      // K_h z_m^{3/2} [N]
  double t_max = 0.0;      // time of maximum compression, t_f/2 [s]
  double t_contact = 0.0;  // t_f [s]
  double e = 1.0;          // [-]
};

// (4/5) B(2/5, 1/2), the dimensionless Hertz contact time t_f v0/z_m, from Boost.Math beta.
double hertz_contact_time_factor();

// Throws ivv::InputError unless mass, K_h, v0 are positive and finite.
HertzImpact solve_hertz(double mass, double K_h, double v0);

}  // namespace ivv::oracles
