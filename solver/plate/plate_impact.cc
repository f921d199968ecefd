#include "solver/plate/plate_impact.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scene/input_error.h"
#include "solver/event_locator.h"
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

template <class Law>
PlateImpactResult run_plate(const Law& law, const Scene& scene, const DerivedParameters& p,
                            const PlateImpactOptions& opt) {
  const Scales k = scales(scene, p, Law::scale_basis);
  const Structure& st = scene.damping.structure;
  const FinitePlate plate =
      finite_plate(st, scene.target_youngs_modulus, scene.target_poisson_ratio);
  const double z_mH =
      std::pow(5.0 * p.effective_mass * scene.velocity * scene.velocity / (4.0 * p.K_h), 0.4);
  const double k_H = 1.5 * p.K_h * std::sqrt(z_mH);
  const double omega_local = std::sqrt(k_H * 4.0 / (plate.mass()));
  const double omega_s = std::max(1.0 / k.time, omega_local);
  const PlateModes modes = plate_modes(plate, {opt.cutoff * omega_s, opt.max_modes});
  PlateImpactResult out;
  out.mode_count = modes.modes.size();
  out.omega_cut = modes.omega_cut;
  out.static_compliance = modes.static_compliance.value;
  out.residual_compliance = opt.residual ? modes.residual_compliance : 0.0;
  out.plate_mass = plate.mass();
  try {
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
  } catch (const PlateRunFailure& f) {
    out.ok = false;
    out.reason = f.reason;
  } catch (const EventLocationError& e) {
    out.ok = false;
    out.reason = e.what();
  } catch (const LawDomainError& e) {
    out.ok = false;
    out.reason = e.what();
  }
  return out;
}

}  // namespace

PlateImpactResult simulate_plate_impact(const Scene& scene, LawKind law,
                                        const LawParameters& parameters,
                                        const PlateImpactOptions& options) {
  require_plate_scene(scene, law);
  validate_parameters(law, parameters);
  const DerivedParameters p = derive(scene);
  return with_builtin_law(law, parameters, p,
                          [&](const auto& l) { return run_plate(l, scene, p, options); });
}

bool has_finite_plate(const Scene& scene) {
  return scene.damping.kind == Damping::Kind::structure && scene.damping.structure.finite_plate();
}

namespace {

void refuse_for_plate(bool given, const char* flag, const char* why) {
  if (given) throw InputError(flag, std::string("not used with a finite plate (") + why + ")");
}

}  // namespace

PlateRun run_plate_simulation(const RequestOptions& o) {
  const char* dashpot =
      "its modes carry the energy away; without length_x/length_y the plate "
      "is infinite and has the dashpot";
  refuse_for_plate(o.zeta.has_value(), "--zeta", dashpot);
  refuse_for_plate(o.c.has_value(), "--c", dashpot);
  refuse_for_plate(o.lambda.has_value(), "--lambda", dashpot);
  refuse_for_plate(o.no_dashpot, "--no-dashpot", dashpot);
  const char* own = "the plate's modes are integrated by dop853 with event location";
  refuse_for_plate(o.integrator != "auto", "--integrator", own);
  refuse_for_plate(o.dt.has_value(), "--dt", own);
  refuse_for_plate(o.max_steps.has_value(), "--max-steps", own);
  refuse_for_plate(o.model != "auto" && o.model != "full", "--model",
                   "the full plate model is the only one built for a finite plate");
  refuse_for_plate(!o.expression.force.empty(), "--force",
                   "an expression law is not modelled "
                   "on a finite plate yet");
  PlateRun run;
  run.scene = load_scene(o.scene);
  if (o.v0) {
    require(std::isfinite(*o.v0) && *o.v0 > 0.0, "--v0", "a finite number > 0 m/s", *o.v0);
    run.scene.velocity = *o.v0;
  }
  run.law = parse_law(o.law);
  run.parameters = o.parameters;
  if (o.rtol) run.options.rtol = *o.rtol;
  if (o.atol) run.options.atol = *o.atol;
  require(run.options.rtol > 0.0 && run.options.rtol < 1.0, "--rtol", "a number in (0, 1)",
          run.options.rtol);
  require(run.options.atol > 0.0 && run.options.atol < 1.0, "--atol", "a number in (0, 1)",
          run.options.atol);
  run.result = simulate_plate_impact(run.scene, run.law, run.parameters, run.options);
  if (run.result.ok) {
    PlateImpactOptions half = run.options;
    half.cutoff /= 2.0;
    const PlateImpactResult r = simulate_plate_impact(run.scene, run.law, run.parameters, half);
    if (r.ok) {
      run.e_half_cutoff = r.e;
      run.truncation_error = std::abs(run.result.e - r.e) / 7.0;
    }
  }
  return run;
}

}  // namespace ivv
