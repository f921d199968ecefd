// The shared event locator on functions with known roots.
#include "solver/event_locator.h"

#include <gtest/gtest.h>

#include <cmath>
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

// Issue 10 item 7: TOMS 748 out of iterations was never checked; the event was placed at
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

}  // namespace
}  // namespace ivv
