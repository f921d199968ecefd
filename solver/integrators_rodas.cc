// Instantiates simulate() for Rodas4Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/rodas.h"

namespace ivv::detail {

ImpactResult simulate_rodas4(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Rodas4Stepper>(v, trajectory);
}

IntegratorTraits traits_rodas4() {
  return stepper_traits<Rodas4Stepper>(IntegratorKind::rodas4);
}

}  // namespace ivv::detail
