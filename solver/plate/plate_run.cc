#include "solver/plate/plate_run.h"

#include <cmath>
#include <string>
#include <utility>

#include "scene/input_error.h"
#include "solver/plate/plate_law.h"

namespace ivv {
namespace {

void refuse_for_plate(bool given, const char* flag, const char* why) {
  if (given) throw InputError(flag, std::string("not used with a finite plate (") + why + ")");
}

}  // namespace

PlateImpactOptions::Stepper plate_stepper(const std::string& integrator) {
  using Stepper = PlateImpactOptions::Stepper;
  if (integrator == "auto" || integrator == "exponential") return Stepper::exponential;
  if (integrator == "dop853") return Stepper::dop853;
  if (integrator == "odeint-dopri5") return Stepper::odeint_dopri5;
  throw InputError("--integrator",
                   "a finite plate is stepped by exponential (auto, the default), dop853 or "
                   "odeint-dopri5; got '" +
                       integrator + "'");
}

void refuse_stepper_choice(const RequestOptions& o, const char* what) {
  if (o.integrator != "auto")
    throw InputError("--integrator", std::string(what) +
                                         " on a finite plate runs the exponential stepper: "
                                         "auto (--integrator chooses it in `ivv simulate`)");
}

void refuse_dashpot_and_integrator_flags(const RequestOptions& o) {
  const char* dashpot =
      "its modes carry the energy away; without length_x/length_y the plate "
      "is infinite and has the dashpot";
  refuse_for_plate(o.zeta.has_value(), "--zeta", dashpot);
  refuse_for_plate(o.c.has_value(), "--c", dashpot);
  refuse_for_plate(o.lambda.has_value(), "--lambda", dashpot);
  refuse_for_plate(o.no_dashpot, "--no-dashpot", dashpot);
  (void)plate_stepper(o.integrator);
  const char* own = "the plate's steppers are adaptive, with event location";
  refuse_for_plate(o.dt.has_value(), "--dt", own);
  refuse_for_plate(o.max_steps.has_value(), "--max-steps", own);
}

PlateModel PlateRun::answered() const {
  if (forced) return *forced;
  return regime ? regime->chosen() : PlateModel::full;
}

const PlateModelOutcome* PlateRun::answer() const {
  return regime ? &regime->outcome(answered()) : nullptr;
}

SimulationRequest PlateRun::law_request() const {
  SimulationRequest r;
  r.scene = scene;
  r.law = law;
  r.parameters = parameters;
  r.expression = expression;
  return r;
}

double PlateRun::estimated_error() const {
  const PlateModelOutcome* a = answer();
  if (a == nullptr) return truncation_error;
  return (a->model == PlateModel::full ? 0.0 : a->error) + truncation_error;
}

PlateRun run_plate_simulation(const RequestOptions& o) {
  refuse_dashpot_and_integrator_flags(o);
  return run_plate_simulation(load_scene(o.scene), o);
}

PlateRun run_plate_simulation(Scene scene, const RequestOptions& o) {
  refuse_dashpot_and_integrator_flags(o);
  PlateRun run;
  run.forced = parse_plate_model(o.model);
  const double tolerance = o.model_tolerance.value_or(kPlateModelTolerance);
  require(std::isfinite(tolerance) && tolerance > 0.0 && tolerance < 1.0, "--model-tol",
          "a number in (0, 1)", tolerance);
  run.scene = std::move(scene);
  if (o.v0) {
    require(std::isfinite(*o.v0) && *o.v0 > 0.0, "--v0", "a finite number > 0 m/s", *o.v0);
    run.scene.velocity = *o.v0;
  }
  SimulationRequest law;
  apply_law(o, law);
  run.law = law.law;
  run.parameters = std::move(law.parameters);
  run.expression = std::move(law.expression);
  run.options.rtol = o.rtol.value_or(kPlateSimulateRtol);
  run.options.atol = o.atol.value_or(kPlateSimulateAtol);
  require(run.options.rtol > 0.0 && run.options.rtol < 1.0, "--rtol", "a number in (0, 1)",
          run.options.rtol);
  require(run.options.atol > 0.0 && run.options.atol < 1.0, "--atol", "a number in (0, 1)",
          run.options.atol);
  run.options.stepper = plate_stepper(o.integrator);
  run.options.truncation_tol = kPlateTruncationTol;
  run.options.cutoff = kPlateFirstCutoff;
  const SimulationRequest request = run.law_request();
  run.result = simulate_plate_law(request, run.options);
  if (!run.result.ok) return run;
  run.e_half_cutoff = run.result.e_coarser;
  run.truncation_error = run.result.truncation_error;
  run.regime = plate_regime({run.scene, run.law, run.parameters, run.options, &run.expression},
                            run.result, tolerance);
  return run;
}

}  // namespace ivv
