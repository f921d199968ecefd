#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_run.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <string>
#include <utility>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "solver/plate/steel_ball_on_plate.h"

namespace ivv {
namespace {

// The ledger is checked at every maximum of compression and separation; each is a sum of a few
// terms integrated to rtol 1e-10, atol 1e-12 per step over a few thousand steps: their local
// errors add to ~1e-8 of the initial energy at most (measured 1e-10 .. 3e-10).
constexpr double kLedger = 1e-8;

// No modes kept (a cut-off below the first mode): the plate is its static compliance in series
// with the Hertz spring, an elastic two-spring model. Then e = 1 and, by energy,
// (1/2) m v0^2 = (2/5) K z_m^{5/2} + (1/2) C F_m^2 with F_m = K z_m^{3/2}. The run must meet this
// to its integration tolerance (1e-10 per step over ~100 steps: 1e-8 with room).
TEST(PlateImpact, WithoutModesIsTheTwoSpringModel) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 1e-3;
  const PlateImpactResult r = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_EQ(r.mode_count, 0u);
  EXPECT_EQ(r.residual_compliance, r.static_compliance);
  EXPECT_NEAR(r.e, 1.0, 1e-8);
  EXPECT_EQ(r.contacts.size(), 1u);
  const double K = derive(s).K_h, C = r.static_compliance, z = r.z_max;
  const double F = K * z * std::sqrt(z);
  EXPECT_NEAR(r.F_max / F, 1.0, 1e-8);
  EXPECT_NEAR((0.4 * K * z * z * std::sqrt(z) + 0.5 * C * F * F) / (0.5 * s.mass), 1.0, 1e-8);
}

// Without modes the flight after the separation is the ball alone leaving the static plate, and
// whichever side of z_f rounding leaves it the run ends there with one contact: at rtol 1e-8 the
// drop-weight coupon's quasi-static model (no mode kept) used to fail ("free flight: no step
// bound") because the separation left alpha a rounding above z_f, where nothing bounds a step.
// Every tolerance from 1e-6 to 1e-12, both shipped scenes.
TEST(PlateImpact, WithoutModesTheFlightEndsOnEitherSideOfTheSet) {
  for (const auto& [scene, law] : {std::pair{"drop-weight-coupon", LawKind::elastoplastic},
                                   std::pair{"steel-ball-on-finite-steel-plate", LawKind::hertz}})
    for (double rtol : {1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12}) {
      PlateImpactOptions opt;
      opt.cutoff = 0.0;
      opt.rtol = rtol;
      opt.atol = 1e-2 * rtol;
      const PlateImpactResult r = simulate_plate_impact(load_scene(scene), law, {}, opt);
      ASSERT_TRUE(r.ok) << scene << " rtol " << rtol << ": " << r.reason;
      EXPECT_EQ(r.mode_count, 0u);
      EXPECT_EQ(r.contacts.size(), 1u) << scene << " rtol " << rtol;
      EXPECT_GT(r.e, 0.0) << scene << " rtol " << rtol;  // both rebound (e 0.91 and ~1)
    }
}

// A small thin plate outruns the ball: the first separation has the ball still moving towards
// the plate (e_first < 0), contacts follow, and the run ends once the bound says no further
// contact is possible. Energy and momentum hold over the whole story.
TEST(PlateImpact, RepeatedContactsKeepTheLedgerAndTheImpulse) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 20.0;
  const PlateImpactResult r = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_LT(r.e_first, 0.0);
  EXPECT_GE(r.contacts.size(), 2u);
  EXPECT_GT(r.e, 0.0);
  EXPECT_LT(r.energy.max_error, kLedger);
  EXPECT_GE(r.energy.checks, 2 * static_cast<int>(r.contacts.size()));
  // impulse m (v0 - alpha'_f) against the contacts' impulses m (alpha'_start - alpha'_end):
  // the same differences telescoped, equal to rounding
  double sum = 0.0;
  for (const PlateContact& c : r.contacts) sum += c.impulse;
  EXPECT_NEAR(sum / r.impulse, 1.0, 1e-12);
  EXPECT_NEAR(r.impulse, s.mass * (1.0 + r.e), 1e-12);
  // the final energies add up to the initial one (Hertz: no plastic work)
  EXPECT_NEAR((r.energy.kinetic + r.energy.plate) / r.energy.initial, 1.0, kLedger);
  for (std::size_t i = 1; i < r.contacts.size(); ++i)
    EXPECT_GT(r.contacts[i].t_start, r.contacts[i - 1].t_end);
}

// The dropped modes as one equivalent oscillator (plate_modes.h) are a mode like the kept ones:
// on the small plate's repeated contacts the ledger holds with its energy among the modes', and
// momentum as before; the static C_res is not in series with the spring then.
TEST(PlateImpact, TheResidualOscillatorKeepsTheLedger) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 20.0;
  opt.dropped = DroppedModes::oscillator;
  const PlateImpactResult r = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_GT(r.residual_omega, r.omega_cut);
  EXPECT_GT(r.residual_compliance, 0.0);
  EXPECT_LT(r.energy.max_error, kLedger);
  EXPECT_NEAR((r.energy.kinetic + r.energy.plate) / r.energy.initial, 1.0, kLedger);
  EXPECT_NEAR(r.impulse, s.mass * (1.0 + r.e), 1e-12);
}

// The scene's [structure] dropped_modes chooses what the run does with the modes above the
// cut-off when the options do not: the oscillator from the scene is the same run, to the bit, as
// the oscillator from the options; options that name one win over the scene; without either the
// static compliance (the default).
TEST(PlateImpact, TheScenesDroppedModesAreUsedUnlessTheOptionsNameThem) {
  Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 20.0;
  const PlateImpactResult plain = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  EXPECT_EQ(plain.dropped, DroppedModes::static_compliance);
  PlateImpactOptions oscillator = opt;
  oscillator.dropped = DroppedModes::oscillator;
  const PlateImpactResult by_options = simulate_plate_impact(s, LawKind::hertz, {}, oscillator);
  s.damping.structure.dropped_modes = DroppedModes::oscillator;
  const PlateImpactResult by_scene = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(plain.ok && by_options.ok && by_scene.ok) << by_scene.reason;
  EXPECT_EQ(by_scene.dropped, DroppedModes::oscillator);
  EXPECT_EQ(by_scene.e, by_options.e);
  EXPECT_EQ(by_scene.residual_omega, by_options.residual_omega);
  EXPECT_NE(by_scene.e, plain.e);
  PlateImpactOptions named = opt;
  named.dropped = DroppedModes::static_compliance;
  const PlateImpactResult overridden = simulate_plate_impact(s, LawKind::hertz, {}, named);
  EXPECT_EQ(overridden.dropped, DroppedModes::static_compliance);
  EXPECT_EQ(overridden.e, plain.e);
}

// The elastoplastic law on a flexible plate: z has several maxima in one contact (the plate's
// vibration reloads the spring), the ledger holds with the plastic work, and W_p is the loop
// area of the largest z_m (reloading below z_m retraces the unloading curve).
TEST(PlateImpact, ElastoplasticReloadingKeepsTheLedger) {
  Scene s = steel_ball_on_plate(0.125, 0.075, 0.004);
  s.mass = 5.5;
  s.radius = 0.008;
  s.velocity = 2.0;
  s.target_youngs_modulus = 7.9e9;
  s.yield_strength = 202e6;
  s.damping.structure.density = 1580.0;
  s.damping.structure.bending = OrthotropicBending{432.111, 254.088, 12.7153, 29.3333};
  PlateImpactOptions opt;
  opt.cutoff = 10.0;  // 17 modes: e within ~3e-6 of the converged 0.9096578, 0.2 s
  const PlateImpactResult r = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_GT(r.compression_maxima, static_cast<int>(r.contacts.size()));
  EXPECT_GT(r.energy.plastic, 0.0);
  EXPECT_LT(r.energy.max_error, kLedger);
  EXPECT_NEAR((r.energy.kinetic + r.energy.plate + r.energy.plastic) / r.energy.initial, 1.0,
              kLedger);
  EXPECT_GT(r.e, 0.5);         // a rebound, not the infinite plate's capture
  EXPECT_GT(r.F_max, 1000.0);  // kN, not the infinite plate's 673 N
}

// The same equations through the hand-written DOP853 and Boost.Odeint's dopri5: each meets rtol
// 1e-10 per step over a few thousand steps, so their e, e_first and F_max agree to ~1e-8 (1e-7
// with room), and they see the same contacts.
TEST(PlateImpact, TwoSteppersAgree) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 10.0;
  opt.stepper = PlateImpactOptions::Stepper::dop853;
  const PlateImpactResult a = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  opt.stepper = PlateImpactOptions::Stepper::odeint_dopri5;
  const PlateImpactResult b = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(a.ok && b.ok) << a.reason << b.reason;
  EXPECT_EQ(a.contacts.size(), b.contacts.size());
  EXPECT_NEAR(a.e, b.e, 1e-7);
  EXPECT_NEAR(a.e_first, b.e_first, 1e-7);
  EXPECT_NEAR(a.F_max / b.F_max, 1.0, 1e-7);
  EXPECT_LT(a.steps, b.steps);  // the eighth-order pair takes fewer steps
}

// A reload located where z already falls (a graze of z_m) must switch back to unloading at
// once: the 5 mm ball on the 200 mm plate at cut-off 80 (1739 modes), rtol 1e-12, grazed z_m
// after its maximum, stayed on the loading branch with no separation root, went on in tension
// and ended with two contacts and e = 0.032. The exponential stepper (a different method,
// which never grazed there) and dop853 itself at rtol 1e-10 give one contact and e = 0.19234.
// Both runs keep the same modes, so only their integration errors differ: rtol 1e-12 per step
// over ~430 steps, ~1e-10 in e (measured: equal to 10 digits); 1e-8 leaves a factor 100, and a
// missed separation costs 0.16.
TEST(PlateImpact, AReloadAtAGrazeOfZmaxStillFindsTheSeparation) {
  const Scene s = steel_ball_on_plate(0.2, 0.2, 0.002);
  PlateImpactOptions opt;
  opt.cutoff = 80.0;
  opt.rtol = 1e-12;
  opt.atol = 1e-14;
  opt.stepper = PlateImpactOptions::Stepper::dop853;
  const PlateImpactResult a = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  opt.stepper = PlateImpactOptions::Stepper::exponential;
  const PlateImpactResult b = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(a.ok && b.ok) << a.reason << b.reason;
  EXPECT_EQ(a.contacts.size(), 1u);
  EXPECT_EQ(b.contacts.size(), 1u);
  EXPECT_NEAR(a.e, b.e, 1e-8);
}

// A reload right after a maximum, from a restart at z_m where z still rose by the locator's
// tolerance, has no bracket on its step and was missed: the drop-weight coupon at cut-off 60,
// rtol 1e-6, stayed on the stiffer unloading curve above z_m and ended with e = 0.9402, F_max
// 6566 N. Now within 1e-6 of the same plate (same modes) at rtol 1e-8: what the loose run's
// rtol 1e-6 promises for e ~ 0.9 (measured 7e-9); a missed reload costs 3e-2.
TEST(PlateImpact, AReloadRightAfterAMaximumIsNotMissed) {
  const Scene s = load_scene("drop-weight-coupon");
  using Stepper = PlateImpactOptions::Stepper;
  for (Stepper stepper : {Stepper::dop853, Stepper::exponential}) {  // both missed it
    PlateImpactOptions opt;
    opt.stepper = stepper;
    opt.cutoff = 60.0;
    opt.rtol = 1e-6;
    opt.atol = 1e-8;
    const PlateImpactResult loose = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
    opt.rtol = 1e-8;
    opt.atol = 1e-10;
    const PlateImpactResult tight = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
    ASSERT_TRUE(loose.ok && tight.ok) << loose.reason << tight.reason;
    EXPECT_NEAR(loose.e, tight.e, 1e-6) << plate_stepper_name(stepper);
    EXPECT_NEAR(loose.F_max / tight.F_max, 1.0, 1e-6) << plate_stepper_name(stepper);
  }
}

// A graze of z_m on an unloading branch (z_kin' touching zero and rising again right after a
// maximum) starts the reload root at zero: no sign change on the next steps, and z rose above
// z_m on the stiffer unloading curve unseen until the next maximum. The exponential stepper at
// rtol 1e-6 on the drop-weight coupon met such grazes and ended off by 6.7e-5 (cut-off 20),
// 6.5e-5 (40) and 3.1e-4 (60) in e, its energy ledger off by 8.7e-6 .. 2.8e-5 (the force jumps
// where the late reload switches the branch), with 24 .. 33 reloads against DOP853's 20 .. 22.
// Now a stop above z_m is a reload located on the step. Against DOP853 at rtol 1e-10 on the same
// modes (its error ~1e-10 in e, measured equal to 10 digits with the exponential stepper): e
// within 1e-6, what a run at rtol 1e-6 per step promises for e ~ 0.9 (measured 1e-10), the same
// contacts and reloads, and the ledger within 1e-6 of the impact's energy (measured 3e-12: the
// exponential stepper advances the modes exactly).
TEST(PlateImpact, AGrazeOfZmaxOnAnUnloadingBranchStillFindsTheReload) {
  const Scene s = load_scene("drop-weight-coupon");
  for (double cutoff : {20.0, 40.0, 60.0}) {
    PlateImpactOptions opt;
    opt.cutoff = cutoff;
    opt.rtol = 1e-10;
    opt.atol = 1e-12;
    opt.stepper = PlateImpactOptions::Stepper::dop853;
    const PlateImpactResult tight = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
    opt.stepper = PlateImpactOptions::Stepper::exponential;
    opt.rtol = 1e-6;
    opt.atol = 1e-8;
    const PlateImpactResult loose = simulate_plate_impact(s, LawKind::elastoplastic, {}, opt);
    ASSERT_TRUE(loose.ok && tight.ok) << loose.reason << tight.reason;
    EXPECT_NEAR(loose.e, tight.e, 1e-6) << "cut-off " << cutoff;
    EXPECT_LT(loose.energy.max_error, 1e-6) << "cut-off " << cutoff;
    EXPECT_EQ(loose.contacts.size(), tight.contacts.size()) << "cut-off " << cutoff;
    EXPECT_EQ(loose.reloads, tight.reloads) << "cut-off " << cutoff;
  }
}

// The cut-off chosen for a truncation tolerance: the answer is the run at the chosen cut-off
// (the same e as a fixed run there, to rounding: the same computation), its estimate within the
// tolerance, from a coarser run whose e it names.
TEST(PlateImpact, CutoffChosenForTheTruncationTolerance) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  PlateImpactOptions opt;
  opt.cutoff = 10.0;
  opt.truncation_tol = 1e-5;
  const PlateImpactResult r = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  ASSERT_TRUE(r.ok) << r.reason;
  EXPECT_GE(r.cutoff_runs, 2);
  EXPECT_LE(r.truncation_error, opt.truncation_tol);
  EXPECT_LT(r.cutoff_coarser, r.cutoff);
  EXPECT_GE(r.cutoff, opt.cutoff);
  const double p = std::pow(r.cutoff / r.cutoff_coarser, truncation_order(r.dropped)) - 1.0;
  EXPECT_DOUBLE_EQ(r.truncation_error, kTruncationSafety * std::abs(r.e - r.e_coarser) / p);
  PlateImpactOptions fixed;
  fixed.cutoff = r.cutoff;
  const PlateImpactResult f = simulate_plate_impact(s, LawKind::hertz, {}, fixed);
  ASSERT_TRUE(f.ok) << f.reason;
  EXPECT_EQ(f.e, r.e);
  EXPECT_EQ(f.mode_count, r.mode_count);
  EXPECT_TRUE(std::isnan(f.truncation_error));
}

// The rule's order is that of what the dropped modes are (plate_impact.h truncation_order): the
// same pair of runs read at order 4 with the equivalent oscillator, 1 with plain truncation.
TEST(PlateImpact, TruncationRuleTakesTheOrderOfTheDroppedModes) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  EXPECT_EQ(truncation_order(DroppedModes::static_compliance), 3.0);
  EXPECT_EQ(truncation_order(DroppedModes::oscillator), 4.0);
  EXPECT_EQ(truncation_order(DroppedModes::truncated), 1.0);
  // plain truncation converges as 1/cut-off: a looser tolerance keeps its modes few
  const std::pair<DroppedModes, double> cases[] = {{DroppedModes::oscillator, 1e-5},
                                                   {DroppedModes::truncated, 1e-3}};
  for (const auto& [d, tol] : cases) {
    PlateImpactOptions opt;
    opt.cutoff = 10.0;
    opt.truncation_tol = tol;
    opt.dropped = d;
    const PlateImpactResult r = simulate_plate_impact(s, LawKind::hertz, {}, opt);
    ASSERT_TRUE(r.ok) << r.reason;
    EXPECT_EQ(r.dropped, d);
    const double p = std::pow(r.cutoff / r.cutoff_coarser, truncation_order(d)) - 1.0;
    EXPECT_DOUBLE_EQ(r.truncation_error, kTruncationSafety * std::abs(r.e - r.e_coarser) / p)
        << dropped_modes_name(d);
    EXPECT_LE(r.truncation_error, opt.truncation_tol) << dropped_modes_name(d);
  }
}

// A tolerance that needs more modes than the limit is refused by name: how many, and that the
// infinite plate may be the model wanted.
TEST(PlateImpact, RefusesATruncationNeedingTooManyModes) {
  const Scene s = steel_ball_on_plate(0.2, 0.2, 0.002);
  PlateImpactOptions opt;
  opt.truncation_tol = 1e-6;
  opt.max_modes = 100;
  try {
    simulate_plate_impact(s, LawKind::hertz, {}, opt);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "structure");
    const std::string what = e.what();
    EXPECT_NE(what.find("modes"), std::string::npos) << what;
    EXPECT_NE(what.find("infinite plate"), std::string::npos) << what;
    EXPECT_NE(what.find("100"), std::string::npos) << what;
  }
}

TEST(PlateImpact, RefusesWhatItDoesNotModel) {
  Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  try {
    simulate_plate_impact(s, LawKind::hunt_crossley, {}, {});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--law");
  }
  s.damping.structure.length_x.reset();
  s.damping.structure.length_y.reset();
  s.damping.structure.edges.reset();
  try {
    simulate_plate_impact(s, LawKind::hertz, {}, {});
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "structure");
  }
}

// The command line's flags for a dashpot or another integrator are refused by name for a finite
// plate (it has no dashpot and runs its own integration), and --v0 replaces the velocity.
TEST(PlateImpact, CommandLineOptionsForAFinitePlate) {
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("ivv_plate_" + std::to_string(getpid()) + ".toml");
  {
    std::ofstream out(file);
    out << "[impactor]\nmass = 0.004168\nradius = 0.005\nyoungs_modulus = 207e9\n"
           "poisson_ratio = 0.3\n[target]\nyoungs_modulus = 207e9\npoisson_ratio = 0.3\n"
           "[structure]\nkind = \"plate\"\nthickness = 0.001\ndensity = 7960\n"
           "length_x = 0.05\nlength_y = 0.04\nedges = \"simply-supported\"\n"
           "[impact]\nvelocity = 1.0\n";
  }
  auto field = [&](auto&& edit) {
    RequestOptions o;
    o.scene = file.string();
    o.law = "hertz";
    edit(o);
    try {
      run_plate_simulation(o);
    } catch (const InputError& e) {
      return e.field();
    }
    return std::string();
  };
  EXPECT_EQ(field([](RequestOptions& o) { o.zeta = 0.1; }), "--zeta");
  EXPECT_EQ(field([](RequestOptions& o) { o.c = 100.0; }), "--c");
  // --integrator names the plate's stepper: its three, and nothing else
  EXPECT_EQ(field([](RequestOptions& o) { o.integrator = "rodas4"; }), "--integrator");
  for (const char* stepper : {"dop853", "odeint-dopri5", "exponential"})
    EXPECT_EQ(field([&](RequestOptions& o) { o.integrator = stepper; }), "") << stepper;
  EXPECT_EQ(field([](RequestOptions& o) { o.v0 = -1.0; }), "--v0");
  EXPECT_EQ(field([](RequestOptions& o) { o.model = "dashpot"; }), "--model");
  EXPECT_EQ(field([](RequestOptions& o) { o.model_tolerance = 0.0; }), "--model-tol");
  EXPECT_EQ(field([](RequestOptions& o) { o.model_tolerance = 1.5; }), "--model-tol");
  RequestOptions o;
  o.scene = file.string();
  o.law = "hertz";
  o.v0 = 0.5;
  const PlateRun run = run_plate_simulation(o);
  EXPECT_EQ(run.scene.velocity, 0.5);
  EXPECT_TRUE(run.result.ok) << run.result.reason;
  std::filesystem::remove(file);
}

}  // namespace
}  // namespace ivv
