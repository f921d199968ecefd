// Registration of the battery, one function per tier file.
#pragma once

#include "verification/registry.h"

namespace ivv::verification {

void register_analytic_cases(Registry& reg);
void register_cross_implementation_cases(Registry& reg);
void register_conservation_cases(Registry& reg);
void register_convergence_cases(Registry& reg);
void register_stability_cases(Registry& reg);
void register_published_trend_cases(Registry& reg);
void register_example_cases(Registry& reg);

}  // namespace ivv::verification
