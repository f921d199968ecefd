// Reads a stepper's declared constants into an IntegratorTraits row (solver/integrators.h).
// Included by the integrators_*.cc units, one per stepper, each of which defines its row.
#pragma once

#include "solver/impact_system.h"
#include "solver/integrators.h"
#include "solver/laws/hertz.h"

namespace ivv {

// The constants do not depend on the system a stepper is instantiated for; any one will do.
template <template <class> class Stepper, class T = double>
constexpr IntegratorTraits stepper_traits(IntegratorKind kind) {
  using S = Stepper<ImpactSystem<HertzLaw, false, T>>;
  return {kind,        S::name,         S::description, S::order,
          S::implicit, S::dense_output, S::fixed_step,  S::fixed_step || S::fixed_step_mode,
          S::reference};
}

namespace detail {
// Defined in integrators_*.cc beside the instantiation of simulate() for each stepper.
IntegratorTraits traits_odeint_dopri5();
IntegratorTraits traits_odeint_rosenbrock4();
IntegratorTraits traits_rk4();
IntegratorTraits traits_dp45();
IntegratorTraits traits_dop853();
IntegratorTraits traits_gsl_rk8pd();
IntegratorTraits traits_gsl_msbdf();
IntegratorTraits traits_rodas4();
IntegratorTraits traits_mp50();
}  // namespace detail

}  // namespace ivv
