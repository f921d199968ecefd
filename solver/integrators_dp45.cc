// Instantiates simulate() for Dp45Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/dp45.h"

namespace ivv::detail {

ImpactResult simulate_dp45(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Dp45Stepper>(v, trajectory);
}

IntegratorTraits traits_dp45() {
  return stepper_traits<Dp45Stepper>(IntegratorKind::dp45);
}

}  // namespace ivv::detail
