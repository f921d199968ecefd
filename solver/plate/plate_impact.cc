#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_truncation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "scene/input_error.h"
#include "solver/driver/event_locator.h"
#include "solver/format.h"
#include "solver/plate/odeint_dense_stepper.h"
#include "solver/plate/plate_impact_driver.h"
#include "solver/plate/plate_modes.h"
#include "solver/steppers/dop853.h"

namespace ivv {
namespace {

void require_plate_scene(const Scene& scene, LawKind law) {
  validate(scene);
  if (scene.damping.kind != Damping::Kind::structure || !scene.damping.structure.finite_plate())
    throw InputError("structure",
                     "a finite plate impact needs [structure] kind = \"plate\" with length_x, "
                     "length_y and edges");
  if (scene.free_target())
    throw InputError("target.mass", "a free target sphere and a finite plate are two targets");
  const LawInfo& info = law_info(law);
  if (law == LawKind::expression || info.rate_dependent)
    throw InputError("--law", std::string(info.name) +
                                  ": a rate-dependent or expression law is not modelled on a "
                                  "finite plate yet; accepted: hertz, elastoplastic, linearized");
  if (info.needs_yield_strength && !scene.yield_strength)
    throw InputError("target.yield_strength", "required by the " + std::string(info.name) +
                                                  " law; give yield_strength or shear_strength");
}

// What the runs of one impact at different cut-offs share: the plate, the law's scales, the
// rate omega_s the cut-off multiplies (plate_impact.h) and C_static.
struct PlateSetup {
  FinitePlate plate;
  Scales scales;
  double omega_s = 0.0;  // [rad/s]
  StaticCompliance static_compliance;
};

template <class Law>
PlateSetup plate_setup(const Scene& scene, const DerivedParameters& p) {
  PlateSetup s{finite_plate(scene.damping.structure, scene.target_youngs_modulus,
                            scene.target_poisson_ratio),
               scales(scene, p, Law::scale_basis),
               0.0,
               {}};
  const double z_mH =
      std::pow(5.0 * p.effective_mass * scene.velocity * scene.velocity / (4.0 * p.K_h), 0.4);
  const double k_H = 1.5 * p.K_h * std::sqrt(z_mH);
  const double omega_local = std::sqrt(k_H * 4.0 / (s.plate.mass()));
  s.omega_s = std::max(1.0 / s.scales.time, omega_local);
  s.static_compliance = plate_static_compliance(s.plate);
  return s;
}

// One run at the cut-off `cutoff` (a multiple of omega_s; 0: no mode).
template <class Law>
PlateImpactResult run_plate(const Law& law, const PlateSetup& setup, const DerivedParameters& p,
                            const PlateImpactOptions& opt, double cutoff) {
  const Scales& k = setup.scales;
  PlateModes modes;
  if (cutoff == 0.0) {
    modes = static_plate_modes(setup.plate);
  } else {
    PlateModeOptions mo;
    mo.omega_cut = cutoff * setup.omega_s;
    mo.max_modes = opt.max_modes;
    mo.static_compliance = setup.static_compliance;
    modes = plate_modes(setup.plate, mo);
  }
  PlateImpactResult out;
  out.mode_count = modes.modes.size();
  out.cutoff = cutoff;
  out.omega_cut = modes.omega_cut;
  out.static_compliance = modes.static_compliance.value;
  out.residual_compliance = opt.residual ? modes.residual_compliance : 0.0;
  out.plate_mass = setup.plate.mass();
  catching_plate_failures(out, [&] {
    if constexpr (!Law::rate_dependent) {
      using System = PlateSystem<Law>;
      if (opt.stepper == PlateImpactOptions::Stepper::dop853) {
        PlateImpactDriver<Law, Dop853Stepper<System>> driver(law, k, modes, p.effective_mass, opt);
        driver.run(out);
      } else {
        PlateImpactDriver<Law, OdeintDenseDopri5<System>> driver(law, k, modes, p.effective_mass,
                                                                 opt);
        driver.run(out);
      }
    }
  });
  return out;
}

template <class Law>
PlateImpactResult run_plate(const Law& law, const Scene& scene, const DerivedParameters& p,
                            const PlateImpactOptions& opt) {
  if (!(opt.truncation_tol >= 0.0 && std::isfinite(opt.truncation_tol)))
    throw std::invalid_argument("PlateImpactOptions::truncation_tol must be finite and >= 0");
  const PlateSetup setup = plate_setup<Law>(scene, p);
  if (opt.truncation_tol > 0.0 && opt.cutoff > 0.0)
    return run_to_truncation_tolerance(
        opt, [&](double c) { return run_plate(law, setup, p, opt, c); },
        [&](double c) { return count_plate_modes(setup.plate, c * setup.omega_s); });
  return run_plate(law, setup, p, opt, opt.cutoff);
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
  return with_builtin_law(law, parameters, p,
                          [&](const auto& l) { return run_plate(l, scene, p, options); });
}

bool has_finite_plate(const Scene& scene) {
  return scene.damping.kind == Damping::Kind::structure && scene.damping.structure.finite_plate();
}

}  // namespace ivv
