// Hunt-Crossley contact law (paper eq. 27; Hunt & Crossley, J. Appl. Mech. 42:440, 1975):
//
//   F = K alpha^{3/2} (1 + mu alpha_dot)
//
// on the impactor displacement alpha [m] and velocity alpha_dot [m/s], with K [N/m^1.5]
// and mu [s/m]. It carries its own damping, so it is used without the series dashpot
// (then z = alpha and the rate argument is alpha_dot). Loading and unloading share the
// formula; the loop area is not known in closed form, so the energy ledger integrates it.
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

struct HuntCrossleyLaw {
  static constexpr std::string_view name = "hunt-crossley";
  static constexpr LawKind kind = LawKind::hunt_crossley;  // its row in the registry
  static constexpr bool rate_dependent = true;
  static constexpr ScaleBasis scale_basis = ScaleBasis::hertz;
  static constexpr bool needs_yield_strength = false;
  static constexpr std::string_view summary =
      "F = K z^{3/2} (1 + mu dz/dt), no series dashpot (paper eq. 27; Hunt & Crossley 1975)";
  static constexpr std::array<ParameterSpec, 2> parameters{{
      {"K", "N/m^1.5", "stiffness (default: the scene's Hertz stiffness K_h)",
       std::numeric_limits<double>::quiet_NaN(), 0.0, std::numeric_limits<double>::infinity(), true,
       [](const DerivedParameters& p) { return p.K_h; }},
      {"mu", "s/m", "damping factor (default 0: Hertz)", 0.0, 0.0,
       std::numeric_limits<double>::infinity(), false},
  }};
  static HuntCrossleyLaw make(const LawParameters& given, const DerivedParameters& p) {
    return {parameter_value(given, parameters[0], p), parameter_value(given, parameters[1], p)};
  }

  double K = 0.0;   // [N/m^1.5]
  double mu = 0.0;  // [s/m]

  template <class T>
  T force(const Branch<T>&, const T& z, const T& v) const {
    return K * signed_pow_1_5(z) * (1 + mu * v);
  }
  template <class T>
  T stiffness(const Branch<T>&, const T& z, const T& v) const {
    using std::abs;
    using std::sqrt;
    return 1.5 * K * sqrt(abs(z)) * (1 + mu * v);
  }
  template <class T>
  T rate_stiffness(const Branch<T>&, const T& z, const T&) const {
    return K * mu * signed_pow_1_5(z);
  }
  // one loading segment; unloading retraces the loading curve: the defaults of law.h
  // The elastic part (2/5) K z^{5/2} bounds the rebound energy: on restitution
  // alpha_dot < 0, so the damping factor (1 + mu alpha_dot) < 1 only removes energy.
  template <class T>
  T stored_energy(const Branch<T>&, const T& z) const {
    using std::sqrt;
    return z > 0 ? T(0.4 * K * z * z * sqrt(z)) : T(0);
  }
  template <class T>
  std::optional<double> hysteresis_work(const Branch<T>&) const {
    return std::nullopt;
  }
};

}  // namespace ivv
