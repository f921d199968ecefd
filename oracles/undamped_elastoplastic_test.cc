// Tests of the undamped elastoplastic oracle (undamped_elastoplastic.h), on the paper's
// Table 1 scene unless stated.
#include "oracles/undamped_elastoplastic.h"

#include <gtest/gtest.h>

#include <cmath>

#include "oracles/hertz.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace ivv::oracles {
namespace {

// Algebraic closed forms: a few dozen roundings of ~1.1e-16 each.
constexpr double kRoundOff = 1e-13;
// Each quadrature is asked for 1e-12 relative; the contact time sums two or three of them.
constexpr double kQuadratureTol = 5e-12;

ElastoplasticInput paper_input(double v0) {
  const Scene s = paper_scene();
  ElastoplasticInput in = elastoplastic_input(s, derive(s));
  in.v0 = v0;
  return in;
}

double v_yield() {
  return derive(paper_scene()).v_yield;
}

TEST(UndampedElastoplastic, BelowYieldIsHertz) {
  // E0 <= E_y: the law is Hertz throughout, e = 1, and the quadrature of dt = dz/v must give
  // Hertz's closed form (4/5) B(2/5, 1/2) z_m/v0 (Boost beta: an independent route).
  for (double fraction : {1e-3, 0.1, 0.5, 0.999}) {
    const ElastoplasticInput in = paper_input(fraction * v_yield());
    const ElastoplasticImpact r = solve_undamped_elastoplastic(in);
    const HertzImpact h = solve_hertz(in.mass, in.K_h, in.v0);
    EXPECT_FALSE(r.yielded);
    EXPECT_EQ(r.e, 1.0);
    EXPECT_NEAR(r.z_max / h.z_max, 1.0, kRoundOff);
    EXPECT_NEAR(r.t_contact / h.t_contact, 1.0, kQuadratureTol) << "v0/v_y = " << fraction;
    EXPECT_LT(r.t_error, kQuadratureTol * r.t_contact);
  }
}

TEST(UndampedElastoplastic, YieldVelocityIsTheHertzEnergyAtYield) {
  // v_y = sqrt(4 K_h z_y^{5/2}/(5 m)) (docs/design.md §1) must equal the scene's derived v_yield.
  const ElastoplasticImpact r = solve_undamped_elastoplastic(paper_input(1.0));
  EXPECT_NEAR(r.v_yield / v_yield(), 1.0, kRoundOff);
}

TEST(UndampedElastoplastic, RestitutionIsContinuousAtYield) {
  // Just above yield the unloading curve is the Hertz curve lowered by
  // K_h z_f^{3/2} = K_h d^2 (a + b/2)/(a + b)^2 ~ (3/8) K_h d^2/sqrt(z_y); over the width z_y
  // this removes ~(3/8) K_h sqrt(z_y) d^2 of returned energy, with d ~ (4/5) z_y f for
  // v0 = v_y (1 + f). Divided by 2 E0 ~ (4/5) K_h z_y^{5/2}: 1 - e ~ 0.3 f^2.
  constexpr double kLeadingCoefficient = 0.3;
  constexpr double kF = 1e-4;
  // Relative size of the next order, O(f), with margin; round-off in 1 - e is ~1e-16/3e-9.
  constexpr double kNextOrder = 1e-2;
  const ElastoplasticImpact r = solve_undamped_elastoplastic(paper_input(v_yield() * (1 + kF)));
  EXPECT_TRUE(r.yielded);
  EXPECT_NEAR((1.0 - r.e) / (kLeadingCoefficient * kF * kF), 1.0, kNextOrder);

  // The contact time is continuous through yield: just below and just above, t_f differs by
  // the Hertz scaling t_f ~ v0^{-1/5} only, i.e. relative -0.2 x (2e-12) here.
  constexpr double kStep = 1e-12;
  const ElastoplasticImpact below =
      solve_undamped_elastoplastic(paper_input(v_yield() * (1 - kStep)));
  const ElastoplasticImpact above =
      solve_undamped_elastoplastic(paper_input(v_yield() * (1 + kStep)));
  EXPECT_FALSE(below.yielded);
  EXPECT_TRUE(above.yielded);
  EXPECT_NEAR(above.t_contact / below.t_contact, 1.0, kQuadratureTol);
  EXPECT_NEAR(above.e, 1.0, kRoundOff);
}

TEST(UndampedElastoplastic, EnergyLedgerCloses) {
  // W_u (unloading work, from the factorised closed form) + W_p (loading work from d minus
  // W_u) = E0, where the loading work E_y + F_y d + (K_y/2) d^2 checks the quadratic's root.
  for (double ratio : {1.01, 2.0, 7.64, 38.2, 1e3, 1e5}) {
    const ElastoplasticImpact r = solve_undamped_elastoplastic(paper_input(ratio * v_yield()));
    EXPECT_NEAR((r.W_u + r.W_p) / r.energy_initial, 1.0, kRoundOff) << ratio;
    EXPECT_NEAR(r.e * r.e * r.energy_initial / r.W_u, 1.0, kRoundOff);
  }
}

TEST(UndampedElastoplastic, StableFormsEqualTheTextbookFormsAtModerateVelocity) {
  // At 10 v_y neither form suffers cancellation, so the naive formulas of docs/design.md §2
  // z_f = (z_m^{3/2} - F_m/K_h)^{2/3} and W_u = (2/5)K_h(z_m^{5/2} - z_f^{5/2})
  // - (K_h z_m^{3/2} - F_m)(z_m - z_f) must agree with the factorised ones.
  // The naive z_f loses ~z_m^{3/2}/z_f^{3/2} ~ 10 of its digits' worth; allow 1e-12.
  constexpr double kNaiveTol = 1e-12;
  const ElastoplasticInput in = paper_input(10.0 * v_yield());
  const ElastoplasticImpact r = solve_undamped_elastoplastic(in);
  const double zm = r.z_max;
  const double zf_naive = std::pow(std::pow(zm, 1.5) - r.F_max / in.K_h, 2.0 / 3.0);
  EXPECT_NEAR(r.z_perm / zf_naive, 1.0, kNaiveTol);
  const double Wu_naive = 0.4 * in.K_h * (std::pow(zm, 2.5) - std::pow(zf_naive, 2.5)) -
                          (in.K_h * std::pow(zm, 1.5) - r.F_max) * (zm - zf_naive);
  EXPECT_NEAR(r.W_u / Wu_naive, 1.0, kNaiveTol);
  // The loading quadratic: (K_y/2) d^2 + K_h z_y^{3/2} d = E0 - E_y.
  const double d = zm - in.z_y;
  const double K_y = 1.5 * in.K_h * std::sqrt(in.z_y);
  EXPECT_NEAR((0.5 * K_y * d * d + in.K_h * std::pow(in.z_y, 1.5) * d) /
                  (r.energy_initial - r.energy_yield),
              1.0, kNaiveTol);
}

double local_slope(double v0) {
  // d ln e / d ln v0 by central differences in ln v0; step h gives an O(h^2) error
  // (~1e-5 here) and e is accurate to ~1e-15, so round-off adds ~1e-13.
  constexpr double h = 1e-2;
  const double up = solve_undamped_elastoplastic(paper_input(v0 * std::exp(h))).e;
  const double down = solve_undamped_elastoplastic(paper_input(v0 * std::exp(-h))).e;
  return (std::log(up) - std::log(down)) / (2.0 * h);
}

TEST(UndampedElastoplastic, HighVelocitySlopeTendsToMinusOneQuarter) {
  // Johnson (1985) ch. 11 and paper eq 21: e ~ v0^{-1/4} at high velocity. docs/design.md §3:
  // assert the limit where it holds (within 0.005 at 1e4 v_y), not just above yield.
  constexpr double kSlopeTolerance = 0.005;
  EXPECT_NEAR(local_slope(1e4 * v_yield()), -0.25, kSlopeTolerance);
  // ... and the approach is from below: docs/design.md §3 quotes about -0.257 near 15 v_y, steeper
  // than the limit; 0.002 covers "about" at three printed digits.
  constexpr double kQuotedTolerance = 0.002;
  EXPECT_NEAR(local_slope(15.0 * v_yield()), -0.257, kQuotedTolerance);
  EXPECT_LT(std::abs(local_slope(1e4 * v_yield()) + 0.25),
            std::abs(local_slope(1e2 * v_yield()) + 0.25));
}

TEST(UndampedElastoplastic, TimesAreOrderedAndQuadratureConverged) {
  for (double ratio : {1.5, 7.64, 38.2, 1e3}) {
    const ElastoplasticImpact r = solve_undamped_elastoplastic(paper_input(ratio * v_yield()));
    EXPECT_GT(r.t_max, 0.0);
    EXPECT_GT(r.t_contact, r.t_max);
    // Unloading is stiffer than loading (the secant of eq 10 is steeper than K_y), so it is
    // shorter than the loading phase.
    EXPECT_LT(r.t_contact - r.t_max, r.t_max);
    EXPECT_LT(r.t_error, kQuadratureTol * r.t_contact);
    EXPECT_GT(r.z_perm, 0.0);
    EXPECT_LT(r.z_perm, r.z_max);
  }
}

TEST(UndampedElastoplastic, RejectsNonPositiveInput) {
  ElastoplasticInput in = paper_input(1.0);
  in.z_y = 0.0;
  EXPECT_THROW(solve_undamped_elastoplastic(in), InputError);
  in = paper_input(-1.0);
  EXPECT_THROW(solve_undamped_elastoplastic(in), InputError);
}

}  // namespace
}  // namespace ivv::oracles
