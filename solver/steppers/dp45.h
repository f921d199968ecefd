// Dormand-Prince 5(4) (Dormand & Prince, J. Comput. Appl. Math. 6:19, 1980), written from its
// Butcher tableau; shares no code with odeint. Seven stages with FSAL (the last stage is f at
// the new point), a fifth-order solution and an embedded fourth-order error estimate:
//
//   err_i = h sum_j (b_j - b*_j) k_j,   ||err|| = rms_i err_i / (atol + rtol max(|x0_i|, |x1_i|))
//
// Step accepted when ||err|| <= 1; next step h * clamp(0.9 ||err||^{-1/5}, 0.2, 5), no growth
// right after a rejection: the one controller of step_controller.h.
// Dense output: the fourth-order continuous extension of Hairer, Norsett & Wanner, Solving ODEs I
// (2nd ed., §II.6; coefficients d_j of their DOPRI5 code):
//   x(t0 + theta h) = x0 + theta (r1 + (1 - theta)(r2 + theta (r3 + (1 - theta) r4)))
//   r1 = x1 - x0, r2 = h k1 - r1, r3 = r1 - h k7 - r2, r4 = h sum_j d_j k_j.
// With fixed_step the error control is off and h = dt (convergence studies).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"
#include "solver/steppers/step_state.h"

namespace ivv {

namespace dp45_tableau {
inline constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
inline constexpr double a21 = 1.0 / 5;
inline constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
inline constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
inline constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                        a54 = -212.0 / 729;
inline constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247,
                        a64 = 49.0 / 176, a65 = -5103.0 / 18656;
// fifth-order weights (= row 7, FSAL)
inline constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                        b6 = 11.0 / 84;
// b - b* (b* the fourth-order weights)
inline constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                        e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
// dense output
inline constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                        d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                        d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
}  // namespace dp45_tableau

template <class System>
class Dp45Stepper : public AdaptiveStepState<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "dp45";
  static constexpr bool dense_output = true;
  static constexpr int order = 5;
  static constexpr int error_exponent = 5;  // 1 + the order of the embedded solution
  static constexpr bool implicit = false;
  static constexpr bool fixed_step = false;  // adaptive; IntegratorOptions::fixed_step turns it off
  static constexpr bool fixed_step_mode = true;
  static constexpr bool reference = false;
  // the paper scene at default settings, relative error of e against mp50: measured 9.7e-11
  static constexpr double measured_relative_error = 1e-9;
  static constexpr std::string_view description =
      "hand-written Dormand-Prince 5(4) from its tableau, own dense output";

  explicit Dp45Stepper(const IntegratorOptions& opt) : AdaptiveStepState<System>(opt) {}

  void start(const System& sys, T t, const state_type& x) {
    t1_ = t;
    x1_ = x;
    for (state_type* v : {&x0_, &k1_, &k2_, &k3_, &k4_, &k5_, &k6_, &k7_, &tmp_}) size_like(*v, x);
    sys(x1_, k7_, t1_);
  }

  StepResult step(const System& sys) {
    t0_ = t1_;
    x0_ = x1_;
    k1_ = k7_;
    this->begin_attempts();
    for (;;) {
      const T h = h_;
      const AttemptOutcome<T> outcome{attempt(sys, h)};
      if (auto done = this->template judge_attempt<error_exponent>(name, h, outcome)) {
        if (!done->ok) k7_ = k1_;  // f at the restored x1 = x0
        return *done;
      }
    }
  }

  // f(t1, x1) on the law's present branch (the next step's first stage, FSAL)
  const state_type& f1() const { return k7_; }

  void interpolate(const System&, T t, state_type& out) const {
    size_like(out, x1_);
    const T th = (t - t0_) / (t1_ - t0_);
    for (std::size_t i = 0; i < x1_.size(); ++i) out[i] = dense(th, i);
  }
  // The components listed in `which` only (the rest of `out` untouched): the event locator's
  // root functions read two (ImpactSystem::event_components).
  template <std::size_t K>
  void interpolate(const System&, T t, state_type& out,
                   const std::array<std::size_t, K>& which) const {
    const T th = (t - t0_) / (t1_ - t0_);
    for (const std::size_t i : which) out[i] = dense(th, i);
  }

 private:
  using Base = AdaptiveStepState<System>;
  using Base::accept;
  using Base::atol_;
  using Base::fixed_;
  using Base::h_;
  using Base::rtol_;
  using Base::t0_;
  using Base::t1_;
  using Base::x0_;
  using Base::x1_;
  // One attempt of length h from (t0, x0): the seven stages, x1, and the error norm. A
  // fixed-size work vector is a local (kept in registers), a run-time-sized one the member.
  T attempt(const System& sys, T h) {
    if constexpr (requires(state_type & v) { v.resize(0); }) {
      return attempt(sys, h, tmp_);
    } else {
      state_type tmp;
      return attempt(sys, h, tmp);
    }
  }
  T attempt(const System& sys, T h, state_type& tmp) {
    using namespace dp45_tableau;
    const std::size_t n = x0_.size();
    for (std::size_t i = 0; i < n; ++i) tmp[i] = x0_[i] + h * a21 * k1_[i];
    sys(tmp, k2_, t0_ + c2 * h);
    for (std::size_t i = 0; i < n; ++i) tmp[i] = x0_[i] + h * (a31 * k1_[i] + a32 * k2_[i]);
    sys(tmp, k3_, t0_ + c3 * h);
    for (std::size_t i = 0; i < n; ++i)
      tmp[i] = x0_[i] + h * (a41 * k1_[i] + a42 * k2_[i] + a43 * k3_[i]);
    sys(tmp, k4_, t0_ + c4 * h);
    for (std::size_t i = 0; i < n; ++i)
      tmp[i] = x0_[i] + h * (a51 * k1_[i] + a52 * k2_[i] + a53 * k3_[i] + a54 * k4_[i]);
    sys(tmp, k5_, t0_ + c5 * h);
    for (std::size_t i = 0; i < n; ++i)
      tmp[i] =
          x0_[i] + h * (a61 * k1_[i] + a62 * k2_[i] + a63 * k3_[i] + a64 * k4_[i] + a65 * k5_[i]);
    sys(tmp, k6_, t0_ + h);
    for (std::size_t i = 0; i < n; ++i)
      x1_[i] = x0_[i] + h * (b1 * k1_[i] + b3 * k3_[i] + b4 * k4_[i] + b5 * k5_[i] + b6 * k6_[i]);
    sys(x1_, k7_, t0_ + h);
    // the error vector into tmp (its last use as a stage argument is done)
    for (std::size_t i = 0; i < n; ++i)
      tmp[i] =
          h * (e1 * k1_[i] + e3 * k3_[i] + e4 * k4_[i] + e5 * k5_[i] + e6 * k6_[i] + e7 * k7_[i]);
    return weighted_rms_norm(tmp, x0_, x1_, atol_, rtol_);
  }

  // Component i of the continuous extension at theta = (t - t0)/h (the comment at the top).
  T dense(T th, std::size_t i) const {
    using namespace dp45_tableau;
    const T h = t1_ - t0_;
    const T om = 1 - th;
    const T r1 = x1_[i] - x0_[i];
    const T r2 = h * k1_[i] - r1;
    const T r3 = r1 - h * k7_[i] - r2;
    const T r4 =
        h * (d1 * k1_[i] + d3 * k3_[i] + d4 * k4_[i] + d5 * k5_[i] + d6 * k6_[i] + d7 * k7_[i]);
    return x0_[i] + th * (r1 + om * (r2 + th * (r3 + om * r4)));
  }

  state_type k1_{}, k2_{}, k3_{}, k4_{}, k5_{}, k6_{}, k7_{};
  state_type tmp_{};  // a stage's argument, then the error vector
};

}  // namespace ivv
