#include "solver/choice/model_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "closed_forms/undamped_impact.h"
#include "solver/choice/integrator_choice.h"
#include "solver/consistency.h"
#include "solver/laws/hunt_crossley.h"

namespace ivv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

double rel(double x, double ref) {
  return std::abs(x - ref) / std::abs(ref);
}

// The ImpactResult of an undamped closed form (routes 1 and 2).
ImpactResult undamped_result(const Scene& scene, const DerivedParameters& p,
                             const closed_forms::UndampedImpact& u) {
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
                           const closed_forms::LinearModelInput& in,
                           const closed_forms::LinearImpact& L) {
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
    const closed_forms::LinearState s = closed_forms::linear_model_state(in, L, t);
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
    r.failure = FailureKind::inconsistent;
    r.reason = why;
  }
}

double integrated_estimate(IntegratorKind k, const IntegratorOptions& opt) {
  const IntegratorTraits& t = traits(k);  // looked up once: decide_model runs every impact
  if (t.fixed_step) {
    const double h = opt.fixed_dt();
    // The step that starts at onset integrates F ~ z^{3/2} ~ tau^{3/2}, which is not smooth
    // there: its local error is O(h^{5/2}), not the smooth phases' C h^4 (h^4 = 1e-12 was
    // stated at the default h = 1e-3 while rk4's F_max erred by 1.2e-10 to 3.9e-10 at v0 = 10
    // m/s, zeta = 0.05; the same term sets rk4's tolerance in verification/tolerances.h). Held by
    // Rk4.MeetsItsStatedError (integrators_test.cc).
    return h * h * std::sqrt(h);
  }
  if (t.reference) return opt.reference_tolerance;
  return (t.implicit ? kAutoErrorFactorImplicit : kAutoErrorFactorExplicit) * opt.rtol;
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
  const closed_forms::UndampedImpact nl = closed_forms::undamped_elastoplastic(m, p.K_h, p.z_y, v0);
  if (!nl.yielded) return out;
  // the linearized law is undefined below z_m = 2.25 z_y (eq 17): asked, not caught
  const closed_forms::LinearModelInput undamped{m, p.K_h, p.K_y, 0.0, v0};
  if (!closed_forms::linearized_law_defined(undamped)) return out;
  const double g2 = closed_forms::linear_gamma_squared_eq20(m, p.K_h, p.K_y, v0);
  if (!(g2 > 0) || !(growth * rel(std::sqrt(g2), nl.e) <= rtol)) return out;
  const closed_forms::LinearImpact lin0 = closed_forms::solve_linear_model(undamped);
  const closed_forms::UndampedImpact nlt = closed_forms::undamped_elastoplastic(
      m, p.K_h, p.z_y, v0, closed_forms::TimesQuadrature{rtol});
  out.D0 = std::max({rel(lin0.e, nlt.e), rel(lin0.z_max, nlt.z_max), rel(lin0.F_max, nlt.F_max),
                     rel(lin0.t_contact, nlt.t_contact)});
  const closed_forms::LinearModelInput damped = closed_forms::linear_model_input(scene, p);
  if (!closed_forms::linearized_law_defined(damped)) return out;
  out.zeta_unload = closed_forms::solve_linear_model(damped).zeta_unload;
  out.defined = true;
  out.estimate = growth * out.D0;
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

ModelDecision decide_model(const ValidatedRequest& v, RunOutput output) {
  const SimulationRequest& req = v.request();
  const DerivedParameters& p = v.derived();
  ModelDecision d;
  d.integrator = effective_integrator(v);
  d.estimated_error = integrated_estimate(d.integrator, req.options);
  if (req.law == LawKind::expression && v.expression())  // an attractive onset speeds it up
    d.estimated_error *= v.expression()->loading_speed_gain(p.effective_mass);
  if (output == RunOutput::result_and_trajectory || req.law == LawKind::expression) return d;
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
    if (closed_forms::linearized_law_defined(closed_forms::linear_model_input(req.scene, p))) {
      d.route = ModelRoute::linearized_closed_form;
      d.estimated_error = kEstimateClosedForm;
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
      ImpactResult r = undamped_result(
          s, p,
          closed_forms::undamped_elastoplastic(p.effective_mass, p.K_h, p.z_y, s.velocity,
                                               closed_forms::TimesQuadrature{req.options.rtol}));
      check_closed_form(r, s, p, req.options, "closed-form elastoplastic");
      return r;
    }
    case ModelRoute::closed_form_hertz: {
      ImpactResult r =
          undamped_result(s, p, closed_forms::undamped_hertz(p.effective_mass, p.K_h, s.velocity));
      check_closed_form(r, s, p, req.options, "closed-form hertz");
      return r;
    }
    case ModelRoute::linearized_closed_form: {
      const closed_forms::LinearModelInput in = closed_forms::linear_model_input(s, p);
      ImpactResult r = linear_result(s, p, in, closed_forms::solve_linear_model(in));
      check_closed_form(r, s, p, req.options, "linearized closed form");
      return r;
    }
    case ModelRoute::hunt_crossley_lambert_w: {
      ImpactResult r = detail::simulate_full(v, d.integrator, trajectory);
      if (!r.separated()) return r;
      const HuntCrossleyLaw law = HuntCrossleyLaw::make(req.parameters, p);
      const double e = closed_forms::hunt_crossley_cor(law.mu * s.velocity);
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
  finish_route(r, d);
  return r;
}

void finish_route(ImpactResult& r, const ModelDecision& d) {
  r.route = to_string(d.route);
  // the integrated route's result was checked by simulate_full, naming its integrator; the
  // other routes made or changed their numbers here
  if (d.route != ModelRoute::integrated) fail_non_finite_outcome(r, to_string(d.route));
}

ModelRun simulate_model(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  ModelRun run;
  const ModelDecision d =
      decide_model(v, trajectory ? RunOutput::result_and_trajectory : RunOutput::result);
  run.result = run_model(v, d, trajectory);
  run.choice = explain(v, d, run.result);
  if (trajectory && v.request().law != LawKind::expression)
    run.choice.reasons.push_back("a trajectory was asked for: the full model is integrated");
  return run;
}

}  // namespace ivv
