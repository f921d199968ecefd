#include "oracles/published.h"

#include <cmath>
#include <numbers>
#include <sstream>

#include "scene/input_error.h"

namespace ivv::oracles {

double thornton_cor(double r) {
  require(std::isfinite(r) && r > 0.0, "r", "positive and finite (r = V_y/V_i)", r);
  if (r >= 1.0) return 1.0;
  const double r2 = r * r;
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::sqrt(1.0 - r2 / 6.0) *
         std::pow(r / (r + 2.0 * std::sqrt(6.0 / 5.0 - r2 / 5.0)), 0.25);
}

double thornton_asymptote_coefficient_exact() {
  return std::sqrt(6.0 * std::sqrt(3.0) / 5.0) * std::pow(2.0 * std::sqrt(6.0 / 5.0), -0.25);
}

double thornton_asymptote(double r) {
  require(std::isfinite(r) && r > 0.0, "r", "positive and finite (r = V_y/V_i)", r);
  return kThorntonAsymptoteCoefficient * std::pow(r, 0.25);
}

double kuwabara_kono_beta(double A, double E_star, double R, double mass) {
  require(std::isfinite(A) && A >= 0.0, "A", ">= 0 and finite [s]", A);
  require(std::isfinite(E_star) && E_star > 0.0, "E_star", "positive and finite [Pa]", E_star);
  require(std::isfinite(R) && R > 0.0, "R", "positive and finite [m]", R);
  require(std::isfinite(mass) && mass > 0.0, "mass", "positive and finite [kg]", mass);
  const double rho = 4.0 / 3.0 * E_star * std::sqrt(R);
  return 1.5 * A * std::pow(rho / mass, 0.4);
}

double kuwabara_kono_v_star(double beta, double v) {
  require(std::isfinite(beta) && beta >= 0.0, "beta", ">= 0 and finite", beta);
  require(std::isfinite(v) && v >= 0.0, "v", ">= 0 and finite [m/s]", v);
  return std::sqrt(beta) * std::pow(v, 0.1);
}

double kuwabara_kono_series(double v_star) {
  require(std::isfinite(v_star) && v_star >= 0.0, "v_star", ">= 0 and finite", v_star);
  const double s2 = v_star * v_star;
  return 1.0 - 1.15344 * s2 + 0.79826 * s2 * s2;
}

double tsuji_beta(double e) {
  require(std::isfinite(e) && e > 0.0 && e <= 1.0, "e", "in (0, 1]", e);
  const double l = std::log(e);
  return l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

double kuwabara_kono_pade(double v) {
  require(std::isfinite(v) && v >= 0.0, "v_star", ">= 0 and finite", v);
  const double num = 1.0 + v * (1.07232 + v * (0.574198 + v * 0.141552));
  const double den =
      1.0 +
      v * (1.07232 + v * (1.72765 + v * (1.37842 + v * (1.19449 + v * (0.467273 + v * 0.235585)))));
  return num / den;
}

}  // namespace ivv::oracles
