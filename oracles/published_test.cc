// Tests of the published restitution formulas (published.h).
#include "oracles/published.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "scene/input_error.h"

namespace ivv::oracles {
namespace {

constexpr double kRoundOff = 1e-14;

TEST(Thornton, ContinuousAtYield) {
  // At r = 1: 6/5 - r^2/5 = 1, r/(r + 2) = 1/3, so
  // e^2 = (6 sqrt3/5)(1 - 1/6)(1/3)^{1/2} = (6 sqrt3/5)(5/6)/sqrt3 = 1: the formula itself
  // gives e = 1 at yield, matching the elastic branch.
  EXPECT_EQ(thornton_cor(1.0), 1.0);
  EXPECT_NEAR(thornton_cor(std::nextafter(1.0, 0.0)), 1.0, kRoundOff);
  EXPECT_NEAR(thornton_cor(1.0 - 1e-9), 1.0, 1e-8);  // de/dr is O(1) at r = 1
  EXPECT_EQ(thornton_cor(5.0), 1.0);
  // Restitution falls as impact velocity rises (r falls).
  EXPECT_LT(thornton_cor(0.1), thornton_cor(0.5));
}

TEST(Thornton, AsymptoteAtHighVelocity) {
  // r -> 0: sqrt(1 - r^2/6) -> 1 and r/(r + 2 sqrt(6/5 - r^2/5)) -> r/(2 sqrt(6/5)), so
  // e -> sqrt(6 sqrt3/5) (2 sqrt(6/5))^{-1/4} r^{1/4} = 1.184993 r^{1/4}. The first correction
  // is the factor (1 + r/(2 sqrt(6/5)))^{-1/4} ~ 1 - r/8.8: relative O(r).
  const double c = thornton_asymptote_coefficient_exact();
  for (double r : {1e-4, 1e-6, 1e-8}) {
    EXPECT_NEAR(thornton_cor(r) / (c * std::pow(r, 0.25)), 1.0, 0.2 * r + kRoundOff) << r;
  }
  // Thornton's 1.185 is that coefficient to four digits: within half a unit of the last.
  EXPECT_NEAR(c, kThorntonAsymptoteCoefficient, 5e-4);
  // So the ratio to the published asymptote tends to 1 within the 4-digit rounding, 5e-4/1.185.
  EXPECT_NEAR(thornton_cor(1e-8) / thornton_asymptote(1e-8), 1.0, 5e-4 / 1.185 + 1e-8);
  EXPECT_THROW(thornton_cor(0.0), InputError);
}

TEST(KuwabaraKono, PadeAndSeriesAgreeForSmallVelocity) {
  // Expanding the Pade form (header): 1 - 1.153452 v*^2 + 1.6e-6 v*^3 + 0.798270 v*^4
  // + 0.266665 v*^5. Against the series 1 - 1.15344 v*^2 + 0.79826 v*^4 the difference is
  // 1.2e-5 v*^2 (fifth-digit rounding of the printed coefficient) + 1.6e-6 v*^3
  // + 1.0e-5 v*^4 + 0.267 v*^5; bound it by 1.5e-5 v*^2 + 0.3 v*^5 for v* <= 0.1.
  for (double v : {1e-3, 1e-2, 0.03, 0.1}) {
    EXPECT_LE(std::abs(kuwabara_kono_pade(v) - kuwabara_kono_series(v)),
              1.5e-5 * v * v + 0.3 * v * v * v * v * v)
        << v;
  }
  EXPECT_EQ(kuwabara_kono_pade(0.0), 1.0);
}

TEST(KuwabaraKono, PadeLimitsAndMonotonicity) {
  // v* -> inf: e ~ 0.141552/(0.235585 v*^3).
  const double v = 1e4;
  EXPECT_NEAR(kuwabara_kono_pade(v) * v * v * v, 0.141552 / 0.235585, 1e-3);
  double previous = 1.0;
  for (double x = 0.05; x < 20.0; x *= 1.5) {
    const double e = kuwabara_kono_pade(x);
    EXPECT_LT(e, previous) << x;
    EXPECT_GT(e, 0.0);
    previous = e;
  }
}

TEST(KuwabaraKono, BetaAndVelocityScale) {
  // beta = (3/2) A (rho/m)^{2/5}, rho = (4/3) E* sqrt(R). With E* = 3/4 Pa, R = 1 m, m = 1 kg:
  // rho = 1 and beta = 1.5 A. v* = sqrt(beta) v^{1/10}, so beta v^{1/5} = v*^2.
  EXPECT_NEAR(kuwabara_kono_beta(2.0, 0.75, 1.0, 1.0), 3.0, kRoundOff);
  const double beta = kuwabara_kono_beta(1e-6, 100e9, 0.01, 0.05);
  const double vs = kuwabara_kono_v_star(beta, 3.0);
  EXPECT_NEAR(vs * vs / (beta * std::pow(3.0, 0.2)), 1.0, kRoundOff);
  EXPECT_THROW(kuwabara_kono_beta(1e-6, -1.0, 0.01, 0.05), InputError);
}

}  // namespace
}  // namespace ivv::oracles
