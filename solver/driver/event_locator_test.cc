// The shared event locator on functions with known roots.
#include "solver/driver/event_locator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace ivv {
namespace {

// TOMS 748 to all but 3 bits of a double: a few ulps of the root.
constexpr double kRootTolerance = 1e-14;

TEST(EventLocator, FindsSimpleRisingRoot) {
  auto g = [](double t) { return t * t - 2.0; };
  const auto t = locate_first_crossing(g, 0.0, 3.0, g(0.0), Direction::rising);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, std::sqrt(2.0), kRootTolerance);
  EXPECT_GE(g(*t), 0.0);  // returned on the post-event side
}

// solve_crossing tries Anderson-Bjorck first and hands a bracket where g is NaN to TOMS 748 as
// before: a g that is NaN on part of the bracket (a law outside its domain) ends in a named
// EventLocationError, never a hang or a root placed in the NaN (the first trial without the
// fallback hung). A root of z^{3/2} type (F at an elastic separation) converges all the same.
TEST(EventLocator, NaNInTheBracketIsANamedFailureAndAHertzianRootConverges) {
  // the first secant from g(0) = -0.3, g(1) = 0.01 lands at 0.97, where g is NaN
  auto g = [](double t) { return t < 0.5 ? t - 0.3 : t > 0.99 ? 0.01 : std::nan(""); };
  EXPECT_THROW(solve_crossing(g, 0.0, 1.0, g(0.0), g(1.0), Direction::rising), EventLocationError);
  auto hertzian = [](double t) {
    return 0.4 - t > 0 ? std::pow(0.4 - t, 1.5) : -std::pow(t - 0.4, 1.5);
  };
  const double th =
      solve_crossing(hertzian, 0.0, 1.0, hertzian(0.0), hertzian(1.0), Direction::falling);
  EXPECT_NEAR(th, 0.4, 1e-14);
}

// Anderson-Bjorck alone creeps up on a root from the end it keeps; a secant point kept half
// the tolerance from the bracket's ends lands across the root once the secant has it, and the
// bracket closes at once. cos on [0, 2]: 8 evaluations of g, 13 without that (counted with the
// final evaluation at the bracket's end, which solve_crossing no longer takes).
TEST(EventLocator, ASmoothRootIsBracketedFromBothSidesInFewEvaluations) {
  int evaluations = 0;
  auto g = [&](double t) {
    ++evaluations;
    return std::cos(t);
  };
  const double t = solve_crossing(g, 0.0, 2.0, 1.0, std::cos(2.0), Direction::falling);
  EXPECT_LE(evaluations, 8);
  EXPECT_NEAR(t, std::numbers::pi / 2, kRootTolerance);
  EXPECT_LE(std::cos(t), 0.0);  // the post-event end
}

// The tolerance made once per solve is boost's eps_tolerance test, with the nudge half its width,
// on brackets just inside and just outside the width, at the default bits (a constant, no
// ldexp) and at others (ldexp as before).
TEST(EventLocator, CrossingToleranceIsEpsToleranceWithHalfItsWidthAsTheNudge) {
  for (int bits : {std::numeric_limits<double>::digits - 3, 20, 40, 52}) {
    const CrossingTolerance<double> tol = CrossingTolerance<double>::make(bits);
    boost::math::tools::eps_tolerance<double> boost_tol(bits);  // its test is not const
    const double width = std::max(std::ldexp(1.0, 1 - bits), 4 * 2.220446049250313e-16);
    EXPECT_EQ(tol.nudge, width / 2) << bits;
    for (double a : {1e-3, 0.7, 3.0, 2e5}) {
      for (double k : {0.25, 0.5, 0.99, 1.0, 1.01, 2.0, 8.0}) {
        const double b = a + k * tol.eps * a;
        EXPECT_EQ(tol(a, b), boost_tol(a, b)) << bits << " " << a << " " << k;
        EXPECT_EQ(tol(-b, -a), boost_tol(-b, -a)) << bits << " " << a << " " << k;
      }
    }
  }
}

TEST(EventLocator, FindsFallingRootOfCosine) {
  auto g = [](double t) { return std::cos(t); };
  const auto t = locate_first_crossing(g, 0.0, 2.0, 1.0, Direction::falling);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, std::numbers::pi / 2, kRootTolerance);
  EXPECT_LE(g(*t), 0.0);
}

TEST(EventLocator, IgnoresCrossingInTheOtherDirection) {
  auto g = [](double t) { return t - 1.0; };  // rises through 0 at t = 1
  EXPECT_FALSE(locate_first_crossing(g, 0.0, 2.0, g(0.0), Direction::falling));
}

TEST(EventLocator, RootExactlyAtStepEndFiresAndDoesNotRefireAfterRestart) {
  auto g = [](double t) { return 1.0 - t; };
  const auto t = locate_first_crossing(g, 0.0, 1.0, g(0.0), Direction::falling);
  ASSERT_TRUE(t);
  EXPECT_EQ(*t, 1.0);
  // the next step starts on the root: g(t0) = 0 is not strictly before the event
  EXPECT_FALSE(locate_first_crossing(g, 1.0, 2.0, g(1.0), Direction::falling));
}

TEST(EventLocator, TwoRootsInOneStepGivesTheFirst) {
  // g > 0 at both ends of the step, negative between 0.3 and 0.6: endpoint signs see nothing.
  auto g = [](double t) { return (t - 0.3) * (t - 0.6); };
  EXPECT_GT(g(0.0), 0.0);
  EXPECT_GT(g(1.0), 0.0);
  const auto t = locate_first_crossing(g, 0.0, 1.0, g(0.0), Direction::falling);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 0.3, kRootTolerance);
}

TEST(EventLocator, RootOfThreeHalvesPowerLikeHertzSeparation) {
  // F ~ |z|^{3/2} sign(z) with z = 0.7 - t: a root where g' = 0 (Hertz separation at z = 0).
  auto g = [](double t) {
    const double z = 0.7 - t;
    return z * std::sqrt(std::abs(z));
  };
  const auto t = locate_first_crossing(g, 0.0, 1.0, g(0.0), Direction::falling);
  ASSERT_TRUE(t);
  EXPECT_NEAR(*t, 0.7, kRootTolerance);
}

TEST(EventLocator, NoCrossingWhenStartIsAlreadyPastTheEvent) {
  auto g = [](double t) { return -1.0 - t; };
  EXPECT_FALSE(locate_first_crossing(g, 0.0, 1.0, g(0.0), Direction::falling));
}

// TOMS 748 out of iterations was never checked; the event was placed at
// the unconverged bracket's end without a word.
TEST(EventLocator, OutOfIterationsIsAnError) {
  auto g = [](double t) { return std::cos(t); };
  LocatorOptions opt;
  opt.max_iterations = 2;  // far too few for 50 bits from a bracket of width 2
  try {
    solve_crossing(g, 0.0, 2.0, g(0.0), g(2.0), Direction::falling, opt);
    FAIL() << "no error from an unconverged root finder";
  } catch (const EventLocationError& e) {
    EXPECT_NE(std::string(e.what()).find("did not converge in 2 iterations"), std::string::npos)
        << e.what();
  }
  // the default budget converges on the same bracket
  EXPECT_NO_THROW(solve_crossing(g, 0.0, 2.0, g(0.0), g(2.0), Direction::falling));
}

// locate_earliest on a step whose interpolant is x(t) = (t, t^2 - 0.9 t + 0.18) on [0, 1]:
// root 0 is x0 - 0.7 (rising, monotone), root 1 is x1 (falling, positive at both ends but
// negative on (0.3, 0.6): two roots inside the step).
using Pair = std::array<double, 2>;
Pair pair_at(double t) {
  return {t, t * t - 0.9 * t + 0.18};
}
struct PairStep {
  Pair x0 = pair_at(0.0), x1 = pair_at(1.0);
  void operator()(double t, Pair& x) const { x = pair_at(t); }
};
double pair_root(int i, const Pair& x) {
  return i == 0 ? x[0] - 0.7 : x[1];
}

TEST(LocateEarliest, ProbesANonMonotoneRootAndReportsTheEarliestOfSeveral) {
  const PairStep step;
  RootSet<2> set;
  set.add({Direction::rising, true});
  set.add({Direction::falling, false});
  const auto e =
      locate_earliest(0.0, step.x0, 1.0, step.x1, step, set, pair_root, LocatorOptions{}, true);
  ASSERT_TRUE(e.t);
  EXPECT_EQ(e.first, 1);
  EXPECT_NEAR(*e.t, 0.3, kRootTolerance);
  EXPECT_TRUE(e.armed[0] && e.armed[1]);
  // root 0 crosses only in a later probe subinterval: not solved
  EXPECT_FALSE(e.found[0]);
}

TEST(LocateEarliest, AMonotoneDeclarationIsTrustedAtTheStepEnds) {
  const PairStep step;
  RootSet<2> set;
  set.add({Direction::rising, true});
  set.add({Direction::falling, true});  // wrongly declared monotone: the dip is not seen
  const auto e =
      locate_earliest(0.0, step.x0, 1.0, step.x1, step, set, pair_root, LocatorOptions{}, true);
  ASSERT_TRUE(e.t);
  EXPECT_EQ(e.first, 0);
  EXPECT_NEAR(*e.t, 0.7, kRootTolerance);
}

TEST(LocateEarliest, WithoutSolvingACrossingIsPlacedAtTheStepEnd) {
  const PairStep step;
  RootSet<2> set;
  set.add({Direction::rising, true});
  const auto e =
      locate_earliest(0.0, step.x0, 1.0, step.x1, step, set, pair_root, LocatorOptions{}, false);
  ASSERT_TRUE(e.t);
  EXPECT_EQ(*e.t, 1.0);
}

TEST(LocateEarliest, ARootAlreadyPastAtTheStepStartIsNotArmed) {
  const PairStep step;
  RootSet<2> set;
  set.add({Direction::falling, true});  // x0 - 0.7 < 0 at t = 0: already past a falling root
  const auto e =
      locate_earliest(0.0, step.x0, 1.0, step.x1, step, set, pair_root, LocatorOptions{}, true);
  EXPECT_FALSE(e.t);
  EXPECT_FALSE(e.armed[0]);
}

}  // namespace
}  // namespace ivv
