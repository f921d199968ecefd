// JSON views of scenes and impact results: the one writer of the `ivv simulate --json` contract
// (docs/design.md §5), used by every front end that prints an impact.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "scene/scene.h"
#include "scene/scene_json.h"  // scene_json(), structure_json(): the one scene writer
#include "solver/choice/model_choice.h"
#include "solver/plate/plate_run.h"
#include "solver/request_options.h"
#include "solver/result.h"
#include "solver/simulate.h"

namespace ivv {

nlohmann::json result_json(const ImpactResult& r);
// {"scene": ..., "request": ..., "result": ...}
// The law of a request: its summary, every parameter in use (defaults included) and, for an
// expression law, its expressions and contact end.
nlohmann::json law_json(const SimulationRequest& req);
nlohmann::json simulation_json(const SimulationRequest& req, const ImpactResult& r);
// {"model", "route", "law", "integrator", "reasons", "estimated_error"}: what ran and why.
nlohmann::json model_choice_json(const ModelChoice& choice, ModelKind model);
// simulation_json() of the run, with "model_choice" where a choice was made.
nlohmann::json simulation_json(const SimulationRun& run);

// A finite-plate impact (solver/plate/plate_impact.h): {"scene", "model": "finite-plate",
// "law", "plate", "result"}; result carries e (final, once no contact is possible), e_first (at
// the first separation), contacts (each start, end, impulse, peak force), F_max over all,
// t_contact (the first contact's duration), the mode count and compliances, the energy ledger.
nlohmann::json plate_simulation_json(const PlateRun& run);
// The regime's facts (mass ratio, wave return against contact time, relative stiffness, the
// infinite plate's zeta, lambda and c, the regime, Olsson's class).
nlohmann::json plate_regime_json(const PlateRegime& regime);

}  // namespace ivv
