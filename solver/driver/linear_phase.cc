#include "solver/driver/linear_phase.h"

#include <cmath>

namespace ivv {
namespace {

// exp(-s tau) C(tau) and exp(-s tau) S(tau) of the header's exponential.
struct Kernel {
  double c = 1, s = 0;
};

Kernel kernel(double k, double beta, double tau) {
  const double s = 0.5 * k * beta, root_k = std::sqrt(k);
  const double delta = (s - root_k) * (s + root_k);  // s^2 - k without cancellation
  if (delta < 0) {
    const double nu = std::sqrt(-delta), e = std::exp(-s * tau);
    return {e * std::cos(nu * tau), e * std::sin(nu * tau) / nu};
  }
  if (delta > 0) {
    const double mu = std::sqrt(delta);
    const double slow = std::exp(-(k / (s + mu)) * tau);  // exp(-(s - mu) tau)
    const double fast_m1 = std::expm1(-2 * mu * tau);     // exp(-2 mu tau) - 1
    return {slow * (1 + 0.5 * fast_m1), -slow * fast_m1 / (2 * mu)};
  }
  const double e = std::exp(-s * tau);
  return {e, e * tau};
}

}  // namespace

LinearPhasePoint linear_phase_at(double k, double beta, double w0, double u0, double tau) {
  const Kernel K = kernel(k, beta, tau);
  const double s = 0.5 * k * beta;
  // exp(M tau) X0 = exp(-s tau) [C X0 + S (M + s I) X0], (M + s I) X0 = (s w0 - u0, k w0 - s u0)
  return {tau, K.c * w0 + K.s * (s * w0 - u0), K.c * u0 + K.s * (k * w0 - s * u0)};
}

std::optional<LinearPhasePoint> linear_phase_max_compression(double k, double beta, double w0,
                                                             double u0) {
  const double g0 = w0 - beta * u0;
  if (!(k > 0 && beta >= 0 && g0 > 0 && std::isfinite(k * beta) && std::isfinite(u0)))
    return std::nullopt;
  const double s = 0.5 * k * beta, root_k = std::sqrt(k);
  const double delta = (s - root_k) * (s + root_k);
  const double minus_h0 = u0 + s * g0;  // -h0 = -(1, -beta) (M + s I) X0
  double tau;
  if (delta < 0) {  // nu tau in (0, pi): the first zero of C g0 + S h0
    const double nu = std::sqrt(-delta);
    tau = std::atan2(nu * g0, minus_h0) / nu;
  } else if (!(minus_h0 > 0)) {  // not damped oscillating: no zero unless h0 < 0
    return std::nullopt;
  } else if (delta > 0) {
    const double mu = std::sqrt(delta), x = mu * g0 / minus_h0;
    if (!(x < 1)) return std::nullopt;
    tau = std::atanh(x) / mu;
  } else {
    tau = g0 / minus_h0;
  }
  if (!(tau > 0 && std::isfinite(tau))) return std::nullopt;
  return linear_phase_at(k, beta, w0, u0, tau);
}

}  // namespace ivv
