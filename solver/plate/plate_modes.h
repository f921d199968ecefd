// The Navier modes of a simply supported, specially orthotropic Kirchhoff plate, seen from the
// impact point, and its exact static compliance there (docs/design.md §1 "A finite plate").
//
// Plate a x b x h, density rho, bending stiffnesses D11, D22, D12, D66 [N m] (D16 = D26 = 0),
// all four edges simply supported, point force F [N] at (x0, y0). Mode (m, n), m, n >= 1:
//   W_mn(x, y) = sin(m pi x/a) sin(n pi y/b)                                        [-]
//   modal mass  M = rho h a b/4                                                      [kg]
//   omega_mn^2 = pi^4 [D11 (m/a)^4 + 2 H (m/a)^2 (n/b)^2 + D22 (n/b)^4]/(rho h),
//                H = D12 + 2 D66                                                     [rad^2/s^2]
// (S. G. Lekhnitskii, Anisotropic Plates, 1968, §62; A. W. Leissa, Vibration of Plates, NASA
// SP-160, 1969, §11.2: the simply supported specially orthotropic plate has these modes
// exactly; isotropic D11 = D22 = H = D.) With u_k = W_k(x0, y0) q_k the k-th mode's share of the
// deflection under the force, M q'' + M omega^2 q = W_k(x0, y0) F becomes
//   u_k'' = -omega_k^2 u_k + g_k F,   g_k = W_k(x0, y0)^2/M                          [1/kg]
// and the deflection there is w = sum_k u_k. A mode with W_k(x0, y0)^2 < kNodalShape (a nodal
// line through the impact point; sin(m pi/2) of an even m is ~1e-16, not 0) is not excited and
// is not kept (its compliance, ~1e-32 of the rest, stays in the residual below).
//
// Static compliance at the impact point, w = C_static F [m/N]:
//   C_static = sum_{m,n} g_mn/omega_mn^2
//            = (4/(a b)) sum_m sin^2(m pi xi) (b^4/(pi^4 D22)) S_m,   xi = x0/a, eta = y0/b,
//   S_m = sum_n sin^2(n pi eta)/((n^2 + r1)(n^2 + r2)),
// r1, r2 the roots of s^2 + 2 (H/D22) mu^2 s + (D11/D22) mu^4 (mu = m b/a; Re r > 0, a complex
// pair for most laminates, a double root r = mu^2 for an isotropic plate). The n-sum is exact by
//   f(r) = sum_n sin^2(n pi eta)/(n^2 + r) = (pi/(4c)) [E(c, 0) - E(c, theta)],  c = sqrt(r),
//   E(c, theta) = (e^{-c theta} + e^{-c (2 pi - theta)})/(1 - e^{-2 pi c}),  theta = 2 pi eta
// (from sum_n cos(n theta)/(n^2 + c^2) = (pi/(2c)) cosh(c (pi - theta))/sinh(c pi) - 1/(2c^2),
// 0 <= theta <= 2 pi; I. S. Gradshteyn & I. M. Ryzhik, Table of Integrals, 7th ed., 1.445.2),
// written with decaying exponentials only (no overflow): S_m = (f(r1) - f(r2))/(r2 - r1), or
// -f'(r) for roots closer than kDoubleRoot (then the double-root form's error is below
// kDoubleRoot^2/4 relative and the partial fractions' cancellation is avoided). Once the
// exponentials are below e^-40 the m-term is its asymptote K sin^2(m pi xi)/m^3 (K from c_i =
// m (b/a) sqrt(r_i)), so the m-sum is exact up to such an M (M = 40/(c_lo 2 pi min(eta, 1 -
// eta)), c_lo = (b/a) sqrt(min Re r_i) at mu = 1; 13 terms at the centre of a square plate) and
// the rest is summed in closed form:
//   K sum_{m>M} sin^2(m pi xi)/m^3 = K [(zeta(3) - C3(2 pi xi))/2 - sum_{m<=M} sin^2(m pi xi)/m^3],
//   C3(phi) = sum_m cos(m phi)/m^3 = zeta(3) - 3 phi^2/4 + (phi^2/2) ln phi
//             - sum_{k>=1} |B_2k|/(2 (2k)!) phi^{2k+2}/(k (2k+1)(2k+2)),   0 < phi <= pi
// (term by term from Clausen's Cl_2, Abramowitz & Stegun 27.8.2; C3 is even and 2 pi-periodic).
// What the asymptote leaves out beyond M is bounded by `tail_bound` (the exponentials'
// derivative bound, plate_modes.cc: ~1e-19 relative at the threshold); the value carries
// besides ~1e-15 relative of rounding. This is the Navier double sum done exactly in n and in
// closed form in m beyond M; for the isotropic plate at its centre it equals Timoshenko &
// Woinowsky-Krieger's single (Levy) series, TWK §30 eq. (f)/(g): w = alpha P a^2/D, alpha =
// 0.01160 for a square plate.
//
// Truncation: the modes with omega <= omega_cut are kept; the rest respond quasi-statically
// (mode acceleration / residual flexibility):
//   C_res = C_static - sum_kept g_k/omega_k^2                                       [m/N]
// the compliance the impact model puts in series with the contact spring. Each dropped mode's
// response is u_k = g_k F/omega_k^2 - g_k F''/omega_k^4 + ... (for a force slow against omega_k),
// so the static compliance leaves out the second moment
//   D_res = sum_dropped g_k/omega_k^4                                               [m s^2/N]
// and that term sets the error of e: with ~ gamma d omega of gain per d omega (below) D_res ~
// gamma/(3 omega_cut^3), and e converges as cut-off^-3 (case plate.convergence.with-residual).
// D_res is summed over the dropped modes up to kMomentReach omega_cut, and beyond that by the
// gain density: sum_{omega > Omega} g/omega^4 ~ gamma/(3 Omega^3) (a kMomentReach^-3 = 1/512
// share of D_res; the lattice's scatter about the density is a few per cent of that share).
//
// The dropped modes as one equivalent oscillator (DroppedModes::oscillator): a mode of its own,
// u_e'' = -omega_e^2 u_e + g_e F, whose static compliance and second moment match the dropped
// modes', g_e/omega_e^2 = C_res and g_e/omega_e^4 = D_res:
//   omega_e^2 = C_res/D_res,   g_e = C_res omega_e^2                         [rad^2/s^2], [1/kg]
// (omega_e > omega_cut, since every dropped omega_k is). It is a real mass-spring system, so the
// energy ledger holds with its energy (u_e'^2 + omega_e^2 u_e^2)/(2 g_e) among the modes', and
// the first term the static compliance misses, -D_res F'', is carried: the error of e then falls
// faster than cut-off^-3 (case plate.convergence.with-oscillator: order 4 measured on the 5 mm
// ball). The same idea as the residual flexibility and residual mass of component mode synthesis
// (R. R. Craig and A. J. Kurdila, Fundamentals of Structural Dynamics, 2nd ed., 2006): the
// dropped modes' quasi-static expansion carried to second order.
//
// What the oscillator gets wrong: it rings. A jump in the force's slope F' (or a singular F'',
// as at a Hertzian onset, F ~ t^{3/2}) leaves every dropped mode a free vibration of amplitude
// g_k dF'/omega_k^3; the oscillator takes the same energy, g_e dF'^2/(2 omega_e^4) = D_res dF'^2/2,
// the sum over the dropped modes. But the dropped modes' vibrations have different frequencies
// and their sum at the impact point dies away within a few 1/omega_cut (a band's transient), while
// the oscillator keeps its ringing at the impact point, at one frequency (omega_e = 1.70 to 1.79
// omega_cut on both shipped scenes from cut-off 10 on), for the rest of the contact: it moves zdot
// (extra maxima of compression) and trades energy with the spring at every later slope jump, with a
// phase that depends on omega_e, so on the cut-off. Its error in e therefore changes sign as the
// cut-off grows, around an envelope that falls as the static compliance's error does or faster.
// Measured (rtol 1e-11 and 1e-12: e moves < 2e-12 with rtol, so these are the models, not the
// integration), e - e_conv against the converged e of each scene:
//   5 mm ball, Hertz (one contact, no reloading; e_conv = 0.19233955746, where the oscillator at
//   cut-off 320 and the static compliance at 320 extrapolated at order 3 agree to 1e-11):
//     cut-off      5        7        10       14       20       28       40       80       160
//     oscillator  +2.9e-4  -6.9e-6  -1.1e-5  +3.4e-6  -6.2e-7  +6.6e-8  +1.4e-8  +9e-10   -1e-10
//     static      .        .        -7.7e-5  .        -9.6e-6  .        -1.2e-6  -1.5e-7  -1.9e-8
//   drop-weight coupon, elastoplastic (one contact, ~20 reloads onto the plastic branch, each a
//   jump of F' from the unloading slope 1.5 K_h sqrt(z_m) to K_y; e_conv = 0.9096577896 +- 1.5e-9,
//   the static compliance at cut-offs 80 to 640 and the oscillator at 320 and 640):
//     cut-off      5        10       14       20       28       40       80       160      320
//     oscillator  +4.2e-5  +9.6e-6  -3.4e-6  +2.4e-6  -1.4e-7  -6.3e-8  -2.1e-7  +2.8e-8  +2.6e-9
//     static      +5.8e-5  -2.5e-6  -9.6e-7  -3.9e-7  -8.1e-8  +5.5e-8  +5e-10   -9e-10   +3e-10
//     maxima of compression: oscillator 100 to 478 (varying with the cut-off), static 43 to 81
//     plain truncation: -1.6e-4 at 20, -3.7e-5 at 80, -4.6e-6 at 640 (order 1, to the same e).
// So the offset the coupon showed at cut-off 80 (2e-7 from the static compliance) is the
// oscillator's ringing before its asymptotic range, not a different limit: both treatments (and
// plain truncation) converge to the same e, the oscillator to within 2.6e-9 at 320 and 1.9e-9 at
// 640. The same coupon with the Hertz law (no slope jumps: reloading retraces one curve) shows no
// ringing: the oscillator is within 3.4e-11 of its converged e from cut-off 20 on (the static
// compliance 9.1e-8 at 20, order 3) and both count the same 28 maxima. The ringing also costs
// steps: on the coupon the oscillator takes 2.0 to 3.3 times the static compliance's steps at the
// same cut-off (13677 against 6704 at 40), on the ball 1.6 to 3.3 times (294 against 117 at 20).
//
// Gain density: the excited modes below omega number ~ a b omega sqrt(rho h) I/(2 pi^2) (the
// lattice points (m, n) under omega_mn <= omega: in p = m/a, q = n/b the region r^4 Q(phi) <=
// rho h omega^2/pi^4, Q = D11 cos^4 + 2 H cos^2 sin^2 + D22 sin^4, of area (omega sqrt(rho h)/
// (2 pi^2)) I, I = int_0^{pi/2} Q^{-1/2} dphi; R. Courant and D. Hilbert, Methods of
// Mathematical Physics I, 1953, ch. VI §4, for the leading term), and W(x0, y0)^2 averages 1/4
// over them (sin^2 averages 1/2 along each index at any interior point), so
//   gamma = sum_k g_k per unit omega = I/(2 pi^2 sqrt(rho h))                       [1/(kg rad/s)]
// For an isotropic plate I = pi/(2 sqrt(D)), gamma = 1/(4 pi sqrt(rho h D)), and (pi/2) gamma =
// 1/(8 sqrt(rho h D)) is the infinite plate's point mobility (the dashpot c = 8 sqrt(rho h D)).
//
// Units: SI (m, kg, N m, rad/s, m/N).
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "scene/structure.h"
#include "solver/plate/mode_phases.h"

namespace ivv {

// W(x0, y0)^2 below which a mode counts as not excited (see above).
inline constexpr double kNodalShape = 1e-24;
// Relative distance |r1 - r2|/|r1| below which the two roots are treated as one (see above).
inline constexpr double kDoubleRoot = 1e-5;

// D_res is summed mode by mode up to this multiple of omega_cut, by the gain density beyond.
inline constexpr double kMomentReach = 8.0;

// What the impact model does with the modes above the cut-off (above): DroppedModes, declared
// with the scene's [structure] key that chooses it (scene/structure.h).

struct PlateMode {
  int m = 0, n = 0;    // half-waves along x and y
  double omega = 0.0;  // [rad/s]
  double shape = 0.0;  // W(x0, y0) [-]
  double gain = 0.0;   // g = W(x0, y0)^2/(rho h a b/4) [1/kg]
};

// omega_mn [rad/s] of the formula above.
double plate_mode_frequency(const FinitePlate& p, int m, int n);
// omega_mn as along_x m^2 + along_y n^2 [rad/s] when D11 D22 = H^2 to 1e-12 relative (the
// frequency formula's square root then separates: mode_phases.h), else both 0.
SeparableFrequency separable_frequency(const FinitePlate& p);

struct StaticCompliance {
  double value = 0.0;       // C_static [m/N]
  double tail_bound = 0.0;  // bound on what the closed-form tail leaves out [m/N] (above)
  int terms = 0;            // m-terms summed exactly (M)
};
struct StaticComplianceOptions {
  // at least this many m-terms summed exactly (more than the threshold needs: the tests'
  // check that the closed-form tail does not depend on where it starts)
  int min_terms = 0;
};
StaticCompliance plate_static_compliance(const FinitePlate& p,
                                         const StaticComplianceOptions& options = {});

struct PlateModeOptions {
  double omega_cut = 0.0;          // keep the modes with omega <= omega_cut [rad/s]
  std::size_t max_modes = 200000;  // more kept modes than this is bad input (InputError)
  // C_static of this plate when already computed (plate_static_compliance() is then not
  // called again: several cut-offs of one plate share it)
  std::optional<StaticCompliance> static_compliance = std::nullopt;
  bool residual_moment = false;  // also sum D_res (the equivalent oscillator needs it)
};

struct PlateModes {
  std::vector<PlateMode> modes;        // kept, by increasing omega
  double omega_cut = 0.0;              // [rad/s]
  double modal_mass = 0.0;             // rho h a b/4 [kg]
  StaticCompliance static_compliance;  // C_static
  double kept_compliance = 0.0;        // sum_kept g/omega^2 [m/N]
  double residual_compliance = 0.0;    // C_res = C_static - kept [m/N]
  // D_res = sum_dropped g/omega^4 [m s^2/N] (options.residual_moment; NaN otherwise)
  double residual_moment = std::numeric_limits<double>::quiet_NaN();
  // omega_mn = along_x m^2 + along_y n^2 when the frequency separates (D11 D22 = H^2, every
  // isotropic plate: mode_phases.h), else both 0
  SeparableFrequency separable;
};

// The gain density gamma [1/(kg rad/s)] of the header: sum_k g_k per unit omega, on average.
double plate_gain_density(const FinitePlate& p);

// D_res [m s^2/N] of the modes above omega_cut (header): summed up to kMomentReach omega_cut
// (`reach` times when given), by the gain density beyond.
double dropped_compliance_moment(const FinitePlate& p, double omega_cut,
                                 double reach = kMomentReach);

// The equivalent oscillator of the dropped modes (header).
struct ResidualOscillator {
  double omega = 0.0;  // omega_e = sqrt(C_res/D_res) [rad/s]
  double gain = 0.0;   // g_e = C_res omega_e^2 [1/kg]
};
// Throws std::invalid_argument when `modes` has no D_res (plate_modes() not asked for it) or
// C_res or D_res is not > 0 (no mode dropped, or rounding ate them).
ResidualOscillator residual_oscillator(const PlateModes& modes);

// The kept modes and the compliances. Throws InputError("structure", ...) when more than
// max_modes modes lie below omega_cut (the message says how many, and that the infinite
// plate may be the model wanted), std::invalid_argument for omega_cut not > 0 and finite.
PlateModes plate_modes(const FinitePlate& p, const PlateModeOptions& options);
// No mode kept: the whole plate responds statically, C_res = C_static (the quasi-static model
// of plate_regime.h).
PlateModes static_plate_modes(const FinitePlate& p);

// The time a flexural wave needs to return to the impact point from the nearest edge, 2 d/c_g
// [s], d = min(x0, a - x0, y0, b - y0), at the group velocity of the Kirchhoff plate at the
// contact's own frequency omega_c = pi/t_contact: c_g = 2 (D*/(rho h))^{1/4} sqrt(omega_c) (D*
// Olsson's effective stiffness; Graff, Wave Motion in Elastic Solids, 1975, §4.2: c_g = 2 c_p for
// bending waves). Waves faster than that (higher frequencies) return earlier: a fact for
// comparing with the contact time, not a bound.
double flexural_return_time(const FinitePlate& p, double t_contact);

// Number of excited modes (W(x0, y0)^2 >= kNodalShape) with omega <= omega_cut, without
// storing them (the check above, and a cost estimate).
std::size_t count_plate_modes(const FinitePlate& p, double omega_cut);

}  // namespace ivv
