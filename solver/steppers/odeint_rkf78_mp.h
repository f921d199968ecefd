// The 50-digit reference: Boost.Odeint's Runge-Kutta-Fehlberg 7(8) (Fehlberg, NASA TR R-287,
// 1968) under odeint's step-size controller, on boost::multiprecision::cpp_bin_float_50, at a
// tolerance (default 1e-26) far below anything double precision can resolve. It shares the
// laws, the normalised system and the event definitions with the double-precision
// integrators, and nothing else. No dense output: the event locator works on cubic Hermite
// and refines by re-stepping with the eighth-order formula.
#pragma once

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/numeric/odeint.hpp>
#include <sstream>

#include "solver/driver/hermite.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

using mp50 = boost::multiprecision::cpp_bin_float_50;

// odeint's default error checker cannot take the inf-norm of std::array<cpp_bin_float_50, N>
// (extract_value_type has no specialisation for multiprecision numbers); this one computes the
// same scaled max norm, max_i |err_i| / (atol + rtol |x_i|), element by element.
template <class T>
struct MpErrorChecker {
  using value_type = T;
  using algebra_type = boost::numeric::odeint::array_algebra;
  T atol, rtol;
  template <class State, class Deriv, class Err, class Time>
  T error(algebra_type&, const State& x_old, const Deriv&, Err& x_err, Time) const {
    using std::abs;
    T worst = 0;
    for (std::size_t i = 0; i < x_err.size(); ++i) {
      const T e = abs(x_err[i]) / (atol + rtol * abs(x_old[i]));
      if (e > worst) worst = e;
    }
    return worst;
  }
};

template <class System>
class OdeintRkf78MpStepper : public HermiteSteps<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "mp50";
  static constexpr int order = 8;
  static constexpr bool implicit = false;
  static constexpr bool fixed_step = false;
  static constexpr bool fixed_step_mode = false;
  static constexpr bool reference = true;  // the yardstick the others are measured against
  // the reference (rtol 1e-26 in 50 digits), its result rounded to double
  static constexpr double measured_relative_error = 1e-15;
  static constexpr std::string_view description =
      "50-digit reference: odeint Runge-Kutta-Fehlberg 7(8) on cpp_bin_float_50, tol 1e-26";

  explicit OdeintRkf78MpStepper(const IntegratorOptions& opt)
      : controlled_(MpErrorChecker<T>{T(opt.reference_tolerance), T(opt.reference_tolerance)}),
        h_(opt.initial_dt * 1e-3) {}

  StepResult step(const System& sys) {
    this->begin_step();
    auto rhs = [&sys](const state_type& x, state_type& dxdt, T t) { sys(x, dxdt, t); };
    T t = t0_;
    state_type x = x0_;
    for (int attempt = 0;; ++attempt) {
      if (controlled_.try_step(rhs, x, t, h_) == boost::numeric::odeint::success) break;
      if (attempt > 200 || h_ < T(1e-40)) {
        std::ostringstream os;
        os << "mp50: step size underflow at tau = " << static_cast<double>(t0_);
        return StepResult::failure(StepFailure::step_underflow, os.str());
      }
    }
    this->end_step(sys, t, x);
    return StepResult::success();
  }

  StepResult restep(const System& sys, T t, state_type& out) {
    auto rhs = [&sys](const state_type& x, state_type& dxdt, T tt) { sys(x, dxdt, tt); };
    error_stepper().do_step(rhs, x0_, t0_, out, t - t0_);
    return StepResult::success();
  }

 private:
  using Base = HermiteSteps<System>;
  using Base::f0_;
  using Base::t0_;
  using Base::x0_;

  using error_stepper =
      boost::numeric::odeint::runge_kutta_fehlberg78<state_type, T, state_type, T>;
  using controlled_type =
      boost::numeric::odeint::controlled_runge_kutta<error_stepper, MpErrorChecker<T>>;
  controlled_type controlled_;
  T h_;
};

}  // namespace ivv
