#include "solver/simulate.h"

#include <array>
#include <cmath>
#include <sstream>

#include "solver/input_error.h"
#include "solver/simulate_impl.h"

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

std::span<const LawKind> all_laws() {
  return kLaws;
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

std::string IntegratorOptions::invalid_reason() const {
  const bool valid = rtol >= 1e-15 && rtol <= 1e-2 && atol > 0 && atol <= 1e-2 && dt >= 0 &&
                     dt <= 0.5 && std::isfinite(dt) && max_steps > 0;
  if (valid) return {};  // no stream on the hot path (validated once per impact)
  std::ostringstream os;
  if (!(rtol >= 1e-15 && rtol <= 1e-2))
    os << "--rtol must lie in [1e-15, 1e-2] (got " << rtol << ")";
  else if (!(atol > 0 && atol <= 1e-2))
    os << "--atol must lie in (0, 1e-2] (got " << atol << ")";
  else if (!(dt >= 0 && dt <= 0.5 && std::isfinite(dt)))
    os << "--dt (normalised step) must lie in (0, 0.5] (got " << dt << ")";
  else if (!(max_steps > 0))
    os << "max_steps must be > 0 (got " << max_steps << ")";
  return os.str();
}

void validate(const IntegratorOptions& options) {
  const std::string why = options.invalid_reason();
  if (!why.empty()) throw InputError(why.substr(0, why.find(' ')), why.substr(why.find(' ') + 1));
}

void validate(const SimulationRequest& req) {
  validate(req.scene);
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
  if (req.law == LawKind::expression)
    rate_dependent = detail::compile_expression_law(req, derive(req.scene))->uses_rate();
  if (rate_dependent && req.scene.damping.kind != Damping::Kind::none) {
    throw InputError(
        req.scene.damping.kind == Damping::Kind::ratio ? "--zeta" : "--c",
        std::string(req.law == LawKind::expression ? "an expression that uses zdot"
                                                   : "the " + std::string(law.name) + " law") +
            " carries its own damping and runs without the series dashpot");
  }
}

namespace detail {
std::shared_ptr<const CompiledExpressions> compile_expression_law(const SimulationRequest& req,
                                                                  const DerivedParameters& p) {
  return std::make_shared<const CompiledExpressions>(req.expression, req.parameters, req.scene, p);
}
}  // namespace detail

ImpactResult simulate(const SimulationRequest& req, std::vector<TrajectoryPoint>* trajectory) {
  validate(req);
  const DerivedParameters p = derive(req.scene);
  switch (req.integrator) {
    case IntegratorKind::odeint_dopri5:
      return detail::simulate_odeint_dopri5(req, p, trajectory);
    case IntegratorKind::odeint_rosenbrock4:
      return detail::simulate_odeint_rosenbrock4(req, p, trajectory);
    case IntegratorKind::rk4:
      return detail::simulate_rk4(req, p, trajectory);
    case IntegratorKind::dp45:
      return detail::simulate_dp45(req, p, trajectory);
    case IntegratorKind::dop853:
      return detail::simulate_dop853(req, p, trajectory);
    case IntegratorKind::gsl_rk8pd:
      return detail::simulate_gsl_rk8pd(req, p, trajectory);
    case IntegratorKind::gsl_msbdf:
      return detail::simulate_gsl_msbdf(req, p, trajectory);
    case IntegratorKind::mp50:
      return detail::simulate_mp50(req, p, trajectory);
  }
  return {};
}

}  // namespace ivv
