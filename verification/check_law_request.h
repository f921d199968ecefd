// What a law's author asks of `ivv check-law` (its flags) and of ivv.check_law (its keywords),
// turned into the conformance grid and claims in one place, with the same checks of the input
// and the same words for bad input; and the JSON both print (the verdict plus the law as given).
#pragma once

#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "solver/laws/expression.h"
#include "solver/request_options.h"
#include "verification/conformance.h"

namespace ivv::conformance {

// The claims and the grid as typed; an absent field keeps the default (conformance.h).
struct CheckLawAsk {
  std::optional<std::vector<double>> velocities = std::nullopt;  // --v0 [m/s], each > 0
  std::optional<std::vector<double>> zetas = std::nullopt;     // --zeta, each >= 0 (0: no dashpot)
  std::optional<std::vector<double>> dashpots = std::nullopt;  // --c [N s/m], each finite and > 0
  bool elastic_at_low_speed = false;                           // --elastic-at-low-speed
  bool monotone = true;                                        // false: --no-monotone
  bool cor_increasing_in_v0 = false;                           // --cor-increasing-in-v0
  std::optional<double> captured_below = std::nullopt;  // --captured-below V [m/s], finite and > 0
  std::string expect_cor = {};                          // --expect-cor EXPR; empty: not claimed
  std::optional<double> cor_tolerance = std::nullopt;   // --cor-tolerance, in (0, 1)
};

// An expression law's declared onset force (--onset-force EXPR) into its options. Throws
// InputError("--onset-force") when the law is not an expression law or the text is empty.
void declare_onset_force(RequestOptions& options, const std::optional<std::string>& onset_force);

// The grid: default_grid(request.scene) with the request's integrator options and the axes given.
// Throws InputError naming the flag for a value out of range.
Grid check_law_grid(const SimulationRequest& request, const CheckLawAsk& ask);

// The claims; an --expect-cor expression is compiled against the request's parameters and scene
// and may call `functions` (oracles/expression_functions.h). Throws InputError naming the flag.
Claims check_law_claims(const SimulationRequest& request, const CheckLawAsk& ask,
                        std::span<const ExpressionFunction> functions);

// to_json(result) and the law as given: its parameters, its expression (force, unload,
// allow_tension, onset_force), the scene's name and the claimed COR's text.
nlohmann::json check_law_json(const ConformanceResult& result, const SimulationRequest& request,
                              const Claims& claims);

}  // namespace ivv::conformance
