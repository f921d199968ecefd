// A Hertz law that restitutes a fixed fraction of the impact velocity: a law author's own law,
// written against the installed ivv (solver/laws/law.h) and kept outside the ivv tree.
//
//   loading     F = K z^{3/2}
//   unloading   F = K_u (z - z_p)^{3/2},   K_u = K / e^3,   z_p = (1 - e^2) z_m
// F is continuous at z_m: K_u (e^2 z_m)^{3/2} = K z_m^{3/2}. The energy returned on unloading,
// (2/5) K_u (z_m - z_p)^{5/2} = e^2 (2/5) K z_m^{5/2}, is e^2 times the work of loading, so
// without a dashpot the law delivers COR e at every impact velocity.
// Units: K [N/m^1.5], z [m], F [N]; e [-] in (0, 1].
#pragma once

#include <cmath>
#include <optional>
#include <string_view>

#include "solver/laws/law.h"

namespace downstream {

struct RestitutionHertz {
  static constexpr std::string_view name = "restitution-hertz";
  static constexpr bool rate_dependent = false;

  double K = 0.0;  // loading stiffness [N/m^1.5]
  double e = 1.0;  // the COR the law delivers [-]

  double K_unloading() const { return K / (e * e * e); }

  template <class T>
  T force(const ivv::Branch<T>& h, const T& z, const T&) const {
    if (h.phase == ivv::Phase::unloading)
      return K_unloading() * ivv::signed_pow_1_5(T(z - h.z_perm));
    return K * ivv::signed_pow_1_5(z);
  }
  template <class T>
  T stiffness(const ivv::Branch<T>& h, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    if (h.phase == ivv::Phase::unloading) return 1.5 * K_unloading() * sqrt(abs(T(z - h.z_perm)));
    return 1.5 * K * sqrt(abs(z));
  }
  template <class T>
  T rate_stiffness(const ivv::Branch<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const ivv::Branch<T>&) const {
    return std::nullopt;  // one loading segment
  }
  template <class T>
  void next_segment(ivv::Branch<T>& h) const {
    ++h.segment;
  }
  template <class T>
  void begin_unloading(ivv::Branch<T>& h, const T& z_m) const {
    h.phase = ivv::Phase::unloading;
    h.z_max = z_m;
    h.z_perm = (1 - e * e) * z_m;
  }
  // (2/5) k (z - z_p)^{5/2} on the current curve: what unloading from z would return [J]
  template <class T>
  T stored_energy(const ivv::Branch<T>& h, const T& z) const {
    using std::sqrt;
    const T s = z - h.z_perm;
    if (!(s > 0)) return T(0);
    const double k = h.phase == ivv::Phase::unloading ? K_unloading() : K;
    return 0.4 * k * s * s * sqrt(s);
  }
  template <class T>
  std::optional<double> hysteresis_work(const ivv::Branch<T>& h) const {
    const double z_m = static_cast<double>(h.z_max);
    return 0.4 * K * z_m * z_m * std::sqrt(z_m) * (1 - e * e);
  }
};

}  // namespace downstream
