#include "solver/fit_hunt_crossley.h"

#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <stdexcept>

#include "scene/input_error.h"
#include "solver/consistency.h"
#include "solver/format.h"

namespace ivv {

HuntCrossleyFit fit_hunt_crossley(const SimulationRequest& model) {
  if (model.law == LawKind::hunt_crossley)
    throw InputError("--law", "fit-hc matches another law; hunt-crossley cannot be the model");
  HuntCrossleyFit fit;
  fit.model = simulate(model);
  if (fit.model.status != ImpactStatus::separated) {
    const std::string why = fit.model.reason.empty() ? "" : ": " + fit.model.reason;
    throw std::runtime_error("the model impact did not rebound (" +
                             std::string(to_string(fit.model.status)) + why +
                             "); Hunt-Crossley (e > 0 always) cannot match it");
  }
  fit.e = fit.model.e;
  fit.F_max = fit.model.F_max;
  fit.t_contact_model = fit.model.t_contact;
  const DerivedParameters p = derive(model.scene);

  SimulationRequest hc = model;
  hc.law = LawKind::hunt_crossley;
  hc.expression = {};  // the model may be an expression law; Hunt-Crossley is not one
  hc.parameters.clear();
  hc.scene.damping = Damping::none();
  hc.parameters["K"] = p.K_h;
  const double v0 = model.scene.velocity;
  auto run = [&](double u0) {
    hc.parameters["mu"] = u0 / v0;
    ++fit.evaluations;
    const ImpactResult r = simulate(hc);
    if (!r.separated()) throw std::runtime_error("Hunt-Crossley run failed: " + r.reason);
    return r;
  };

  // An elastic model impact (e = 1 to within the integration error) is matched by mu = 0:
  // there is nothing to bracket, and e_HC(0) = 1 exactly.
  if (1.0 - fit.e <= accumulated_error_bound(fit.model.steps, model.options)) {
    const ImpactResult trial = run(0.0);
    fit.mu = 0.0;
    fit.K = p.K_h * std::pow(fit.F_max / trial.F_max, 2.5);
    hc.parameters["K"] = fit.K;
    fit.hc = run(0.0);
    fit.t_contact_hc = fit.hc.t_contact;
    return fit;
  }
  // e_HC falls monotonically from 1 (u0 = 0) towards 0 as u0 grows; bracket then solve.
  double lo = 0.0, hi = 1.0;
  double f_lo = 1.0 - fit.e;
  double f_hi = run(hi).e - fit.e;
  while (f_hi > 0) {
    lo = hi;
    f_lo = f_hi;
    hi *= 4;
    if (hi > 1e6)
      throw std::runtime_error("cannot bracket the Hunt-Crossley mu for e = " + fmt(fit.e, 9) +
                               " (mu v0 > 1e6 still gives a larger e)");
    f_hi = run(hi).e - fit.e;
  }
  // the COR of the runs is accurate to ~1e-10 (rtol); stop the bracket near that
  boost::math::tools::eps_tolerance<double> tol(34);
  std::uintmax_t iterations = 100;
  const auto bracket = boost::math::tools::toms748_solve(
      [&](double u0) { return run(u0).e - fit.e; }, lo, hi, f_lo, f_hi, tol, iterations);
  if (iterations >= 100 && !tol(bracket.first, bracket.second))
    throw std::runtime_error("fit-hc: TOMS 748 did not resolve mu in 100 iterations (bracket [" +
                             fmt(bracket.first / v0, 9) + ", " + fmt(bracket.second / v0, 9) +
                             "] s/m)");
  const double u0 = 0.5 * (bracket.first + bracket.second);
  const ImpactResult trial = run(u0);
  fit.mu = u0 / v0;
  fit.K = p.K_h * std::pow(fit.F_max / trial.F_max, 2.5);
  hc.parameters["K"] = fit.K;
  fit.hc = run(u0);
  fit.t_contact_hc = fit.hc.t_contact;
  return fit;
}

}  // namespace ivv
