// The summaries `ivv simulate` and `ivv scene show` print.
//
// impact_summary: for one impact: the scene and request in one line, then the
// status, the CORs, peak force, contact time, deformations, the energy ledger, the impulse with
// its momentum check, the bodies after impact (a free target) and the work done; and, under
// --model auto, what ran (ModelChoice::brief()).
#pragma once

#include <string>

#include "solver/request_options.h"

namespace ivv {

std::string impact_summary(const SimulationRun& run);

// What `ivv scene show` prints: the scene's inputs and every derived parameter with its unit.
std::string scene_summary(const Scene& scene);

// Lines for `scene show`: the structure's elements (c_i with formulas), then c, zeta (with a
// yield strength) and Zener's lambda, each with the formula it came from.
std::string dashpot_text(const Scene& scene, const DerivedParameters& p);

}  // namespace ivv
