// Elastoplastic contact law (paper eqs 8-12; Majeed, Yigit & Christoforou, Nonlinear Dyn.):
//
//   I   Hertz loading          F = K_h z^{3/2}                                  0 <= z <= z_y
//   II  elastic-plastic        F = K_y (z - z_y) + K_h z_y^{3/2}                z_y <= z <= z_m
//   III Hertz unloading        F = K_h (z^{3/2} - z_m^{3/2} + z_y^{3/2}) + K_y (z_m - z_y)
//
// K_h [N/m^1.5], z_y [m], K_y = 1.5 K_h sqrt(z_y) [N/m]. Unloading from z_m <= z_y (no
// yield) follows the Hertz curve. The unloading force vanishes at the permanent set
//   z_f = (z_m^{3/2} - F_m/K_h)^{2/3},  F_m = F(z_m),
// and the loop area (plastic work) is  W_p = int_0^{z_m} F_load dz - int_{z_f}^{z_m} F_unload dz.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "solver/law.h"
#include "solver/law_parameters.h"
#include "solver/scene.h"

namespace ivv {

struct ElastoplasticLaw {
  static constexpr std::string_view name = "elastoplastic";
  static constexpr bool rate_dependent = false;
  static constexpr ScaleBasis scale_basis = ScaleBasis::yield;
  static constexpr bool needs_yield_strength = true;
  static constexpr std::string_view summary =
      "Hertz to z_y, then linear K_y; Hertz-shaped unloading (paper eqs 8-10)";
  static constexpr std::array<ParameterSpec, 0> parameters{};
  static ElastoplasticLaw make(const LawParameters&, const DerivedParameters& p) {
    return {p.K_h, p.z_y, p.K_y};
  }

  // Unloading is "Hertz plus a constant": F = K_h z^{3/2} + hertz_offset.
  template <class T>
  struct History : Branch<T> {
    T hertz_offset = 0;  // F_m - K_h z_m^{3/2} [N] (<= 0; 0 when unloading from z_m <= z_y)
  };

  double K_h = 0.0;  // [N/m^1.5]
  double z_y = 0.0;  // [m]
  double K_y = 0.0;  // [N/m]

  // Hertz force at the yield point, K_h z_y^{3/2} [N].
  double yield_force() const { return K_h * z_y * std::sqrt(z_y); }

  template <class T>
  T force(const History<T>& b, const T& z, const T&) const {
    if (b.phase == Phase::loading && b.segment == 1) return K_y * (z - z_y) + yield_force();
    return K_h * signed_pow_1_5(z) + b.hertz_offset;
  }
  template <class T>
  T stiffness(const History<T>& b, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    if (b.phase == Phase::loading && b.segment == 1) return T(K_y);
    return 1.5 * K_h * sqrt(abs(z));
  }
  template <class T>
  T rate_stiffness(const History<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const History<T>& b) const {
    if (b.phase == Phase::loading && b.segment == 0) return z_y;
    return std::nullopt;
  }
  template <class T>
  void next_segment(History<T>& b) const {
    ++b.segment;
  }
  template <class T>
  void begin_unloading(History<T>& b, const T& z_m) const {
    using std::sqrt;
    const bool yielded = b.segment == 1;
    b.phase = Phase::unloading;
    b.z_max = z_m;
    if (!yielded) {  // elastic: back down the Hertz curve
      b.hertz_offset = T(0);
      b.z_perm = T(0);
      return;
    }
    const T F_m = K_y * (z_m - z_y) + yield_force();
    b.hertz_offset = F_m - K_h * z_m * sqrt(z_m);
    const T zf_1_5 = -b.hertz_offset / K_h;  // z_f^{3/2} = z_m^{3/2} - F_m/K_h >= 0
    b.z_perm = zf_1_5 > 0 ? cube_root(T(zf_1_5 * zf_1_5)) : T(0);
  }
  // int_{z_f}^{z} F_unload ds = (2/5) K_h (z^{5/2} - z_f^{5/2}) + hertz_offset (z - z_f)
  template <class T>
  T stored_energy(const History<T>& b, const T& z) const {
    using std::sqrt;
    if (z <= b.z_perm) return T(0);
    const T zf = b.z_perm;
    return 0.4 * K_h * (z * z * sqrt(z) - zf * zf * sqrt(zf)) + b.hertz_offset * (z - zf);
  }
  template <class T>
  std::optional<double> hysteresis_work(const History<T>& b) const {
    using std::sqrt;
    const double z_m = static_cast<double>(b.z_max);
    double loading;
    if (z_m <= z_y || b.segment == 0) {
      loading = 0.4 * K_h * z_m * z_m * sqrt(z_m);
    } else {
      const double d = z_m - z_y;
      loading = 0.4 * K_h * z_y * z_y * sqrt(z_y) + yield_force() * d + 0.5 * K_y * d * d;
    }
    return loading - static_cast<double>(stored_energy(b, b.z_max));
  }
};

}  // namespace ivv
