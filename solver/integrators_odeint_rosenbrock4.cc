// Instantiates simulate() for OdeintRosenbrock4Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/odeint_rosenbrock4.h"

namespace ivv::detail {

ImpactResult simulate_odeint_rosenbrock4(const ValidatedRequest& v,
                                         std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<OdeintRosenbrock4Stepper>(v, trajectory);
}

IntegratorTraits traits_odeint_rosenbrock4() {
  return stepper_traits<OdeintRosenbrock4Stepper>(IntegratorKind::odeint_rosenbrock4);
}

}  // namespace ivv::detail
