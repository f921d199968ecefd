#include "solver/plate/plate_free_flight.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "solver/laws/hertz.h"
#include "solver/plate/plate_modes.h"
#include "solver/plate/plate_system.h"
#include "solver/plate/steel_ball_on_plate.h"

namespace ivv {
namespace {

// The 200 mm steel plate of the shipped scene with its modes below 2e6 rad/s (~500), in time
// units of 10 us, and a ringing state after a separation: mode k with amplitude ~ 1/omega_k up to
// a corner at 2e5 rad/s and ~ 1/omega_k^3 above (an impact pulse's spectrum), phases spread by a
// fixed rule; the ball 1 % of B below the plate, moving away.
struct Flight {
  PlateModes modes;
  PlateSystem<HertzLaw> sys;
  std::vector<double> x0;
};
Flight ringing_plate() {
  const FinitePlate p =
      finite_plate(steel_ball_on_plate(0.2, 0.2, 0.002).damping.structure, 207e9, 0.3);
  PlateModes modes = plate_modes(p, {2e6});
  Scales k;
  k.time = 1e-5;
  k.length = 1e-6;
  k.velocity = 0.1;
  k.force = 1.0;
  k.energy = 1.0;
  PlateSystem<HertzLaw> sys(HertzLaw{1e10}, k, modes, 0.004, DroppedModes::static_compliance);
  std::vector<double> x(sys.size(), 0.0);
  double w = 0.0, B = 0.0;
  for (std::size_t j = 0; j < sys.modes(); ++j) {
    const double om = sys.omega(j), corner = 2e5 * k.time;
    const double A = om < corner ? 1.0 / om : corner * corner / (om * om * om);
    const double phase = 2.399963 * static_cast<double>(j);  // the golden angle
    x[2 + 2 * j] = A * std::cos(phase);
    x[3 + 2 * j] = -A * om * std::sin(phase);
    w += x[2 + 2 * j];
    B += A;
  }
  x[0] = w - 0.01 * B;
  x[1] = -0.2;
  return {std::move(modes), std::move(sys), std::move(x)};
}

// The levels' tails and curvatures are the sums they stand for: the same terms added in another
// order, rounding (~1e-15 of B), with room.
TEST(PlateFreeFlight, LevelsHoldTheirTailsAndCurvatures) {
  const Flight f = ringing_plate();
  const FlightLevels lv = flight_levels(f.sys, f.x0);
  ASSERT_GE(lv.levels.size(), 3u);
  EXPECT_EQ(lv.levels.back().modes, f.sys.modes());
  EXPECT_EQ(lv.levels.back().tail, 0.0);
  for (const FlightLevel& l : lv.levels) {
    double head = 0.0, curvature = 0.0;
    for (std::size_t j = 0; j < l.modes; ++j) {
      const double om = f.sys.omega(j);
      const double A = std::hypot(f.x0[2 + 2 * j], f.x0[3 + 2 * j] / om);
      head += A;
      curvature += om * om * A;
    }
    EXPECT_NEAR(l.tail, lv.excursion - head, 1e-13 * lv.excursion) << l.modes;
    EXPECT_NEAR(l.curvature, curvature, 1e-13 * curvature) << l.modes;
  }
}

// Every step a slower level allows is free of contact: the exact gap, sampled at 100 points of
// the step, stays below zero. The flight is marched from the separation until the ball is beyond
// the excursion bound, by the slow levels where they allow a step and by 1/(20 omega_max) where
// they do not (there the plate may strike the ball: not the bound's business); the slow levels
// must carry most of the flight's length.
TEST(PlateFreeFlight, SlowLevelStepsAreFreeOfContact) {
  const Flight f = ringing_plate();
  const FlightLevels lv = flight_levels(f.sys, f.x0);
  const double h_min = 0.05 / lv.omega_max;
  auto gap = [&](double s) { return free_flight_state(f.sys, f.x0, s, nullptr).z_kin; };
  int slow = 0;
  double s = 0.0, slow_length = 0.0;
  while (f.x0[0] + f.x0[1] * s + lv.excursion >= 0.0) {
    const double h = slow_flight_step(f.sys, lv, f.x0, s, 0.0, h_min);
    if (h > 0.0) {
      for (int i = 0; i <= 100; ++i) ASSERT_LT(gap(s + h * i / 100.0), 0.0) << s << " " << h;
      ++slow;
      slow_length += h;
    }
    s += h > 0.0 ? h : h_min;
  }
  EXPECT_GT(slow, 0);
  EXPECT_GT(slow_length, 0.5 * s);
}

}  // namespace
}  // namespace ivv
