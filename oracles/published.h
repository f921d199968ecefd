// Published restitution formulas (docs/design.md §3).
//
// Thornton, "Coefficient of restitution for collinear collisions of elastic-perfectly plastic
// spheres", J. Appl. Mech. 64 (1997) 383-386, with r = V_y/V_i (yield velocity over impact
// velocity, both [m/s]):
//   e = 1                                                        r >= 1 (no yield)
//   e = sqrt(6 sqrt(3)/5) sqrt(1 - r^2/6) [r/(r + 2 sqrt(6/5 - r^2/5))]^{1/4}    r < 1
// At r = 1 the formula gives e^2 = (6 sqrt3/5)(5/6)(1/3)^{1/2} = 1 exactly: continuous.
// As r -> 0: e -> sqrt(6 sqrt3/5) (2 sqrt(6/5))^{-1/4} r^{1/4} = 1.18529... r^{1/4}; Thornton
// quotes 1.185 r^{1/4}.
//
// Viscoelastic Hertz (Kuwabara & Kono, Jpn. J. Appl. Phys. 26 (1987) 1230; Ramirez, Poschel,
// Brilliantov & Schwager, Phys. Rev. E 60 (1999) 4465; Muller & Poschel, Phys. Rev. E 84
// (2011) 021302): F = rho (xi^{3/2} + (3/2) A sqrt(xi) xi'), rho = (4/3) E* sqrt(R)
// [N/m^1.5], A [s] the dissipative constant, m the (effective) mass [kg];
//   beta = (3/2) A (rho/m)^{2/5}  [s^{1/5} m^{-1/5}], so beta v^{1/5} is dimensionless;
//   two-term series:  1 - e = 1.15344 beta v^{1/5} - 0.79826 beta^2 v^{2/5}
//   Pade form in v* = beta^{1/2} v^{1/10}:
//   e = (1 + 1.07232 v* + 0.574198 v*^2 + 0.141552 v*^3)
//     / (1 + 1.07232 v* + 1.72765 v*^2 + 1.37842 v*^3 + 1.19449 v*^4 + 0.467273 v*^5
//        + 0.235585 v*^6)
// The Pade form expands to 1 - 1.153452 v*^2 + 1.6e-6 v*^3 + 0.798270 v*^4 + 0.266665 v*^5
// + O(v*^6): it reproduces both series coefficients to the digits printed (1.15344, 0.79826)
// and first departs from the series at order v*^5.
#pragma once

namespace ivv::oracles {

// Thornton's e(r), r = V_y/V_i > 0 [-]. Throws ivv::InputError for r <= 0 or NaN.
double thornton_cor(double r);
// The coefficient Thornton quotes for the asymptote, and the exact one of his formula.
inline constexpr double kThorntonAsymptoteCoefficient = 1.185;
double thornton_asymptote_coefficient_exact();
// 1.185 r^{1/4}.
double thornton_asymptote(double r);

// beta = (3/2) A (rho/m)^{2/5}, rho = (4/3) E* sqrt(R): A [s], E* [Pa], R [m], m [kg].
double kuwabara_kono_beta(double A, double E_star, double R, double mass);
// v* = beta^{1/2} v^{1/10} for an impact velocity v [m/s].
double kuwabara_kono_v_star(double beta, double v);
// Two-term series, as a function of v*: e = 1 - 1.15344 v*^2 + 0.79826 v*^4.
double kuwabara_kono_series(double v_star);
// Pade form, as a function of v* >= 0.
double kuwabara_kono_pade(double v_star);

// Tsuji-type Hertz damping as DEM codes use it (LIGGGHTS `model hertz`; Tsuji, Tanaka & Ishida,
// Powder Technol. 71 (1992) 239): F = K_h z^{3/2} + gamma_n dz/dt with
// gamma_n = -2 sqrt(5/6) beta sqrt(S_n m), S_n = 2 E* sqrt(R z), and for a target COR e_t in
// (0, 1]: beta = ln e_t / sqrt(ln^2 e_t + pi^2) (<= 0; 0 for e_t = 1). Throws ivv::InputError
// outside (0, 1].
double tsuji_beta(double e_target);

}  // namespace ivv::oracles
