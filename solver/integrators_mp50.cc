// Instantiates simulate() for the 50-digit reference (IntegratorKind::mp50).
#include "solver/hermite.h"
#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/odeint_rkf78_mp.h"

namespace ivv::detail {

ImpactResult simulate_mp50(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<OdeintRkf78MpStepper, mp50>(v, trajectory);
}

IntegratorTraits traits_mp50() {
  return stepper_traits<OdeintRkf78MpStepper, mp50>(IntegratorKind::mp50);
}

}  // namespace ivv::detail
