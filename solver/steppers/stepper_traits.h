// Reads a stepper's declared constants into an IntegratorTraits row
// (solver/steppers/integrators.h). Used by IntegratorInstance<I>::traits()
// (solver/steppers/integrator_instance_impl.h), one per entry of the integrator list.
#pragma once

#include "solver/driver/impact_system.h"
#include "solver/laws/hertz.h"
#include "solver/steppers/integrators.h"

namespace ivv {

// The constants do not depend on the system a stepper is instantiated for; any one will do.
template <template <class> class Stepper, class T = double>
constexpr IntegratorTraits stepper_traits(IntegratorKind kind) {
  using S = Stepper<ImpactSystem<HertzLaw, false, T>>;
  return {kind,           S::name,
          S::description, S::order,
          S::implicit,    S::dense_output,
          S::fixed_step,  S::fixed_step || S::fixed_step_mode,
          S::reference,   S::measured_relative_error};
}

}  // namespace ivv
