// The exponential collocation stepper of the plate (solver/plate/exponential_stepper.h): its
// Duhamel weights against their series in 50 digits, its order on a fixed ladder of steps against
// a linear system's tight reference, and the plate impacts it runs against DOP853.
#include "solver/plate/exponential_stepper.h"

#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_law.h"
#include "solver/steppers/dop853.h"

namespace ivv {
namespace {

using Big = boost::multiprecision::cpp_bin_float_50;

// s_n(x) = n! sum_k (-1)^k x^2k/(n + 2 + 2k)! (s_-1 = sin(x)/x) in 50 digits.
double weight_reference(int n, double x) {
  const Big X = x, x2 = X * X;
  if (x > 10.0) {  // the forward recurrence (the series would cancel e^x of the digits)
    std::vector<Big> s{sin(X) / X, (1 - cos(X)) / x2};
    s.push_back((1 - s[0]) / x2);
    for (int m = 2; m <= n; ++m) s.push_back((1 - Big(m) * (m - 1) * s[m - 1]) / x2);
    return static_cast<double>(s[static_cast<std::size_t>(n + 1)]);
  }
  Big term = n < 0 ? Big(1) : Big(1) / ((n + 1) * (n + 2)), sum = term;
  for (int k = 0; k < 400; ++k) {
    const int a = n < 0 ? 2 * k + 2 : n + 3 + 2 * k;
    term *= -x2 / (Big(a) * (a + 1));
    sum += term;
    if (abs(term) < Big(1e-40) * (1 + abs(sum))) break;
  }
  return static_cast<double>(sum);
}

// Below kSeriesBelow the top two weights come from the series and the rest from the downward
// recurrence (errors damped); above it from the forward recurrence (errors grown by at most 1.3
// for P = 8, header). Either way a weight is within a few ulp of the scale of the weights there,
// 1/max(1, x) (s_-1 = sin(x)/x, the others ~ 1/x^2 for large x): 1e-15 of that, room for 4 ulp.
TEST(DuhamelWeights, MatchTheirSeriesInFiftyDigits) {
  for (double x : {0.0, 1e-3, 0.3, 1.4, 2.9, 3.999, 4.0, 4.5, 2 * M_PI, 9.7, 31.0, 500.0}) {
    std::array<double, 10> s{};
    duhamel_weights<8>(x, std::cos(x), std::sin(x), s);
    const double scale = 1.0 / std::max(1.0, x);
    for (int n = -1; n <= 8; ++n)
      EXPECT_NEAR(s[static_cast<std::size_t>(n + 1)], weight_reference(n, x), 1e-15 * scale)
          << "s_" << n << "(" << x << ")";
  }
}

// Modes and an impactor joined by a linear spring with tension, F = k (z_kin - C F): a linear
// system, smooth for all time, so a fixed step shows the method's order (no onset, no kink).
struct LinearModes {
  using state_type = std::vector<double>;
  using value_type = double;
  std::vector<double> w, g;
  double k = 0.0, C = 0.0;
  std::string none;
  std::size_t modes() const { return w.size(); }
  std::size_t size() const { return 2 + 2 * w.size(); }
  double omega(std::size_t i) const { return w[i]; }
  double gain(std::size_t i) const { return g[i]; }
  double compliance() const { return C; }
  double law_force(double z) const { return k * z; }
  double law_stiffness(double) const { return k; }
  double force(double zk) const { return k * zk / (1.0 + k * C); }
  const std::string& failure() const { return none; }
  void operator()(const state_type& x, state_type& dxdt, double) const {
    double wsum = 0.0;
    for (std::size_t i = 0; i < w.size(); ++i) wsum += x[2 + 2 * i];
    const double F = force(x[0] - wsum);
    dxdt[0] = x[1];
    dxdt[1] = -F;
    for (std::size_t i = 0; i < w.size(); ++i) {
      dxdt[2 + 2 * i] = x[3 + 2 * i];
      dxdt[3 + 2 * i] = -w[i] * w[i] * x[2 + 2 * i] + g[i] * F;
    }
  }
};

// Three modes (omega = 2.5, 9, 19.5, normalised) and a fast one (omega = 290), the fastest
// turning 290 rad in a step of h = 1, the third 19.5: an explicit Runge-Kutta step would need
// h <~ 5/290. Their gains fall as a plate's do (g ~ 1/i^2 as omega ~ i^2), so the force they
// ring into is smooth on the step; modes 4 .. 11 are left out because their ringing (amplitude
// ~ g/omega^3, 5e-7 .. 1e-9) is a force the polynomial of a step of h = 1 cannot follow (with
// them the error at h = 1, 1/2 is 2.6e-6, 8e-8: the step must then resolve them first).
LinearModes linear_modes() {
  LinearModes s;
  for (int i : {1, 2, 3, 12}) {
    s.w.push_back(2.0 * i * i + 0.5 * i);
    s.g.push_back(0.3 / (i * i));
  }
  s.k = 1.0, s.C = 0.05;
  return s;
}

std::vector<double> linear_start(const LinearModes& s) {  // an onset: z_kin = 0, F = 0
  std::vector<double> x(s.size(), 0.0);
  x[1] = 1.0;
  return x;
}

// The state at T = 4 by DOP853 at rtol 1e-13 (its error ~1e-13, below the smallest of the errors
// compared with it).
std::vector<double> linear_reference(const LinearModes& s, double T) {
  IntegratorOptions io;
  io.rtol = 1e-13;
  io.atol = 1e-15;
  io.initial_dt = 1e-4;
  Dop853Stepper<LinearModes> d(io);
  d.start(s, 0.0, linear_start(s));
  while (d.t1() < T) EXPECT_TRUE(d.step(s).ok);
  std::vector<double> x;
  d.interpolate(s, T, x);
  return x;
}

double alpha_error_at_fixed_step(const LinearModes& s, int rung, double T,
                                 const std::vector<double>& ref) {
  PlateExponentialStepper<LinearModes> st(1e-10, 1e-12, 1.0);
  st.fix_step(rung);
  st.start(s, 0.0, linear_start(s));
  while (st.t1() < T) EXPECT_TRUE(st.step(s).ok);
  EXPECT_EQ(st.t1(), T);  // the ladder's steps divide T
  double w = 0.0, w_ref = 0.0;
  for (std::size_t i = 0; i < s.modes(); ++i) w += st.x1()[2 + 2 * i], w_ref += ref[2 + 2 * i];
  return std::max(
      {std::abs(st.x1()[0] - ref[0]), std::abs(st.x1()[1] - ref[1]), std::abs(w - w_ref)});
}

// The order at the step ends on a fixed ladder h = 1, 1/2: the error of alpha, alpha' and
// w = sum u at T = 4 falls at least as h^kObservedOrder. Measured 2.6e-6 and 9.5e-10, order 11.4
// (the nine equispaced nodes integrate like Newton-Cotes' nine-point rule, exact to degree 9:
// local error h^11); asserted 9 (a method of the embedded degree-7 solution's order, 8, fails it).
// At h = 1/4 the error, 2e-11, is the fast mode's unresolved ringing and the reference's own
// error (~2e-12 at h <= 1/8): the ladder stops before it.
TEST(ExponentialStepper, OrderOnAFixedLadderOfSteps) {
  constexpr double kObservedOrder = 9.0;
  const LinearModes s = linear_modes();
  const double T = 4.0;
  const std::vector<double> ref = linear_reference(s, T);
  std::vector<double> err;
  for (int rung = 0; rung <= 1; ++rung) err.push_back(alpha_error_at_fixed_step(s, rung, T, ref));
  for (std::size_t i = 1; i < err.size(); ++i) {
    const double order = std::log2(err[i - 1] / err[i]);
    EXPECT_GT(order, kObservedOrder)
        << "h = 2^-" << i << " .. 2^-" << i + 1 << ": errors " << err[i - 1] << ", " << err[i];
  }
  EXPECT_GT(err.back(), 1e-12);  // above the reference's own error: the order is the method's
}

// The adaptive stepper on the same system meets its tolerance (rtol 1e-10 per step, an estimate of
// a lower order than the method: the error ends far below), in fewer steps than DOP853 at the same
// tolerance, whose step the fast mode bounds (measured 99 against 749: the estimate, the
// eighth difference of the nodal forces, sees the fast mode's ringing of 1e-10 in F).
TEST(ExponentialStepper, AdaptiveStepsMeetTheTolerance) {
  const LinearModes s = linear_modes();
  const double T = 4.0;
  const std::vector<double> ref = linear_reference(s, T);
  PlateExponentialStepper<LinearModes> st(1e-10, 1e-12, 0.01);
  st.start(s, 0.0, linear_start(s));
  while (st.t1() < T) ASSERT_TRUE(st.step(s).ok);
  std::vector<double> x;
  st.interpolate(s, T, x);
  EXPECT_NEAR(x[0], ref[0], 1e-9);
  EXPECT_NEAR(x[1], ref[1], 1e-9);
  IntegratorOptions io;
  io.rtol = 1e-10, io.atol = 1e-12, io.initial_dt = 0.01;
  Dop853Stepper<LinearModes> d(io);
  d.start(s, 0.0, linear_start(s));
  while (d.t1() < T) ASSERT_TRUE(d.step(s).ok);
  EXPECT_LT(st.steps(), d.steps());
  const auto gap = st.event_gap(T - 0.3 * (st.t1() - st.t0()));  // off the probes: the formula
  std::vector<double> y;
  st.interpolate(s, T - 0.3 * (st.t1() - st.t0()), y);
  double w = 0.0, wr = 0.0;
  for (std::size_t i = 0; i < s.modes(); ++i) w += y[2 + 2 * i], wr += y[3 + 2 * i];
  EXPECT_NEAR(gap[0], y[0] - w, 1e-14);  // the locator's z_kin is the interpolated state's
  EXPECT_NEAR(gap[1], y[1] - wr, 1e-14);
}

// Free motion (no force): z_kin and its rate at the probes and off them against every mode's own
// cos and sin. 41 slow modes (omega h from 0.01 to 3.99, below kSeriesBelow: summed over the
// modes first as a polynomial, in every band of term counts and with blocks of four and their
// remainders) and three fast ones (turned per mode). The polynomial's rounding is ~eps sum |u_k|
// cosh(omega_k h) (<= 27 eps a mode at omega h = 4, the terms alternate), the per-mode sum's a few
// eps a mode: 1e-14 of the amplitudes' sum holds both with room for the 44 modes' sums.
TEST(ExponentialStepper, FreeMotionOfSlowAndFastModesIsExact) {
  LinearModes s;
  for (int i = 0; i <= 40; ++i) s.w.push_back(0.01 + 3.98 * i / 40.0);
  for (double om : {4.5, 31.0, 290.0}) s.w.push_back(om);
  s.g.assign(s.w.size(), 0.1);
  s.k = 0.0, s.C = 0.0;
  std::vector<double> x(s.size(), 0.0);
  x[0] = 0.3, x[1] = -0.2;
  double amplitude = 0.0;
  for (std::size_t i = 0; i < s.modes(); ++i) {
    x[2 + 2 * i] = std::sin(1.7 * i + 0.4) / (1.0 + i);
    x[3 + 2 * i] = std::cos(0.9 * i) * s.w[i] / (2.0 + i);
    amplitude += std::hypot(x[2 + 2 * i], x[3 + 2 * i] / s.w[i]) * std::max(1.0, s.w[i]);
  }
  PlateExponentialStepper<LinearModes> st(1e-10, 1e-12, 1.0);
  st.fix_step(0);  // h = 1
  st.start(s, 0.0, x);
  ASSERT_TRUE(st.step(s).ok);
  for (double t : {1.0 / 16, 0.25, 0.5, 13.0 / 16, 0.37, 0.9, 1.0}) {
    double w = 0.0, wr = 0.0;
    for (std::size_t i = 0; i < s.modes(); ++i) {
      const double c = std::cos(s.w[i] * t), sn = std::sin(s.w[i] * t);
      w += x[2 + 2 * i] * c + x[3 + 2 * i] / s.w[i] * sn;
      wr += -x[2 + 2 * i] * s.w[i] * sn + x[3 + 2 * i] * c;
    }
    const auto gap = st.event_gap(t);
    EXPECT_NEAR(gap[0], x[0] + x[1] * t - w, 1e-14 * amplitude) << "t = " << t;
    EXPECT_NEAR(gap[1], x[1] - wr, 1e-14 * amplitude) << "t = " << t;
  }
}

// A linear spring on the 200 mm plate (an expression law, clamped at F >= 0): the contact force is
// smooth from its onset (F ~ k v0 t, a polynomial), only the separation's kink is not. The
// exponential stepper at its default rtol 1e-10 against DOP853 at rtol 1e-12 on the same modes:
// both errors ~1e-10 or below over ~100 steps, held to 1e-8 in e and F_max.
TEST(ExponentialStepper, LinearSpringOnAPlateAgreesWithDop853) {
  SimulationRequest r;
  r.scene = load_scene("steel-ball-on-finite-steel-plate");
  r.law = LawKind::expression;
  r.expression.force = "K_h*1e-3*z";
  PlateImpactOptions o;
  o.cutoff = 20.0;
  o.stepper = PlateImpactOptions::Stepper::exponential;
  const PlateImpactResult a = simulate_plate_law(r, o);
  o.stepper = PlateImpactOptions::Stepper::dop853;
  o.rtol = 1e-12, o.atol = 1e-14;
  const PlateImpactResult b = simulate_plate_law(r, o);
  ASSERT_TRUE(a.ok && b.ok) << a.reason << b.reason;
  EXPECT_EQ(a.contacts.size(), b.contacts.size());
  EXPECT_NEAR(a.e, b.e, 1e-8);
  EXPECT_NEAR(a.F_max / b.F_max, 1.0, 1e-8);
  EXPECT_LT(a.steps, b.steps);
}

// The shipped plate scenes, exponential at its default rtol 1e-10 against DOP853 at rtol 1e-12 on
// the same modes (cut-off 40): |de| <= 1e-7, the same contacts and reloads, F_max to 1e-7.
// Measured |de| 5e-11 (steel ball, 866 modes) and 1e-12 (coupon, 21 reloads). The count of
// compression maxima is not compared: DOP853 counts 82, 80, 79 on the coupon at rtol 1e-10,
// 1e-12, 1e-13 (local maxima of z on an unloading branch as shallow as its interpolant's
// error), the exponential stepper 79 at 1e-10 and 1e-12.
TEST(ExponentialStepper, ShippedPlateScenesAgreeWithDop853) {
  for (auto [scene, law] : {std::pair{"steel-ball-on-finite-steel-plate", LawKind::hertz},
                            std::pair{"drop-weight-coupon", LawKind::elastoplastic}}) {
    const Scene s = load_scene(scene);
    PlateImpactOptions o;
    o.stepper = PlateImpactOptions::Stepper::exponential;
    const PlateImpactResult a = simulate_plate_impact(s, law, {}, o);
    o.stepper = PlateImpactOptions::Stepper::dop853;
    o.rtol = 1e-12, o.atol = 1e-14;
    const PlateImpactResult b = simulate_plate_impact(s, law, {}, o);
    ASSERT_TRUE(a.ok && b.ok) << scene << ": " << a.reason << b.reason;
    EXPECT_NEAR(a.e, b.e, 1e-7) << scene;
    EXPECT_NEAR(a.e_first, b.e_first, 1e-7) << scene;
    EXPECT_NEAR(a.F_max / b.F_max, 1.0, 1e-7) << scene;
    EXPECT_EQ(a.contacts.size(), b.contacts.size()) << scene;
    EXPECT_EQ(a.reloads, b.reloads) << scene;
    EXPECT_LT(a.steps, b.steps) << scene;
  }
}

// Accuracy at loose tolerances, over cut-offs and tolerances on both shipped scenes: the
// exponential stepper and DOP853 at rtol 1e-6 and 1e-8 against DOP853 at rtol 1e-10 on the same
// modes (so the truncation cancels; the two steppers agree to 1e-10 there, the reference's own
// error). The exponential stepper is within rtol of it (what a run at rtol per step promises for
// e ~ 0.2 .. 0.9), no farther from it than DOP853 at the same settings or 1e-9 (ten times the
// reference's error), with the same contacts and reloads. Measured: at most 4e-10 (ball, cut-off
// 10, rtol 1e-6) against DOP853's 8.4e-8 there; before a reload after a graze of z_m was
// located (plate_impact_driver.h, missed_reload) the coupon at rtol 1e-6 was off by up to 3.1e-4
// with 24 .. 33 reloads for 20 .. 22.
TEST(ExponentialStepper, AtLooseTolerancesAsAccurateAsDop853OnTheShippedScenes) {
  constexpr double kReferenceError = 1e-9;
  for (auto [scene, law] : {std::pair{"steel-ball-on-finite-steel-plate", LawKind::hertz},
                            std::pair{"drop-weight-coupon", LawKind::elastoplastic}}) {
    const Scene s = load_scene(scene);
    for (double cutoff : {10.0, 30.0, 60.0}) {
      PlateImpactOptions o;
      o.cutoff = cutoff;
      o.rtol = 1e-10, o.atol = 1e-12;
      const PlateImpactResult ref = simulate_plate_impact(s, law, {}, o);
      ASSERT_TRUE(ref.ok) << scene << ": " << ref.reason;
      for (double rtol : {1e-6, 1e-8}) {
        o.rtol = rtol, o.atol = rtol * 1e-2;
        o.stepper = PlateImpactOptions::Stepper::dop853;
        const PlateImpactResult d = simulate_plate_impact(s, law, {}, o);
        o.stepper = PlateImpactOptions::Stepper::exponential;
        const PlateImpactResult x = simulate_plate_impact(s, law, {}, o);
        ASSERT_TRUE(d.ok && x.ok) << scene << ": " << d.reason << x.reason;
        const std::string at = std::string(scene) + ", cut-off " + std::to_string(cutoff) +
                               ", rtol " + std::to_string(rtol);
        EXPECT_NEAR(x.e, ref.e, rtol) << at;
        EXPECT_LE(std::abs(x.e - ref.e), std::max(std::abs(d.e - ref.e), kReferenceError)) << at;
        EXPECT_EQ(x.contacts.size(), ref.contacts.size()) << at;
        EXPECT_EQ(x.reloads, ref.reloads) << at;
      }
    }
  }
}

}  // namespace
}  // namespace ivv
