// A deliberately wrong law for tests: Hertz loading, F = K_h z^{3/2} [N], with an unloading
// curve 1.1 times it (F_unload = 1.1 F_load), which returns more energy than loading stored
// (e ~ sqrt(1.1) > 1 without damping). A contact-law check must catch it (verification's
// conformance tests), and code that special-cases HertzLaw must not treat this derived type as
// Hertz (the machine-code copy of solver/steppers/dop853_fma.h).
#pragma once

#include "solver/laws/hertz.h"

namespace ivv {

struct EnergyCreatingHertz : HertzLaw {
  template <class T>
  T force(const Branch<T>& b, const T& z, const T& v) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::force(b, z, v);
  }
  template <class T>
  T stiffness(const Branch<T>& b, const T& z, const T& v) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::stiffness(b, z, v);
  }
  template <class T>
  T stored_energy(const Branch<T>& b, const T& z) const {
    return (b.phase == Phase::unloading ? 1.1 : 1.0) * HertzLaw::stored_energy(b, z);
  }
};

}  // namespace ivv
