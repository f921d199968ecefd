// Outcome of one attempted step of an integrator adapter: ok, or a failure with a code (for
// tests and programs) and a reason (for people).
#pragma once

#include <string>
#include <string_view>

namespace ivv {

// Every way one step can fail. The codes are stable: tests assert them, and the run's
// FailureKind (solver/result.h) carries them to JSON and the command line.
enum class StepFailure {
  none,
  step_underflow,      // the step the error test needs is below 1e-14 (1 + |t|)
  attempts_exhausted,  // the error test rejected every attempt of one step
  non_finite_state,    // f, its Jacobian or the new state is NaN or infinite (fixed step)
  singular_matrix,     // an implicit stepper's iteration matrix is singular
  unstable_step,       // a fixed step outside the method's stability region
  library_error,       // a library integrator (odeint, GSL) reported an error of its own
};

constexpr std::string_view to_string(StepFailure f) {
  switch (f) {
    case StepFailure::none:
      return "none";
    case StepFailure::step_underflow:
      return "step_underflow";
    case StepFailure::attempts_exhausted:
      return "attempts_exhausted";
    case StepFailure::non_finite_state:
      return "non_finite_state";
    case StepFailure::singular_matrix:
      return "singular_matrix";
    case StepFailure::unstable_step:
      return "unstable_step";
    case StepFailure::library_error:
      return "library_error";
  }
  return "unknown";
}

struct StepResult {
  bool ok = true;
  StepFailure code = StepFailure::none;
  std::string reason;  // why the integrator could not go on (empty when ok)
  static StepResult success() { return {}; }
  static StepResult failure(StepFailure code, std::string why) {
    return {false, code, std::move(why)};
  }
};

}  // namespace ivv
