// Instantiates simulate() for Rk4Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/rk4.h"

namespace ivv::detail {

ImpactResult simulate_rk4(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Rk4Stepper>(v, trajectory);
}

IntegratorTraits traits_rk4() {
  return stepper_traits<Rk4Stepper>(IntegratorKind::rk4);
}

}  // namespace ivv::detail
