#include "oracles/expression_functions.h"

#include <array>
#include <limits>

#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "oracles/published.h"

namespace ivv::oracles {
namespace {

// The oracle's value, or NaN where it refuses its argument (it throws InputError there).
template <class F>
double or_nan(F&& f) {
  try {
    return f();
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

double hc_cor(double u0) {
  return or_nan([&] { return closed_forms::hunt_crossley_cor(u0); });
}
double kk_cor(double beta, double v) {
  return or_nan([&] { return kuwabara_kono_pade(kuwabara_kono_v_star(beta, v)); });
}
double thornton(double v_y, double v) {
  return or_nan([&] { return thornton_cor(v_y / v); });
}
double tsuji(double e) {
  return or_nan([&] { return tsuji_beta(e); });
}
double linear(double zeta) {
  return or_nan([&] { return closed_forms::linear_spring_dashpot_cor(zeta); });
}

constexpr std::array kFunctions = {
    ExpressionFunction{"hc_cor", "hc_cor(u0)",
                       "Hunt-Crossley's exact COR for u0 = mu v0 (Lambert W)", hc_cor, nullptr},
    ExpressionFunction{"kk_cor", "kk_cor(beta, v)",
                       "viscoelastic Hertz (Kuwabara-Kono), Mueller-Poeschel Pade form in "
                       "v* = beta^(1/2) v^(1/10); beta [s^(1/5) m^(-1/5)], v [m/s]",
                       nullptr, kk_cor},
    ExpressionFunction{"thornton_cor", "thornton_cor(v_y, v)",
                       "Thornton (1997) elastic-perfectly-plastic spheres, yield velocity v_y "
                       "and impact velocity v [m/s]",
                       nullptr, thornton},
    ExpressionFunction{"tsuji_beta", "tsuji_beta(e)",
                       "ln e / sqrt(ln^2 e + pi^2): Tsuji-type damping factor for target e", tsuji,
                       nullptr},
    ExpressionFunction{"linear_cor", "linear_cor(zeta)",
                       "linear spring-dashpot with tension, exp(-pi zeta/sqrt(1 - zeta^2)); 0 "
                       "for zeta >= 1",
                       linear, nullptr},
};

}  // namespace

std::span<const ExpressionFunction> expression_functions() {
  return kFunctions;
}

}  // namespace ivv::oracles
