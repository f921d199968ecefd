// The free flight between two contacts of the plate impact (plate_impact.h): exact motion,
// the next onset by a rigorous step bound, or the proof that no contact can follow.
#pragma once

#include <cmath>
#include <limits>

#include "solver/driver/event_locator.h"
#include "solver/plate/plate_impact_driver.h"

namespace ivv {

// The flight s after a separation at state x0 (normalised): alpha linear, each mode a free
// oscillator u(s) = u cos(omega s) + (u'/omega) sin(omega s). Writes the state into y when
// given; returns z_kin(s) and its rate.
struct FlightPoint {
  double z_kin = 0.0, rate = 0.0;
};
template <class System>
FlightPoint free_flight_state(const System& sys, const std::vector<double>& x0, double s,
                              std::vector<double>* y) {
  double w = 0.0, w_rate = 0.0;
  for (std::size_t k = sys.modes(); k-- > 0;) {
    const std::size_t i = 2 + 2 * k;
    const double om = sys.omega(k);
    const double c = std::cos(om * s), sn = std::sin(om * s);
    const double u = x0[i] * c + x0[i + 1] / om * sn;
    const double v = -x0[i] * om * sn + x0[i + 1] * c;
    w += u;
    w_rate += v;
    if (y) {
      (*y)[i] = u;
      (*y)[i + 1] = v;
    }
  }
  const double alpha = x0[0] + x0[1] * s;
  if (y) {
    (*y)[0] = alpha;
    (*y)[1] = x0[1];
  }
  return {alpha - w, x0[1] - w_rate};
}

// The longest flight h from a point with gap d >= 0 (to the contact) and gap rate r (z_kin')
// in which z_kin cannot reach the contact when |z_kin''| <= M2: r h + M2 h^2/2 < d.
inline double safe_flight_step(double d, double r, double M2) {
  d = std::max(d, 0.0);
  if (M2 > 0.0) {  // the positive root, each form without cancellation
    const double root = std::sqrt(r * r + 2.0 * M2 * d);
    return r > 0.0 ? 2.0 * d / (r + root) : (root - r) / M2;
  }
  return r > 0.0 ? d / r : std::numeric_limits<double>::infinity();
}

template <class Law, class Stepper>
bool PlateImpactDriver<Law, Stepper>::free_flight(double& t, State& x, PlateImpactResult& out) {
  const State x0 = x;
  const double t0 = t;
  double B = 0.0, M2 = 0.0, omega_max = 0.0;  // sum A_k, sum omega_k^2 A_k, max omega_k
  for (std::size_t k = 0, i = 2; k < sys_.modes(); ++k, i += 2) {
    const double om = sys_.omega(k);
    const double A = std::hypot(x0[i], x0[i + 1] / om);
    B += A;
    M2 += om * om * A;
    omega_max = std::max(omega_max, om);
  }
  out.excursion_bound = B * sys_.length();
  const double z0 = zero_force_point();
  const double h_min = omega_max > 0.0 ? 0.05 / omega_max : std::numeric_limits<double>::infinity();
  auto gap = [&](double s) { return free_flight_state(sys_, x0, s, nullptr).z_kin - z0; };
  double s = 0.0;
  FlightPoint here = free_flight_state(sys_, x0, 0.0, nullptr);
  double ga = here.z_kin - z0;
  for (;;) {
    if (++out.free_flight_steps + out.steps > opt_.max_steps)
      throw PlateRunFailure{
          "more than " + std::to_string(opt_.max_steps) +
          " steps (free flight at t = " + std::to_string((t0 + s) * scales_.time) + " s)"};
    if (x0[1] <= 0.0 && x0[0] + x0[1] * s + B < z0) {  // moving away, beyond any excursion
      t = t0 + s;
      free_flight_state(sys_, x0, s, &x);
      return false;
    }
    double h = safe_flight_step(-ga, here.rate, M2);
    if (!(h >= 0.0) || !(std::min(h, h_min) < std::numeric_limits<double>::infinity()))
      throw PlateRunFailure{
          "free flight: no step bound at t = " + std::to_string((t0 + s) * scales_.time) + " s"};
    const bool probe = !(h >= h_min);
    if (probe) h = h_min;
    const int n = probe ? 4 : 1;
    double a = s;
    for (int i = 1; i <= n; ++i) {
      const double b = s + h * i / n;
      const double gb = gap(b);
      if (gb >= 0.0) {
        const double onset = solve_crossing(gap, a, b, ga, gb, Direction::rising);
        t = t0 + onset;
        free_flight_state(sys_, x0, onset, &x);
        return true;
      }
      a = b;
      ga = gb;
    }
    s += h;
    here = free_flight_state(sys_, x0, s, nullptr);
    ga = here.z_kin - z0;
  }
}

}  // namespace ivv
