#include "solver/driver/onset_series.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "solver/driver/onset_series_coefficients.h"

namespace ivv {
namespace {

using onset_series::kDegree;

// sum_{a + b <= kDegree} c[a][b] p^a r^b, by Horner in r inside Horner in p.
double evaluate(const double (&c)[kDegree + 1][kDegree + 1], double p, double r) {
  double sum = 0;
  for (int a = kDegree; a >= 0; --a) {
    double row = 0;
    for (int b = kDegree - a; b >= 0; --b) row = row * r + c[a][b];
    sum = sum * p + row;
  }
  return sum;
}

// The series' motion at tau (tau, J, w, a, z of OnsetSeriesState; the works not yet) and its
// arguments p, r: what Newton's method in onset_series_at_z reads, without the dashpot work's
// series, a third of the cost of a state.
struct Motion {
  OnsetSeriesState s;
  double p = 0, r = 0;
};
Motion motion(double kappa, double beta, double tau) {
  const double sqrt_tau = std::sqrt(tau);
  Motion m;
  m.r = kappa * tau * tau * sqrt_tau;   // kappa tau^{5/2}
  m.p = beta * kappa * tau * sqrt_tau;  // beta kappa tau^{3/2}
  OnsetSeriesState& s = m.s;
  s.tau = tau;
  s.J = m.r * evaluate(onset_series::kImpulse, m.p, m.r);
  s.w = 1 - s.J;
  s.a = tau - tau * m.r * evaluate(onset_series::kImpulseIntegral, m.p, m.r);
  s.z = s.a - beta * s.J;
  return m;
}
// The state of the motion m, with the works.
OnsetSeriesState with_works(const Motion& m) {
  OnsetSeriesState s = m.s;
  s.Wa = s.J - 0.5 * s.J * s.J;
  s.Wv = m.p * m.r * evaluate(onset_series::kDashpotWork, m.p, m.r);
  return s;
}

}  // namespace

OnsetSeriesState onset_series_state(double kappa, double beta, double tau) {
  return with_works(motion(kappa, beta, tau));
}

double onset_series_error_bound(double kappa, double beta, double tau) {
  const double sqrt_tau = std::sqrt(tau);
  const double s = std::max(kappa * tau * tau * sqrt_tau, beta * kappa * tau * sqrt_tau);
  return onset_series::kErrorConstant * std::pow(s, kDegree + 1);
}

double onset_series_dashpot_work_error_bound(double kappa, double beta, double tau) {
  return onset_series_error_bound(kappa, beta, tau) * onset_series::kDashpotWorkErrorConstant /
         onset_series::kErrorConstant;
}

double onset_series_reach(double kappa, double beta, double tolerance) {
  // max(p, r) <= s_max  <=>  tau <= (s_max/kappa)^{2/5} and tau <= (s_max/(beta kappa))^{2/3}
  // s_max depends on the tolerance alone, the same for every impact of a sweep, and kappa on
  // the scene and v0 alone (not on the damping): the last of each is kept per thread with its
  // power, so a sweep over zeta at one v0 takes one pow an impact instead of three (the same
  // numbers: a pure function of its arguments, whatever the order of the impacts)
  thread_local double last_tolerance = 0.0, last_s_max = 0.0;
  constexpr double none = std::numeric_limits<double>::quiet_NaN();  // equal to no kappa
  thread_local double last_kappa = none, last_kappa_tau = 0.0;
  if (tolerance != last_tolerance) {
    last_s_max = std::pow(tolerance / onset_series::kErrorConstant, 1.0 / (kDegree + 1));
    last_tolerance = tolerance;
    last_kappa = none;  // its power was for the old s_max
  }
  const double s_max = last_s_max;
  if (!(kappa == last_kappa)) {
    last_kappa_tau = std::pow(s_max / kappa, 0.4);
    last_kappa = kappa;
  }
  double tau = last_kappa_tau;
  if (beta > 0) {  // x^{2/3} as cbrt(x)^2, half a pow's cost (each impact's beta is its own)
    const double root = std::cbrt(s_max / (beta * kappa));
    tau = std::min(tau, root * root);
  }
  return tau;
}

std::optional<OnsetSeriesState> onset_series_at_z(double kappa, double beta, double z_target,
                                                  double reach) {
  if (!(z_target > 0 && z_target < reach && kappa > 0 && beta >= 0)) return std::nullopt;
  constexpr double ulps = 4 * std::numeric_limits<double>::epsilon();
  const double leading = kappa * z_target * std::sqrt(z_target);
  double tau = z_target * (1 + leading * (0.4 * beta + (4.0 / 35.0) * z_target));
  for (int k = 0; k < kOnsetNewtonIterations; ++k) {
    if (!(tau > 0 && tau <= reach)) return std::nullopt;
    const Motion m = motion(kappa, beta, tau);
    const OnsetSeriesState& S = m.s;
    const double slope = S.w - beta * kappa * S.z * std::sqrt(S.z);
    if (!(slope > 0)) return std::nullopt;
    const double step = (S.z - z_target) / slope;
    if (std::abs(step) <= ulps * tau && S.z >= z_target) return with_works(m);
    // short of the target by less than Newton's step can resolve: one ulp up
    tau = step < 0 && tau - step == tau ? std::nextafter(tau, reach) : tau - step;
  }
  return std::nullopt;
}

}  // namespace ivv
