#include "closed_forms/hunt_crossley.h"

#include <boost/math/special_functions/lambert_w.hpp>
#include <boost/math/special_functions/log1p.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <sstream>

#include "scene/input_error.h"

namespace ivv::closed_forms {

namespace {

void require_target(double e) {
  require(std::isfinite(e) && e > 0.0 && e < 1.0, "e_target", "in (0, 1)", e);
}

// Below this u0 one Newton step on log1pmx(-e u0) = log1pmx(u0) polishes the estimate; above
// it the Lambert-W form is already within a few ulps (its error is ~eps/u0^2).
constexpr double kPolishMaxU0 = 1.0;
// ... and above this one: the polish divides by the slope -e u0^2/(1 - e u0), which underflows
// (to 0 below u0 ~ 1e-162, giving e = 0/0 = NaN: `simulate --law hunt-crossley --hc-mu 1e-200`
// printed "separated, e = -nan") or loses digits in the subnormal range well before; at u0 = 1e-4
// it is 1e-8, a normal number, and below it the series' truncation, |c9| u0^9 < 1e-36, leaves
// nothing to polish.
constexpr double kPolishMinU0 = 1e-4;

}  // namespace

double hunt_crossley_cor_series(double u) {
  // Coefficients c_k of e = sum c_k u^k (exact fractions in the header).
  static constexpr double c[] = {
      1.0,           -2.0 / 3.0,       4.0 / 9.0,         -44.0 / 135.0,     104.0 / 405.0,
      -40.0 / 189.0, 7648.0 / 42525.0, -2848.0 / 18225.0, 31712.0 / 229635.0};
  double sum = 0.0;
  for (int k = 8; k >= 0; --k) sum = sum * u + c[k];
  return sum;
}

double hunt_crossley_cor(double u0) {
  require(std::isfinite(u0) && u0 >= 0.0, "u0", ">= 0 and finite", u0);
  if (u0 == 0.0) return 1.0;
  using boost::math::log1pmx;
  double e = 0.0;
  if (u0 < kSeriesMaxU0) {
    e = hunt_crossley_cor_series(u0);
  } else {
    // -(1 + u0) e^{-(1 + u0)} = -exp(-1 + log1pmx(u0)), in [-1/e, 0).
    const double x = -std::exp(-1.0 + log1pmx(u0));
    e = (1.0 + boost::math::lambert_w0(x)) / u0;
  }
  if (u0 >= kPolishMinU0 && u0 < kPolishMaxU0) {
    const double residual = log1pmx(-e * u0) - log1pmx(u0);
    const double slope = -e * u0 * u0 / (1.0 - e * u0);
    e -= residual / slope;
  }
  return e;
}

double hunt_crossley_u0_for_cor(double e_target) {
  require_target(e_target);
  auto f = [e_target](double u) { return hunt_crossley_cor(u) - e_target; };
  std::uintmax_t max_iter = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      f, 0.0, 1.0 / e_target, 1.0 - e_target, hunt_crossley_cor(1.0 / e_target) - e_target,
      boost::math::tools::eps_tolerance<double>(52), max_iter);
  return 0.5 * (bracket.first + bracket.second);
}

HuntCrossleyImpact solve_hunt_crossley(const HuntCrossleyInput& in) {
  require(std::isfinite(in.K) && in.K > 0.0, "K", "positive and finite", in.K);
  require(std::isfinite(in.mu) && in.mu >= 0.0, "mu", ">= 0 and finite", in.mu);
  require(std::isfinite(in.mass) && in.mass > 0.0, "mass", "positive and finite", in.mass);
  require(std::isfinite(in.v0) && in.v0 > 0.0, "v0", "positive and finite", in.v0);
  HuntCrossleyImpact r;
  r.u0 = in.mu * in.v0;
  r.e = hunt_crossley_cor(r.u0);
  // f(u0)/u0^2 with f = -log1pmx: accurate for small u0, 1/2 in the limit.
  const double f_over_u2 = r.u0 == 0.0 ? 0.5 : -boost::math::log1pmx(r.u0) / (r.u0 * r.u0);
  r.x_max = std::pow(2.5 * in.mass / in.K * in.v0 * in.v0 * f_over_u2, 0.4);
  return r;
}

namespace {
void require_map_args(double e, double v0) {
  require_target(e);
  require(std::isfinite(v0) && v0 > 0.0, "v0", "positive and finite", v0);
}
}  // namespace

double mu_hunt_crossley(double e, double v0) {
  require_map_args(e, v0);
  return 3.0 * (1.0 - e) / (2.0 * v0);
}
double mu_lankarani_nikravesh(double e, double v0) {
  require_map_args(e, v0);
  return 3.0 * (1.0 - e * e) / (4.0 * v0);
}
double mu_lee_wang(double e, double v0) {
  require_map_args(e, v0);
  return 3.0 * (1.0 - e) / (4.0 * v0);
}
double mu_gonthier(double e, double v0) {
  require_map_args(e, v0);
  return (1.0 - e * e) / (e * v0);
}
double mu_flores(double e, double v0) {
  require_map_args(e, v0);
  return 8.0 * (1.0 - e) / (5.0 * e * v0);
}
double mu_hu_guo(double e, double v0) {
  require_map_args(e, v0);
  return 3.0 * (1.0 - e) / (2.0 * e * v0);
}
double mu_gharib_hurmuzlu(double e, double v0) {
  require_map_args(e, v0);
  return (1.0 / e - 1.0) / v0;
}

const std::array<DampingMap, 7>& damping_maps() {
  static const std::array<DampingMap, 7> maps{{
      {"hunt-crossley", "3(1-e)/(2 v0)", &mu_hunt_crossley},
      {"lankarani-nikravesh", "3(1-e^2)/(4 v0)", &mu_lankarani_nikravesh},
      {"lee-wang", "3(1-e)/(4 v0)", &mu_lee_wang},
      {"gonthier", "(1-e^2)/(e v0)", &mu_gonthier},
      {"flores", "8(1-e)/(5 e v0)", &mu_flores},
      {"hu-guo", "3(1-e)/(2 e v0)", &mu_hu_guo},
      {"gharib-hurmuzlu", "(1/e-1)/v0", &mu_gharib_hurmuzlu},
  }};
  return maps;
}

std::optional<DampingMap> find_damping_map(std::string_view name) {
  for (const DampingMap& m : damping_maps()) {
    if (m.name == name) return m;
  }
  return std::nullopt;
}

double delivered_cor(const DampingMap& map, double e_target) {
  // u0 = v0 mu(e, v0) does not depend on v0; evaluate at v0 = 1 m/s.
  return hunt_crossley_cor(map.mu(e_target, 1.0));
}

}  // namespace ivv::closed_forms
