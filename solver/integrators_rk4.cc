// Instantiates simulate() for Rk4Stepper (one translation unit per integrator).
#include "solver/simulate_impl.h"
#include "solver/steppers/rk4.h"

namespace ivv::detail {

ImpactResult simulate_rk4(const SimulationRequest& req, const DerivedParameters& p,
                          std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<Rk4Stepper>(req, p, trajectory);
}

}  // namespace ivv::detail
