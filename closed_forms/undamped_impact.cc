#include "closed_forms/undamped_impact.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>

namespace ivv::closed_forms {
namespace {

// (4/5) B(2/5, 1/2) z_H / v0 is the Hertz contact time; this is its half up to u = (z/z_H)^{5/2}:
// t(z) = (z_H/v0)(2/5) B(u; 2/5, 1/2) (incomplete beta, not normalised).
double hertz_time_to(double z_H, double v0, double u) {
  // in double (Boost's default promotes to long double: 3x the cost for digits not needed)
  using namespace boost::math::policies;
  return z_H / v0 * 0.4 *
         boost::math::beta(0.4, 0.5, std::min(u, 1.0), make_policy(promote_double<false>()));
}

// hertz_time_to(z_H, v0, u) written with x = 1 - u: (z_H/v0)(2/5)[B(2/5, 1/2) - B(x; 1/2, 2/5)],
// accurate when u is within rounding of 1 (x given without the cancellation of 1 - u).
double hertz_time_beyond_yield_complement(double z_H, double v0, double x) {
  using namespace boost::math::policies;
  const auto policy = make_policy(promote_double<false>());
  return z_H / v0 * 0.4 *
         (boost::math::beta(0.4, 0.5, policy) -
          boost::math::beta(0.5, 0.4, std::clamp(x, 0.0, 1.0), policy));
}

}  // namespace

double hertz_z_max(double m, double K_h, double v0) {
  return std::pow(1.25 * m * v0 * v0 / K_h, 0.4);
}

UndampedImpact undamped_hertz(double m, double K_h, double v0) {
  UndampedImpact r;
  r.E0 = 0.5 * m * v0 * v0;
  r.z_max = hertz_z_max(m, K_h, v0);
  r.F_max = K_h * r.z_max * std::sqrt(r.z_max);
  r.t_max = hertz_time_to(r.z_max, v0, 1.0);
  r.t_contact = 2.0 * r.t_max;
  return r;
}

// Undamped elastoplastic impact by energy; with `times`, t_max and t_contact too (tolerance
// times->rtol relative for the unloading quadrature).
UndampedImpact undamped_elastoplastic(double m, double K_h, double z_y, double v0,
                                      std::optional<TimesQuadrature> times) {
  const double E0 = 0.5 * m * v0 * v0;
  const double sqrt_zy = std::sqrt(z_y);
  const double F_y = K_h * z_y * sqrt_zy;
  const double E_y = 0.4 * F_y * z_y;
  if (E0 <= E_y) return undamped_hertz(m, K_h, v0);
  UndampedImpact r;
  r.yielded = true;
  r.E0 = E0;
  const double K_y = 1.5 * K_h * sqrt_zy;
  const double d = 2.0 * (E0 - E_y) / (F_y + std::sqrt(F_y * F_y + 2.0 * K_y * (E0 - E_y)));
  r.z_max = z_y + d;
  r.F_max = K_y * d + F_y;
  const double a = std::sqrt(r.z_max), b = sqrt_zy;
  const double zf15 = d * d * (a + 0.5 * b) / ((a + b) * (a + b));  // z_f^{3/2}, no cancellation
  r.z_perm = std::pow(std::cbrt(zf15), 2.0);
  const double A = a, B = std::sqrt(r.z_perm), t = B / A;
  const double AmB = (r.F_max / K_h) / (A * A + A * B + B * B);
  const double W_u = K_h * A * A * A * AmB * AmB * (((3.0 * t + 6.0) * t + 4.0) * t + 2.0) / 5.0;
  r.e = std::sqrt(W_u / E0);
  r.W_p = E0 - W_u;
  if (!times) return r;
  const double tol = times->rtol;
  // loading: elastic leg 0 -> z_y (incomplete beta), plastic leg z_y -> z_m (harmonic).
  // Just above yield both legs are ill-conditioned (the impactor crosses z_y at the speed
  // sqrt(v0^2 - v_y^2) -> 0: the elastic leg's time falls, and the plastic leg's grows, by
  // m sqrt(2 (E0 - E_y)/m)/F_y), but their sum is not. Both are computed from the same rounded
  // E0 - E_y so that those terms cancel: the elastic leg as the Hertz half-time less the part
  // beyond u_y = E_y/E0 = (z_y/z_H)^{5/2}, B(u; 2/5, 1/2) = B(2/5, 1/2) - B(1 - u; 1/2, 2/5)
  // with 1 - u_y = (E0 - E_y)/E0. (Evaluating u_y on its own put t_F_max 1.3e-8 and t_f 6.7e-9
  // off mp50 at v0 = 0.13085169358677584 m/s on the paper scene, against a stated rtol/10.)
  const double z_H = hertz_z_max(m, K_h, v0);
  // (far above yield, u_y -> 0, the direct form avoids the opposite cancellation)
  const double x_y = (E0 - E_y) / E0;
  const double t_elastic = x_y < 0.5 ? hertz_time_beyond_yield_complement(z_H, v0, x_y)
                                     : hertz_time_to(z_H, v0, E_y / E0);
  const double t_plastic =
      2.0 * std::sqrt(m / K_y) * std::asin(std::sqrt(K_y * d / (2.0 * r.F_max)));
  r.t_max = t_elastic + t_plastic;
  // unloading z_m -> z_f on F = K_h (z^{3/2} - z_f^{3/2}): v^2 = (2 K_h/m)[(2/5)(z_m^{5/2} -
  // z^{5/2}) - z_f^{3/2} (z_m - z)]; with z = z_m - s^2, dt = 2 ds / sqrt(v^2/s^2) and
  // z_m^{5/2} - z^{5/2} = s^2 (A^4 + A^3 c + A^2 c^2 + A c^3 + c^4)/(A + c), c = sqrt(z).
  const double S = std::sqrt(r.z_max - r.z_perm);
  const double k2 = 2.0 * K_h / m;
  auto integrand = [&](double s) {
    const double c = std::sqrt(std::max(0.0, r.z_max - s * s));
    const double p4 = (((A + c) * A + c * c) * A + c * c * c) * A + c * c * c * c;
    const double q = k2 * (0.4 * p4 / (A + c) - zf15);
    return 2.0 / std::sqrt(q);
  };
  using boost::math::quadrature::gauss;
  const double g20 = gauss<double, 20>::integrate(integrand, 0.0, S);
  const double g30 = gauss<double, 30>::integrate(integrand, 0.0, S);
  double t_unload = g30, err = std::abs(g30 - g20);
  if (!(err <= 0.1 * tol * (r.t_max + g30))) {
    double e_gk = 0.0;
    t_unload = boost::math::quadrature::gauss_kronrod<double, 31>::integrate(integrand, 0.0, S, 15,
                                                                             0.01 * tol, &e_gk);
    err = e_gk;
  }
  r.t_contact = r.t_max + t_unload;
  r.t_error = err;
  return r;
}

}  // namespace ivv::closed_forms
