// Tests of the exact Hunt-Crossley restitution and the damping maps (hunt_crossley.h).
#include "closed_forms/hunt_crossley.h"

#include <gtest/gtest.h>

#include <boost/math/special_functions/log1p.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "oracles/hertz.h"
#include "scene/input_error.h"
#include "solver/simulate.h"

namespace ivv::closed_forms {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// A handful of roundings in the polished Lambert-W / series evaluation.
constexpr double kRoundOff = 8 * kEps;

TEST(HuntCrossley, ExactRelationIsSatisfied) {
  // f(u0) = f(-e u0), f(u) = u - ln(1 + u) = -log1pmx(u): the separation condition. Both sides
  // are ~u0^2/2 for small u0 and log1pmx is accurate to a few ulps relative, so the residual
  // is a few ulps of f(u0). (Not checked for u0 >> 1: there 1 - e u0 is exponentially small
  // and the rounding of e u0 alone moves ln(1 - e u0) by eps/(1 - e u0); LargeDampingLimit
  // covers that regime.)
  for (double u0 : {1e-6, 1e-3, 0.01, 0.1, 0.5, 1.0, 3.0}) {
    const double e = hunt_crossley_cor(u0);
    const double lhs = boost::math::log1pmx(u0);
    const double rhs = boost::math::log1pmx(-e * u0);
    EXPECT_NEAR(rhs / lhs, 1.0, 16 * kEps) << "u0 = " << u0;
    EXPECT_GT(e, 0.0);
    EXPECT_LT(e, 1.0);
    EXPECT_LT(e * u0, 1.0);  // -e u0 > -1: the rebound force 1 - mu e v0 stays positive
  }
}

TEST(HuntCrossley, SeriesAndLambertWAgreeAcrossTheSwitch) {
  // Above kSeriesMaxU0 the value comes from Lambert W (then a Newton polish), below from the
  // series; the series truncation is c9 u^9 with |c9| = 0.124, i.e. < 1e-19 at u = 0.02, so
  // the two routes must agree to round-off just above the switch, and the function is
  // continuous across it.
  for (double u : {kSeriesMaxU0, 1.2 * kSeriesMaxU0, 2.0 * kSeriesMaxU0}) {
    EXPECT_NEAR(hunt_crossley_cor(u), hunt_crossley_cor_series(u), kRoundOff) << u;
  }
  const double below = hunt_crossley_cor(std::nextafter(kSeriesMaxU0, 0.0));
  const double at = hunt_crossley_cor(kSeriesMaxU0);
  // de/du ~ -2/3, so one ulp of u (1.7e-18) moves e by ~1e-18: only round-off remains.
  EXPECT_NEAR(below, at, kRoundOff);
}

TEST(HuntCrossley, SmallDampingLimit) {
  // e = 1 - (2/3) u0 + (4/9) u0^2 - (44/135) u0^3 + ... (series derived in the header): the
  // remainder of (1 - e)/u0 after two terms is (44/135) u0^2 < 0.4 u0^2; 1 - e itself is
  // rounded to eps/2 absolute, i.e. eps/(2 u0) after the division.
  for (double u0 : {1e-8, 1e-5, 1e-3}) {
    const double e = hunt_crossley_cor(u0);
    EXPECT_NEAR((1.0 - e) / u0, 2.0 / 3.0 - 4.0 / 9.0 * u0, 0.4 * u0 * u0 + kEps / u0) << u0;
  }
  EXPECT_EQ(hunt_crossley_cor(0.0), 1.0);
}

// At u0 = mu v0 ~ 1e-165 the Newton polish divided 0 by an underflowed slope
// and `simulate --law hunt-crossley --hc-mu 1e-200` printed "separated, e = -nan". Down to the
// smallest subnormal u0 the COR is 1 - (2/3) u0 to round-off, i.e. 1.
TEST(HuntCrossley, TinyDampingIsFiniteNotNaN) {
  for (double u0 : {1e-20, 1e-100, 1e-165, 1e-200, 1e-300, std::numeric_limits<double>::min(),
                    std::numeric_limits<double>::denorm_min()}) {
    const double e = hunt_crossley_cor(u0);
    EXPECT_TRUE(std::isfinite(e)) << u0;
    EXPECT_NEAR(e, 1.0, kRoundOff) << u0;
  }
}

// The same through the solver: `simulate --law hunt-crossley --hc-mu 1e-200` (model auto, so
// the Lambert-W route) printed "separated, e = -nan".
TEST(HuntCrossley, SimulateAtTinyDampingSeparatesWithEOfOne) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.law = LawKind::hunt_crossley;
  req.parameters = {{"mu", 1e-200}};
  req.model = ModelKind::automatic;
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.separated()) << r.reason;
  // e = 1 - (2/3) mu v0 to round-off: exactly elastic at mu v0 = 1e-200
  EXPECT_EQ(r.e, 1.0);
}

TEST(HuntCrossley, LargeDampingLimit) {
  // e = (1 - s)/u0 with s = -W0(-(1+u0)e^{-(1+u0)}) ~ (1+u0) e^{-(1+u0)}: e u0 -> 1 with an
  // exponentially small defect (1.5e-5 at u0 = 10, below double precision at u0 = 50).
  const double s10 = 11.0 * std::exp(-11.0);
  EXPECT_NEAR(hunt_crossley_cor(10.0) * 10.0, 1.0 - s10, 1e-3 * s10);
  EXPECT_NEAR(hunt_crossley_cor(50.0) * 50.0, 1.0, kRoundOff);
  EXPECT_NEAR(hunt_crossley_cor(1e6) * 1e6, 1.0, kRoundOff);
}

TEST(HuntCrossley, InverseReproducesTheTarget) {
  for (double e : {0.001, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.999, 0.999999}) {
    const double u0 = hunt_crossley_u0_for_cor(e);
    // TOMS 748 to ~2 ulps of u0, times |d ln e/d ln u0| <= 1, plus the forward round-off.
    EXPECT_NEAR(hunt_crossley_cor(u0) / e, 1.0, 4 * kRoundOff) << e;
  }
  EXPECT_THROW(hunt_crossley_u0_for_cor(1.0), InputError);
  EXPECT_THROW(hunt_crossley_u0_for_cor(0.0), InputError);
}

TEST(HuntCrossley, MaximumIndentationTendsToHertz) {
  // (K/m) x_m^{5/2}/(5/2) = v0^2 f(u0)/u0^2 and f(u0)/u0^2 = 1/2 - u0/3 + O(u0^2): the
  // mu -> 0 limit is Hertz's (5 m v0^2/(4K))^{2/5}, and x_m falls with mu.
  const double K = 1.1e9, m = 0.5, v0 = 1.0;
  const double hertz = oracles::solve_hertz(m, K, v0).z_max;
  EXPECT_NEAR(solve_hunt_crossley({K, 0.0, m, v0}).x_max / hertz, 1.0, kRoundOff);
  constexpr double kMu = 1e-6;  // u0 = 1e-6: x_m/x_hertz = (1 - 2u0/3)^{2/5} ~ 1 - 0.27e-6
  EXPECT_NEAR(solve_hunt_crossley({K, kMu, m, v0}).x_max / hertz, 1.0 - 0.4 * (2.0 / 3.0) * kMu,
              1e-12);
  double previous = hertz;
  for (double mu : {0.1, 0.5, 1.0, 5.0}) {
    const HuntCrossleyImpact r = solve_hunt_crossley({K, mu, m, v0});
    EXPECT_LT(r.x_max, previous);
    EXPECT_DOUBLE_EQ(r.u0, mu * v0);
    previous = r.x_max;
  }
  EXPECT_THROW(solve_hunt_crossley({K, -1.0, m, v0}), InputError);
}

// Small-(1 - e) behaviour of the maps. With delta = 1 - e_target, inverting the series,
// the exact u0 delivering e_target is u0 = (3/2) delta + (3/2) delta^2 + (27/20) delta^3 + ...
// and the delivered e answers a map's u0 with slope de/du0 = -2/3 + (8/9) u0:
//   hunt-crossley        u0 = (3/2) delta                 e_del - e_t = +delta^2 + O(delta^3)
//   lankarani-nikravesh  u0 = (3/2) delta - (3/4) delta^2 e_del - e_t = +(3/2) delta^2 + ...
//   hu-guo               u0 = (3/2) delta/(1 - delta)     e_del - e_t = -delta^3/10 + ...
//   lee-wang             u0 = (3/4) delta                 (1 - e_del)/delta -> 1/2
//   gonthier             u0 = delta(2 - delta)/(1 - delta) (1 - e_del)/delta -> 4/3
//   flores               u0 = (8/5) delta/(1 - delta)     (1 - e_del)/delta -> 16/15
//   gharib-hurmuzlu      u0 = delta/(1 - delta)           (1 - e_del)/delta -> 2/3
// So only Hunt-Crossley/Marhefka-Orin, Lankarani-Nikravesh and Hu-Guo deliver the target in
// the nearly-elastic limit, Hu-Guo to second order.
TEST(DampingMaps, NearlyElasticLimit) {
  constexpr double kDelta = 1e-3;
  // Next order relative to the leading term is O(delta); 5 delta bounds its coefficient.
  constexpr double kNextOrder = 5 * kDelta;
  const double e_t = 1.0 - kDelta;
  auto delivered = [&](const char* name) { return delivered_cor(*find_damping_map(name), e_t); };
  EXPECT_NEAR((delivered("hunt-crossley") - e_t) / (kDelta * kDelta), 1.0, kNextOrder);
  EXPECT_NEAR((delivered("lankarani-nikravesh") - e_t) / (kDelta * kDelta), 1.5, kNextOrder);
  // e_del - e_t = -delta^3/10 ~ 1e-10 while round-off in e is ~1e-16: relative 1e-6 noise.
  EXPECT_NEAR((delivered("hu-guo") - e_t) / (kDelta * kDelta * kDelta), -0.1,
              0.1 * kNextOrder + 1e-5);
  EXPECT_NEAR((1.0 - delivered("lee-wang")) / kDelta, 0.5, kNextOrder);
  EXPECT_NEAR((1.0 - delivered("gonthier")) / kDelta, 4.0 / 3.0, kNextOrder);
  EXPECT_NEAR((1.0 - delivered("flores")) / kDelta, 16.0 / 15.0, kNextOrder);
  EXPECT_NEAR((1.0 - delivered("gharib-hurmuzlu")) / kDelta, 2.0 / 3.0, kNextOrder);
}

// Nearly-plastic limit e_target -> 0: the exact e ~ 1/u0 (LargeDampingLimit), so a map with
// u0 ~ 1/e_target is exact there. Gharib-Hurmuzlu: u0 = 1/e - 1, e_del ~ e/(1 - e), so
// e_del/e_t - 1 ~ e_t. Gonthier: u0 = 1/e - e, e_del ~ e/(1 - e^2), e_del/e_t - 1 ~ e_t^2.
// Hu-Guo (u0 ~ 3/(2e)) and Flores (u0 ~ 8/(5e)) give 2/3 and 5/8 of the target instead; the
// others keep u0 bounded and deliver a finite e as e_target -> 0.
TEST(DampingMaps, NearlyPlasticLimit) {
  constexpr double kTarget = 1e-3;
  // Relative next order: O(e_t) beyond the leading term, plus the exponentially small s.
  constexpr double kNextOrder = 5 * kTarget;
  auto delivered = [&](const char* name) {
    return delivered_cor(*find_damping_map(name), kTarget);
  };
  EXPECT_NEAR((delivered("gharib-hurmuzlu") / kTarget - 1.0) / kTarget, 1.0, kNextOrder);
  EXPECT_NEAR((delivered("gonthier") / kTarget - 1.0) / (kTarget * kTarget), 1.0, 1e-3);
  EXPECT_NEAR(delivered("hu-guo") / kTarget, 2.0 / 3.0, kNextOrder);
  EXPECT_NEAR(delivered("flores") / kTarget, 5.0 / 8.0, kNextOrder);
  // Hunt-Crossley: u0 -> 3/2, Lankarani-Nikravesh and Lee-Wang: u0 -> 3/4.
  EXPECT_NEAR(delivered("hunt-crossley"), hunt_crossley_cor(1.5), 1e-3);
  EXPECT_NEAR(delivered("lee-wang"), hunt_crossley_cor(0.75), 1e-3);
  EXPECT_NEAR(delivered("lankarani-nikravesh"), hunt_crossley_cor(0.75), 1e-3);
}

TEST(DampingMaps, TableIsCompleteAndNamed) {
  EXPECT_EQ(damping_maps().size(), 7u);
  for (const DampingMap& m : damping_maps()) {
    ASSERT_TRUE(find_damping_map(m.name).has_value()) << m.name;
    EXPECT_GT(m.mu(0.5, 2.0), 0.0);
    // mu ~ 1/v0: u0 = mu v0 is the same at every velocity.
    EXPECT_NEAR(m.mu(0.5, 2.0) * 2.0, m.mu(0.5, 1.0), kRoundOff) << m.name;
  }
  EXPECT_FALSE(find_damping_map("no-such-map").has_value());
  EXPECT_THROW(mu_flores(1.5, 1.0), InputError);
  EXPECT_THROW(mu_flores(0.5, 0.0), InputError);
}

}  // namespace
}  // namespace ivv::closed_forms
