// Instantiates simulate() for Dp45Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/steppers/dp45.h"

namespace ivv::detail {

ImpactResult simulate_dp45(const SimulationRequest& req, const DerivedParameters& p,
                           std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Dp45Stepper>(req, p, trajectory);
}

}  // namespace ivv::detail
