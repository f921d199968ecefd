#include "oracles/undamped_elastoplastic.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scene/input_error.h"

namespace ivv::oracles {

namespace {

// Relative tolerance asked of each quadrature: the integrands are smooth after the
// substitutions, so QAGS reaches a few ulps above round-off.
constexpr double kQuadratureRelTol = 1e-12;
constexpr std::size_t kQuadratureIntervals = 200;

struct Quadrature {
  double value = 0.0;
  double abserr = 0.0;
};

// GSL's default handler aborts the process; the status is checked instead. Turned off once,
// process-wide, the first time a quadrature runs.
void disable_gsl_abort() {
  static const bool once = [] {
    gsl_set_error_handler_off();
    return true;
  }();
  (void)once;
}

template <class F>
Quadrature integrate(const char* leg, F f, double lo, double hi) {
  disable_gsl_abort();
  struct Deleter {
    void operator()(gsl_integration_workspace* w) const { gsl_integration_workspace_free(w); }
  };
  std::unique_ptr<gsl_integration_workspace, Deleter> ws(
      gsl_integration_workspace_alloc(kQuadratureIntervals));
  gsl_function gf;
  gf.function = [](double x, void* p) -> double { return (*static_cast<F*>(p))(x); };
  gf.params = &f;
  Quadrature q;
  const int status = gsl_integration_qags(&gf, lo, hi, 0.0, kQuadratureRelTol, kQuadratureIntervals,
                                          ws.get(), &q.value, &q.abserr);
  if (status != GSL_SUCCESS) {
    std::ostringstream os;
    os << "undamped elastoplastic oracle: quadrature of the " << leg
       << " leg failed: " << gsl_strerror(status) << " (estimate " << q.value << " s, error "
       << q.abserr << " s)";
    throw std::runtime_error(os.str());
  }
  return q;
}

// z_top^{5/2} - (z_top - u^2)^{5/2}, without cancellation for small u.
double drop_52(double z_top, double u) {
  return -std::pow(z_top, 2.5) * std::expm1(2.5 * std::log1p(-(u * u) / z_top));
}

// Time of the elastic leg 0 -> z_top with kinetic energy delta_E left at z_top:
// (1/2) m v^2 = delta_E + (2/5) K_h (z_top^{5/2} - z^{5/2}), z = z_top - u^2, dt = 2u du/v.
// Near u = 0, (2/5) K_h (z_top^{5/2} - z^{5/2}) ~ F_top u^2 (F_top = K_h z_top^{3/2}), so with
// delta_E > 0 the integrand 2u/v rises from 0 to its plateau over u ~ u_s = sqrt(delta_E/F_top),
// which just above yield is a sliver of [0, sqrt(z_top)] that Gauss-Kronrod rules step over
// with a falsely small error estimate. u = u_s sinh(sigma) stretches that sliver to
// sigma ~ 1: dt = 2 u u_s cosh(sigma) dsigma / v, smooth in sigma.
Quadrature elastic_leg_time(double mass, double K_h, double z_top, double delta_E) {
  const double u_end = std::sqrt(z_top);
  if (delta_E == 0.0) {
    const double limit = 2.0 / std::sqrt(2.0 / mass * K_h * z_top * std::sqrt(z_top));
    auto integrand = [=](double u) {
      if (u == 0.0) return limit;
      return 2.0 * u / std::sqrt(2.0 / mass * 0.4 * K_h * drop_52(z_top, u));
    };
    return integrate("elastic loading", integrand, 0.0, u_end);
  }
  const double u_s = std::sqrt(delta_E / (K_h * z_top * std::sqrt(z_top)));
  auto integrand = [=](double sigma) {
    const double u = u_s * std::sinh(sigma);
    const double kinetic = delta_E + 0.4 * K_h * drop_52(z_top, u);
    return 2.0 * u * u_s * std::cosh(sigma) / std::sqrt(2.0 / mass * kinetic);
  };
  return integrate("elastic loading", integrand, 0.0, std::asinh(u_end / u_s));
}

// Time of the unloading leg z_m -> z_f: (1/2) m v^2 = K_h u^2 G(u) with z = z_m - u^2,
// G(u) = (2/5)(z_m^{5/2} - z^{5/2})/u^2 - z_f^{3/2}  ->  F_m/K_h as u -> 0; dt = 2 du/sqrt(...).
Quadrature unloading_leg_time(double mass, double K_h, double z_m, double z_f, double F_m) {
  const double zf32 = z_f * std::sqrt(z_f);
  auto integrand = [=](double u) {
    const double G = (u == 0.0) ? F_m / K_h : 0.4 * drop_52(z_m, u) / (u * u) - zf32;
    return 2.0 / std::sqrt(2.0 * K_h / mass * G);
  };
  return integrate("unloading", integrand, 0.0, std::sqrt(z_m - z_f));
}

}  // namespace

ElastoplasticInput elastoplastic_input(const Scene& scene, const DerivedParameters& p) {
  return {p.effective_mass, p.K_h, p.z_y, scene.velocity};
}

ElastoplasticImpact solve_undamped_elastoplastic(const ElastoplasticInput& in) {
  require_positive("mass", in.mass);
  require_positive("K_h", in.K_h);
  require_positive("z_y", in.z_y);
  require_positive("v0", in.v0);
  const double m = in.mass;
  const double K_h = in.K_h;
  const double z_y = in.z_y;
  const double b = std::sqrt(z_y);
  const double K_y = 1.5 * K_h * b;
  const double F_y = K_h * z_y * b;

  ElastoplasticImpact r;
  r.energy_initial = 0.5 * m * in.v0 * in.v0;
  r.energy_yield = 0.4 * K_h * z_y * z_y * b;
  r.v_yield = std::sqrt(2.0 * r.energy_yield / m);

  if (r.energy_initial <= r.energy_yield) {
    r.yielded = false;
    r.z_max = std::pow(1.25 * m * in.v0 * in.v0 / K_h, 0.4);
    r.F_max = K_h * r.z_max * std::sqrt(r.z_max);
    r.z_perm = 0.0;
    r.e = 1.0;
    r.W_u = r.energy_initial;
    r.W_p = 0.0;
    const Quadrature leg = elastic_leg_time(m, K_h, r.z_max, 0.0);
    r.t_max = leg.value;
    r.t_contact = 2.0 * leg.value;
    r.t_error = 2.0 * leg.abserr;
    return r;
  }

  r.yielded = true;
  const double delta_E = r.energy_initial - r.energy_yield;
  const double d = 2.0 * delta_E / (F_y + std::sqrt(F_y * F_y + 2.0 * K_y * delta_E));
  r.z_max = z_y + d;
  r.F_max = K_y * d + F_y;
  const double a = std::sqrt(r.z_max);
  const double zf32 = d * d * (a + 0.5 * b) / ((a + b) * (a + b));  // z_f^{3/2}
  r.z_perm = std::cbrt(zf32 * zf32);
  const double A = a;
  const double B = std::sqrt(r.z_perm);
  const double t = B / A;
  const double A_minus_B = (r.F_max / K_h) / (A * A + A * B + B * B);
  r.W_u = K_h * A * A * A * A_minus_B * A_minus_B * (((3.0 * t + 6.0) * t + 4.0) * t + 2.0) / 5.0;
  const double loading_work = r.energy_yield + F_y * d + 0.5 * K_y * d * d;
  r.W_p = loading_work - r.W_u;
  r.e = std::sqrt(r.W_u / r.energy_initial);

  const Quadrature elastic = elastic_leg_time(m, K_h, z_y, delta_E);
  const double t_plastic =
      2.0 * std::sqrt(m / K_y) * std::asin(std::sqrt(K_y * d / (2.0 * r.F_max)));
  const Quadrature unloading = unloading_leg_time(m, K_h, r.z_max, r.z_perm, r.F_max);
  r.t_max = elastic.value + t_plastic;
  r.t_contact = r.t_max + unloading.value;
  r.t_error = elastic.abserr + unloading.abserr;
  return r;
}

}  // namespace ivv::oracles
