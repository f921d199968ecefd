// The integrators ivv offers, as ONE list of types (Boost.Mp11). Everything else is generated
// from it: the traits table and the name lookup (solver/steppers/integrators.cc, from each
// stepper's own constants), the run-time dispatch (solver/simulate.cc, simulate_law.h), and the
// explicit instantiations, one translation unit per entry (solver/CMakeLists.txt generates them
// from the count of entries below).
//
// Adding an integrator: its stepper header in solver/steppers/ (with the constants name,
// description, order, implicit, dense_output, fixed_step, fixed_step_mode, reference), its test,
// an enumerator in IntegratorKind (solver/steppers/integrators.h: code and tests name integrators
// by it) and one IntegratorEntry here, in enumerator order. The static_asserts below refuse an
// entry out of order or a missing one at compile time; there is no `default:` that would run
// another integrator.
//
// Heavy: includes every stepper (odeint, GSL, Boost.Multiprecision). Only the translation
// units that instantiate or inspect steppers include it; the rest of the code uses
// solver/steppers/integrators.h.
#pragma once

#include <boost/mp11/algorithm.hpp>
#include <boost/mp11/list.hpp>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "solver/steppers/dop853.h"
#include "solver/steppers/dp45.h"
#include "solver/steppers/gsl_odeiv2.h"
#include "solver/steppers/integrators.h"
#include "solver/steppers/odeint_dopri5.h"
#include "solver/steppers/odeint_rkf78_mp.h"
#include "solver/steppers/odeint_rosenbrock4.h"
#include "solver/steppers/rk4.h"
#include "solver/steppers/rodas.h"

namespace ivv {

// One integrator: its IntegratorKind, the stepper template (instantiated per system) and the
// scalar it integrates in.
template <IntegratorKind Kind, template <class> class Stepper, class Scalar = double>
struct IntegratorEntry {
  static constexpr IntegratorKind kind = Kind;
  template <class System>
  using stepper = Stepper<System>;
  using scalar = Scalar;
};

template <class System>
using GslRk8pdStepper = GslStepper<System, GslMethod::rk8pd>;
template <class System>
using GslMsbdfStepper = GslStepper<System, GslMethod::msbdf>;

using IntegratorList = boost::mp11::mp_list<
    IntegratorEntry<IntegratorKind::odeint_dopri5, OdeintDopri5Stepper>,
    IntegratorEntry<IntegratorKind::odeint_rosenbrock4, OdeintRosenbrock4Stepper>,
    IntegratorEntry<IntegratorKind::rk4, Rk4Stepper>,
    IntegratorEntry<IntegratorKind::dp45, Dp45Stepper>,
    IntegratorEntry<IntegratorKind::dop853, Dop853Stepper>,
    IntegratorEntry<IntegratorKind::gsl_rk8pd, GslRk8pdStepper>,
    IntegratorEntry<IntegratorKind::gsl_msbdf, GslMsbdfStepper>,
    IntegratorEntry<IntegratorKind::rodas4, Rodas4Stepper>,
    IntegratorEntry<IntegratorKind::mp50, OdeintRkf78MpStepper, mp50>>;

inline constexpr std::size_t kIntegratorCount = boost::mp11::mp_size<IntegratorList>::value;

namespace detail {
template <std::size_t... I>
constexpr bool entries_in_kind_order(std::index_sequence<I...>) {
  return ((boost::mp11::mp_at_c<IntegratorList, I>::kind == static_cast<IntegratorKind>(I)) && ...);
}
}  // namespace detail

static_assert(detail::entries_in_kind_order(std::make_index_sequence<kIntegratorCount>{}),
              "IntegratorList: entry i must be IntegratorKind number i (enumerator order)");
static_assert(kIntegratorCount == kIntegratorKinds,
              "IntegratorList: one entry per IntegratorKind enumerator");

// Calls f.template operator()<Entry>() for the entry of `kind`, chosen once per impact.
// An out-of-range kind (a cast from a bad number) is refused: std::out_of_range.
template <class F>
decltype(auto) with_integrator(IntegratorKind kind, F&& f) {
  const auto index = static_cast<std::size_t>(kind);
  if (index >= kIntegratorCount)
    throw std::out_of_range("no integrator with the number " + std::to_string(index));
  return boost::mp11::mp_with_index<kIntegratorCount>(index, [&](auto I) -> decltype(auto) {
    return f.template operator()<boost::mp11::mp_at_c<IntegratorList, I>>();
  });
}

}  // namespace ivv
