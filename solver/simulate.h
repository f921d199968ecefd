// One impact, chosen at run time: scene x contact law x integrator.
//
// The runtime choice dispatches once per impact into code templated on the law, the presence
// of a dashpot and the stepper (impact_driver.h), so the right-hand side is never dispatched
// per evaluation.
#pragma once

#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"
#include "solver/laws/expression.h"
#include "solver/laws/law_registry.h"
#include "solver/result.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/integrators.h"

namespace ivv {

// IntegratorKind, the table of integrator traits and parse_integrator:
// solver/steppers/integrators.h.

// The built-in laws (not `expression`), in registry order.
std::span<const LawKind> all_laws();
// Parse a name; throws InputError(field, "unknown ...; valid names: ...") otherwise.

// What runs for a request (solver/choice/model_choice.h). `full`: the ODE model of the law,
// integrated by `integrator` (the library's default). `automatic` (`--model auto`, the CLI's
// default): what the scene needs within the requested tolerance - an exact closed form where one
// exists, the linearized closed form where its estimated error is within rtol, otherwise the full
// model.
enum class ModelKind { automatic, full };
std::string_view to_string(ModelKind kind);      // "auto", "full"
ModelKind parse_model(const std::string& name);  // throws InputError("--model", ...)

struct SimulationRequest {
  Scene scene;
  LawKind law = LawKind::elastoplastic;
  IntegratorKind integrator = IntegratorKind::odeint_dopri5;
  // --integrator auto: `integrator` is replaced per run by choose_integrator()'s choice
  // (solver/choice/integrator_choice.h), so each point of a sweep gets its own.
  bool auto_integrator = false;
  ModelKind model = ModelKind::full;
  IntegratorOptions options;
  LawParameters parameters;      // the law's --param values (law_info(law).parameters)
  ExpressionLawSpec expression;  // law == LawKind::expression: the typed law
};

// One sample of the trajectory (SI and the normalised variables of paper eq. 26).
struct TrajectoryPoint {
  double t, alpha, alpha_dot, y, z, force;  // [s, m, m/s, m, m, N]
  double tau, alpha_bar, force_bar;         // [-]
};

struct SweepRequest;

// A request that passed the one validation, with what validation had to compute kept for the
// run, so an impact validates once and compiles its expression law once: the derived
// parameters and, for an expression law, the compiled law (validation compiles it to learn
// whether it uses zdot; the run uses the same). Refers to the request, which must outlive it.
class ValidatedRequest {
 public:
  // Runs every check of validate(request); throws InputError naming the field.
  explicit ValidatedRequest(const SimulationRequest& request);
  ValidatedRequest(SimulationRequest&&) = delete;  // would refer to a temporary

  const SimulationRequest& request() const { return *request_; }
  const DerivedParameters& derived() const { return derived_; }
  // The compiled expression law; null unless request().law == LawKind::expression.
  const std::shared_ptr<const CompiledExpressions>& expression() const { return expression_; }

  // Point `index` of a grid that validate(SweepRequest) accepted (`point` = its
  // point_request()): the grid's checks cover every point (v0 and zeta enter the derived
  // scales separately, and each is checked), so only the point's expression law is compiled.
  static ValidatedRequest grid_point(const SweepRequest& grid, const SimulationRequest& point);
  // The same with the point's derived parameters given: `derived` = derive(point.scene), made
  // from what the grid's points share (SweepPointRequests, solver/sweep/sweep_grid.h).
  static ValidatedRequest grid_point(const SweepRequest& grid, const SimulationRequest& point,
                                     const DerivedParameters& derived);

 private:
  struct Trusted {};
  ValidatedRequest(const SimulationRequest& request, Trusted);
  ValidatedRequest(const SimulationRequest& request, const DerivedParameters& derived, Trusted);
  const SimulationRequest* request_;
  DerivedParameters derived_;
  std::shared_ptr<const CompiledExpressions> expression_;
};

// Validates the request (InputError naming the field) and runs it. Failures of the
// integration or of the law's domain come back in ImpactResult::status/failure/reason.
// `trajectory`, when given, receives samples along the solution (several per step).
ImpactResult simulate(const SimulationRequest& request,
                      std::vector<TrajectoryPoint>* trajectory = nullptr);
// Runs a request validated before (no check repeated).
ImpactResult simulate(const ValidatedRequest& request,
                      std::vector<TrajectoryPoint>* trajectory = nullptr);

// The integrator a run uses: auto_integrator()'s choice (solver/choice/integrator_choice.h) when
// request.auto_integrator, request.integrator otherwise.
IntegratorKind effective_integrator(const ValidatedRequest& request);

namespace detail {
// The full ODE model of the law with `integrator`, whatever request.model says.
ImpactResult simulate_full(const ValidatedRequest& request, IntegratorKind integrator,
                           std::vector<TrajectoryPoint>* trajectory);
// What simulate_full adds to the run's result: the integrator's name, and a failure for a
// non-finite outcome or for a failure without a reason (a batch in lanes, simulate_batch.h, adds
// it to the results it made).
void finish_full(ImpactResult& result, IntegratorKind integrator);
}  // namespace detail

// Throws InputError for invalid options or an incompatible combination: the one validation
// of a request (ValidatedRequest's constructor), called by every entry point.
void validate(const SimulationRequest& request);
// Throws InputError naming the option (--rtol, --atol, --dt, --max-steps) when out of range.
void validate(const IntegratorOptions& options);

}  // namespace ivv
