#include "oracles/plate_convolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "scene/scene.h"
#include "solver/plate/plate_modes.h"
#include "solver/plate/steel_ball_on_plate.h"

namespace ivv {
namespace {

// No kept modes: the Hertz spring in series with the plate's static compliance C, elastic, so
// e = 1 and (1/2) m v0^2 = (2/5) K z_m^{5/2} + (1/2) C (K z_m^{3/2})^2 (z_m by bisection here).
// The march is second order: halving dt must cut the error of F_max by about 4 (between 3 and 5:
// the kinks at onset and separation fall between grid points), and at 400 steps per contact
// the error is below 1e-4.
TEST(PlateConvolution, WithoutModesIsTheTwoSpringModelToSecondOrder) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  const FinitePlate plate = finite_plate(s.damping.structure, 207e9, 0.3);
  const PlateModes none = plate_modes(plate, {1.0});  // below the first mode
  ASSERT_EQ(none.modes.size(), 0u);
  const double K = derive(s).K_h, C = none.residual_compliance, E = 0.5 * s.mass;
  double lo = 0.0, hi = 1e-3;
  for (int i = 0; i < 200; ++i) {
    const double z = 0.5 * (lo + hi), F = K * z * std::sqrt(z);
    (0.4 * F * z + 0.5 * C * F * F > E ? hi : lo) = z;
  }
  const double F_ref = K * lo * std::sqrt(lo);
  double error[2];
  for (int k = 0; k < 2; ++k) {
    const ConvolutionResult r =
        plate_impact_by_convolution(s, LawKind::hertz, {}, none, {2e-7 / (1 << k), 1.0, true});
    ASSERT_TRUE(r.ok) << r.reason;
    EXPECT_EQ(r.contacts.size(), 1u);
    EXPECT_NEAR(r.e, 1.0, 1e-4);
    error[k] = std::abs(r.F_max / F_ref - 1.0);
  }
  EXPECT_LT(error[1], 1e-4);
  EXPECT_GT(error[0] / error[1], 3.0);
  EXPECT_LT(error[0] / error[1], 5.0);
}

TEST(PlateConvolution, RefusesANonPositiveStep) {
  const Scene s = steel_ball_on_plate(0.05, 0.04, 0.001);
  const PlateModes none = plate_modes(finite_plate(s.damping.structure, 207e9, 0.3), {1.0});
  EXPECT_THROW(plate_impact_by_convolution(s, LawKind::hertz, {}, none, {0.0, 1.0, true}),
               std::invalid_argument);
}

}  // namespace
}  // namespace ivv
