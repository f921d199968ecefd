// Tests of Zener's problem (oracles/zener.h): the small-lambda slope by quadrature, and the
// Taylor-series solution e(lambda) against closed forms and a second implementation.
#include "oracles/zener.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace ivv::oracles {
namespace {

// The tanh-sinh rule converges to about 1e-15 on this integrand (smooth but for the
// integrable inverse square root at the end, which the rule's endpoint clustering resolves);
// 1e-12 relative leaves a margin of three digits over double rounding of the Beta function.
TEST(Zener, SlopeQuadratureMatchesBetaFunction) {
  EXPECT_NEAR(zener_small_lambda_slope() / zener_small_lambda_slope_closed_form(), 1.0, 1e-12);
  EXPECT_NEAR(zener_small_lambda_slope(), 1.7301, 1e-4);  // hand value: 0.8 * 1.4291 * 1.5133
}

// The undamped contact time in Zener's units is the Hertz factor 2.9432752 times
// z_m/z* = (5/4)^{2/5} (docs/design.md §2, Hertz undamped).
TEST(Zener, UndampedContactTimeIsTheHertzFactor) {
  EXPECT_NEAR(zener_undamped_contact_time(), 2.9432752 * std::pow(1.25, 0.4), 1e-6);
}

// lambda = 0 is the undamped Hertz impact: e = 1, the contact time above and the peak force
// sigma_m^{3/2} = (5/4)^{3/5}, in closed form. The series solution is good to ~1e-40; 1e-14
// allows for the double rounding of the closed forms (Beta function, tanh-sinh quadrature).
TEST(ZenerImpact, UndampedLimitIsTheHertzImpact) {
  const ZenerImpact z = zener_impact(0.0);
  EXPECT_NEAR(z.e, 1.0, 1e-15);
  EXPECT_NEAR(z.contact_time, zener_undamped_contact_time(), 1e-14);
  EXPECT_NEAR(z.peak_force, std::pow(1.25, 0.6), 1e-15);
  EXPECT_LT(z.error, 1e-15);
}

// Small lambda: g = (1 - e)/lambda = a + b lambda + O(lambda^2), so Richardson's
// 2 g(lambda) - g(2 lambda) at lambda = 1e-4 leaves an O(lambda^2) remainder ~1e-8 of a (the
// coefficients are of order 1); 1e-6 relative is a hundred times that, and far below the
// first-order term b lambda ~ 1e-4 that an error in the damping term would leave.
TEST(ZenerImpact, SmallLambdaSlopeIsTheQuadrature) {
  auto g = [](double lambda) { return (1.0 - zener_impact(lambda).e) / lambda; };
  EXPECT_NEAR((2.0 * g(1e-4) - g(2e-4)) / zener_small_lambda_slope(), 1.0, 1e-6);
}

// A second implementation of the same formulation: mpmath 1.3 odefun (its own Taylor series
// and step control) at 30 digits on dr/ds = u - lambda r^3, du/ds = -2 r^4, dtau/ds = 2 r,
// the end located by mpmath.findroot. Its values, printed to 18 digits: e and tau_f below.
// The two agree to ~1e-25; 1e-15 is the double rounding of the comparison.
TEST(ZenerImpact, AgreesWithASecondSeriesImplementation) {
  struct Row {
    double lambda, e, contact_time;
  };
  const Row rows[] = {{0.1, 0.843339410924882923, 3.27849498821759262},
                      {0.5, 0.436895300942335860, 3.62444145102221563},
                      {1.0, 0.184122874165049994, 4.38761201801007173}};
  for (const Row& row : rows) {
    const ZenerImpact z = zener_impact(row.lambda);
    EXPECT_NEAR(z.e, row.e, 1e-15) << "lambda = " << row.lambda;
    EXPECT_NEAR(z.contact_time, row.contact_time, 4e-15) << "lambda = " << row.lambda;
    EXPECT_LT(z.error, 1e-15) << "lambda = " << row.lambda;
  }
}

// e falls with lambda (more of the energy goes into the plate) and the sphere always leaves.
TEST(ZenerImpact, RestitutionFallsWithLambdaAndStaysPositive) {
  double previous = 1.0;
  for (double lambda : {0.01, 0.1, 1.0, 5.0, 10.0}) {
    const double e = zener_impact(lambda).e;
    EXPECT_LT(e, previous) << "lambda = " << lambda;
    EXPECT_GT(e, 0.0) << "lambda = " << lambda;
    previous = e;
  }
}

TEST(ZenerImpact, RejectsNegativeOrNonFiniteLambda) {
  EXPECT_THROW(zener_impact(-0.1), std::invalid_argument);
  EXPECT_THROW(zener_impact(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace ivv::oracles
