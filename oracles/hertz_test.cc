// Tests of the undamped Hertz closed form (hertz.h).
#include "oracles/hertz.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scene/input_error.h"

namespace ivv::oracles {
namespace {

// docs/design.md §2 types the factor as 2.94327. The value is 2.9432752..., so the typed digits are
// truncated, not rounded (rounding gives 2.94328): the factor must lie in
// [2.94327, 2.94327 + one unit of the sixth digit).
constexpr double kTypedFactor = 2.94327;
constexpr double kTypedFactorUnit = 1e-5;
// Closed forms evaluated in double precision: a handful of roundings, each <= 1.1e-16.
constexpr double kRoundOff = 1e-14;

TEST(Hertz, ContactTimeFactorMatchesTheTypedDigits) {
  EXPECT_GE(hertz_contact_time_factor(), kTypedFactor);
  EXPECT_LT(hertz_contact_time_factor(), kTypedFactor + kTypedFactorUnit);
}

TEST(Hertz, ContactTimeFactorEqualsTheGammaFunctionForm) {
  // B(a, b) = Gamma(a) Gamma(b)/Gamma(a + b), with std::tgamma (libm, not Boost).
  const double by_gamma = 0.8 * std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  EXPECT_NEAR(hertz_contact_time_factor() / by_gamma, 1.0, kRoundOff);
}

TEST(Hertz, MaximumCompressionStoresTheKineticEnergy) {
  // (2/5) K_h z_m^{5/2} = (1/2) m v0^2: the work of F = K_h z^{3/2} from 0 to z_m.
  const double m = 0.5, K_h = 1.0e9, v0 = 0.3;
  const HertzImpact r = solve_hertz(m, K_h, v0);
  EXPECT_NEAR(0.4 * K_h * std::pow(r.z_max, 2.5) / (0.5 * m * v0 * v0), 1.0, kRoundOff);
  EXPECT_NEAR(r.F_max / (K_h * std::pow(r.z_max, 1.5)), 1.0, kRoundOff);
  EXPECT_EQ(r.e, 1.0);
}

// t_max independently of hertz.cc (which sets it to half the contact time): the energy
// balance gives dz/dt = v0 sqrt(1 - (z/z_m)^{5/2}), so t_max = (z_m/v0) int_0^1 du /
// sqrt(1 - u^{5/2}). With u = 1 - s^2 the endpoint singularity goes away:
// int_0^1 2 ds / sqrt((1 - (1 - s^2)^{5/2}) / s^2), a smooth integrand, by composite Simpson.
TEST(Hertz, TimeOfMaximumCompressionByQuadrature) {
  const double m = 0.5, K_h = 1.0e9, v0 = 0.3;
  const HertzImpact r = solve_hertz(m, K_h, v0);
  auto f = [](double s) {
    if (s == 0.0) return 2.0 / std::sqrt(2.5);                       // the limit s -> 0
    const double one_minus = -std::expm1(2.5 * std::log1p(-s * s));  // 1 - (1 - s^2)^{5/2}
    return 2.0 * s / std::sqrt(one_minus);
  };
  const int n = 2000;  // even
  const double h = 1.0 / n;
  double sum = f(0.0) + f(1.0);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(i * h);
  const double t_max = r.z_max / v0 * sum * h / 3.0;
  // Simpson's error (h^4/180) max|f''''| with h = 5e-4 and |f''''| = O(10): ~1e-14; 1e-11
  // leaves room for round-off in the sum of 2000 terms
  EXPECT_NEAR(r.t_max / t_max, 1.0, 1e-11);
}

TEST(Hertz, VelocityScalingOfDepthAndDuration) {
  // z_m ~ v0^{4/5} and t_f ~ z_m/v0 ~ v0^{-1/5}: doubling v0 scales them by 2^{4/5}, 2^{-1/5}.
  const HertzImpact a = solve_hertz(0.5, 1.0e9, 0.1);
  const HertzImpact b = solve_hertz(0.5, 1.0e9, 0.2);
  EXPECT_NEAR(b.z_max / a.z_max, std::pow(2.0, 0.8), kRoundOff);
  EXPECT_NEAR(b.t_contact / a.t_contact, std::pow(2.0, -0.2), kRoundOff);
}

TEST(Hertz, RejectsNonPositiveInput) {
  EXPECT_THROW(solve_hertz(0.0, 1.0e9, 1.0), InputError);
  EXPECT_THROW(solve_hertz(0.5, -1.0, 1.0), InputError);
  EXPECT_THROW(solve_hertz(0.5, 1.0e9, std::nan("")), InputError);
}

}  // namespace
}  // namespace ivv::oracles
