#include "solver/simulate.h"

#include <array>
#include <cmath>
#include <sstream>

#include "scene/input_error.h"
#include "solver/choice/integrator_choice.h"
#include "solver/choice/model_choice.h"
#include "solver/consistency.h"
#include "solver/simulate_impl.h"
#include "solver/steppers/integrator_instance.h"

namespace ivv {
namespace {

constexpr std::array kLaws = [] {
  std::array<LawKind, static_cast<std::size_t>(LawKind::expression)> kinds{};
  for (std::size_t i = 0; i < kinds.size(); ++i) kinds[i] = static_cast<LawKind>(i);
  return kinds;
}();
template <class Kind, std::size_t N>
std::string name_list(const std::array<Kind, N>& kinds) {
  std::string out;
  for (Kind k : kinds) out += (out.empty() ? "" : ", ") + std::string(to_string(k));
  return out;
}

}  // namespace

std::string_view to_string(ModelKind kind) {
  return kind == ModelKind::automatic ? "auto" : "full";
}

ModelKind parse_model(const std::string& name) {
  if (name == "auto") return ModelKind::automatic;
  if (name == "full") return ModelKind::full;
  throw InputError("--model", "unknown model '" + name +
                                  "'; valid names: auto (what the scene needs within --rtol), "
                                  "full (the ODE model of the law, integrated)");
}

std::span<const LawKind> all_laws() {
  return kLaws;
}

std::string_view to_string(FailureKind k) {
  switch (k) {
    case FailureKind::none:
      return "none";
    case FailureKind::law_domain:
      return "law_domain";
    case FailureKind::law_non_finite:
      return "law_non_finite";
    case FailureKind::step_underflow:
      return "step_underflow";
    case FailureKind::attempts_exhausted:
      return "attempts_exhausted";
    case FailureKind::non_finite_state:
      return "non_finite_state";
    case FailureKind::singular_matrix:
      return "singular_matrix";
    case FailureKind::unstable_step:
      return "unstable_step";
    case FailureKind::library_error:
      return "library_error";
    case FailureKind::event_location:
      return "event_location";
    case FailureKind::event_refinement:
      return "event_refinement";
    case FailureKind::step_limit:
      return "step_limit";
    case FailureKind::time_limit:
      return "time_limit";
    case FailureKind::still_approaching:
      return "still_approaching";
    case FailureKind::inconsistent:
      return "inconsistent";
    case FailureKind::integrator:
      return "integrator";
  }
  return "unknown";
}

bool is_integrator_failure(FailureKind k) {
  return k != FailureKind::none && k != FailureKind::law_domain && k != FailureKind::law_non_finite;
}

FailureKind failure_of_step(StepFailure f) {
  switch (f) {
    case StepFailure::none:
      return FailureKind::integrator;  // a failure without its code
    case StepFailure::step_underflow:
      return FailureKind::step_underflow;
    case StepFailure::attempts_exhausted:
      return FailureKind::attempts_exhausted;
    case StepFailure::non_finite_state:
      return FailureKind::non_finite_state;
    case StepFailure::singular_matrix:
      return FailureKind::singular_matrix;
    case StepFailure::unstable_step:
      return FailureKind::unstable_step;
    case StepFailure::library_error:
      return FailureKind::library_error;
  }
  return FailureKind::integrator;
}

std::string_view to_string(ImpactStatus s) {
  switch (s) {
    case ImpactStatus::separated:
      return "separated";
    case ImpactStatus::captured:
      return "captured";
    case ImpactStatus::failed:
      return "failed";
  }
  return "?";
}

std::string_view to_string(EventKind k) {
  switch (k) {
    case EventKind::onset:
      return "onset";
    case EventKind::yield:
      return "yield";
    case EventKind::max_compression:
      return "max_compression";
    case EventKind::max_displacement:
      return "max_displacement";
    case EventKind::peak_force:
      return "peak_force";
    case EventKind::separation:
      return "separation";
    case EventKind::capture:
      return "capture";
  }
  return "?";
}

std::optional<IntegratorOptions::Invalid> IntegratorOptions::invalid() const {
  auto bad = [](std::string field, std::string range, auto got) {
    std::ostringstream os;
    os << "must lie in " << range << " (got " << got << ")";
    return Invalid{std::move(field), os.str()};
  };
  if (!(rtol >= 1e-15 && rtol <= 1e-2)) return bad("--rtol", "[1e-15, 1e-2]", rtol);
  if (!(atol > 0 && atol <= 1e-2)) return bad("--atol", "(0, 1e-2]", atol);
  if (!(dt >= 0 && dt <= 0.5 && std::isfinite(dt)))
    return bad("--dt", "(0, 0.5] (normalised step)", dt);
  if (!(max_steps > 0)) return bad("--max-steps", "[1, 9223372036854775807]", max_steps);
  if (const std::string& why = machine_code_environment_problem(); !why.empty())
    return Invalid{"IVV_MACHINE_CODE", why};
  return std::nullopt;
}

std::string IntegratorOptions::invalid_reason() const {
  const auto why = invalid();
  return why ? why->field + " " + why->message : std::string();
}

void validate(const IntegratorOptions& options) {
  if (const auto why = options.invalid()) throw InputError(why->field, why->message);
}

void validate(const SimulationRequest& req) {
  const ValidatedRequest checked(req);
}

ValidatedRequest::ValidatedRequest(const SimulationRequest& req) : request_(&req) {
  derived_ = validate_and_derive(req.scene);
  if (req.scene.damping.kind == Damping::Kind::structure &&
      req.scene.damping.structure.finite_plate())
    throw InputError("structure.length_x",
                     "a finite plate is modelled by its modes (ivv simulate), not by the "
                     "paper's dashpot this command runs; without length_x and length_y the "
                     "plate is infinite and its dashpot c = 8 sqrt(rho h D*) is used");
  validate(req.options);
  validate_parameters(req.law, req.parameters);
  const LawInfo& law = law_info(req.law);
  if (law.needs_yield_strength && !req.scene.yield_strength) {
    throw InputError("target.yield_strength",
                     "required by the " + std::string(law.name) +
                         " law (its yield deformation z_y = 0.68 S_y^2 pi^2 R*/E*^2); give "
                         "yield_strength or shear_strength in [target], a finite number > 0 "
                         "Pa, or use a law without yield (hertz, hunt-crossley)");
  }
  if (req.law != LawKind::expression && !req.expression.force.empty())
    throw InputError("--force", "an expression law replaces --law " + std::string(law.name) +
                                    "; give one or the other");
  if (req.law == LawKind::expression && req.expression.force.empty())
    throw InputError("--force", "the expression law needs a force expression");
  bool rate_dependent = law.rate_dependent;
  if (req.law == LawKind::expression) {
    expression_ = detail::compile_expression_law(req, derived_);  // once: the run uses it too
    rate_dependent = expression_->uses_rate();
  }
  if (rate_dependent && req.scene.damping.kind != Damping::Kind::none) {
    throw InputError(
        req.scene.damping.kind == Damping::Kind::ratio          ? "--zeta"
        : req.scene.damping.kind == Damping::Kind::zener_lambda ? "--lambda"
        : req.scene.damping.kind == Damping::Kind::structure    ? "structure"
                                                                : "--c",
        std::string(req.law == LawKind::expression ? "an expression that uses zdot"
                                                   : "the " + std::string(law.name) + " law") +
            " carries its own damping and runs without the series dashpot");
  }
}

ValidatedRequest::ValidatedRequest(const SimulationRequest& req, Trusted t)
    : ValidatedRequest(req, derive(req.scene), t) {}

ValidatedRequest::ValidatedRequest(const SimulationRequest& req, const DerivedParameters& derived,
                                   Trusted)
    : request_(&req), derived_(derived) {
  if (req.law == LawKind::expression) expression_ = detail::compile_expression_law(req, derived_);
}

namespace detail {
std::shared_ptr<const CompiledExpressions> compile_expression_law(const SimulationRequest& req,
                                                                  const DerivedParameters& p) {
  return std::make_shared<const CompiledExpressions>(req.expression, req.parameters, req.scene, p);
}
}  // namespace detail

namespace {

template <std::size_t... I>
ImpactResult dispatch(const ValidatedRequest& v, std::size_t index,
                      std::vector<TrajectoryPoint>* trajectory, std::index_sequence<I...>) {
  using Run = ImpactResult (*)(const ValidatedRequest&, std::vector<TrajectoryPoint>*);
  static constexpr Run runs[] = {&detail::IntegratorInstance<I>::simulate...};
  return runs[index](v, trajectory);
}

ImpactResult dispatch(const ValidatedRequest& v, IntegratorKind integrator,
                      std::vector<TrajectoryPoint>* trajectory) {
  const auto index = static_cast<std::size_t>(integrator);
  if (index < kIntegratorKinds)
    return dispatch(v, index, trajectory, std::make_index_sequence<kIntegratorKinds>{});
  ImpactResult r;
  r.failure = FailureKind::integrator;
  r.reason =
      "no integrator with the number " + std::to_string(index) + " (not in all_integrators())";
  return r;
}

}  // namespace

ImpactResult simulate(const SimulationRequest& req, std::vector<TrajectoryPoint>* trajectory) {
  return simulate(ValidatedRequest(req), trajectory);
}

ImpactResult simulate(const ValidatedRequest& v, std::vector<TrajectoryPoint>* trajectory) {
  if (v.request().model == ModelKind::automatic)
    return run_model(
        v, decide_model(v, trajectory ? RunOutput::result_and_trajectory : RunOutput::result),
        trajectory);
  return detail::simulate_full(v, effective_integrator(v), trajectory);
}

IntegratorKind effective_integrator(const ValidatedRequest& v) {
  return v.request().auto_integrator ? auto_integrator(v.request(), v.derived())
                                     : v.request().integrator;
}

namespace detail {
ImpactResult simulate_full(const ValidatedRequest& v, IntegratorKind integrator,
                           std::vector<TrajectoryPoint>* trajectory) {
  ImpactResult r = dispatch(v, integrator, trajectory);
  finish_full(r, integrator);
  return r;
}

void finish_full(ImpactResult& r, IntegratorKind integrator) {
  // (an out-of-range kind was answered by dispatch with a failure; it has no name)
  if (static_cast<std::size_t>(integrator) < integrator_table().size()) {
    r.integrator = to_string(integrator);
    fail_non_finite_outcome(r, r.integrator);  // never a NaN beside a success status
  }
  // A failure always says why: one that reached here without a reason is named as such.
  if (!r.ok() && r.reason.empty()) {
    if (r.failure == FailureKind::none) r.failure = FailureKind::integrator;
    r.reason = std::string(to_string(integrator)) + ": the run failed without a reason";
  }
}
}  // namespace detail

}  // namespace ivv
