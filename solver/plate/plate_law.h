// The law of a request on a finite plate: the one front door that `simulate`, `sweep`, the
// regime's quasi-static model and the Python module use, so that every law the registry knows
// (solver/laws/law_registry.h) reaches the plate the same way.
//
// A built-in law runs by its kind (plate_impact.h); the expression law of the request (--force,
// --unload, --param) is compiled once and runs through plate_law_impact.h. What the plate does not
// model is refused by name (InputError): a rate-dependent law (hunt-crossley, an expression that
// uses zdot), a law with tension (--allow-tension), a law needing a yield strength the scene
// lacks. An expression that evaluates to NaN or infinity inside a contact fails the run with the
// expression, z and zdot named (ok = false).
#pragma once

#include "solver/plate/plate_impact.h"
#include "solver/simulate.h"

namespace ivv {

// The checks simulate_plate_law() makes before it runs (InputError naming the field): the scene
// with its finite plate, the law and its parameters (request.scene, law, parameters, expression;
// the integrator and options are not read).
void validate_plate_law(const SimulationRequest& request);

// One impact of the request's law on its scene's finite plate.
PlateImpactResult simulate_plate_law(const SimulationRequest& request,
                                     const PlateImpactOptions& options = {});

}  // namespace ivv
