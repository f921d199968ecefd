// Several impacts computed together, as a sweep computes a batch of its points: each result is
// what simulate() gives for its request, and the impacts that integrate the paper's law with a
// dashpot by dop853 on the fastest machine code run four at a time in SIMD lanes
// (simulate_lanes.h, solver/driver/lanes_driver.h): every impact in its own lane with its own
// steps, events and end, a lane that finishes taking the next impact.
//
// A run in lanes rounds its stage arithmetic on vectors, with fused multiply-adds where the
// scalar FMA copy contracts differently, so its last bits differ from simulate()'s within the
// sum of the two runs' stated errors (the case cross.lanes.elastoplastic-map). They do not depend
// on the batch: a lane computes only its own impact, so a point's result is the same whichever
// points share the batch, one of them or thirty-two (and so for any number of threads).
#pragma once

#include <span>

#include "solver/result.h"
#include "solver/simulate.h"

namespace ivv {

// results[i] = the result of requests[i] (no trajectory). Throws std::invalid_argument unless the
// two spans have one size; exceptions of a run propagate as from simulate() (results then
// partly written).
void simulate_batch(std::span<const ValidatedRequest> requests, std::span<ImpactResult> results);

// Whether simulate_batch runs `request` in the lanes: the elastoplastic law with a dashpot, the
// integrator the request runs being dop853 (the auto model's integrated route, or the full
// model), the fastest machine code in use (solver/steppers/machine_code.h), adaptive steps, and
// events located.
bool runs_in_lanes(const ValidatedRequest& request);

}  // namespace ivv
