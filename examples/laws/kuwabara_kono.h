// Kuwabara-Kono viscoelastic Hertz law, as a user-defined (rate-dependent) ivv contact law.
//
// Sources: G. Kuwabara & K. Kono, Jpn. J. Appl. Phys. 26 (1987) 1230; Brilliantov et al.,
// Phys. Rev. E 53 (1996) 5382; restitution: Ramirez et al., Phys. Rev. E 60 (1999) 4465, and
// the Pade form of Muller & Poschel, Phys. Rev. E 84 (2011) 021302 (oracles/published.h).
//
//   F = rho (xi^{3/2} + (3/2) A sqrt(xi) dxi/dt),    rho = (4/3) E* sqrt(R)
//
// on the deformation xi [m] and its rate [m/s]; A [s] is the dissipative constant. Contact ends
// when F returns to zero (the force is clamped at 0, as in Schwager & Poschel's analysis), which
// happens before xi = 0. The law carries its own damping (no series dashpot).
//
// With beta = (3/2) A (rho/m)^{2/5} and v* = beta^{1/2} v^{1/10}, the COR is e(v*) (Pade form).
#pragma once

#include <cmath>
#include <optional>
#include <string_view>

#include "solver/laws/law.h"

namespace ivv::examples {

struct KuwabaraKonoLaw {
  static constexpr std::string_view name = "kuwabara-kono";
  static constexpr bool rate_dependent = true;

  double rho = 0.0;  // (4/3) E* sqrt(R) [N/m^1.5]
  double A = 0.0;    // dissipative constant [s]

  template <class T>
  T force(const Branch<T>&, const T& z, const T& v) const {
    using std::abs;
    using std::sqrt;
    return rho * (signed_pow_1_5(z) + 1.5 * A * sqrt(abs(z)) * v);
  }
  template <class T>
  T stiffness(const Branch<T>&, const T& z, const T& v) const {
    using std::abs;
    using std::sqrt;
    // d/dz of z|z|^{1/2} is 1.5 |z|^{1/2}; of |z|^{1/2} is sign(z) / (2 |z|^{1/2})
    const T root = sqrt(abs(z));
    const T sign = z < 0 ? T(-1) : T(1);
    const T damping = root > 0 ? T(1.5 * A * v * sign / (2 * root)) : T(0);
    return rho * (1.5 * root + damping);
  }
  template <class T>
  T rate_stiffness(const Branch<T>&, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    return rho * 1.5 * A * sqrt(abs(z));
  }
  // one loading segment; unloading retraces the loading curve: the defaults of law.h
  // The elastic part bounds the rebound: on restitution dxi/dt < 0 and damping only removes.
  template <class T>
  T stored_energy(const Branch<T>&, const T& z) const {
    using std::sqrt;
    return z > 0 ? T(0.4 * rho * z * z * sqrt(z)) : T(0);
  }
  template <class T>
  std::optional<double> hysteresis_work(const Branch<T>&) const {
    return std::nullopt;
  }
};

}  // namespace ivv::examples
