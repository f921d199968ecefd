// The discontinuity scan: smooth curves (also with infinite slope at an end) pass, and a jump,
// a downward jump inside a rising curve, a jump at z = 0 and a NaN are located with their
// one-sided values.
#include "verification/continuity_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ivv::conformance {
namespace {

constexpr double kTau = 1e-12;  // the check's rounding allowance (1e-12 F_ref, F_ref = 1 here)

TEST(ContinuityScan, SmoothCurvesHaveNoJump) {
  for (auto f : {+[](double z) { return std::pow(z, 1.5); }, +[](double z) { return std::sqrt(z); },
                 +[](double z) { return std::sin(40 * z); }}) {
    const ScanResult s = scan_for_jumps(f, 0.0, 1.0, 1000, kTau);
    EXPECT_EQ(s.jumps, 0);
    EXPECT_FALSE(s.largest);
    EXPECT_GT(s.resolution, 0.0);
  }
}

TEST(ContinuityScan, AJumpIsLocatedWithItsOneSidedValues) {
  const double z1 = 0.123456789;
  const auto f = [z1](double z) { return z < z1 ? z * z : 1.5 * z * z; };
  const ScanResult s = scan_for_jumps(f, 0.0, 1.0, 1000, kTau);
  ASSERT_TRUE(s.largest);
  EXPECT_EQ(s.jumps, 1);
  // the bracket is a few ulps wide around z1 (adjacent doubles)
  EXPECT_LE(s.largest->z_left, z1);
  EXPECT_GE(s.largest->z_right, z1);
  EXPECT_LE(s.largest->z_right - s.largest->z_left, 4 * std::numeric_limits<double>::epsilon());
  EXPECT_NEAR(s.largest->F_left, z1 * z1, 1e-15);
  EXPECT_NEAR(s.largest->F_right, 1.5 * z1 * z1, 1e-15);
}

TEST(ContinuityScan, ADownwardJumpSmallerThanTheRiseOfItsIntervalIsStillFoundAboveR) {
  // rise 1 per unit z, jump -0.01 at 0.5003: the interval's change is 1e-3 - 1e-2
  const auto f = [](double z) { return z < 0.5003 ? z : z - 0.01; };
  const ScanResult s = scan_for_jumps(f, 0.0, 1.0, 1000, kTau);
  ASSERT_TRUE(s.largest);
  EXPECT_NEAR(s.largest->size(), 0.01, 1e-12);
  EXPECT_NEAR(s.largest->z_left, 0.5003, 1e-15);
  EXPECT_NEAR(s.resolution, 2e-3, 1e-12);  // 2 x the largest smooth change, 1e-3
}

TEST(ContinuityScan, AJumpAtTheLeftEndAndANanAreLocated) {
  const auto step = [](double z) { return z > 0 ? 1.0 + z : 0.0; };
  const ScanResult a = scan_for_jumps(step, 0.0, 1.0, 100, kTau);
  ASSERT_TRUE(a.largest);
  EXPECT_EQ(a.largest->z_left, 0.0);
  EXPECT_NEAR(a.largest->F_right, 1.0, 1e-12);

  const auto hole = [](double z) { return z > 0.25 && z < 0.26 ? NAN : z; };
  const ScanResult b = scan_for_jumps(hole, 0.0, 1.0, 1000, kTau);
  ASSERT_TRUE(b.largest);
  EXPECT_FALSE(b.largest->finite());
}

TEST(ContinuityScan, APulseBetweenTwoSamplesIsItsStatedBlindSpot) {
  // a pulse narrower than dz = 1e-3 between samples 0.500 and 0.501 of a flat curve: the two
  // samples agree, so nothing is bisected; the scan says that such a pulse can be missed
  const auto pulse = [](double z) { return z > 0.5002 && z < 0.5004 ? 2.0 : 1.0; };
  const ScanResult s = scan_for_jumps(pulse, 0.0, 1.0, 1000, kTau);
  EXPECT_FALSE(s.largest);
  EXPECT_NE(blind_spots(s).find("pulse narrower than dz = 0.001 m"), std::string::npos)
      << blind_spots(s);
}

}  // namespace
}  // namespace ivv::conformance
