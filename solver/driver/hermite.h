// Cubic Hermite interpolation on one step [t0, t1] from the end-point states and derivatives.
//
//   x(t0 + theta h) = h00 x0 + h10 h f0 + h01 x1 + h11 h f1,   theta in [0, 1]
//   h00 = (1 + 2 theta)(1 - theta)^2, h10 = theta (1 - theta)^2,
//   h01 = theta^2 (3 - 2 theta),      h11 = theta^2 (theta - 1)
//
// Local error O(h^4) for smooth solutions; the interpolant for steppers without dense output.
#pragma once

#include <cstddef>

#include "solver/steppers/step_state.h"

namespace ivv {

template <class State, class T>
void hermite_interpolate(const T& t0, const State& x0, const State& f0, const T& t1,
                         const State& x1, const State& f1, const T& t, State& out) {
  const T h = t1 - t0;
  const T th = (t - t0) / h;
  const T om = 1 - th;
  const T h00 = (1 + 2 * th) * om * om;
  const T h10 = th * om * om * h;
  const T h01 = th * th * (3 - 2 * th);
  const T h11 = th * th * (th - 1) * h;
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = h00 * x0[i] + h10 * f0[i] + h01 * x1[i] + h11 * f1[i];
}

// The step bookkeeping of a stepper without dense output: the last accepted step's end points
// and their derivatives, the cubic Hermite interpolant over it, and the accessors the driver
// (impact_driver.h) uses to refine events by re-stepping. A stepper derives from it, calls
// begin_step() before taking a step from (t1, x1) and end_step() with the new point after.
template <class System>
class HermiteSteps : public StepState<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr bool dense_output = false;

  // A new smooth phase starts at (t, x): it becomes the end of a zero-length step.
  void start(const System& sys, T t, const state_type& x) {
    t1_ = t;
    x1_ = x;
    sys(x1_, f1_, t1_);
  }

  void interpolate(const System&, T t, state_type& out) const {
    hermite_interpolate(t0_, x0_, f0_, t1_, x1_, f1_, t, out);
  }

  const state_type& f0() const { return f0_; }
  const state_type& f1() const { return f1_; }

 protected:
  using Base = StepState<System>;
  using Base::steps_;
  using Base::t0_;
  using Base::t1_;
  using Base::x0_;
  using Base::x1_;

  void begin_step() {
    t0_ = t1_;
    x0_ = x1_;
    f0_ = f1_;
  }
  // Records the accepted step's end (one right-hand-side evaluation: the next step's f0).
  void end_step(const System& sys, T t, const state_type& x) {
    t1_ = t;
    x1_ = x;
    sys(x1_, f1_, t1_);
    ++steps_;
  }

  state_type f0_{}, f1_{};
};

}  // namespace ivv
