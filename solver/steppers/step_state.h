// What every stepper keeps about its last accepted step [t0, t1], and the accessors the driver
// (impact_driver.h) reads: t0(), t1(), x0(), x1() and steps(), the number of accepted steps.
//
//   StepState          the step's ends and the count (the base of every stepper written here)
//   AdaptiveStepState  adds the tolerances rtol/atol, the step h to try next and fixed-step
//                      mode (IntegratorOptions::fixed_step: error control off, h = dt), and
//                      judge_attempt(), the verdict of the one step controller
//                      (step_controller.h) on each attempt of a step, for the error-controlled
//                      one-step methods (dop853, dp45, rodas4)
// HermiteSteps (hermite.h) adds the end derivatives and the cubic Hermite interpolant for the
// steppers without a dense output. A stepper's traits (name, order, implicit, dense_output,
// fixed_step, fixed_step_mode, reference) stay its own.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string_view>

#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_controller.h"
#include "solver/steppers/step_result.h"

namespace ivv {

// {0, 1, ..., N - 1}: every component, for a stepper's interpolate(sys, t, out, which).
template <std::size_t N>
constexpr std::array<std::size_t, N> all_components() {
  std::array<std::size_t, N> all{};
  for (std::size_t i = 0; i < N; ++i) all[i] = i;
  return all;
}

// Sizes v as x when the state type has a run-time size (std::vector: the finite plate's state);
// nothing for std::array. Steppers size their work vectors so in start(), never per step.
template <class State>
void size_like(State& v, const State& x) {
  if constexpr (requires { v.resize(x.size()); }) v.resize(x.size());
}

// What one attempt of a controlled step reports: its error norm, or a failure that no smaller
// step can cure (a singular iteration matrix).
template <class T>
struct AttemptOutcome {
  T norm{};
  StepFailure failure = StepFailure::none;
};

template <class System>
class StepState {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;

  T t0() const { return t0_; }
  T t1() const { return t1_; }
  const state_type& x0() const { return x0_; }
  const state_type& x1() const { return x1_; }
  long steps() const { return steps_; }

 protected:
  T t0_{}, t1_{};
  state_type x0_{}, x1_{};
  long steps_ = 0;
};

template <class System>
class AdaptiveStepState : public StepState<System> {
 public:
  using T = typename System::value_type;

  // The error-controlled steppers written here may start past onset, from the onset series
  // (impact_driver.h, onset_series.h); odeint's, GSL's and the reference start at tau = 0, so
  // that the cross-implementation cases compare a series start with an integration from onset.
  static constexpr bool starts_from_onset_series = true;
  // The step to try first from the state start() is given next (ignored in fixed-step mode).
  void propose_step(T h) {
    if (!fixed_) h_ = h;
  }
  // The step the controller proposes to try next (the fixed dt in fixed-step mode).
  T proposed_step() const { return h_; }
  // The step to try next scaled by `factor` (ignored in fixed-step mode).
  void scale_proposed_step(T factor) {
    if (!fixed_) h_ *= factor;
  }

 protected:
  explicit AdaptiveStepState(const IntegratorOptions& opt)
      : rtol_(opt.rtol),
        atol_(opt.atol),
        fixed_(opt.fixed_step),
        h_(opt.fixed_step ? opt.fixed_dt() : opt.initial_dt) {}

  // The attempts of one step from (t0, x0), a loop in the stepper (its attempt stays inline,
  // where the right-hand side is inlined into the stages: a loop in here behind a callback
  // cost 15 % more instructions on a paper map, the system no longer inlined):
  //   begin_attempts();
  //   for (;;) { const T h = h_; <attempt: x1 and its error norm>;
  //              if (auto done = judge_attempt<Q>(name, h, outcome)) return *done; }
  // judge_attempt applies the controller of step_controller.h with the stepper's error
  // exponent Q: accepted or failed it returns the step's result (on failure t1 = t0,
  // x1 = x0), otherwise h_ is the next attempt's length.
  void begin_attempts() { control_.begin(); }

  template <int Q>
  std::optional<StepResult> judge_attempt(std::string_view stepper, T h,
                                          const AttemptOutcome<T>& outcome) {
    if (outcome.failure != StepFailure::none)
      return fail(stepper, outcome.failure, control_.attempts());
    if (fixed_) {
      if (std::isfinite(static_cast<double>(outcome.norm))) return accept(h, h);
      return fail(stepper, StepFailure::non_finite_state, 1);
    }
    T next{};
    const StepVerdict verdict = control_.template judge<Q>(h, outcome.norm, this->t0_, next);
    if (verdict.action == StepVerdict::Action::accept) return accept(h, next);
    h_ = next;
    if (verdict.action == StepVerdict::Action::fail)
      return fail(stepper, verdict.failure, control_.attempts());
    return std::nullopt;
  }

  // The attempt of length h from t0 passed: t1 = t0 + h, and `next` is the step to try next
  // (ignored in fixed-step mode, where h stays dt).
  StepResult accept(T h, T next) {
    this->t1_ = this->t0_ + h;
    if (!fixed_) h_ = next;
    ++this->steps_;
    return StepResult::success();
  }

  // A failed step leaves the stepper at its start (t1 = t0, x1 = x0), with the one message.
  StepResult fail(std::string_view stepper, StepFailure code, int attempts) {
    this->t1_ = this->t0_;
    this->x1_ = this->x0_;
    return StepResult::failure(code,
                               step_failure_message(stepper, code, static_cast<double>(this->t0_),
                                                    static_cast<double>(rtol_), attempts));
  }

  T rtol_, atol_;
  bool fixed_;
  T h_;
  StepController<T> control_;
};

}  // namespace ivv
