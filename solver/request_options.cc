#include "solver/request_options.h"

#include <array>
#include <string_view>
#include <utility>

#include "scene/input_error.h"
#include "solver/choice/integrator_choice.h"
#include "solver/plate/plate_law.h"
#include "solver/plate/plate_run.h"

namespace ivv {
namespace {

// A scene key or law parameter and the override that replaces it.
struct Override {
  std::string_view field;  // as the validation names it
  std::string_view flag;   // as the user typed it
  bool given;
};

// The value, in the scene, of every override the options carry.
void apply_scene_overrides(const RequestOptions& o, Scene& scene) {
  if (o.v0) scene.velocity = *o.v0;
  if (o.zeta) scene.damping = Damping::ratio(*o.zeta);
  if (o.c) scene.damping = Damping::coefficient(*o.c);
  if (o.lambda) scene.damping = Damping::zener(*o.lambda);
  if (o.no_dashpot) scene.damping = Damping::none();
}

void apply_integration(const RequestOptions& o, SimulationRequest& req) {
  req.auto_integrator = o.integrator == "auto";
  // auto: a placeholder until run_simulation() (or each sweep point) chooses
  req.integrator = req.auto_integrator ? IntegratorKind::dop853 : parse_integrator(o.integrator);
  req.model = parse_model(o.model);
  if (o.rtol) req.options.rtol = *o.rtol;
  if (o.atol) req.options.atol = *o.atol;
  if (o.dt) {
    // 0 stands for "the default step" inside IntegratorOptions; typed, it is no step at all
    require(*o.dt > 0, "--dt", "a normalised step > 0", *o.dt);
    req.options.dt = *o.dt;
  }
  if (o.max_steps) req.options.max_steps = *o.max_steps;
}

// Runs `check`; an InputError about a value an override replaced names the override's flag
// (what the user typed) instead of the scene's key.
template <class Check>
void naming_overrides(const RequestOptions& o, Check check) {
  const std::array<Override, 6> overrides = {{{"impact.velocity", "--v0", o.v0.has_value()},
                                              {"damping.zeta", "--zeta", o.zeta.has_value()},
                                              {"damping.c", "--c", o.c.has_value()},
                                              {"damping.lambda", "--lambda", o.lambda.has_value()},
                                              {"--param K", "--hc-k", o.hc_k.has_value()},
                                              {"--param mu", "--hc-mu", o.hc_mu.has_value()}}};
  try {
    check();
  } catch (const InputError& e) {
    for (const Override& ov : overrides) {
      if (ov.given && e.field() == ov.field) {
        std::string message = std::string(e.what()).substr(e.field().size() + 2);
        // zeta = 0 means "no dashpot" to a reader of the paper: say how to ask for that
        if (std::string_view(ov.flag) == "--zeta" && o.zeta && *o.zeta == 0)
          message += "; for an impact without a dashpot give --no-dashpot";
        throw InputError(std::string(ov.flag), message);
      }
    }
    throw;
  }
}

}  // namespace

void apply_law(const RequestOptions& o, SimulationRequest& req) {
  if (!o.expression.force.empty()) {
    req.law = LawKind::expression;
    req.expression = o.expression;
  } else {
    if (!o.expression.unload.empty())
      throw InputError("--unload", "needs a loading expression (--force)");
    req.law = parse_law(o.law);
  }
  req.parameters = o.parameters;
  if (o.hc_k || o.hc_mu) {
    if (req.law != LawKind::hunt_crossley)
      throw InputError(o.hc_k ? "--hc-k" : "--hc-mu",
                       "only the hunt-crossley law has K and mu (--law hunt-crossley)");
    if (o.hc_k) req.parameters["K"] = *o.hc_k;
    if (o.hc_mu) req.parameters["mu"] = *o.hc_mu;
  }
}

SimulationRequest to_request(const RequestOptions& o) {
  return to_request(load_scene(o.scene), o);
}

SimulationRequest to_request(Scene scene, const RequestOptions& o) {
  if (o.model_tolerance)
    throw InputError("--model-tol",
                     "the tolerance of a finite plate's choice of model; this scene has no "
                     "finite plate (give [structure] length_x and length_y)");
  SimulationRequest req;
  req.scene = std::move(scene);
  apply_scene_overrides(o, req.scene);
  apply_law(o, req);
  apply_integration(o, req);
  naming_overrides(o, [&] { validate(req); });
  return req;
}

SimulationRequest to_sweep_base(const RequestOptions& o) {
  return to_sweep_base(load_scene(o.scene), o);
}

SimulationRequest to_sweep_base(Scene scene, const RequestOptions& o) {
  if (!has_finite_plate(scene)) return to_request(std::move(scene), o);
  refuse_dashpot_and_integrator_flags(o);
  refuse_stepper_choice(o, "a sweep");
  if (o.model != "auto" && o.model != "full")
    throw InputError("--model", "a sweep on a finite plate runs the full plate: auto or full");
  SimulationRequest req;
  req.scene = std::move(scene);
  apply_scene_overrides(o, req.scene);
  apply_law(o, req);
  apply_integration(o, req);
  naming_overrides(o, [&] {
    validate(req.options);
    validate_plate_law(req);
  });
  return req;
}

SimulationRequest to_check_law_request(Scene scene, const RequestOptions& o) {
  if (!has_finite_plate(scene)) return to_request(std::move(scene), o);
  refuse_dashpot_and_integrator_flags(o);
  refuse_stepper_choice(o, "check-law");
  Scene without_plate = scene;
  without_plate.damping = Damping::none();
  SimulationRequest req = to_request(std::move(without_plate), o);
  apply_scene_overrides(o, scene);
  req.scene = std::move(scene);
  return req;
}

Scene to_scene(Scene scene, const RequestOptions& o) {
  apply_scene_overrides(o, scene);
  naming_overrides(o, [&] { validate(scene); });
  return scene;
}

std::optional<RequestOptions::Invalid> RequestOptions::invalid() const {
  try {
    to_request(*this);
  } catch (const InputError& e) {
    return Invalid{e.field(), std::string(e.what()).substr(e.field().size() + 2)};
  }
  return std::nullopt;
}

SimulationRun run_simulation(SimulationRequest request, std::vector<TrajectoryPoint>* trajectory) {
  SimulationRun run;
  run.request = std::move(request);
  SimulationRequest& req = run.request;
  const ValidatedRequest checked(req);  // refers to run.request, which outlives it
  std::optional<IntegratorChoice> integrator_choice;
  if (req.auto_integrator) {
    integrator_choice = choose_integrator(req);
    req.integrator = integrator_choice->integrator;
  }
  if (req.model == ModelKind::automatic) {
    ModelRun m = simulate_model(checked, trajectory);
    run.result = std::move(m.result);
    run.choice = std::move(m.choice);
    return run;
  }
  run.result = simulate(checked, trajectory);
  if (integrator_choice) run.choice = integrated_choice(req, *integrator_choice);
  return run;
}

}  // namespace ivv
