#include "oracles/zener.h"

#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>

namespace ivv::oracles {

namespace {
const double kSigmaMax = std::pow(1.25, 0.4);  // (5/4)^{2/5}
}

double zener_small_lambda_slope() {
  boost::math::quadrature::tanh_sinh<double> rule;
  // 1 - (4/5) sigma^{5/2} = 1 - u^{5/2}, u = sigma/sigma_m. Near sigma_m it is computed from the
  // distance to the endpoint the rule supplies (xc), as -expm1((5/2) log1p(-delta)) with
  // delta = 1 - u: a direct 1 - u^{5/2} there loses digits to cancellation (2e-8 of a).
  auto f = [](double s, double xc) {
    const bool right = s > 0.5 * kSigmaMax;
    const double delta = right ? std::abs(xc) / kSigmaMax : 1.0 - s / kSigmaMax;
    const double gap =
        right ? -std::expm1(2.5 * std::log1p(-delta)) : 1.0 - std::pow(s / kSigmaMax, 2.5);
    return gap > 0.0 ? s * s * s / std::sqrt(gap) : 0.0;
  };
  return 2.0 * rule.integrate(f, 0.0, kSigmaMax);
}

double zener_small_lambda_slope_closed_form() {
  return 0.8 * std::pow(1.25, 1.6) * boost::math::beta(1.6, 0.5);
}

double zener_undamped_contact_time() {
  return 0.8 * kSigmaMax * boost::math::beta(0.4, 0.5);
}

}  // namespace ivv::oracles
