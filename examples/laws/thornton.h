// Thornton's elastic-perfectly-plastic contact law, as a user-defined ivv contact law.
//
// Source: C. Thornton, "Coefficient of restitution for collinear collisions of
// elastic-perfectly plastic spheres", J. Appl. Mech. 64 (1997) 383-386, eqs (1)-(12).
//
//   elastic loading     F = (4/3) E* sqrt(R) z^{3/2}                    z <= z_y
//   plastic loading     F = F_y + pi p_y R (z - z_y)                    z >= z_y
//   unloading           F = (4/3) E* sqrt(R_p) (z - z_p)^{3/2}           after z = z_m
//     z_y = (pi p_y / (2 E*))^2 R,   F_y = (4/3) E* sqrt(R) z_y^{3/2}
//     R_p = (4 E* / (3 F_m)) ((2 F_m + F_y) / (2 pi p_y))^{3/2}
//     z_m - z_p = (3 F_m / (4 E* sqrt(R_p)))^{2/3}        (F continuous at z_m)
// Units: E* [Pa], R [m], p_y [Pa] the limiting contact pressure, z [m], F [N].
//
// Thornton integrates these exactly: with r = V_y/V_i and (1/2) m V_y^2 = (2/5) K_h z_y^{5/2},
//   e = sqrt(6 sqrt(3)/5) sqrt(1 - r^2/6) [r / (r + 2 sqrt(6/5 - r^2/5))]^{1/4}   (r < 1)
// (oracles/published.h), so the law must deliver that COR to the integrator's tolerance.
//
// The law is templated on its scalar, so it also runs in the 50-digit reference and its
// stiffness is checked by automatic differentiation.
#pragma once

#include <cmath>
#include <numbers>
#include <optional>
#include <string_view>

#include "solver/laws/law.h"

namespace ivv::examples {

struct ThorntonLaw {
  static constexpr std::string_view name = "thornton";
  static constexpr bool rate_dependent = false;

  double E_star = 0.0;  // [Pa]
  double R = 0.0;       // [m]
  double p_y = 0.0;     // limiting contact pressure [Pa]

  template <class T>
  struct History : Branch<T> {
    T unloading_radius = 0;  // R_p [m] of the unloading Hertz curve
  };

  double K() const { return 4.0 / 3.0 * E_star * std::sqrt(R); }  // [N/m^1.5]
  double z_y() const {
    const double a = std::numbers::pi * p_y / (2.0 * E_star);
    return a * a * R;
  }
  double F_y() const { return K() * z_y() * std::sqrt(z_y()); }
  double plastic_stiffness() const { return std::numbers::pi * p_y * R; }  // [N/m]
  // V_y [m/s] for a mass m [kg]: the impact velocity whose Hertz energy reaches z_y.
  double yield_velocity(double m) const { return std::sqrt(0.8 * K() * std::pow(z_y(), 2.5) / m); }

  template <class T>
  T force(const History<T>& h, const T& z, const T&) const {
    if (h.phase == Phase::unloading) {
      using std::sqrt;
      return 4.0 / 3.0 * E_star * sqrt(h.unloading_radius) * signed_pow_1_5(T(z - h.z_perm));
    }
    if (h.segment == 1) return F_y() + plastic_stiffness() * (z - z_y());
    return K() * signed_pow_1_5(z);
  }
  template <class T>
  T stiffness(const History<T>& h, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    if (h.phase == Phase::unloading)
      return 2.0 * E_star * sqrt(h.unloading_radius) * sqrt(abs(T(z - h.z_perm)));
    if (h.segment == 1) return T(plastic_stiffness());
    return 1.5 * K() * sqrt(abs(z));
  }
  template <class T>
  T rate_stiffness(const History<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const History<T>& h) const {
    if (h.phase == Phase::loading && h.segment == 0) return z_y();
    return std::nullopt;
  }
  template <class T>
  void next_segment(History<T>& h) const {
    ++h.segment;
  }
  template <class T>
  void begin_unloading(History<T>& h, const T& z_m) const {
    using std::sqrt;
    h.phase = Phase::unloading;
    h.z_max = z_m;
    if (h.segment == 0) {  // elastic: back down the loading curve
      h.unloading_radius = T(R);
      h.z_perm = T(0);
      return;
    }
    const T F_m = F_y() + plastic_stiffness() * (z_m - z_y());
    const T ratio = (2 * F_m + F_y()) / (2 * std::numbers::pi * p_y);
    h.unloading_radius = 4 * E_star / (3 * F_m) * ratio * sqrt(ratio);
    const T depth = 3 * F_m / (4 * E_star * sqrt(h.unloading_radius));  // (z_m - z_p)^{3/2}
    h.z_perm = z_m - cube_root(T(depth * depth));
  }
  // (8/15) E* sqrt(R_p) (z - z_p)^{5/2} on unloading; the Hertz energy while loading elastically
  template <class T>
  T stored_energy(const History<T>& h, const T& z) const {
    using std::sqrt;
    const T s = z - h.z_perm;
    if (!(s > 0)) return T(0);
    const T radius = h.phase == Phase::unloading ? h.unloading_radius : T(R);
    return 8.0 / 15.0 * E_star * sqrt(radius) * s * s * sqrt(s);
  }
  template <class T>
  std::optional<double> hysteresis_work(const History<T>& h) const {
    const double z_m = static_cast<double>(h.z_max);
    double loading;
    if (h.segment == 0) {
      loading = 0.4 * K() * z_m * z_m * std::sqrt(z_m);
    } else {
      const double d = z_m - z_y();
      loading = 0.4 * K() * z_y() * z_y() * std::sqrt(z_y()) + F_y() * d +
                0.5 * plastic_stiffness() * d * d;
    }
    return loading - static_cast<double>(stored_energy(h, h.z_max));
  }
};

}  // namespace ivv::examples
