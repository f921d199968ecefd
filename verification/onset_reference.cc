#include "verification/onset_reference.h"

#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>

namespace ivv::verification {
namespace {

using Real = boost::multiprecision::cpp_bin_float_50;
using State = std::array<Real, 6>;  // a, w, u, J, Wa, Wv
enum { A, W, U, J, WA, WV };

State rhs(const Real& q, const State& x, const Real& kappa, const Real& beta) {
  const Real u32 = x[U] * sqrt(x[U]);
  const Real q2 = q * q, q4 = q2 * q2;
  State d;
  d[A] = 2 * q * x[W];
  d[W] = -2 * kappa * q4 * u32;
  d[U] = (q == 0 ? Real(0) : 2 * (x[W] - x[U]) / q) - 2 * beta * kappa * q2 * u32;
  d[J] = 2 * kappa * q4 * u32;
  d[WA] = 2 * kappa * q4 * u32 * x[W];
  d[WV] = 2 * beta * kappa * kappa * q4 * q2 * q * u32 * u32;
  return d;
}

State integrate(const Real& q_end, int n, const Real& kappa, const Real& beta) {
  State x{0, 1, 1, 0, 0, 0};
  const Real h = q_end / n;
  auto axpy = [](const State& x, const Real& c, const State& k) {
    State y;
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = x[i] + c * k[i];
    return y;
  };
  for (int i = 0; i < n; ++i) {
    const Real q = h * i;
    const State k1 = rhs(q, x, kappa, beta);
    const State k2 = rhs(q + h / 2, axpy(x, h / 2, k1), kappa, beta);
    const State k3 = rhs(q + h / 2, axpy(x, h / 2, k2), kappa, beta);
    const State k4 = rhs(q + h, axpy(x, h, k3), kappa, beta);
    for (std::size_t j = 0; j < x.size(); ++j)
      x[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return x;
}

}  // namespace

OnsetSeriesState onset_reference_state(double kappa, double beta, double tau, int steps) {
  const Real K(kappa), B(beta), q_end = sqrt(Real(tau));
  const State coarse = integrate(q_end, steps, K, B), fine = integrate(q_end, 2 * steps, K, B);
  State x;
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = fine[j] + (fine[j] - coarse[j]) / 15;
  OnsetSeriesState s;
  s.tau = tau;
  s.a = static_cast<double>(x[A]);
  s.w = static_cast<double>(x[W]);
  s.z = static_cast<double>(x[U] * Real(tau));
  s.J = static_cast<double>(x[J]);
  s.Wa = static_cast<double>(x[WA]);
  s.Wv = static_cast<double>(x[WV]);
  return s;
}

}  // namespace ivv::verification
