// Test support: the mid-step error of dp45's dense output on x' = x, x(0) = 1, one step of
// size h taken with error control off. The continuous extension is of order 4, so the local
// interpolation error is O(h^5).
#pragma once

#include <array>
#include <cmath>

#include "solver/steppers/dp45.h"

namespace ivv {

struct ExponentialSystem {
  using value_type = double;
  using state_type = std::array<double, 1>;
  void operator()(const state_type& x, state_type& d, double) const { d[0] = x[0]; }
};

inline double dp45_midpoint_error_exponential(double h) {
  IntegratorOptions opt;
  opt.fixed_step = true;
  opt.dt = h;
  Dp45Stepper<ExponentialSystem> stepper(opt);
  ExponentialSystem sys;
  stepper.start(sys, 0.0, {1.0});
  stepper.step(sys);
  ExponentialSystem::state_type mid;
  stepper.interpolate(sys, h / 2, mid);
  return std::abs(mid[0] - std::exp(h / 2));
}

}  // namespace ivv
