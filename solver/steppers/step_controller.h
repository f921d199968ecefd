// The one adaptive step-size controller of the error-controlled one-step methods written here
// (dp45.h, dop853.h, rodas.h), generic in the state type and size: a stepper supplies an
// attempt of length h that returns the weighted error norm ||err|| of that attempt, and the
// controller decides (E. Hairer, S. P. Norsett, G. Wanner, Solving Ordinary Differential
// Equations I, 2nd ed., Springer 1993, §II.4, "Automatic step size control"; the same rules as
// Boost.Odeint's default_error_checker and default_step_adjuster):
//
//   accept         ||err|| <= 1
//   next step      h · clamp(0.9 · ||err||^(-1/q), 0.2, 5),   q = the stepper's error_exponent
//                  (the order of the lower of its embedded pair plus one: 5 dp45, 8 dop853,
//                  4 rodas4); ||err|| = 0 grows by 5
//   no growth      after a rejection within the same step the accepted step's successor is
//                  at most the accepted h (Hairer's rule against oscillating step sizes)
//   non-finite     ||err|| NaN or infinite (a stage left the law's domain, or overflowed):
//                  a rejection, h · 0.2
//   failure        the next h below 1e-14 (1 + |t0|) (StepFailure::step_underflow), or
//                  StepControl::max_attempts rejections in one step (attempts_exhausted). A failed
//                  step leaves the stepper at its start: t1 = t0, x1 = x0, so no state that did not
//                  pass the error test is ever exposed (the driver reads x1 on failure).
//
// Measured against the three controllers it replaces, on a 60 x 60 paper map (v0 0.1-10 m/s
// log, zeta 0-1, rtol 1e-8, dop853, one thread, callgrind): 235.0M -> 240.9M instructions
// (+2.5 %), 50,516 -> 50,747 steps (+0.46 %; dop853's growth was clamped at 6, not 5), every e
// within 4.0e-9 of the old map.
//
// In fixed-step mode (IntegratorOptions::fixed_step: convergence studies) there is no error
// control: h is accepted as it is, unless its state is not finite (non_finite_state).
//
// The weighted norm itself stays with the stepper (dop853's is Hairer's blend of its fifth- and
// third-order estimates); weighted_rms_norm below is the usual one, for the others:
//   ||err|| = sqrt( (1/n) sum_i (err_i / (atol + rtol max(|x0_i|, |x1_i|)))^2 ).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <string_view>

#include "solver/steppers/step_result.h"

namespace ivv {

struct StepControl {
  static constexpr double safety = 0.9;      // of the optimal step
  static constexpr double min_factor = 0.2;  // shrink at most 5 times per rejection
  static constexpr double max_factor = 5.0;  // grow at most 5 times per acceptance
  static constexpr int max_attempts = 100;   // per step: each shrinks h by at least 0.9
  // below this relative to 1 + |t| a step is an underflow (in the normalised time tau)
  static constexpr double underflow = 1e-14;
};

// s norm^(-1/Q): for Q = 4 and 8 by square roots (no pow on the hot path), pow otherwise.
template <int Q, class T>
T scaled_inverse_root(T s, T norm) {
  using std::pow;
  using std::sqrt;
  if constexpr (Q == 4)
    return s / sqrt(sqrt(norm));
  else if constexpr (Q == 8)
    return s / sqrt(sqrt(sqrt(norm)));
  else
    return s * pow(norm, T(-1) / T(Q));
}

// The controller's verdict on one attempt of length h with error norm `norm`.
struct StepVerdict {
  enum class Action { accept, retry, fail };
  Action action = Action::accept;
  StepFailure failure = StepFailure::none;
};

template <class T>
class StepController {
 public:
  // A new step begins: no rejection yet.
  void begin() {
    rejected_ = false;
    attempts_ = 0;
  }

  // Judges the attempt of length h from t0 whose error norm is `norm`, and sets `h_next`:
  // the step to take next (accept) or to try again (retry).
  template <int Q>
  StepVerdict judge(T h, T norm, T t0, T& h_next) {
    using std::abs;
    ++attempts_;
    const bool finite = std::isfinite(static_cast<double>(norm));
    if (finite && norm <= 1) {
      const T grow = norm == 0 ? T(StepControl::max_factor) : factor<Q>(norm);
      h_next = rejected_ ? h * std::min(grow, T(1)) : h * grow;
      return {StepVerdict::Action::accept, StepFailure::none};
    }
    rejected_ = true;
    h_next = finite ? h * factor<Q>(norm) : h * T(StepControl::min_factor);
    if (h_next <= T(StepControl::underflow) * (1 + abs(t0)))
      return {StepVerdict::Action::fail, StepFailure::step_underflow};
    if (attempts_ >= StepControl::max_attempts)
      return {StepVerdict::Action::fail, StepFailure::attempts_exhausted};
    return {StepVerdict::Action::retry, StepFailure::none};
  }

  int attempts() const { return attempts_; }

 private:
  template <int Q>
  static T factor(T norm) {
    return std::clamp(scaled_inverse_root<Q>(T(StepControl::safety), norm),
                      T(StepControl::min_factor), T(StepControl::max_factor));
  }

  bool rejected_ = false;
  int attempts_ = 0;
};

// The one message of a failed step: "<stepper>: <what> at tau = <t0> (cannot meet rtol = R)".
inline std::string step_failure_message(std::string_view stepper, StepFailure f, double t0,
                                        double rtol, int attempts) {
  std::ostringstream os;
  os << stepper << ": ";
  switch (f) {
    case StepFailure::step_underflow:
      os << "step size underflow";
      break;
    case StepFailure::attempts_exhausted:
      os << attempts << " rejected attempts";
      break;
    case StepFailure::non_finite_state:
      os << "the state, the right-hand side or its Jacobian is not finite";
      break;
    case StepFailure::singular_matrix:
      os << "the iteration matrix I/(h gamma) - J is singular";
      break;
    default:
      os << to_string(f);
      break;
  }
  os << " at tau = " << t0;
  if (f == StepFailure::step_underflow || f == StepFailure::attempts_exhausted)
    os << " (cannot meet rtol = " << rtol << ")";
  return os.str();
}

// The usual weighted RMS norm of an error vector (header comment).
template <class State, class T>
T weighted_rms_norm(const State& err, const State& x0, const State& x1, T atol, T rtol) {
  using std::abs;
  using std::max;
  using std::sqrt;
  const std::size_t n = x0.size();
  T sum = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const T r = err[i] / (atol + rtol * max(abs(x0[i]), abs(x1[i])));
    sum += r * r;
  }
  return sqrt(sum / T(n));
}

}  // namespace ivv
