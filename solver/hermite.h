// Cubic Hermite interpolation on one step [t0, t1] from the end-point states and derivatives.
//
//   x(t0 + theta h) = h00 x0 + h10 h f0 + h01 x1 + h11 h f1,   theta in [0, 1]
//   h00 = (1 + 2 theta)(1 - theta)^2, h10 = theta (1 - theta)^2,
//   h01 = theta^2 (3 - 2 theta),      h11 = theta^2 (theta - 1)
//
// Local error O(h^4) for smooth solutions; the interpolant for steppers without dense output.
#pragma once

#include <cstddef>

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

}  // namespace ivv
