// The integrators ivv offers and what each one is: one table, generated from the one list of
// steppers (solver/steppers/integrator_list.h) and the steppers' own constants (each stepper in
// solver/steppers/ declares name, description, order, implicit, dense_output, fixed_step and
// reference), read by the CLI (`ivv integrators`), the benchmarks, the report's speed section,
// the verification cases and the automatic choice. Nothing else keeps a list of integrator
// names or properties; capabilities are read from the traits, never by comparing kinds.
//
// Traits (what each column means):
//   order         classical order of the solution the stepper propagates (the generic
//                 convergence case, verification/cases_convergence.cc, checks it)
//   implicit      the stepper solves with the Jacobian: stable on stiff scenes (large zeta)
//   dense_output  the stepper has its own continuous extension; otherwise the event locator
//                 works on a cubic Hermite interpolant and refines by re-stepping
//   fixed_step    no error control: accuracy is set by IntegratorOptions::dt, not rtol
//   fixed_step_mode  runs at the fixed step IntegratorOptions::dt with its error control off
//                 when IntegratorOptions::fixed_step is set (convergence studies); false for
//                 the library implicit steppers, whose controllers (odeint's Rosenbrock, the
//                 variable-order BDF) are not separable from the method, and rodas4 (see
//                 solver/steppers/rodas.h)
//   reference     the 50-digit yardstick, not a production integrator (slow)
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace ivv {

enum class IntegratorKind {
  odeint_dopri5,
  odeint_rosenbrock4,
  rk4,
  dp45,
  dop853,
  gsl_rk8pd,
  gsl_msbdf,
  rodas4,
  mp50  // the 50-digit reference (slow: the yardstick, not a production integrator)
};
// The number of enumerators (keep mp50 last, or name the new last one here). The list of
// solver/steppers/integrator_list.h has exactly one entry per enumerator (a static_assert holds
// it).
inline constexpr std::size_t kIntegratorKinds = static_cast<std::size_t>(IntegratorKind::mp50) + 1;

struct IntegratorTraits {
  IntegratorKind kind = IntegratorKind::odeint_dopri5;
  std::string_view name;         // the CLI name (--integrator)
  std::string_view description;  // one line, for `ivv integrators -v`
  int order = 0;
  bool implicit = false;
  bool dense_output = false;
  bool fixed_step = false;
  bool fixed_step_mode = false;
  bool reference = false;
  // The largest relative error of e measured on the paper scene at default settings against
  // the 50-digit reference, rounded up to a power of ten (solver/choice/integrator_accuracy.h;
  // integrators_test.cc re-measures it): each stepper's own measured_relative_error.
  double measured_relative_error = 0.0;
};

// Every integrator, in IntegratorKind order.
std::span<const IntegratorTraits> integrator_table();
const IntegratorTraits& traits(IntegratorKind k);

std::span<const IntegratorKind> all_integrators();
// The double-precision integrators (every one but the reference).
std::vector<IntegratorKind> production_integrators();
std::string_view to_string(IntegratorKind k);
std::string_view describe(IntegratorKind k);
// Parse a name; throws InputError(field, "unknown ...; valid names: ...") otherwise.
IntegratorKind parse_integrator(const std::string& name, const std::string& field = "--integrator");

}  // namespace ivv
