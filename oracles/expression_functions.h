// Published formulas as functions of --expect-cor expressions (`ivv check-law --functions`
// lists them). Each calls the oracle that implements it; a value outside the formula's domain
// is NaN (the claim then fails at that velocity, naming it), never an exception inside the
// expression parser.
//
//   hc_cor(u0)          Hunt-Crossley's exact COR, u0 = mu v0 (Lambert W; hunt_crossley.h)
//   kk_cor(beta, v)     viscoelastic Hertz (Kuwabara-Kono), the Mueller-Poeschel Pade form in
//                       v* = beta^{1/2} v^{1/10}; beta [s^{1/5} m^{-1/5}], v [m/s] (published.h)
//   thornton_cor(v_y, v) Thornton (1997) elastic-perfectly-plastic spheres, r = v_y/v
//                       (published.h)
//   tsuji_beta(e)       beta = ln e / sqrt(ln^2 e + pi^2), the damping factor of Tsuji-type
//                       Hertz damping for a target COR e in (0, 1] (published.h)
//   linear_cor(zeta)    linear spring-dashpot with tension allowed, e = exp(-pi zeta /
//                       sqrt(1 - zeta^2)); 0 for zeta >= 1 (linear_model.h)
#pragma once

#include <span>

#include "solver/laws/expression.h"

namespace ivv::oracles {

std::span<const ExpressionFunction> expression_functions();

}  // namespace ivv::oracles
