// The dop853 run of the paper's law with a dashpot in SIMD lanes, four impacts at once
// (solver/driver/lanes_driver.h), compiled for AVX2 + FMA in simulate_lanes.cc where the build
// compiles the FMA copy (solver/steppers/fma_copy.h). simulate_batch (simulate_batch.h) decides
// which impacts run here; this is the run itself.
#pragma once

#include <span>

#include "solver/result.h"
#include "solver/simulate.h"

namespace ivv::detail {

// One impact of the lanes: its request (the elastoplastic law with a dashpot, integrated by
// dop853) and where its result goes.
struct LaneImpact {
  const ValidatedRequest* request = nullptr;
  ImpactResult* result = nullptr;
};

// Whether this process can run the lanes: the CPU has what their unit was compiled for
// (cpu_has_fma_clone() where that is AVX2 + FMA; always in a baseline build).
bool dop853_lanes_impacts_runnable();

// Each impact integrated in the lanes, its result as run_law<Dop853Stepper> gives it before
// simulate_full's finish (finish_full): to_physical of the driver's run. Every request must
// have the options of the first (the lanes share rtol, atol and the first step). Throws
// std::logic_error for a request of another law or without a dashpot, or where
// !dop853_lanes_impacts_runnable().
void run_dop853_lanes(std::span<const LaneImpact> impacts);

}  // namespace ivv::detail
