// JSON views of scenes and results (the `ivv simulate --json` contract of SPEC §5).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "solver/result.h"
#include "solver/scene.h"
#include "solver/simulate.h"

namespace ivv {

nlohmann::json scene_json(const Scene& scene, const DerivedParameters& p);
nlohmann::json result_json(const ImpactResult& r);
// The [structure] of a scene: each element's dashpot, the series c, the formula; null without.
nlohmann::json structure_json(const Scene& scene);
// Lines for `scene show`: the structure's elements (c_i with formulas), then c, zeta (with a
// yield strength) and Zener's lambda, each with the formula it came from.
std::string dashpot_text(const Scene& scene, const DerivedParameters& p);
// {"scene": ..., "request": ..., "result": ...}
// The law of a request: its summary, every parameter in use (defaults included) and, for an
// expression law, its expressions and contact end.
nlohmann::json law_json(const SimulationRequest& req);
nlohmann::json simulation_json(const SimulationRequest& req, const ImpactResult& r);

}  // namespace ivv
