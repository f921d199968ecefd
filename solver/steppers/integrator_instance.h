// Entry I of IntegratorList (solver/steppers/integrator_list.h), compiled in a translation unit of
// its own that solver/CMakeLists.txt generates for each entry, to spread the compile time of the
// heavy stepper instantiations. This header only declares: the dispatch (solver/simulate.cc)
// and the traits table (solver/steppers/integrators.cc) call the members without instantiating a
// stepper. The definitions are in solver/steppers/integrator_instance_impl.h; an entry whose unit
// is missing is a link error naming IntegratorInstance<I>, never another integrator run instead.
#pragma once

#include <cstddef>
#include <vector>

#include "solver/result.h"
#include "solver/steppers/integrators.h"

namespace ivv {
class ValidatedRequest;
struct TrajectoryPoint;
}  // namespace ivv

namespace ivv::detail {

template <std::size_t I>
struct IntegratorInstance {
  // simulate() of the request with entry I's stepper (solver/simulate.h).
  static ImpactResult simulate(const ValidatedRequest& request,
                               std::vector<TrajectoryPoint>* trajectory);
  // Entry I's row of the traits table, read from the stepper's constants.
  static IntegratorTraits traits();
};

}  // namespace ivv::detail
