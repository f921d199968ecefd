// Boost.Odeint's dense-output Dormand-Prince 5(4) behind the stepper interface of the
// hand-written steppers (solver/steppers/dop853.h): start(sys, t, x), step(sys) -> StepResult,
// interpolate(sys, t, out), t0(), t1(), x0(), x1(), steps(), for a state of any size
// (std::vector<double>: the plate's 2N + 2 entries). The plate driver (plate_impact.h) is a
// template on its stepper; this one is its second integrator beside the hand-written DOP853
// (PlateImpactOptions::stepper), sharing nothing with it but the interface.
//
// Error control: odeint's controlled_runge_kutta with its default error checker,
// max_i |err_i|/(atol + rtol (|x_i| + h |x'_i|)) <= 1; the dense output is dopri5's fourth-order
// continuous extension (Hairer, Norsett & Wanner I, §II.6). A step that cannot meet the tolerance
// (odeint throws after its 500 tries) is a failed StepResult with odeint's message, never a silent
// step.
#pragma once

#include <boost/numeric/odeint.hpp>
#include <exception>
#include <string>
#include <string_view>

#include "solver/steppers/step_result.h"

namespace ivv {

template <class System>
class OdeintDenseDopri5 {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "odeint-dopri5";

  OdeintDenseDopri5(T rtol, T atol, T initial_dt)
      : stepper_(boost::numeric::odeint::make_dense_output(
            atol, rtol, boost::numeric::odeint::runge_kutta_dopri5<state_type>())),
        dt_(initial_dt) {}

  void start(const System&, T t, const state_type& x) {
    stepper_.initialize(x, t, dt_);
    t1_ = t;
    x1_ = x;
  }

  StepResult step(const System& sys) {
    auto f = [&sys](const state_type& x, state_type& dxdt, T t) { sys(x, dxdt, t); };
    try {
      stepper_.do_step(f);
    } catch (const std::exception& e) {
      return StepResult::failure(StepFailure::library_error,
                                 std::string("odeint-dopri5: ") + e.what());
    }
    ++steps_;
    dt_ = stepper_.current_time_step();
    t0_ = stepper_.previous_time();
    t1_ = stepper_.current_time();
    x0_ = stepper_.previous_state();
    x1_ = stepper_.current_state();
    return StepResult::success();
  }

  void interpolate(const System&, T t, state_type& out) const {
    if (out.size() != x1_.size()) out.resize(x1_.size());
    stepper_.calc_state(t, out);
  }

  T t0() const { return t0_; }
  T t1() const { return t1_; }
  const state_type& x0() const { return x0_; }
  const state_type& x1() const { return x1_; }
  long steps() const { return steps_; }

 private:
  using Controlled = boost::numeric::odeint::controlled_runge_kutta<
      boost::numeric::odeint::runge_kutta_dopri5<state_type>>;
  boost::numeric::odeint::dense_output_runge_kutta<Controlled> stepper_;
  T dt_;
  T t0_{}, t1_{};
  state_type x0_, x1_;
  long steps_ = 0;
};

}  // namespace ivv
