// The summaries `ivv simulate` and `ivv scene show` print.
//
// impact_summary: for one impact: the scene and request in one line, then the
// status, the CORs, peak force, contact time, deformations, the energy ledger, the impulse with
// its momentum check, the bodies after impact (a free target) and the work done; and, under
// --model auto, what ran (ModelChoice::brief()).
#pragma once

#include <string>

#include "solver/plate/plate_run.h"
#include "solver/request_options.h"

namespace ivv {

std::string impact_summary(const SimulationRun& run);

// What `ivv scene show` prints: the scene's inputs and every derived parameter with its unit.
std::string scene_summary(const Scene& scene);

// Lines for `scene show`: the structure's elements (c_i with formulas), then c, zeta (with a
// yield strength) and Zener's lambda, each with the formula it came from.
std::string dashpot_text(const Scene& scene, const DerivedParameters& p);

// A finite-plate impact: final e, e_first, the contacts (start, end, impulse, peak force),
// F_max, the first contact's t_contact, the mode count and truncation, the energy ledger,
// then the regime: every model against the full plate, and the model that answers.
std::string plate_impact_summary(const PlateRun& run);
// The regime lines alone (run.regime must be set): every model against the full plate, the
// published criterion, the answer.
std::string plate_regime_text(const PlateRun& run);

// Lines for `scene show` of a finite plate: size, impact point, D's, mass against the
// impactor's, the first mode's frequency and the static compliance under the impactor.
std::string finite_plate_text(const Scene& scene);

}  // namespace ivv
