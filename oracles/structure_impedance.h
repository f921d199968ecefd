// Driving-point impedances of a plate and a bar, stated independently of scene/structure.h:
// from the modes of a finite structure, counted one by one, instead of from the travelling-wave
// formula. No ODE integration.
//
// Statistical statement (L. Cremer, M. Heckl, B. A. T. Petersson, Structure-Borne Sound, 3rd
// ed., Springer 2005, on point mobilities of finite and infinite structures; R. H. Lyon,
// R. G. DeJong, Theory and Application of Statistical Energy Analysis, 2nd ed., 1995, ch. 7):
// the point mobility of a lightly damped finite structure of mass M is
//     Y(omega) = i omega sum_n phi_n(x0)^2 / (M (omega_n^2 - omega^2 + i eta omega_n omega)),
// with mass-normalised modes (integral of the mass density times phi_n^2 = M). Each mode
// contributes pi/2 to the integral of Re Y over omega, so over a band [omega1, omega2] holding
// N modes the band-averaged real mobility is
//     <Re Y> = (pi/2) sum_{band} phi_n(x0)^2 / (M (omega2 - omega1)),
// and the impedance the infinite structure shows is c = 1/<Re Y> (the waves never return).
//
//   plate: simply supported a x b, thickness h, density rho, bending stiffness D:
//     omega_mn = sqrt(D/(rho h)) k_mn^2, k_mn^2 = (m pi/a)^2 + (n pi/b)^2, m, n >= 1;
//     phi = 2 sin(m pi x/a) sin(n pi y/b), whose mean of phi^2 over the plate is 1 (a driving
//     point averaged over the plate). The modes are counted exactly (lattice points); the count
//     differs from the infinite plate's by Weyl's boundary term: N(k) = a b k^2/(4 pi)
//     - (a + b) k/(2 pi) + ..., so the counted c is high by about 2 (a + b)/(a b (k1 + k2)),
//     returned as `boundary_term` (the tolerance of a comparison should cover it).
//   bar: length L, area A, clamped at x = 0 and driven at its free end x = L:
//     omega_n = (2n - 1) pi c_L/(2 L), c_L = sqrt(E/rho), phi_n(L)^2 = 2; a band whose edges lie
//     half-way between modes holds exactly the modes of its width, and the count is exact.
//
// Units: SI (m, kg/m^3, N m, Pa); c in N s/m.
#pragma once

namespace ivv::oracles {

struct ModalImpedance {
  double c = 0.0;              // 1/<Re Y> over the band [N s/m]
  long long modes = 0;         // modes counted in the band
  double boundary_term = 0.0;  // plate: 2 (a + b)/(a b (k1 + k2)), Weyl's relative excess; bar: 0
};

// Plate a x b [m] over the wavenumber band [k1, k2] [rad/m] (k2 > k1 > 0). Throws
// std::invalid_argument for non-positive inputs or an empty band.
ModalImpedance plate_impedance_from_modes(double density, double thickness,
                                          double bending_stiffness, double a, double b, double k1,
                                          double k2);

// Bar of length L [m] over the modes n_first..n_last (band edges half-way between modes).
ModalImpedance bar_impedance_from_modes(double area, double youngs_modulus, double density,
                                        double length, long long n_first, long long n_last);

}  // namespace ivv::oracles
