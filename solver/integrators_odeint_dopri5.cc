// Instantiates simulate() for OdeintDopri5Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/odeint_dopri5.h"

namespace ivv::detail {

ImpactResult simulate_odeint_dopri5(const ValidatedRequest& v,
                                    std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<OdeintDopri5Stepper>(v, trajectory);
}

IntegratorTraits traits_odeint_dopri5() {
  return stepper_traits<OdeintDopri5Stepper>(IntegratorKind::odeint_dopri5);
}

}  // namespace ivv::detail
