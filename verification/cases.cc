#include "verification/cases.h"

namespace ivv::verification {

const Registry& all_cases() {
  static const Registry registry = [] {
    Registry reg;
    register_analytic_cases(reg);
    register_cross_implementation_cases(reg);
    register_conservation_cases(reg);
    register_convergence_cases(reg);
    register_stability_cases(reg);
    register_published_trend_cases(reg);
    register_example_cases(reg);
    register_dem_cases(reg);
    register_structure_cases(reg);
    register_plate_cases(reg);
    register_plate_regime_cases(reg);
    register_conformance_cases(reg);
    register_validation_cases(reg);
    return reg;
  }();
  return registry;
}

}  // namespace ivv::verification
