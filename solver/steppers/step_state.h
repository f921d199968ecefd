// What every stepper keeps about its last accepted step [t0, t1], and the accessors the driver
// (impact_driver.h) reads: t0(), t1(), x0(), x1() and steps(), the number of accepted steps.
//
//   StepState          the step's ends and the count (the base of every stepper written here)
//   AdaptiveStepState  adds the tolerances rtol/atol, the step h to try next and fixed-step
//                      mode (IntegratorOptions::fixed_step: error control off, h = dt), and
//                      accept(h, next) for the error-controlled one-step methods (dop853, dp45,
//                      rodas4)
// HermiteSteps (hermite.h) adds the end derivatives and the cubic Hermite interpolant for the
// steppers without a dense output. A stepper's traits (name, order, implicit, dense_output,
// fixed_step, fixed_step_mode, reference) stay its own.
#pragma once

#include <array>
#include <cstddef>

#include "solver/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

// {0, 1, ..., N - 1}: every component, for a stepper's interpolate(sys, t, out, which).
template <std::size_t N>
constexpr std::array<std::size_t, N> all_components() {
  std::array<std::size_t, N> all{};
  for (std::size_t i = 0; i < N; ++i) all[i] = i;
  return all;
}

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

 protected:
  explicit AdaptiveStepState(const IntegratorOptions& opt)
      : rtol_(opt.rtol),
        atol_(opt.atol),
        fixed_(opt.fixed_step),
        h_(opt.fixed_step ? opt.fixed_dt() : opt.initial_dt) {}

  // The attempt of length h from t0 passed: t1 = t0 + h, and `next` is the step to try next
  // (ignored in fixed-step mode, where h stays dt).
  StepResult accept(T h, T next) {
    this->t1_ = this->t0_ + h;
    if (!fixed_) h_ = next;
    ++this->steps_;
    return StepResult::success();
  }

  T rtol_, atol_;
  bool fixed_;
  T h_;
};

}  // namespace ivv
