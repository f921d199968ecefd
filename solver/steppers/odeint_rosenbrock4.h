// Boost.Odeint Rosenbrock4: a linearly implicit, L-stable fourth-order method with an
// embedded third-order estimate (Kaps & Rentrop 1979; Hairer & Wanner, Solving ODEs II, §IV.7)
// for stiff scenes (a weak dashpot, zeta >> 1, makes the spring-dashpot relaxation time
// c/K far shorter than the contact). Uses the analytic Jacobian of impact_system.h and
// odeint's rosenbrock4_dense_output.
#pragma once

#include <boost/numeric/odeint.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4_controller.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4_dense_output.hpp>
#include <exception>
#include <string>

#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

template <class System>
class OdeintRosenbrock4Stepper {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "odeint-rosenbrock4";
  static constexpr bool dense_output = true;
  static constexpr int order = 4;
  static constexpr bool implicit = true;
  static constexpr bool fixed_step = false;
  static constexpr bool fixed_step_mode = false;
  static constexpr bool reference = false;
  // the paper scene at default settings, relative error of e against mp50: measured 2.0e-11
  static constexpr double measured_relative_error = 1e-9;
  static constexpr std::string_view description =
      "Boost.Odeint Rosenbrock 4(3), linearly implicit, dense output: stiff scenes";
  static constexpr std::size_t N = System::N;

  explicit OdeintRosenbrock4Stepper(const IntegratorOptions& opt)
      : stepper_(boost::numeric::odeint::make_dense_output(
            opt.atol, opt.rtol, boost::numeric::odeint::rosenbrock4<double>())),
        dt_(opt.initial_dt),
        buffer_(N) {}

  void start(const System&, T t, const state_type& x) {
    if (started_) dt_ = stepper_.current_time_step();
    to_vector(x, buffer_);
    stepper_.initialize(buffer_, t, dt_);
    started_ = true;
  }

  StepResult step(const System& sys) {
    auto rhs = [&sys](const vector_type& x, vector_type& dxdt, double t) {
      state_type a, d;
      from_vector(x, a);
      sys(a, d, t);
      to_vector(d, dxdt);
    };
    auto jac = [&sys](const vector_type& x, matrix_type& J, double, vector_type& dfdt) {
      state_type a;
      from_vector(x, a);
      sys.jacobian(a, J);
      for (std::size_t i = 0; i < N; ++i) dfdt[i] = 0.0;  // autonomous system
    };
    try {
      stepper_.do_step(std::make_pair(rhs, jac));
    } catch (const std::exception& e) {
      return StepResult::failure(StepFailure::library_error,
                                 std::string("odeint-rosenbrock4: ") + e.what());
    }
    from_vector(stepper_.previous_state(), x0_);
    from_vector(stepper_.current_state(), x1_);
    ++steps_;
    return StepResult::success();
  }

  void interpolate(const System&, T t, state_type& out) const {
    vector_type v(N);
    stepper_.calc_state(t, v);
    from_vector(v, out);
  }

  T t0() const { return stepper_.previous_time(); }
  T t1() const { return stepper_.current_time(); }
  const state_type& x0() const { return x0_; }
  const state_type& x1() const { return x1_; }
  long steps() const { return steps_; }

 private:
  using vector_type = boost::numeric::ublas::vector<double>;
  using matrix_type = boost::numeric::ublas::matrix<double>;
  static void to_vector(const state_type& a, vector_type& v) {
    for (std::size_t i = 0; i < N; ++i) v[i] = a[i];
  }
  static void from_vector(const vector_type& v, state_type& a) {
    for (std::size_t i = 0; i < N; ++i) a[i] = v[i];
  }
  using dense_type = decltype(boost::numeric::odeint::make_dense_output(
      0.0, 0.0, boost::numeric::odeint::rosenbrock4<double>()));
  mutable dense_type stepper_;
  T dt_;
  bool started_ = false;
  vector_type buffer_;
  state_type x0_{}, x1_{};
  long steps_ = 0;
};

}  // namespace ivv
