// One lane of Dop853Lanes (dop853_lanes.h) seen as the scalar Dop853Stepper that the impact
// driver (solver/driver/impact_driver.h) reads and restarts: t0, t1, x0, x1, f1, steps, the
// dense output on the last step, start() at an event, and the step proposed next. The lane's
// steps themselves are taken by the caller, all lanes at once (Dop853Lanes::attempt(),
// solver/driver/lanes_driver.h), so this stepper has no step(): its driver is run a step at a
// time (ImpactDriver::after_step).
//
// Each accessor is the lane's number as the scalar stepper would hold it after the same steps
// (dop853_lanes_test.cc compares the lanes with the scalar step lane by lane).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include "solver/steppers/dop853_lanes.h"

namespace ivv {

template <class System, class Lanes>
class Dop853LaneStepper {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  using Stepper = Dop853Lanes<System, Lanes>;
  // the traits the driver reads, the scalar stepper's
  static constexpr std::string_view name = Stepper::name;
  static constexpr bool dense_output = true;
  static constexpr bool implicit = false;
  static constexpr bool starts_from_onset_series = true;

  Dop853LaneStepper(Stepper& lanes, std::size_t lane) : lanes_(&lanes), i_(lane) {}

  void start(const System& sys, T t, const state_type& x) { lanes_->start(i_, sys, t, x); }
  void propose_step(T h) { lanes_->propose_step(i_, h); }
  T proposed_step() const { return lanes_->h(i_); }
  void scale_proposed_step(T factor) { lanes_->propose_step(i_, lanes_->h(i_) * factor); }

  T t0() const { return lanes_->t0(i_); }
  T t1() const { return lanes_->t1(i_); }
  const state_type& x0() const { return lanes_->x0(i_); }
  const state_type& x1() const { return lanes_->x1(i_); }
  const state_type& f1() const { return lanes_->f1(i_); }
  long steps() const { return lanes_->steps(i_); }

  void interpolate(const System&, T t, state_type& out) const { lanes_->interpolate(i_, t, out); }
  template <std::size_t K>
  void interpolate(const System&, T t, state_type& out,
                   const std::array<std::size_t, K>& which) const {
    lanes_->interpolate(i_, t, out, which);
  }

 private:
  Stepper* lanes_;
  std::size_t i_;
};

}  // namespace ivv
