// The impact equations in the normalised variables of paper eq. 26.
//
// Physical model (paper eqs 1-4):  m alpha'' = -F,  c y' = F,  z = alpha - y,  F = f(z) >= 0.
// With tau = omega0 t, alpha = (v0/omega0) a, y = (v0/omega0) y_bar, F = m v0 omega0 F_bar:
//
//   a' = w,   w' = -F_bar,   z_bar' = w - 2 zeta F_bar          (' = d/dtau)
//
// since m omega0 / c = 2 zeta and z = alpha - y. Initial state a = z = 0, w = 1. The spring
// deformation z is integrated rather than the dashpot displacement y: with a weak dashpot
// (zeta >> 1) alpha and y both grow to O(zeta) while z stays O(1/zeta), and error control on
// alpha and y separately would swamp the small difference that sets the force. y = a - z is
// recovered on output. Without a dashpot (c = inf) z = a and only (a, w) are integrated.
//
// Three quadratures ride along (they are outputs, not dynamics), in units of m v0 and m v0^2:
//   J   = int F_bar dtau            impulse
//   Wa  = int F_bar w dtau          work of the contact force on the impactor
//   Wv  = int 2 zeta F_bar^2 dtau   dashpot dissipation (only with a dashpot)
// Wa is not an invariant of a Runge-Kutta method (1/2 w^2 + Wa is quadratic in the state), so
// comparing it with 1/2(1 - w_f^2) measures integration error; likewise Wv closes the ledger.
#pragma once

#include <array>
#include <cmath>
#include <complex>
#include <cstddef>
#include <optional>

#include "solver/laws/law.h"

namespace ivv {

template <class Law, bool Dashpot, class T = double>
struct ImpactSystem {
  static_assert(!(Dashpot && Law::rate_dependent),
                "a rate-dependent law carries its own damping and is used without a dashpot");

  using law_type = Law;
  using history_type = history_t<Law, T>;
  static constexpr bool has_dashpot = Dashpot;
  static constexpr bool rate_dependent = Law::rate_dependent;
  static constexpr std::size_t N = Dashpot ? 6 : 4;
  using value_type = T;
  using state_type = std::array<T, N>;

  // state indices
  static constexpr std::size_t A = 0;  // normalised impactor displacement
  static constexpr std::size_t W = 1;  // normalised impactor velocity
  static constexpr std::size_t Z = 2;  // normalised spring deformation (Dashpot only)
  static constexpr std::size_t J = Dashpot ? 3 : 2;
  static constexpr std::size_t WA = J + 1;
  static constexpr std::size_t WV = Dashpot ? 5 : N;  // == N: absent
  // The components every event root reads (impact_events.h: z, w and the force of z and w):
  // the event locator interpolates only these.
  static constexpr std::array<std::size_t, 2> event_components = {Dashpot ? Z : A, W};
  // The components operator() reads: the force's z and w (and dxdt[A] = w). The rest are
  // quadratures and the displacement, which feed nothing back: a stepper forms only these of a
  // stage's argument (dop853.h), the same arithmetic on the components that matter.
  static constexpr std::array<std::size_t, 2> rhs_components = {Dashpot ? Z : A, W};

  Law law;
  history_type branch;
  bool tension = false;              // law_allows_tension(law): contact ends at z = 0, F may be < 0
  double length = 1.0;               // v0/omega0 [m]
  double velocity = 1.0;             // v0 [m/s]
  double force_scale = 1.0;          // m v0 omega0 [N]
  double inverse_force_scale = 1.0;  // 1 / force_scale [1/N]: a product, not a division, per
                                     // right-hand-side evaluation
  double two_zeta = 0.0;             // 2 zeta (Dashpot only)
  // The pull-off work of the unloading branch, -int_0^{z_f} F ds (the depth of the attractive
  // well below zero force), normalised by m v0^2; set by the driver when unloading begins, for
  // a law that allows tension and states its separation_work (law.h); 0: no well.
  double pull_off_work = 0.0;
  mutable long rhs_evaluations = 0;

  static state_type initial_state() {
    state_type x{};
    x[W] = T(1);
    return x;
  }

  T z(const state_type& x) const {
    if constexpr (Dashpot) return x[Z];
    return x[A];
  }
  // The force on the current branch [N] (smooth continuation; may be < 0 past separation).
  T physical_force(const state_type& x) const {
    return law.force(branch, T(length * z(x)), T(velocity * x[W]));
  }
  // Normalised force on the current branch.
  T force(const state_type& x) const { return physical_force(x) * inverse_force_scale; }
  // Normalised dashpot displacement y = a - z.
  T y(const state_type& x) const {
    if constexpr (Dashpot) return x[A] - x[Z];
    return T(0);
  }
  // dz/dtau = w - 2 zeta F_bar, as (2 zeta / force_scale) F: the product of the two constants is
  // formed off the path from z to dz/dtau, which then holds one multiply-add after the law's
  // force instead of a product and a multiply-add (the path every dop853 stage waits on).
  T z_rate(const state_type& x) const {
    if constexpr (Dashpot) return z_rate_of(x, physical_force(x));
    return x[W];
  }
  // z_rate at x where the force there is force_N [N] (Dashpot only)
  T z_rate_of(const state_type& x, const T& force_N) const {
    return x[W] - (two_zeta * inverse_force_scale) * force_N;
  }

  void operator()(const state_type& x, state_type& dxdt, T /*tau*/) const {
    ++rhs_evaluations;
    const T force_N = physical_force(x);
    const T F = force_N * inverse_force_scale;
    dxdt[A] = x[W];
    dxdt[W] = -F;
    if constexpr (Dashpot) {
      dxdt[Z] = z_rate_of(x, force_N);
      dxdt[WV] = two_zeta * F * F;
    }
    dxdt[J] = F;
    dxdt[WA] = F * x[W];
  }

  // Normalised partial derivatives of F_bar: dF_bar/dz_bar and dF_bar/dw.
  T stiffness(const state_type& x) const {
    return law.stiffness(branch, T(length * z(x)), T(velocity * x[W])) * length / force_scale;
  }
  T rate_stiffness(const state_type& x) const {
    if constexpr (Law::rate_dependent)
      return law.rate_stiffness(branch, T(length * z(x)), T(velocity * x[W])) * velocity /
             force_scale;
    return T(0);
  }

  // d F_bar / d tau along the solution (for the peak-force event of rate-dependent laws).
  T force_rate(const state_type& x) const {
    return stiffness(x) * z_rate(x) - rate_stiffness(x) * force(x);
  }

  // Full Jacobian d(dxdt)/dx, row-major into any matrix with m(i, j) access.
  template <class Matrix>
  void jacobian(const state_type& x, Matrix& m) const {
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < N; ++j) m(i, j) = T(0);
    const T F = force(x);
    const T k = stiffness(x);
    const T kv = rate_stiffness(x);
    // dF/dx: z is x[Z] with a dashpot, x[A] without; the rate argument is w
    std::array<T, N> dF{};
    dF[Dashpot ? Z : A] = k;
    dF[W] = kv;
    m(A, W) = T(1);
    for (std::size_t j = 0; j < N; ++j) {
      m(W, j) = -dF[j];
      m(J, j) = dF[j];
      m(WA, j) = dF[j] * x[W];
      if constexpr (Dashpot) {
        m(Z, j) = -two_zeta * dF[j];
        m(WV, j) = 2 * two_zeta * F * dF[j];
      }
    }
    if constexpr (Dashpot) m(Z, W) += T(1);
    m(WA, W) += F;
  }

  // Non-zero eigenvalues of the linearised dynamics: roots of lambda^2 + b lambda + k with
  // b = 2 zeta k (dashpot) or dF/dw (rate law). Used for explicit stability checks.
  std::array<std::complex<double>, 2> eigenvalues(const state_type& x) const {
    const double k = static_cast<double>(stiffness(x));
    const double b = Dashpot ? two_zeta * k : static_cast<double>(rate_stiffness(x));
    const std::complex<double> disc = std::sqrt(std::complex<double>(b * b - 4 * k));
    return {(-b + disc) / 2.0, (-b - disc) / 2.0};
  }

  // Exact capture test (with a dashpot, rate-independent laws whose unloading curve has a slope
  // floor k_f, law.h). Near the permanent set u = z - z_f the unloading dynamics are
  //   u' = w - 2 zeta F_bar,  w' = -F_bar,  F_bar >= k u   (k = k_f normalised),
  // and when the relaxation at z_f is overdamped, (2 zeta k)^2 >= 4 k, the slow root
  //   s1 = 2k / (2 zeta k + sqrt((2 zeta k)^2 - 4k))   of s^2 - 2 zeta k s + k = 0
  // bounds a forward-invariant region R = {u > 0, w >= s1 u}: on its edge w = s1 u,
  //   (w - s1 u)' = F_bar (2 zeta s1 - 1) - s1 w >= k u (2 zeta s1 - 1) - s1^2 u = 0,
  // using 2 zeta s1 >= 1 (s1 s2 = k, s2 <= 2 zeta k) and that z' <= 0 throughout unloading (no
  // reloading, docs/design.md §1), so F_bar >= k u holds all along. In R the impactor keeps
  // approaching (w > 0) while the spring relaxes towards z_f: it never turns back, so the contact
  // never ends (e = 0 exactly, no rebound at any time). Returns (w - s1 u) / (1 + s1), the margin
  // by which the state is inside R in units of an error in w and u (an error d in both moves
  // w - s1 u by at most (1 + s1) d); nullopt where the test does not apply (no floor, not
  // overdamped at z_f, u <= 0 or w <= 0).
  std::optional<double> capture_margin(const state_type& x) const {
    if constexpr (!Dashpot || Law::rate_dependent) {
      return std::nullopt;
    } else {
      const std::optional<double> floor = unloading_slope_floor(law, branch);
      if (!floor || !(*floor > 0)) return std::nullopt;
      const double k = *floor * length * inverse_force_scale;
      const double c = two_zeta * k;
      const double disc = c * c - 4 * k;
      if (!(disc >= 0)) return std::nullopt;
      const double s1 = 2 * k / (c + std::sqrt(disc));
      const double u = static_cast<double>(z(x)) - static_cast<double>(branch.z_perm) / length;
      const double w = static_cast<double>(x[W]);
      if (!(u > 0 && w > 0)) return std::nullopt;
      return (w - s1 * u) / (1 + s1);
    }
  }

  // The energy the impactor would have on reaching separation (z = 0) along the unloading
  // branch, at most 1/2 w^2 + S(z) with S = separation_work (law.h), normalised by m v0^2: the
  // dashpot only removes energy (d/dt (1/2 m alpha'^2 + U(z)) = -F^2/c), and without one it is
  // conserved. nullopt where there is no attractive well (pull_off_work = 0) or the law states
  // no separation work.
  std::optional<double> separation_energy(const state_type& x) const {
    if constexpr (Law::rate_dependent) {
      return std::nullopt;
    } else {
      if (!(pull_off_work > 0)) return std::nullopt;
      const std::optional<double> S =
          separation_work(law, branch, length * static_cast<double>(z(x)));
      if (!S) return std::nullopt;
      const double w = static_cast<double>(x[W]);
      return 0.5 * w * w + *S * inverse_force_scale / length;
    }
  }

  // Energy that could still come back as rebound, normalised by m v0^2: 1/2 w^2 + U(z).
  // The final rebound speed |w_f| <= sqrt(2 * this) whatever happens next.
  T recoverable_energy(const state_type& x) const {
    const T u = law.stored_energy(branch, T(length * z(x))) /
                (force_scale * length);  // m v0 omega0 * v0/omega0 = m v0^2
    return T(0.5) * x[W] * x[W] + u;
  }
};

}  // namespace ivv
