#include "solver/model_choice.h"

#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "oracles/hunt_crossley.h"
#include "oracles/linear_model.h"
#include "solver/consistency.h"
#include "solver/integrator_choice.h"
#include "solver/laws/hunt_crossley.h"

namespace ivv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fmt(double v) {
  std::ostringstream os;
  os.precision(3);
  os << v;
  return os.str();
}

double rel(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

// ---- closed forms of the undamped impact (SPEC §2), SI units -------------------------------

struct UndampedImpact {
  bool yielded = false;
  double z_max = 0.0, F_max = 0.0, z_perm = 0.0, e = 1.0;
  double E0 = 0.0, W_p = 0.0;             // [J]
  double t_max = kNaN, t_contact = kNaN;  // [s] (NaN: not computed)
  double t_error = 0.0;                   // quadrature error estimate [s]
};

// (4/5) B(2/5, 1/2) z_H / v0 is the Hertz contact time; this is its half up to u = (z/z_H)^{5/2}:
// t(z) = (z_H/v0)(2/5) B(u; 2/5, 1/2) (incomplete beta, not normalised).
double hertz_time_to(double z_H, double v0, double u) {
  // in double (Boost's default promotes to long double: 3x the cost for digits not needed)
  using namespace boost::math::policies;
  return z_H / v0 * 0.4 *
         boost::math::beta(0.4, 0.5, std::min(u, 1.0), make_policy(promote_double<false>()));
}

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
// `tol` relative for the unloading quadrature).
UndampedImpact undamped_elastoplastic(double m, double K_h, double z_y, double v0, bool times,
                                      double tol) {
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
  // loading: elastic leg 0 -> z_y (incomplete beta), plastic leg z_y -> z_m (harmonic)
  const double z_H = hertz_z_max(m, K_h, v0);
  const double u_y = std::pow(z_y / z_H, 2.5);
  const double t_elastic = hertz_time_to(z_H, v0, u_y);
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

// The ImpactResult of an undamped closed form (routes 1 and 2).
ImpactResult undamped_result(const Scene& scene, const DerivedParameters& p,
                             const UndampedImpact& u) {
  ImpactResult r;
  const double v0 = scene.velocity, m = p.effective_mass;
  r.status = ImpactStatus::separated;
  r.e = r.e_poisson = r.e_energetic = u.e;
  r.F_max = u.F_max;
  r.t_F_max = r.t_z_max = r.t_alpha_max = u.t_max;
  r.z_max = r.alpha_max = u.z_max;
  r.z_perm = u.z_perm;
  r.y_final = 0.0;
  r.t_contact = u.t_contact;
  r.rebound_velocity = -u.e * v0;
  const BodyVelocities bodies = body_velocities_after(scene, r.rebound_velocity);
  r.impactor_velocity_after = bodies.impactor;
  r.target_velocity_after = bodies.target;
  r.impulse = m * v0 * (1.0 + u.e);
  r.impulse_compression = m * v0;
  r.energy.initial = u.E0;
  r.energy.final = u.E0 * u.e * u.e;
  r.energy.plastic = u.W_p;
  r.energy.residual = r.energy.initial - r.energy.final - r.energy.plastic;
  r.events = {{EventKind::onset, 0.0, 0.0, 0.0, 0.0},
              {EventKind::max_compression, u.t_max, u.z_max, u.z_max, u.F_max},
              {EventKind::max_displacement, u.t_max, u.z_max, u.z_max, u.F_max},
              {EventKind::separation, u.t_contact, u.z_perm, u.z_perm, 0.0}};
  return r;
}

// The ImpactResult of the linearized model's closed form (route 4, and the linearized law).
ImpactResult linear_result(const Scene& scene, const DerivedParameters& p,
                           const oracles::LinearModelInput& in, const oracles::LinearImpact& L) {
  ImpactResult r;
  const double v0 = scene.velocity, m = p.effective_mass;
  r.status = L.captured ? ImpactStatus::captured : ImpactStatus::separated;
  r.e = r.e_poisson = r.e_energetic = L.e;
  r.F_max = L.F_max;
  r.t_F_max = r.t_z_max = L.t_max;
  r.z_max = L.z_max;
  r.alpha_max = L.alpha_max;
  r.t_alpha_max = L.t_alpha_max;  // +inf when captured (the limit is approached, not reached)
  r.z_perm = L.z_perm;
  r.y_final = L.y_final;
  r.t_contact = L.t_contact;  // +inf when captured
  r.rebound_velocity = -L.e * v0;
  const BodyVelocities bodies = body_velocities_after(scene, r.rebound_velocity);
  r.impactor_velocity_after = bodies.impactor;
  r.target_velocity_after = bodies.target;
  r.impulse = L.impulse;
  r.impulse_compression = m * v0;  // momentum: all of m v0 is taken up by alpha' = 0
  r.energy.initial = L.energy_initial;
  r.energy.final = L.energy_final;
  r.energy.plastic = L.W_p;
  r.energy.viscous = L.W_v;
  r.energy.residual = r.energy.initial - r.energy.final - r.energy.plastic - r.energy.viscous;
  auto event = [&](EventKind kind, double t) {
    const oracles::LinearState s = oracles::linear_model_state(in, L, t);
    return ImpactEvent{kind, t, s.z, s.alpha, std::max(0.0, s.F)};
  };
  r.events.push_back({EventKind::onset, 0.0, 0.0, 0.0, 0.0});
  r.events.push_back(event(EventKind::max_compression, L.t_max));
  if (!L.captured) {
    r.events.push_back(event(EventKind::max_displacement, L.t_alpha_max));
    r.events.push_back(event(EventKind::separation, L.t_contact));
  }
  return r;
}

// The consistency check of consistency.h on a closed-form result, counted as one step.
void check_closed_form(ImpactResult& r, const Scene& scene, const DerivedParameters& p,
                       const IntegratorOptions& opt, std::string_view what) {
  ConsistencyMeasures c;
  const double mv2 = p.effective_mass * scene.velocity * scene.velocity;
  c.has_restitution = r.separated();
  c.e = r.e;
  c.e_poisson = r.e_poisson;
  c.e_energetic_sq = r.e_energetic * r.e_energetic;
  c.ledger_residual = r.energy.residual / mv2;
  c.steps = c.restitution_steps = 1;
  const std::string why = consistency_failure(c, opt, what);
  if (!why.empty()) {
    r.status = ImpactStatus::failed;
    r.failure = FailureKind::integrator;
    r.reason = why;
  }
}

double integrator_error_factor(IntegratorKind k) {
  return traits(k).implicit ? kAutoErrorFactorImplicit : kAutoErrorFactorExplicit;
}

double integrated_estimate(IntegratorKind k, const IntegratorOptions& opt) {
  if (traits(k).fixed_step) {
    const double h = opt.fixed_dt();
    return h * h * h * h;  // C h^4 with C = O(1) in tau (integrator_options.h)
  }
  if (k == IntegratorKind::mp50) return opt.reference_tolerance;
  return integrator_error_factor(k) * opt.rtol;
}

struct LinearEstimate {
  double D0 = -1.0;  // < 0: not estimated (pre-screen failed or undefined)
  double estimate = kInf;
  double zeta_unload = kNaN;
  bool defined = false;
};

// Route 4's estimate: exact undamped difference of the two laws, grown with zeta.
LinearEstimate linear_estimate(const Scene& scene, const DerivedParameters& p, double rtol) {
  LinearEstimate out;
  const double m = p.effective_mass, v0 = scene.velocity;
  const double growth = kLinearSafety * (1.0 + kLinearZetaGrowth * p.zeta);
  // pre-screen without any closed form (kLinearDifferenceFloor), then on e alone (no
  // quadrature, no linear solve): e_lin = gamma (eq 20) undamped
  if (!(p.v_yield > 0) || growth * kLinearDifferenceFloor / std::sqrt(v0 / p.v_yield) > rtol)
    return out;
  const UndampedImpact nl = undamped_elastoplastic(m, p.K_h, p.z_y, v0, false, rtol);
  if (!nl.yielded) return out;
  try {  // eq 20 and the linear model throw below z_m = 2.25 z_y, where the law is undefined
    const double g2 = oracles::linear_gamma_squared_eq20(m, p.K_h, p.K_y, v0);
    if (!(g2 > 0) || !(growth * rel(std::sqrt(g2), nl.e) <= rtol)) return out;
    const oracles::LinearImpact lin0 = oracles::solve_linear_model({m, p.K_h, p.K_y, 0.0, v0});
    const UndampedImpact nlt = undamped_elastoplastic(m, p.K_h, p.z_y, v0, true, rtol);
    out.D0 = std::max({rel(lin0.e, nlt.e), rel(lin0.z_max, nlt.z_max), rel(lin0.F_max, nlt.F_max),
                       rel(lin0.t_contact, nlt.t_contact)});
    const oracles::LinearImpact lin =
        oracles::solve_linear_model(oracles::linear_model_input(scene, p));
    out.zeta_unload = lin.zeta_unload;
    out.defined = true;
    out.estimate = growth * out.D0;
  } catch (const oracles::LinearizedLawUndefined&) {
    out.defined = false;
  }
  return out;
}

}  // namespace

std::string_view to_string(ModelRoute r) {
  switch (r) {
    case ModelRoute::closed_form_elastoplastic:
      return "closed-form-elastoplastic";
    case ModelRoute::closed_form_hertz:
      return "closed-form-hertz";
    case ModelRoute::hunt_crossley_lambert_w:
      return "hunt-crossley-lambert-w";
    case ModelRoute::linearized_closed_form:
      return "linearized-closed-form";
    case ModelRoute::integrated:
      return "integrated";
  }
  return "integrated";
}

ModelDecision decide_model(const ValidatedRequest& v, bool trajectory_wanted) {
  const SimulationRequest& req = v.request();
  const DerivedParameters& p = v.derived();
  ModelDecision d;
  d.integrator = effective_integrator(v);
  d.estimated_error = integrated_estimate(d.integrator, req.options);
  if (trajectory_wanted || req.law == LawKind::expression) return d;
  if (req.law == LawKind::elastoplastic && !p.has_dashpot()) {
    d.route = ModelRoute::closed_form_elastoplastic;
    d.estimated_error = kEstimateClosedForm;
  } else if (req.law == LawKind::hertz && !p.has_dashpot()) {
    d.route = ModelRoute::closed_form_hertz;
    d.estimated_error = kEstimateClosedForm;
  } else if (req.law == LawKind::hunt_crossley) {
    d.route = ModelRoute::hunt_crossley_lambert_w;
  } else if (req.law == LawKind::linearized) {
    // its own closed form is exact for it; where the law is undefined the integrator says so
    try {
      oracles::solve_linear_model(oracles::linear_model_input(req.scene, p));
      d.route = ModelRoute::linearized_closed_form;
      d.estimated_error = kEstimateClosedForm;
    } catch (const oracles::LinearizedLawUndefined&) {
    }
  } else if (req.law == LawKind::elastoplastic) {
    const LinearEstimate lin = linear_estimate(req.scene, p, req.options.rtol);
    d.linear_difference = lin.D0;
    if (lin.defined && lin.zeta_unload <= kLinearMaxUnloadingDamping &&
        lin.estimate <= req.options.rtol) {
      d.route = ModelRoute::linearized_closed_form;
      d.estimated_error = lin.estimate;
    }
  }
  return d;
}

namespace {
// The run of one route (run_model adds the route's name to the result).
ImpactResult run_route(const ValidatedRequest& v, const ModelDecision& d,
                       std::vector<TrajectoryPoint>* trajectory) {
  const SimulationRequest& req = v.request();
  const DerivedParameters& p = v.derived();
  const Scene& s = req.scene;
  switch (d.route) {
    case ModelRoute::closed_form_elastoplastic: {
      ImpactResult r = undamped_result(s, p,
                                       undamped_elastoplastic(p.effective_mass, p.K_h, p.z_y,
                                                              s.velocity, true, req.options.rtol));
      check_closed_form(r, s, p, req.options, "closed-form elastoplastic");
      return r;
    }
    case ModelRoute::closed_form_hertz: {
      ImpactResult r = undamped_result(s, p, undamped_hertz(p.effective_mass, p.K_h, s.velocity));
      check_closed_form(r, s, p, req.options, "closed-form hertz");
      return r;
    }
    case ModelRoute::linearized_closed_form: {
      const oracles::LinearModelInput in = oracles::linear_model_input(s, p);
      ImpactResult r = linear_result(s, p, in, oracles::solve_linear_model(in));
      check_closed_form(r, s, p, req.options, "linearized closed form");
      return r;
    }
    case ModelRoute::hunt_crossley_lambert_w: {
      ImpactResult r = detail::simulate_full(v, d.integrator, trajectory);
      if (!r.separated()) return r;
      const HuntCrossleyLaw law = HuntCrossleyLaw::make(req.parameters, p);
      const double e = oracles::hunt_crossley_cor(law.mu * s.velocity);
      r.e = e;
      r.rebound_velocity = -e * s.velocity;
      const BodyVelocities bodies = body_velocities_after(s, r.rebound_velocity);
      r.impactor_velocity_after = bodies.impactor;
      r.target_velocity_after = bodies.target;
      r.energy.final = r.energy.initial * e * e;
      r.energy.residual =
          r.energy.initial - r.energy.final - r.energy.stored - r.energy.plastic - r.energy.viscous;
      return r;
    }
    case ModelRoute::integrated:
      break;
  }
  return detail::simulate_full(v, d.integrator, trajectory);
}
}  // namespace

ImpactResult run_model(const ValidatedRequest& v, const ModelDecision& d,
                       std::vector<TrajectoryPoint>* trajectory) {
  ImpactResult r = run_route(v, d, trajectory);
  r.route = to_string(d.route);
  return r;
}

namespace {
// The integrator's words: choose_integrator()'s reasons under --integrator auto, else the
// integrator requested.
void add_integrator_reasons(const SimulationRequest& req, const ModelDecision& d,
                            std::vector<std::string>& reasons) {
  if (req.auto_integrator)
    for (std::string& why : choose_integrator(req).reasons) reasons.push_back(std::move(why));
  else
    reasons.push_back("integrator " + std::string(to_string(d.integrator)) +
                      " as requested (--integrator)");
}

// Why route 5 integrates the full model, with the integrator's words and the capture criterion.
void add_integrated_reasons(const SimulationRequest& req, const DerivedParameters& p,
                            const ModelDecision& d, std::vector<std::string>& reasons) {
  const std::string law(to_string(req.law));
  if (req.law == LawKind::expression)
    reasons.push_back("an expression law has no closed form: integrated");
  else if (req.law == LawKind::elastoplastic) {
    std::string why = "elastoplastic with a dashpot: no exact closed form; ";
    if (d.linear_difference >= 0)
      why += "the linearized closed form's estimated error 2 (1 + 10 zeta) D0 = " +
             fmt(kLinearSafety * (1 + kLinearZetaGrowth * p.zeta) * d.linear_difference) +
             " (D0 = " + fmt(d.linear_difference) + ") exceeds rtol " + fmt(req.options.rtol) +
             " or its unloading is near capture";
    else
      why += "the linearized closed form is not within rtol " + fmt(req.options.rtol) +
             " (its undamped difference in e alone exceeds it) or is undefined here";
    reasons.push_back(why);
  } else if (req.law == LawKind::linearized) {
    reasons.push_back(
        "the linearized law is undefined here (z_m < 2.25 z_y): run so that "
        "the integrator names the failure");
  } else {
    reasons.push_back(law + " with a dashpot: no exact closed form; integrated");
  }
  add_integrator_reasons(req, d, reasons);
  reasons.push_back(
      "capture, if any, by the driver's criterion: the rebound still "
      "attainable from the remaining energy, sqrt(w^2 + 2U), below "
      "capture_cor = " +
      fmt(req.options.capture_cor));
  if (!req.auto_integrator)  // choose_integrator's reasons state it otherwise
    reasons.push_back("estimated relative error of e, F_max, t_f: " + fmt(d.estimated_error) +
                      " (the integrator's global error)");
}
}  // namespace

ModelChoice explain(const ValidatedRequest& v, const ModelDecision& d, const ImpactResult& r) {
  const SimulationRequest& req = v.request();
  const DerivedParameters& p = v.derived();
  ModelChoice c;
  c.decision = d;
  c.estimated_error = d.estimated_error;
  const std::string law(to_string(req.law));
  const std::string integrator(to_string(d.integrator));
  auto integrator_words = [&] { add_integrator_reasons(req, d, c.reasons); };
  switch (d.route) {
    case ModelRoute::closed_form_elastoplastic:
      c.law = "closed-form elastoplastic (energy)";
      c.integrator = "none";
      c.reasons.push_back(
          "elastoplastic law without a dashpot: z_m, F_max, z_f, e and the hysteresis work "
          "exactly by energy (SPEC §2); t_f in closed form on the loading legs and by "
          "Gauss-Legendre quadrature on the unloading leg; no integration");
      c.reasons.push_back(
          "events: onset, maximum compression (= maximum displacement) and separation; the "
          "yield event's time is not computed by the closed form (absent)");
      c.reasons.push_back("estimated relative error: round-off (" + fmt(kEstimateClosedForm) +
                          "); the contact time's quadrature within rtol/10");
      break;
    case ModelRoute::closed_form_hertz:
      c.law = "closed-form hertz (energy)";
      c.integrator = "none";
      c.reasons.push_back(
          "hertz law without a dashpot: z_m = (5 m v0^2/(4 K_h))^(2/5), F_max = K_h z_m^1.5, "
          "t_f = (4/5) B(2/5, 1/2) z_m/v0, e = 1 exactly (SPEC §2); no integration");
      c.reasons.push_back("estimated relative error: round-off (" + fmt(kEstimateClosedForm) + ")");
      break;
    case ModelRoute::hunt_crossley_lambert_w: {
      c.law = "hunt-crossley: e by Lambert W, the rest integrated";
      c.integrator = integrator;
      const double mu = HuntCrossleyLaw::make(req.parameters, p).mu;
      c.reasons.push_back(
          "hunt-crossley: e = [1 + W0(-(1 + u0) e^-(1 + u0))]/u0 exactly (u0 = mu v0 = " +
          fmt(mu * req.scene.velocity) +
          ", SPEC §2); F_max, t_f, z_max and the impulses have no closed form: integrated");
      integrator_words();
      if (r.separated())
        c.reasons.push_back("the integrated Poisson COR " + fmt(r.e_poisson) +
                            " against the exact e " + fmt(r.e) + ": difference " +
                            fmt(std::abs(r.e_poisson - r.e)));
      c.reasons.push_back("estimated relative error of F_max, t_f: the integrator's, " +
                          fmt(d.estimated_error) + "; e exact");
      break;
    }
    case ModelRoute::linearized_closed_form:
      c.law = "linearized closed form (paper eqs 22-25)";
      c.integrator = "none";
      if (req.law == LawKind::linearized) {
        c.reasons.push_back(
            "the linearized law has an exact closed form (paper eqs 22-25, "
            "oracles/linear_model.h); no integration");
      } else {
        c.reasons.push_back(
            "elastoplastic law with a dashpot at rtol " + fmt(req.options.rtol) +
            ": the linearized closed form's estimated error " + fmt(d.estimated_error) +
            " = 2 (1 + 10 zeta) D0 with D0 = " + fmt(d.linear_difference) +
            " (the exact undamped difference of the two laws in e, z_m, F_max, t_f) is within "
            "rtol; its unloading damping ratio zeta1 <= " +
            fmt(kLinearMaxUnloadingDamping) + " (far from capture)");
      }
      break;
    case ModelRoute::integrated:
      c.law = law + " (full model, integrated)";
      c.integrator = integrator;
      add_integrated_reasons(req, p, d, c.reasons);
      break;
  }
  return c;
}

ModelRun simulate_model(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  ModelRun run;
  const ModelDecision d = decide_model(v, trajectory != nullptr);
  run.result = run_model(v, d, trajectory);
  run.choice = explain(v, d, run.result);
  if (trajectory && v.request().law != LawKind::expression)
    run.choice.reasons.push_back("a trajectory was asked for: the full model is integrated");
  return run;
}

}  // namespace ivv
