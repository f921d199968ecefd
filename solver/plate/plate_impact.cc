#include "solver/plate/plate_impact.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/input_error.h"
#include "solver/plate/plate_law_impact.h"

namespace ivv {
namespace {

void require_plate_scene(const Scene& scene, LawKind law) {
  validate(scene);
  require_finite_plate(scene);
  const LawInfo& info = law_info(law);
  if (law == LawKind::expression || info.rate_dependent)
    throw InputError("--law", std::string(info.name) +
                                  ": a rate-dependent or expression law is not modelled on a "
                                  "finite plate yet; accepted: hertz, elastoplastic, linearized");
  if (info.needs_yield_strength && !scene.yield_strength)
    throw InputError("target.yield_strength", "required by the " + std::string(info.name) +
                                                  " law; give yield_strength or shear_strength");
}

}  // namespace

void validate_plate_impact(const Scene& scene, LawKind law, const LawParameters& parameters) {
  require_plate_scene(scene, law);
  validate_parameters(law, parameters);
}

ImpactResult as_sweep_result(const PlateImpactResult& r) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  ImpactResult out;
  out.route = "finite-plate";
  out.integrator = "dop853";
  out.steps = r.steps + r.free_flight_steps;
  out.rhs_evaluations = r.rhs_evaluations;
  if (!r.ok) {
    out.status = ImpactStatus::failed;
    out.failure = FailureKind::integrator;  // the plate driver's integration (its reason says how)
    out.reason = r.reason;
    return out;
  }
  out.status = ImpactStatus::separated;
  out.e = r.e;
  out.e_poisson = out.e_energetic = nan;
  out.F_max = r.F_max;
  out.t_F_max = nan;
  out.t_contact = r.t_contact;
  out.z_max = r.z_max;
  out.alpha_max = out.z_perm = nan;
  out.energy.residual = r.energy.max_error * r.energy.initial;
  return out;
}

PlateImpactResult simulate_plate_impact(const Scene& scene, LawKind law,
                                        const LawParameters& parameters,
                                        const PlateImpactOptions& options) {
  validate_plate_impact(scene, law, parameters);
  const DerivedParameters p = derive(scene);
  return with_builtin_law(law, parameters, p, [&](const auto& l) {
    return detail::plate_impact(l, scene, p, options);
  });
}

bool has_finite_plate(const Scene& scene) {
  return scene.damping.kind == Damping::Kind::structure && scene.damping.structure.finite_plate();
}

}  // namespace ivv
