// The definitions of IntegratorInstance<I> (solver/steppers/integrator_instance.h). Included only
// by the generated translation units, one per entry of IntegratorList, each of which instantiates
// its own entry:  template struct ivv::detail::IntegratorInstance<I>;
#pragma once

#include <boost/mp11/algorithm.hpp>

#include "solver/simulate_impl.h"
#include "solver/steppers/integrator_instance.h"
#include "solver/steppers/integrator_list.h"
#include "solver/steppers/stepper_traits.h"

namespace ivv::detail {

template <std::size_t I>
ImpactResult IntegratorInstance<I>::simulate(const ValidatedRequest& request,
                                             std::vector<TrajectoryPoint>* trajectory) {
  using Entry = boost::mp11::mp_at_c<IntegratorList, I>;
  return simulate_with<Entry::template stepper, typename Entry::scalar>(request, trajectory);
}

template <std::size_t I>
IntegratorTraits IntegratorInstance<I>::traits() {
  using Entry = boost::mp11::mp_at_c<IntegratorList, I>;
  return stepper_traits<Entry::template stepper, typename Entry::scalar>(Entry::kind);
}

}  // namespace ivv::detail
