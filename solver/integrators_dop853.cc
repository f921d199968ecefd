// Instantiates simulate() for Dop853Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/dop853.h"

namespace ivv::detail {

ImpactResult simulate_dop853(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Dop853Stepper>(v, trajectory);
}

IntegratorTraits traits_dop853() {
  return stepper_traits<Dop853Stepper>(IntegratorKind::dop853);
}

}  // namespace ivv::detail
