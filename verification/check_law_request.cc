#include "verification/check_law_request.h"

#include <cmath>

#include "scene/input_error.h"

namespace ivv::conformance {

void declare_onset_force(RequestOptions& options, const std::optional<std::string>& onset_force) {
  if (!onset_force) return;
  if (options.expression.force.empty())
    throw InputError("--onset-force",
                     "declares the onset force of an expression law (--force); a C++ law "
                     "declares its own (the member onset_force())");
  if (onset_force->find_first_not_of(" \t") == std::string::npos)
    throw InputError("--onset-force", "is empty; give the force [N] at z = 0, e.g. '-Fad'");
  options.expression.onset_force = *onset_force;
}

Grid check_law_grid(const SimulationRequest& request, const CheckLawAsk& ask) {
  Grid grid = default_grid(request.scene);
  grid.options = request.options;
  if (ask.velocities) grid.velocities = *ask.velocities;
  for (double v : grid.velocities)
    if (!(v > 0)) throw InputError("--v0", "velocities must be > 0 m/s");
  if (ask.zetas) grid.zetas = *ask.zetas;
  for (double z : grid.zetas)
    if (!(z >= 0)) throw InputError("--zeta", "damping ratios must be >= 0 (0: no dashpot)");
  if (ask.dashpots) grid.dashpots = *ask.dashpots;
  for (double d : grid.dashpots)
    if (!(d > 0 && std::isfinite(d)))
      throw InputError("--c", "dashpot coefficients must be finite and > 0 N s/m");
  return grid;
}

Claims check_law_claims(const SimulationRequest& request, const CheckLawAsk& ask,
                        std::span<const ExpressionFunction> functions) {
  Claims claims;
  claims.elastic_at_low_speed = ask.elastic_at_low_speed;
  claims.cor_nonincreasing_in_v0 = claims.cor_nonincreasing_in_damping = ask.monotone;
  if (ask.cor_increasing_in_v0) {  // replaces the default claim that e falls with v0
    claims.cor_nonincreasing_in_v0 = false;
    claims.cor_nondecreasing_in_v0 = true;
  }
  if (ask.captured_below) {
    if (!(*ask.captured_below > 0 && std::isfinite(*ask.captured_below)))
      throw InputError("--captured-below", "a speed in m/s, finite and > 0");
    claims.captured_below = ask.captured_below;
  }
  if (!ask.expect_cor.empty()) {
    claims.expected_cor =
        compile_cor_claim(ask.expect_cor, request.parameters, request.scene, functions);
    claims.expected_cor_text = ask.expect_cor;
  }
  if (ask.cor_tolerance) {
    if (!(*ask.cor_tolerance > 0 && *ask.cor_tolerance < 1))
      throw InputError("--cor-tolerance", "must lie in (0, 1)");
    claims.cor_tolerance = *ask.cor_tolerance;
    claims.cor_tolerance_reason = "given on the command line (--cor-tolerance)";
  }
  return claims;
}

nlohmann::json check_law_json(const ConformanceResult& result, const SimulationRequest& request,
                              const Claims& claims) {
  nlohmann::json j = to_json(result);
  j["law"]["parameters"] = request.parameters;
  if (request.law == LawKind::expression) {
    j["law"]["force"] = request.expression.force;
    j["law"]["unload"] = request.expression.unload;
    j["law"]["allow_tension"] = request.expression.allow_tension;
    if (!request.expression.onset_force.empty())
      j["law"]["onset_force"] = request.expression.onset_force;
  }
  j["law"]["scene"] = request.scene.name;
  if (claims.expected_cor) j["law"]["expect_cor"] = claims.expected_cor_text;
  return j;
}

}  // namespace ivv::conformance
