// Laws of a request on a finite plate (solver/plate/plate_law.h): an expression law runs the same
// model as the built-in law it restates, reloads on its unloading curve like it, closes its
// ledger, and what the plate does not model is refused by name.
#include "solver/plate/plate_law.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "solver/plate/plate_law_impact.h"
#include "solver/plate/steel_ball_on_plate.h"

namespace ivv {
namespace {

SimulationRequest expression(const Scene& s, std::string force, std::string unload = "") {
  SimulationRequest r;
  r.scene = s;
  r.law = LawKind::expression;
  r.expression.force = std::move(force);
  r.expression.unload = std::move(unload);
  return r;
}

// Both runs integrate the same modes at rtol 1e-10 per step, in different normalisations (the
// expression law on the yield scales, Hertz on its own): their e differ by the integration error,
// N rtol over N ~ 300 steps of the three contacts, far below 1e-7.
constexpr double kSameModel = 1e-7;

// The 50 x 40 x 1 mm plate outruns the ball: repeated contacts, e_first < 0.
TEST(PlateLaw, AnExpressionLawRunsTheModelOfTheBuiltInLawItRestates) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  const PlateImpactResult hertz = simulate_plate_impact(s, LawKind::hertz, {});
  const PlateImpactResult typed = simulate_plate_law(expression(s, "K_h*z^1.5"));
  ASSERT_TRUE(hertz.ok && typed.ok) << hertz.reason << typed.reason;
  EXPECT_GT(hertz.contacts.size(), 1u);           // the case is the repeated one
  EXPECT_EQ(typed.mode_count, hertz.mode_count);  // the same cut-off rule
  EXPECT_EQ(typed.contacts.size(), hertz.contacts.size());
  EXPECT_NEAR(typed.e, hertz.e, kSameModel);
  EXPECT_NEAR(typed.e_first, hertz.e_first, kSameModel);
  EXPECT_NEAR(typed.F_max / hertz.F_max, 1.0, kSameModel);
  // the expression law's ledger is closed at the end from its own curves (Hertz: W_p = 0);
  // 1e-8 of E0 is N rtol with room, as plate_impact_test.cc's kLedger
  EXPECT_EQ(typed.energy.checks, 1);
  EXPECT_NEAR(typed.energy.plastic, 0.0, 1e-8 * typed.energy.initial);
  EXPECT_LT(typed.energy.max_error, 1e-8);
}

// The paper's elastoplastic law typed as expressions (eqs 8-10), on the plate where the spring
// reloads past z_m (S_y = 400 MPa): the unloading expression is retraced below z_m and the loading
// one resumes beyond it, as the built-in law does. The expression law declares no kink at z_y, so
// its stepper crosses it inside a step: the error there is the step's local error at a kink in the
// second derivative (~1e-8 at rtol 1e-10), hence 1e-6.
TEST(PlateLaw, AnExpressionLawReloadsOnItsUnloadingCurveLikeTheBuiltInLaw) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001, 400e6);
  PlateImpactOptions opt;
  opt.cutoff = 20.0;
  const PlateImpactResult builtin = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
  const PlateImpactResult typed = simulate_plate_law(
      expression(s, "z <= z_y ? K_h*z^1.5 : K_y*(z - z_y) + K_h*z_y^1.5",
                 "zmax <= z_y ? K_h*z^1.5 : K_h*(z^1.5 - zmax^1.5 + z_y^1.5) + K_y*(zmax - z_y)"),
      opt);
  ASSERT_TRUE(builtin.ok && typed.ok) << builtin.reason << typed.reason;
  ASSERT_GT(builtin.reloads, 0);  // the case reloads
  EXPECT_EQ(typed.reloads, builtin.reloads);
  EXPECT_EQ(typed.contacts.size(), builtin.contacts.size());
  EXPECT_NEAR(typed.e, builtin.e, 1e-6);
  EXPECT_NEAR(typed.z_max / builtin.z_max, 1.0, 1e-6);
  // W_p from the expressions' curves against the closed form of the built-in law
  EXPECT_NEAR(typed.energy.plastic / builtin.energy.plastic, 1.0, 1e-6);
  EXPECT_LT(typed.energy.max_error, 1e-6);
}

void expect_refused(const SimulationRequest& r, const std::string& field) {
  try {
    simulate_plate_law(r);
    ADD_FAILURE() << "accepted on a finite plate: " << r.expression.force;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), field) << e.what();
  }
  EXPECT_THROW(validate_plate_law(r), InputError);
}

TEST(PlateLaw, WhatThePlateDoesNotModelIsRefusedByName) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  expect_refused(expression(s, "K_h*z^1.5 + 10*zdot"), "--force");  // rate-dependent
  SimulationRequest tension = expression(s, "K_h*z^1.5");
  tension.expression.allow_tension = true;
  expect_refused(tension, "--allow-tension");
  SimulationRequest hc;
  hc.scene = s;
  hc.law = LawKind::hunt_crossley;
  expect_refused(hc, "--law");
  SimulationRequest both = expression(s, "K_h*z^1.5");
  both.law = LawKind::hertz;
  expect_refused(both, "--force");
  expect_refused(expression(s, "K_h*z^1.5 +"), "--force");  // malformed
}

// A NaN inside the contact fails the run with the expression named, never a number.
TEST(PlateLaw, ANonFiniteForceFailsTheRunWithItsReason) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  const PlateImpactResult r = simulate_plate_law(expression(s, "z < 1e-6 ? K_h*z^1.5 : sqrt(-z)"));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.reason.find("--force"), std::string::npos) << r.reason;
}

// A C++ law of a user runs on the plate through the template, with the built-in law's result.
struct UserHertz {
  static constexpr std::string_view name = "user-hertz";
  static constexpr bool rate_dependent = false;
  double K = 0;
  double force(const Branch<double>&, double z, double) const { return K * signed_pow_1_5(z); }
  double stiffness(const Branch<double>&, double z, double) const {
    return 1.5 * K * std::sqrt(std::abs(z));
  }
  double rate_stiffness(const Branch<double>&, double, double) const { return 0.0; }
  double stored_energy(const Branch<double>&, double z) const {
    return z > 0 ? 0.4 * K * z * z * std::sqrt(z) : 0.0;
  }
  std::optional<double> hysteresis_work(const Branch<double>&) const { return 0.0; }
};

TEST(PlateLaw, ACxxLawOfAUserRunsOnThePlate) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  const PlateImpactResult hertz = simulate_plate_impact(s, LawKind::hertz, {});
  const PlateImpactResult user = simulate_plate_impact_of(UserHertz{derive(s).K_h}, s);
  ASSERT_TRUE(user.ok) << user.reason;
  EXPECT_EQ(user.mode_count, hertz.mode_count);
  EXPECT_NEAR(user.e, hertz.e, kSameModel);
  EXPECT_GT(user.energy.checks, 1);  // its closed-form hysteresis: the driver's ledger per event
}

}  // namespace
}  // namespace ivv
