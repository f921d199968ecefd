#include "oracles/zener.h"

#include <algorithm>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

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

namespace {

using mp50 = boost::multiprecision::cpp_bin_float_50;

template <class T>
struct TaylorRun {
  T e, contact_time, peak_force;
  long steps = 0;
};

// The series of r, u, tau about the current point to order n (docs in zener.h).
template <class T>
struct Series {
  std::vector<T> r, u, tau;
  explicit Series(int n) : r(n + 1), u(n + 1), tau(n + 1) {}
};

template <class T>
void expand(Series<T>& c, const T& lambda, std::vector<T>& q2, std::vector<T>& q3,
            std::vector<T>& q4) {
  const int n = static_cast<int>(c.r.size()) - 1;
  for (int k = 0; k < n; ++k) {
    T s2 = 0, s3 = 0, s4 = 0;
    for (int j = 0; j <= k; ++j) s2 += c.r[j] * c.r[k - j];
    q2[k] = s2;
    for (int j = 0; j <= k; ++j) {
      s3 += q2[j] * c.r[k - j];
      s4 += q2[j] * q2[k - j];
    }
    q3[k] = s3;
    q4[k] = s4;
    c.r[k + 1] = (c.u[k] - lambda * q3[k]) / (k + 1);
    c.u[k + 1] = -2 * q4[k] / (k + 1);
    c.tau[k + 1] = 2 * c.r[k] / (k + 1);
  }
}

// sum_k a_k h^k and its derivative (Horner)
template <class T>
T value(const std::vector<T>& a, const T& h) {
  T v = 0;
  for (std::size_t k = a.size(); k-- > 0;) v = v * h + a[k];
  return v;
}
template <class T>
T slope(const std::vector<T>& a, const T& h) {
  T v = 0;
  for (std::size_t k = a.size(); k-- > 1;) v = v * h + a[k] * static_cast<int>(k);
  return v;
}
template <class T>
std::vector<T> derivative(const std::vector<T>& a) {
  std::vector<T> d(a.size() - 1);
  for (std::size_t k = 1; k < a.size(); ++k) d[k - 1] = a[k] * static_cast<int>(k);
  return d;
}

// The root of the polynomial a in (0, h], where a(0) > 0 >= a(h): Newton steps kept inside
// the bracket (bisection when a step leaves it), to a relative width eps.
template <class T>
T root_in_step(const std::vector<T>& a, T h, const T& eps) {
  using std::abs;
  T lo = 0, hi = h, x = h / 2;
  for (int it = 0; it < 400; ++it) {
    const T f = value(a, x);
    if (f > 0)
      lo = x;
    else
      hi = x;
    const T d = slope(a, x);
    T next = d != 0 ? T(x - f / d) : T((lo + hi) / 2);
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (abs(next - x) <= eps * h) return next;
    x = next;
  }
  return x;
}

template <class T>
T step_size(const Series<T>& c, const T& eps) {
  using std::abs;
  using std::pow;
  const int n = static_cast<int>(c.r.size()) - 1;
  T h = -1;
  for (int j : {n - 1, n}) {
    const T norm = std::max({T(abs(c.r[j])), T(abs(c.u[j])), T(abs(c.tau[j]))});
    if (norm == 0) continue;
    const T hj = pow(eps / norm, T(1) / j);
    if (h < 0 || hj < h) h = hj;
  }
  return h < 0 ? T(1) : h;
}

template <class T>
TaylorRun<T> integrate(const T& lambda, int order, const T& eps) {
  constexpr long kMaxSteps = 1000000;  // separation is certain (zener.h); this only guards
  Series<T> c(order);
  std::vector<T> q2(order), q3(order), q4(order);
  T r = 0, u = 1, tau = 0;
  TaylorRun<T> out;
  for (out.steps = 1; out.steps <= kMaxSteps; ++out.steps) {
    c.r[0] = r;
    c.u[0] = u;
    c.tau[0] = tau;
    expand(c, lambda, q2, q3, q4);
    T h = step_size(c, eps);
    const std::vector<T> dr = derivative(c.r);
    // maximum compression: dr/ds falls through zero in this step
    if (value(dr, T(0)) > 0 && value(dr, h) <= 0) {
      const T peak_r = value(c.r, root_in_step(dr, h, eps));
      out.peak_force = peak_r * peak_r * peak_r;
    }
    // end of contact: r returns to zero (never at the start, where r = 0 and dr/ds = 1)
    if (r > 0 && value(c.r, h) <= 0) {
      const T s = root_in_step(c.r, h, eps);
      out.e = -value(c.u, s);
      out.contact_time = value(c.tau, s);
      return out;
    }
    r = value(c.r, h);
    u = value(c.u, h);
    tau = value(c.tau, h);
  }
  throw std::runtime_error("Zener's problem at lambda = " + std::to_string(double(lambda)) +
                           ": no end of contact within " + std::to_string(kMaxSteps) +
                           " Taylor steps");
}

void check_lambda(double lambda) {
  if (!std::isfinite(lambda) || lambda < 0.0)
    throw std::invalid_argument("Zener's lambda must be finite and >= 0, got " +
                                std::to_string(lambda));
}

}  // namespace

ZenerImpact zener_impact(double lambda) {
  check_lambda(lambda);
  constexpr int kOrder = 30;
  const mp50 lam(lambda);
  const TaylorRun<mp50> fine = integrate(lam, kOrder, mp50("1e-40"));
  const TaylorRun<mp50> coarse = integrate(lam, kOrder, mp50("1e-30"));
  using boost::multiprecision::abs;
  const mp50 diff =
      std::max({mp50(abs(fine.e - coarse.e)), mp50(abs(fine.contact_time - coarse.contact_time)),
                mp50(abs(fine.peak_force - coarse.peak_force))});
  constexpr double kDoubleRounding = 2.2e-16;  // one unit in the last place of a number of order 1
  ZenerImpact z;
  z.lambda = lambda;
  z.e = static_cast<double>(fine.e);
  z.contact_time = static_cast<double>(fine.contact_time);
  z.peak_force = static_cast<double>(fine.peak_force);
  z.error = static_cast<double>(diff) + kDoubleRounding;
  z.steps = fine.steps;
  return z;
}

}  // namespace ivv::oracles
