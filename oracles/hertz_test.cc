// Tests of the undamped Hertz closed form (hertz.h).
#include "oracles/hertz.h"

#include <gtest/gtest.h>

#include <cmath>

#include "solver/input_error.h"

namespace ivv::oracles {
namespace {

// SPEC §2 types the factor as 2.94327. The value is 2.9432752..., so the typed digits are
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
  EXPECT_DOUBLE_EQ(r.t_max, 0.5 * r.t_contact);
  EXPECT_EQ(r.e, 1.0);
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
