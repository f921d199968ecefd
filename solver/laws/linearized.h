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

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <sstream>

#include "scene/scene.h"
#include "solver/laws/law.h"
#include "solver/laws/law_kind.h"
#include "solver/laws/law_parameters.h"

namespace ivv {

struct LinearizedLaw {
  static constexpr std::string_view name = "linearized";
  static constexpr LawKind kind = LawKind::linearized;  // its row in the registry
  static constexpr bool rate_dependent = false;
  static constexpr ScaleBasis scale_basis = ScaleBasis::yield;
  static constexpr bool needs_yield_strength = true;
  static constexpr std::string_view summary =
      "F = K_y z, secant unloading to z_f (paper eqs 15-18; undefined below z_m = 2.25 z_y)";
  static constexpr std::array<ParameterSpec, 0> parameters{};
  static LinearizedLaw make(const LawParameters&, const DerivedParameters& p) {
    return {p.K_h, p.K_y};
  }

  template <class T>
  struct History : Branch<T> {
    T unloading_stiffness = 0;  // K_y / gamma^2 [N/m]
  };

  double K_h = 0.0;  // [N/m^1.5]
  double K_y = 0.0;  // [N/m]

  // Smallest z_m for which the law is defined, (K_y/K_h)^2 [m] (= 2.25 z_y).
  double minimum_z_max() const { return (K_y / K_h) * (K_y / K_h); }

  template <class T>
  T force(const History<T>& b, const T& z, const T&) const {
    if (b.phase == Phase::loading) return K_y * z;
    return b.unloading_stiffness * (z - b.z_perm);
  }
  template <class T>
  T stiffness(const History<T>& b, const T&, const T&) const {
    return b.phase == Phase::loading ? T(K_y) : b.unloading_stiffness;
  }
  template <class T>
  T rate_stiffness(const History<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const History<T>&) const {
    return std::nullopt;
  }
  template <class T>
  void next_segment(History<T>&) const {}
  template <class T>
  void begin_unloading(History<T>& b, const T& z_m) const {
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
    b.z_perm = z_m * cube_root(T(s * s));
    const T gamma2 = 1 - b.z_perm / z_m;
    b.unloading_stiffness = K_y / gamma2;
  }
  // Unloading is the straight line of slope K_y / gamma^2 [N/m] through z_f.
  template <class T>
  std::optional<double> unloading_slope_floor(const History<T>& b) const {
    if (b.phase != Phase::unloading) return std::nullopt;
    return static_cast<double>(b.unloading_stiffness);
  }
  template <class T>
  T stored_energy(const History<T>& b, const T& z) const {
    if (b.phase == Phase::loading) return 0.5 * K_y * z * z;
    return z > b.z_perm ? T(0.5 * b.unloading_stiffness * (z - b.z_perm) * (z - b.z_perm)) : T(0);
  }
  template <class T>
  std::optional<double> hysteresis_work(const History<T>& b) const {
    const double z_m = static_cast<double>(b.z_max);
    return 0.5 * K_y * z_m * z_m - static_cast<double>(stored_energy(b, b.z_max));
  }
};

}  // namespace ivv
