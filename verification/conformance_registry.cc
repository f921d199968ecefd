// The laws of the registry as laws under test: a built-in law by its LawKind, or the expression
// law of a request.
#include <memory>

#include "solver/laws/law_registry.h"
#include "solver/plate/plate_law.h"
#include "solver/simulate_law.h"
#include "verification/conformance.h"
#include "verification/conformance_law.h"

namespace ivv::conformance {

LawUnderTest registry_law(const SimulationRequest& request) {
  LawUnderTest t;
  const LawInfo& info = law_info(request.law);
  t.name = request.law == LawKind::expression ? "expression" : std::string(info.name);
  t.description = std::string(info.summary);
  SimulationRequest base = request;
  if (request.law == LawKind::expression) {
    t.description = "F = " + request.expression.force;
    if (!request.expression.unload.empty())
      t.description += "; unloading F = " + request.expression.unload;
    t.description += request.expression.allow_tension ? "; tension allowed, contact ends at z = 0"
                                                      : "; clamped F >= 0, contact ends at F = 0";
    if (!request.expression.onset_force.empty())
      t.description += "; declared onset force F(0) = " + request.expression.onset_force;
    t.allows_tension = request.expression.allow_tension;
    t.runs_in_reference = false;
    t.rate_dependent = detail::compile_expression_law(request, derive(request.scene))->uses_rate();
    t.probe = [base](const Scene& s) -> std::unique_ptr<LawProbe> {
      const auto compiled = detail::compile_expression_law(
          [&] {
            SimulationRequest r = base;
            r.scene = s;
            return r;
          }(),
          derive(s));
      if (compiled->uses_rate())
        return std::make_unique<TypedProbe<ExpressionLaw<true>>>(
            ExpressionLaw<true>{compiled, base.expression.allow_tension});
      return std::make_unique<TypedProbe<ExpressionLaw<false>>>(
          ExpressionLaw<false>{compiled, base.expression.allow_tension});
    };
  } else {
    t.rate_dependent = info.rate_dependent;
    t.probe = [base](const Scene& s) -> std::unique_ptr<LawProbe> {
      return with_builtin_law(base.law, base.parameters, derive(s),
                              [](const auto& law) -> std::unique_ptr<LawProbe> {
                                using Law = std::decay_t<decltype(law)>;
                                return std::make_unique<TypedProbe<Law>>(law);
                              });
    };
  }
  t.simulate = [base](const Scene& s, IntegratorKind k, const IntegratorOptions& o) {
    SimulationRequest r = base;
    r.scene = s;
    r.integrator = k;
    r.auto_integrator = false;  // this integrator, not the one --integrator auto would pick
    r.model = ModelKind::full;  // the law integrated: the checks judge the integrators on it
    r.options = o;
    return ivv::simulate(r);
  };
  t.simulate_plate = [base](const Scene& s, const PlateImpactOptions& o) {
    SimulationRequest r = base;
    r.scene = s;
    return simulate_plate_law(r, o);
  };
  t.trajectory = [base](const Scene& s, const IntegratorOptions& o) {
    SimulationRequest r = base;
    r.scene = s;
    r.integrator = IntegratorKind::dp45;
    r.auto_integrator = false;
    r.model = ModelKind::full;
    r.options = o;
    std::vector<TrajectoryPoint> points;
    ivv::simulate(r, &points);
    return points;
  };
  return t;
}

}  // namespace ivv::conformance
