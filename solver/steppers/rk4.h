// Classical fourth-order Runge-Kutta (Kutta 1901), fixed step, written from its tableau:
//
//   k1 = f(t, x)            k2 = f(t + h/2, x + h/2 k1)
//   k3 = f(t + h/2, x + h/2 k2)    k4 = f(t + h, x + h k3)
//   x+ = x + h (k1 + 2 k2 + 2 k3 + k4) / 6                     order 4
//
// Interpolant: cubic Hermite from the step's end points (order 4 matches the method), so the
// shared locator's estimate is refined by re-stepping exactly to the event time.
// A fixed step can be unstable on a stiff scene: each step checks that h lambda lies in the
// RK4 stability region for the eigenvalues of the linearised dynamics, and the step fails with
// that reason instead of producing a silently wrong number.
#pragma once

#include <cmath>
#include <complex>
#include <sstream>
#include <string>

#include "solver/driver/hermite.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

template <class System>
class Rk4Stepper : public HermiteSteps<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "rk4";
  static constexpr int order = 4;
  static constexpr bool implicit = false;
  static constexpr bool fixed_step = true;
  static constexpr bool fixed_step_mode = true;
  static constexpr bool reference = false;
  // the paper scene at default settings, relative error of e against mp50: measured 9.2e-11 (fixed
  // step, --dt default)
  static constexpr double measured_relative_error = 1e-9;
  static constexpr std::string_view description =
      "hand-written classical Runge-Kutta 4, fixed step (--dt), Hermite interpolant";

  explicit Rk4Stepper(const IntegratorOptions& opt) : h_(opt.fixed_dt()) {}

  StepResult step(const System& sys) {
    this->begin_step();
    for (const auto& lambda : sys.eigenvalues(x0_)) {
      const std::complex<double> z = lambda * static_cast<double>(h_);
      const std::complex<double> R = 1.0 + z * (1.0 + z * (0.5 + z * (1.0 / 6 + z / 24.0)));
      if (std::abs(R) > 1.0 + 1e-12) {
        std::ostringstream os;
        os << "rk4: step h = " << static_cast<double>(h_)
           << " (normalised) lies outside the RK4 stability region for this scene (h |lambda| = "
           << std::abs(z) << "); use a smaller --dt or an implicit integrator";
        return StepResult::failure(StepFailure::unstable_step, os.str());
      }
    }
    state_type x1;
    advance(sys, h_, x1);
    this->end_step(sys, t0_ + h_, x1);
    return StepResult::success();
  }

  // Exact RK4 step of length t - t0 from the current step's start.
  StepResult restep(const System& sys, T t, state_type& out) const {
    advance(sys, t - t0_, out);
    return StepResult::success();
  }

 private:
  using Base = HermiteSteps<System>;
  using Base::f0_;
  using Base::t0_;
  using Base::x0_;

  void advance(const System& sys, T h, state_type& out) const {
    state_type k2, k3, k4, tmp;
    const std::size_t n = x0_.size();
    for (std::size_t i = 0; i < n; ++i) tmp[i] = x0_[i] + h / 2 * f0_[i];
    sys(tmp, k2, t0_ + h / 2);
    for (std::size_t i = 0; i < n; ++i) tmp[i] = x0_[i] + h / 2 * k2[i];
    sys(tmp, k3, t0_ + h / 2);
    for (std::size_t i = 0; i < n; ++i) tmp[i] = x0_[i] + h * k3[i];
    sys(tmp, k4, t0_ + h);
    for (std::size_t i = 0; i < n; ++i)
      out[i] = x0_[i] + h / 6 * (f0_[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }

  T h_;
};

}  // namespace ivv
