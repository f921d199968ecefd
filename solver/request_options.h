// What a front end (the CLI, a calibration, a test) asks of one impact, before any check: a
// scene and what overrides it, the law, the integrator, the model and the tolerances. The one
// place where such a request is checked and built:
//
//   RequestOptions::invalid()  the first problem, naming the field (Ceres' IsValid shape), or none
//   to_request()               the checked SimulationRequest; InputError naming the field otherwise
//   run_simulation()           the run a front end prints: the request as run (integrator
//                              resolved), the result and, where a choice was made, its reasons
//
// Field names: an override is named by the command-line flag that sets it (--v0, --zeta, --c,
// --lambda,
// --hc-k, --hc-mu, --rtol, --atol, --dt, --max-steps), and a scene value the user overrode is
// reported under that name rather than the scene file's key, since the flag is what they typed.
// Every range is checked once, by the validation the override feeds (scene.cc, law_registry.cc,
// IntegratorOptions::invalid()); nothing here repeats a range.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "solver/choice/model_choice.h"
#include "solver/simulate.h"

namespace ivv {

struct RequestOptions {
  std::string scene = "paper";            // a TOML file, 'paper' or a shipped scene's name
  std::optional<double> v0;               // [m/s] replaces [impact] velocity
  std::optional<double> zeta;             // [-] replaces [damping] with this damping ratio
  std::optional<double> c;                // [N s/m] replaces [damping] with this coefficient
  std::optional<double> lambda;           // [-] replaces [damping] with the c of this Zener lambda
  bool no_dashpot = false;                // drops the scene's dashpot
  std::string law = "elastoplastic";      // a registered law's name (ivv laws)
  ExpressionLawSpec expression;           // a non-empty force: the expression law instead of `law`
  std::string integrator = "auto";        // a name of integrator_table(), or auto
  std::string model = "auto";             // auto or full (solver/choice/model_choice.h)
  std::optional<double> rtol, atol;       // IntegratorOptions
  std::optional<double> dt;               // [-] rk4's fixed normalised step; > 0 when given
  std::optional<double> model_tolerance;  // a finite plate's model choice (plate_regime.h)
  std::optional<long> max_steps;
  std::optional<double> hc_k;   // [N/m^1.5] Hunt-Crossley K (the law's parameter "K")
  std::optional<double> hc_mu;  // [s/m] Hunt-Crossley mu (the law's parameter "mu")
  LawParameters parameters;     // --param NAME=VALUE

  struct Invalid {
    std::string field, message;
  };
  // The first problem with these options, or none. Loads the scene to check it.
  std::optional<Invalid> invalid() const;
};

// The law of `options` into `request`: --law, or the expression law of --force/--unload; --param,
// --hc-k/--hc-mu (InputError naming the flag: --unload without --force, K or mu of another law).
void apply_law(const RequestOptions& options, SimulationRequest& request);

// The checked request. `auto_integrator` is left set for --integrator auto, so that each run
// (each point of a sweep) chooses its own; run_simulation() resolves it once for one impact.
// Throws InputError naming the field.
SimulationRequest to_request(const RequestOptions& options);
// The same for a scene the front end already holds (the Python module's ivv.scene):
// options.scene is not read; the overrides of `options` apply to `scene`.
SimulationRequest to_request(Scene scene, const RequestOptions& options);
// The request every point of a sweep starts from: as to_request(), except that a scene with a
// finite plate is checked as its plate runs (solver/plate/plate_law.h: no dashpot flag, a
// rate-independent law without tension) instead of refused, since a sweep runs such points on
// the plate (solver/sweep/sweep.cc).
SimulationRequest to_sweep_base(const RequestOptions& options);
// The same for a scene the front end already holds (the Python module): options.scene unread.
SimulationRequest to_sweep_base(Scene scene, const RequestOptions& options);
// The request of a law checked on `scene` (ivv check-law, ivv.check_law): as to_request(), except
// that a scene with a finite plate keeps it (the dynamic checks strike it,
// verification/conformance.h); its law is then checked as to_request() checks it on the scene
// without the plate, and the dashpot and integrator flags are refused by name.
SimulationRequest to_check_law_request(Scene scene, const RequestOptions& options);
// `scene` with the overrides of `options` (--v0, --zeta, --c, --lambda, --no-dashpot) applied
// and validated on its own, without a law; InputError naming the flag of an override at fault,
// as to_request() names it.
Scene to_scene(Scene scene, const RequestOptions& options);

// One impact as a front end shows it.
struct SimulationRun {
  SimulationRequest request;  // as run: the integrator --integrator auto chose
  ImpactResult result;
  std::optional<ModelChoice> choice;  // --model auto, or --integrator auto: what ran and why
};

// Validates `request` (InputError naming the field), chooses the integrator once when asked
// to, and runs the model the request names (solver/choice/model_choice.h for --model auto).
SimulationRun run_simulation(SimulationRequest request,
                             std::vector<TrajectoryPoint>* trajectory = nullptr);

}  // namespace ivv
