#include "solver/plate/plate_law.h"

#include <memory>
#include <string>

#include "scene/input_error.h"
#include "solver/plate/plate_law_impact.h"
#include "solver/simulate_impl.h"

namespace ivv {
namespace {

// The expression law of a request, compiled; refused by name where the plate does not model it.
std::shared_ptr<const CompiledExpressions> plate_expression(const SimulationRequest& r) {
  if (r.expression.force.empty())
    throw InputError("--force", "the expression law needs a force expression");
  auto compiled = detail::compile_expression_law(r, derive(r.scene));
  if (compiled->uses_rate())
    throw InputError("--force",
                     "an expression that uses zdot is rate-dependent, which is not modelled on a "
                     "finite plate (its contact force is solved at zdot = 0)");
  require_plate_law(ExpressionLaw<false>{compiled, r.expression.allow_tension}, r.scene);
  return compiled;
}

}  // namespace

void validate_plate_law(const SimulationRequest& r) {
  if (r.law != LawKind::expression) {
    if (!r.expression.force.empty())
      throw InputError("--force", "an expression law replaces --law " +
                                      std::string(to_string(r.law)) + "; give one or the other");
    validate_plate_impact(r.scene, r.law, r.parameters);
    return;
  }
  validate(r.scene);
  require_finite_plate(r.scene);  // the scene, before compiling against it
  plate_expression(r);
}

PlateImpactResult simulate_plate_law(const SimulationRequest& r, const PlateImpactOptions& opt) {
  if (r.law != LawKind::expression) {
    if (!r.expression.force.empty()) validate_plate_law(r);  // the same refusal
    return simulate_plate_impact(r.scene, r.law, r.parameters, opt);
  }
  validate(r.scene);
  require_finite_plate(r.scene);
  const auto compiled = plate_expression(r);
  PlateImpactResult out;
  try {
    out = simulate_plate_impact_of(ExpressionLaw<false>{compiled, false}, r.scene, opt);
  } catch (const std::exception&) {
    if (!compiled->non_finite()) throw;  // a NaN force reached a root finder: reported below
  }
  if (compiled->non_finite()) {
    out.ok = false;
    out.reason = *compiled->non_finite();
  }
  return out;
}

}  // namespace ivv
