// Hertz contact law (paper eq. 5; Johnson, Contact Mechanics, 1985, §4.2):
//
//   F = K_h z^{3/2},   K_h = (4/3) sqrt(R) E*   [N/m^1.5],  z [m],  F [N]
//
// Elastic: loading and unloading follow the same curve, so the hysteresis area is zero and
// the coefficient of restitution without a dashpot is exactly 1.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "scene/scene.h"
#include "solver/laws/law.h"
#include "solver/laws/law_kind.h"
#include "solver/laws/law_parameters.h"

namespace ivv {

struct HertzLaw {
  static constexpr std::string_view name = "hertz";
  static constexpr LawKind kind = LawKind::hertz;  // its row in the registry
  static constexpr bool rate_dependent = false;
  static constexpr ScaleBasis scale_basis = ScaleBasis::hertz;
  static constexpr bool needs_yield_strength = false;
  // F = K_h z |z|^{1/2} has the sign of z, and z_perm = 0 (law.h)
  static constexpr bool separates_at_z_perm = true;
  static constexpr std::string_view summary =
      "F = K_h z^{3/2} (Hertz, elastic; paper eq. 5, Johnson 1985 §4.2)";
  static constexpr std::array<ParameterSpec, 0> parameters{};
  static HertzLaw make(const LawParameters&, const DerivedParameters& p) { return {p.K_h}; }

  double K_h = 0.0;  // [N/m^1.5]

  // Hertzian from onset on, without end (law.h).
  HertzianOnset hertzian_onset() const { return {K_h, std::numeric_limits<double>::infinity()}; }

  template <class T>
  T force(const Branch<T>&, const T& z, const T&) const {
    return K_h * signed_pow_1_5(z);
  }
  template <class T>
  T stiffness(const Branch<T>&, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    return 1.5 * K_h * sqrt(abs(z));
  }
  template <class T>
  T rate_stiffness(const Branch<T>&, const T&, const T&) const {
    return T(0);
  }
  // one loading segment; unloading retraces the loading curve: the defaults of law.h
  // (2/5) K_h z^{5/2}
  template <class T>
  T stored_energy(const Branch<T>&, const T& z) const {
    using std::sqrt;
    return z > 0 ? T(0.4 * K_h * z * z * sqrt(z)) : T(0);
  }
  template <class T>
  std::optional<double> hysteresis_work(const Branch<T>&) const {
    return 0.0;
  }
};

}  // namespace ivv
