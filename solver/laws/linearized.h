// Linearized elastoplastic contact law (paper eqs 15-18):
//
//   loading     F = K_y z                                     0 <= z <= z_m
//   unloading   F = (K_y / gamma^2) (z - z_f)
//   z_f = z_m (1 - K_y / (K_h sqrt(z_m)))^{2/3},   gamma^2 = 1 - z_f / z_m
//
// K_y [N/m], K_h [N/m^1.5]. The unloading branch is the secant of the nonlinear Hertz
// unloading curve, so it exists only when K_y/(K_h sqrt(z_m)) <= 1, that is
// z_m >= (K_y/K_h)^2 = 2.25 z_y. Below that the law is undefined: begin_unloading throws
// LawDomainError saying so (never NaN).
#pragma once

#include <cmath>
#include <optional>
#include <sstream>

#include "solver/law.h"
#include "solver/scene.h"

namespace ivv {

struct LinearizedLaw {
  static constexpr std::string_view name = "linearized";
  static constexpr bool rate_dependent = false;
  static constexpr ScaleBasis scale_basis = ScaleBasis::yield;
  static constexpr bool needs_yield_strength = true;

  double K_h = 0.0;  // [N/m^1.5]
  double K_y = 0.0;  // [N/m]

  // Smallest z_m for which the law is defined, (K_y/K_h)^2 [m] (= 2.25 z_y).
  double minimum_z_max() const { return (K_y / K_h) * (K_y / K_h); }

  // coef = K_y / gamma^2 on unloading.
  template <class T>
  T force(const Branch<T>& b, const T& z, const T&) const {
    if (b.phase == Phase::loading) return K_y * z;
    return b.coef * (z - b.z_perm);
  }
  template <class T>
  T stiffness(const Branch<T>& b, const T&, const T&) const {
    return b.phase == Phase::loading ? T(K_y) : b.coef;
  }
  template <class T>
  T rate_stiffness(const Branch<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const Branch<T>&) const {
    return std::nullopt;
  }
  template <class T>
  void next_segment(Branch<T>&) const {}
  template <class T>
  void begin_unloading(Branch<T>& b, const T& z_m) const {
    using std::cbrt;
    using std::sqrt;
    const T ratio = K_y / (K_h * sqrt(z_m));
    if (!(ratio <= 1)) {
      std::ostringstream os;
      os << "linearized law undefined: maximum spring deformation z_m = "
         << static_cast<double>(z_m) << " m is below (K_y/K_h)^2 = 2.25 z_y = " << minimum_z_max()
         << " m (paper eq. 17 needs K_y/(K_h sqrt(z_m)) <= 1); "
         << "use the elastoplastic law at this velocity";
      throw LawDomainError(os.str());
    }
    const T s = 1 - ratio;
    b.phase = Phase::unloading;
    b.z_max = z_m;
    b.z_perm = z_m * cbrt(s * s);
    const T gamma2 = 1 - b.z_perm / z_m;
    b.coef = K_y / gamma2;
  }
  template <class T>
  T stored_energy(const Branch<T>& b, const T& z) const {
    if (b.phase == Phase::loading) return 0.5 * K_y * z * z;
    return z > b.z_perm ? T(0.5 * b.coef * (z - b.z_perm) * (z - b.z_perm)) : T(0);
  }
  template <class T>
  std::optional<double> hysteresis_work(const Branch<T>& b) const {
    const double z_m = static_cast<double>(b.z_max);
    return 0.5 * K_y * z_m * z_m - static_cast<double>(stored_energy(b, b.z_max));
  }
};

}  // namespace ivv
