// Contact laws by regime: loading, the yield kink, unloading, separation, history.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>

#include "scene/scene.h"
#include "solver/laws/elastoplastic.h"
#include "solver/laws/hertz.h"
#include "solver/laws/hunt_crossley.h"
#include "solver/laws/linearized.h"

namespace ivv {
namespace {

// Closed-form algebra in double: a few ulps of the largest term.
constexpr double kAlgebra = 1e-12;

DerivedParameters paper() {
  return derive(paper_scene());
}

TEST(Hertz, LoadingFollowsThreeHalvesPowerAndUnloadsOnTheSameCurve) {
  const HertzLaw law{2.0e9};
  Branch<double> b;
  const double z = 4e-5;
  EXPECT_NEAR(law.force(b, z, 0.0), 2.0e9 * std::pow(z, 1.5), kAlgebra * 2e9 * std::pow(z, 1.5));
  law_begin_unloading(law, b, z);
  EXPECT_EQ(b.z_perm, 0.0);
  const double half = 2.0e9 * std::pow(z / 2, 1.5);
  EXPECT_NEAR(law.force(b, z / 2, 0.0), half, kAlgebra * half);
  EXPECT_EQ(*law.hysteresis_work(b), 0.0);
}

TEST(Hertz, ContinuationBelowZeroIsOddSoSeparationIsASignChange) {
  const HertzLaw law{1.0};
  Branch<double> b;
  EXPECT_LT(law.force(b, -1e-3, 0.0), 0.0);
  EXPECT_EQ(law.force(b, -1e-3, 0.0), -law.force(b, 1e-3, 0.0));
}

TEST(Elastoplastic, KinkAtYieldIsContinuousWithMatchingSlope) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> b;
  ASSERT_EQ(*law_segment_end(law, b), p.z_y);
  const double hertz_at_yield = law.force(b, p.z_y, 0.0);
  const double hertz_slope = law.stiffness(b, p.z_y, 0.0);
  law_next_segment(law, b);
  EXPECT_FALSE(law_segment_end(law, b).has_value());
  EXPECT_NEAR(law.force(b, p.z_y, 0.0), hertz_at_yield, kAlgebra * hertz_at_yield);
  // K_y is defined as the Hertz slope at z_y (eq. 12): the kink is in curvature only.
  EXPECT_NEAR(law.stiffness(b, p.z_y, 0.0), hertz_slope, kAlgebra * hertz_slope);
}

TEST(Elastoplastic, UnloadingStartsAtPeakForceAndEndsAtPermanentSet) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> b;
  law_next_segment(law, b);
  const double z_m = 5 * p.z_y;
  const double F_m = law.force(b, z_m, 0.0);
  EXPECT_NEAR(F_m, p.K_y * 4 * p.z_y + p.K_h * std::pow(p.z_y, 1.5), kAlgebra * F_m);  // eq. 9
  law_begin_unloading(law, b, z_m);
  EXPECT_NEAR(law.force(b, z_m, 0.0), F_m, kAlgebra * F_m);  // eq. 10 at z = z_m
  const double z_f = std::pow(std::pow(z_m, 1.5) - F_m / p.K_h, 2.0 / 3.0);
  EXPECT_NEAR(b.z_perm, z_f, kAlgebra * z_m);
  EXPECT_NEAR(law.force(b, z_f, 0.0), 0.0, kAlgebra * F_m);
  EXPECT_LT(law.force(b, 0.99 * z_f, 0.0), 0.0);  // separation is a sign change
  EXPECT_NEAR(law.stored_energy(b, z_f), 0.0, kAlgebra * F_m * z_m);
}

TEST(Elastoplastic, HysteresisEqualsLoadingWorkMinusUnloadingWork) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> b;
  law_next_segment(law, b);
  const double z_m = 3 * p.z_y;
  law_begin_unloading(law, b, z_m);
  // trapezoid-free check by Simpson on each piece with many panels (error ~ 1e-12 relative)
  auto simpson = [](auto f, double a, double c, int n) {
    const double h = (c - a) / n;
    double s = f(a) + f(c);
    for (int i = 1; i < n; ++i) s += f(a + i * h) * (i % 2 ? 4 : 2);
    return s * h / 3;
  };
  ElastoplasticLaw::History<double> load;
  auto loading = [&](double z) {
    ElastoplasticLaw::History<double> lb = load;
    if (z > p.z_y) lb.segment = 1;
    return law.force(lb, z, 0.0);
  };
  auto unloading = [&](double z) { return law.force(b, z, 0.0); };
  const double area = simpson(loading, 0, p.z_y, 20000) + simpson(loading, p.z_y, z_m, 2000) -
                      simpson(unloading, b.z_perm, z_m, 20000);
  EXPECT_NEAR(*law.hysteresis_work(b), area, 1e-9 * area);
  EXPECT_GT(area, 0.0);
}

using mp = boost::multiprecision::cpp_bin_float_50;

// The elastoplastic law unloading from z_m after yield, and the textbook (cancelling) formulas'
// F_m, z_f^{3/2} and z_f in 50 digits, which absorb the cancellation.
struct UnloadingReference {
  ElastoplasticLaw::History<double> branch;
  mp Kh, zm, F_m, zf15, zf;
};
UnloadingReference unloading_from(const ElastoplasticLaw& law, const DerivedParameters& p,
                                  double z_m) {
  UnloadingReference u;
  law_next_segment(law, u.branch);
  law_begin_unloading(law, u.branch, z_m);
  u.Kh = p.K_h;
  u.zm = z_m;
  const mp zy = p.z_y;
  u.F_m = p.K_y * (u.zm - zy) + u.Kh * zy * sqrt(zy);
  u.zf15 = u.zm * sqrt(u.zm) - u.F_m / u.Kh;
  u.zf = cbrt(u.zf15 * u.zf15);
  return u;
}

// Far above yield the unloading force and the stored energy are small differences of large
// numbers (K_h z^{3/2} - K_h z_f^{3/2}); written that way they lost sqrt(z_m/z_y) of their
// relative accuracy (~1e23 J wrong at v0 = 1e16 m/s). Reference: the textbook
// (cancelling) formulas evaluated in 50 digits, which absorb the loss. Tolerance: the factored
// forms have only same-sign terms, so a few ulps per operation: 1e-13 relative (at 3 z_y the
// force is the plain form, whose gain 1.2 keeps it inside the same bound: the next test).
TEST(Elastoplastic, UnloadingHasNoCancellationFarAboveYield) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  for (double ratio : {3.0, 1e4, 1e8, 1e12, 1e16}) {
    const double z_m = ratio * p.z_y;
    const UnloadingReference u = unloading_from(law, p, z_m);
    const ElastoplasticLaw::History<double>& b = u.branch;
    const mp &Kh = u.Kh, &zf15 = u.zf15, &zf = u.zf;
    const mp span = u.zm - zf;
    EXPECT_NEAR(b.z_perm, static_cast<double>(zf), 1e-13 * z_m) << ratio;
    EXPECT_NEAR(b.unloading_span, static_cast<double>(span), 1e-13 * static_cast<double>(span))
        << ratio;
    for (double frac : {1.0, 0.5, 1e-3}) {  // z = z_f + frac (z_m - z_f)
      const double z = static_cast<double>(zf + frac * span);
      const mp zz = z;
      const mp force = Kh * (zz * sqrt(zz) - zf15);
      const mp energy =
          0.4 * Kh * (zz * zz * sqrt(zz) - zf * zf * sqrt(zf)) - Kh * zf15 * (zz - zf);
      // z - z_f is formed as (z - z_m) + (z_m - z_f): a few ulps of z_m in absolute terms,
      // which is also what the double state z carries near z_f (4 ulps: 4.4e-16 z_m)
      const double dz = z_m * 4.4e-16;
      const double slack = 1.5 * p.K_h * std::sqrt(z) * dz;
      EXPECT_NEAR(law.force(b, z, 0.0), static_cast<double>(force),
                  1e-13 * static_cast<double>(force) + slack)
          << ratio << " " << frac;
      EXPECT_NEAR(law.stored_energy(b, z), static_cast<double>(energy),
                  1e-13 * static_cast<double>(energy) + static_cast<double>(force) * dz)
          << ratio << " " << frac;
    }
  }
}

// The unloading force is computed plainly, K_h z^{3/2} + hertz_offset, where the cancellation's
// gain g = K_h z_m^{3/2} / F_m is at most kPlainUnloadingGain, and factored above it
// (elastoplastic.h). Reference: the same textbook formula in 50 digits. Tolerance: the plain
// form rounds K_h z^{3/2} (three operations) and adds the offset, a few ulps of K_h z_m^{3/2}:
// 4 ulps, i.e. 4 g ulps of F_m, against the factored form's 1e-13 relative (the test above).
TEST(Elastoplastic, UnloadingIsPlainOnlyWhereTheCancellationGainIsSmall) {
  constexpr double kUlp = 0x1p-52;
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  // z_m / z_y: just above yield, ~6 (the paper impact), 56 (g = 5, v0 = 10 m/s), 560 (g = 15.8,
  // 100 m/s), and past the bound (g ~ (2/3) sqrt(z_m / z_y): 21 at 1e3)
  for (double ratio : {1.01, 6.0, 56.0, 560.0, 1e3, 1e8}) {
    const UnloadingReference u = unloading_from(law, p, ratio * p.z_y);
    const ElastoplasticLaw::History<double>& b = u.branch;
    const mp &Kh = u.Kh, &zm = u.zm, &F_m = u.F_m, &zf15 = u.zf15, &zf = u.zf;
    const double gain = static_cast<double>(Kh * zm * sqrt(zm) / F_m);
    EXPECT_EQ(b.plain_unloading, gain <= ElastoplasticLaw::kPlainUnloadingGain) << ratio;
    if (!b.plain_unloading) continue;  // the factored form: the test above
    const double bound = 4 * gain * kUlp * static_cast<double>(F_m);
    for (double frac : {1.0, 0.5, 1e-3, 0.0}) {  // z = z_f + frac (z_m - z_f)
      const double z = static_cast<double>(zf + frac * (zm - zf));
      const mp zz = z;
      const double force = static_cast<double>(Kh * (zz * sqrt(zz) - zf15));
      EXPECT_NEAR(law.force(b, z, 0.0), force, bound) << ratio << " " << frac;
    }
  }
}

// The segment the law declares linear (law.h: linear_segment, which the driver crosses in closed
// form with its K) is its force: region II only, F = K (z - z_ref) + F_ref there to the rounding
// of the two formulas (kAlgebra), K equal to the law's stiffness; none on region I or unloading.
TEST(Elastoplastic, TheDeclaredLinearSegmentIsRegionTwo) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> b;
  EXPECT_FALSE(law_linear_segment(law, b).has_value());  // region I: Hertz
  law_next_segment(law, b);
  const std::optional<LinearSegment> seg = law_linear_segment(law, b);
  ASSERT_TRUE(seg.has_value());
  for (double ratio : {1.0, 1.5, 4.0, 30.0}) {
    const double z = ratio * p.z_y;
    const double F = law.force(b, z, 0.0);
    EXPECT_NEAR(seg->K * (z - seg->z_ref) + seg->F_ref, F, kAlgebra * F) << ratio;
    EXPECT_EQ(seg->K, law.stiffness(b, z, 0.0)) << ratio;
  }
  law_begin_unloading(law, b, 4 * p.z_y);
  EXPECT_FALSE(law_linear_segment(law, b).has_value());  // unloading: Hertz-shaped
}

TEST(Elastoplastic, UnloadingBeforeYieldIsHertz) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw law{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> b;
  law_begin_unloading(law, b, 0.5 * p.z_y);
  EXPECT_EQ(b.z_perm, 0.0);
  EXPECT_EQ(*law.hysteresis_work(b), 0.0);
  const double hertz = p.K_h * std::pow(0.3 * p.z_y, 1.5);
  EXPECT_NEAR(law.force(b, 0.3 * p.z_y, 0.0), hertz, kAlgebra * hertz);
}

TEST(Linearized, SecantUnloadingMatchesEquations16To18) {
  const DerivedParameters p = paper();
  const LinearizedLaw law{p.K_h, p.K_y};
  EXPECT_NEAR(law.minimum_z_max(), 2.25 * p.z_y, kAlgebra * p.z_y);
  LinearizedLaw::History<double> b;
  const double z_m = 10 * p.z_y;
  EXPECT_EQ(law.force(b, z_m, 0.0), p.K_y * z_m);  // eq. 15
  law_begin_unloading(law, b, z_m);
  const double z_f = z_m * std::pow(1 - p.K_y / (p.K_h * std::sqrt(z_m)), 2.0 / 3.0);  // eq. 17
  const double gamma2 = 1 - z_f / z_m;                                                 // eq. 18
  EXPECT_NEAR(b.z_perm, z_f, kAlgebra * z_m);
  EXPECT_NEAR(law.force(b, z_m, 0.0), p.K_y * z_m, kAlgebra * p.K_y * z_m);  // continuous
  EXPECT_NEAR(law.stiffness(b, z_m, 0.0), p.K_y / gamma2, kAlgebra * p.K_y / gamma2);
  // secant of the nonlinear unloading curve from (z_m, K_y z_m) in the sense of eq. 17: the
  // Hertz unloading curve through that point, K_h (z^{3/2} - z_f^{3/2}), vanishes at the same z_f
  EXPECT_NEAR(p.K_h * (std::pow(z_m, 1.5) - std::pow(z_f, 1.5)), p.K_y * z_m,
              kAlgebra * p.K_y * z_m);
  EXPECT_GT(gamma2, 0.0);
  EXPECT_LT(gamma2, 1.0);
}

TEST(Linearized, UndefinedBelowTwoAndAQuarterYieldDeformations) {
  const DerivedParameters p = paper();
  const LinearizedLaw law{p.K_h, p.K_y};
  LinearizedLaw::History<double> b;
  try {
    law_begin_unloading(law, b, 2.0 * p.z_y);
    FAIL() << "no domain error";
  } catch (const LawDomainError& e) {
    EXPECT_NE(std::string(e.what()).find("2.25 z_y"), std::string::npos) << e.what();
  }
  LinearizedLaw::History<double> edge;
  law_begin_unloading(law, edge,
                      law.minimum_z_max());  // exactly at the boundary: elastic unloading
  EXPECT_NEAR(edge.z_perm, 0.0, 1e-6 * p.z_y);
  EXPECT_TRUE(std::isfinite(edge.unloading_stiffness));
}

TEST(HuntCrossley, DampingTermScalesWithVelocity) {
  const HuntCrossleyLaw law{1e9, 0.5};
  Branch<double> b;
  const double z = 1e-4, elastic = 1e9 * std::pow(z, 1.5);
  EXPECT_NEAR(law.force(b, z, 0.0), elastic, kAlgebra * elastic);
  EXPECT_NEAR(law.force(b, z, 1.0), 1.5 * elastic, kAlgebra * elastic);
  EXPECT_NEAR(law.force(b, z, -1.0), 0.5 * elastic, kAlgebra * elastic);
  EXPECT_NEAR(law.rate_stiffness(b, z, 0.3), 0.5 * elastic, kAlgebra * elastic);
  EXPECT_FALSE(law.hysteresis_work(b).has_value());  // integrated, not closed form
}

// The concept is checked at compile time; these assertions are the test (a law that stops
// modelling it breaks the build of this file).
static_assert(ContactLaw<HertzLaw>);
static_assert(ContactLaw<ElastoplasticLaw>);
static_assert(ContactLaw<LinearizedLaw>);
static_assert(ContactLaw<HuntCrossleyLaw>);
static_assert(law_supports_scalar<ElastoplasticLaw, long double>);
static_assert(law_needs_yield_strength<ElastoplasticLaw>() &&
              !law_needs_yield_strength<HertzLaw>());

// A type that misses a member is not a ContactLaw, and the concept group that fails names it.
struct NoStoredEnergy {
  static constexpr std::string_view name = "broken";
  static constexpr bool rate_dependent = false;
  double force(const Branch<double>&, double z, double) const { return z; }
  double stiffness(const Branch<double>&, double, double) const { return 1; }
  double rate_stiffness(const Branch<double>&, double, double) const { return 0; }
  std::optional<double> segment_end(const Branch<double>&) const { return std::nullopt; }
  void next_segment(Branch<double>&) const {}
  void begin_unloading(Branch<double>&, double) const {}
};
static_assert(law_has_force<NoStoredEnergy> && law_has_history<NoStoredEnergy>);
static_assert(!law_has_energy<NoStoredEnergy> && !ContactLaw<NoStoredEnergy>);

// The single-branch laws leave segment_end, next_segment and begin_unloading to law.h.
static_assert(!law_declares_segment_end<HertzLaw> && !law_declares_next_segment<HertzLaw> &&
              !law_declares_begin_unloading<HertzLaw>);
static_assert(!law_declares_begin_unloading<HuntCrossleyLaw>);
static_assert(law_declares_segment_end<ElastoplasticLaw> &&
              law_declares_begin_unloading<ElastoplasticLaw>);

// The defaults: one loading segment (next_segment changes nothing), and unloading that records
// z_m with no permanent set.
TEST(ContactLawDefaults, ASingleBranchLawUnloadsOnItsLoadingCurve) {
  const HuntCrossleyLaw law{1e9, 0.5};
  Branch<double> b;
  EXPECT_FALSE(law_segment_end(law, b).has_value());
  law_next_segment(law, b);
  EXPECT_EQ(b.segment, 0);
  EXPECT_EQ(b.phase, Phase::loading);
  b.z_perm = 1.0;  // so that the default is seen to set it
  law_begin_unloading(law, b, 3e-5);
  EXPECT_EQ(b.phase, Phase::unloading);
  EXPECT_EQ(b.z_max, 3e-5);
  EXPECT_EQ(b.z_perm, 0.0);
}

TEST(ContactLawHistory, EachLawNamesItsOwnUnloadingState) {
  const DerivedParameters p = paper();
  const ElastoplasticLaw ep{p.K_h, p.z_y, p.K_y};
  ElastoplasticLaw::History<double> h;
  law_next_segment(ep, h);
  const double z_m = 4 * p.z_y;
  law_begin_unloading(ep, h, z_m);
  // the offset is a force: F_m - K_h z_m^{3/2}
  const double F_m = p.K_y * 3 * p.z_y + p.K_h * std::pow(p.z_y, 1.5);
  EXPECT_NEAR(h.hertz_offset, F_m - p.K_h * std::pow(z_m, 1.5), kAlgebra * F_m);
  const LinearizedLaw li{p.K_h, p.K_y};
  LinearizedLaw::History<double> g;
  law_begin_unloading(li, g, 10 * p.z_y);
  // the unloading stiffness is the secant from (z_f, 0) to (z_m, K_y z_m)
  const double secant = p.K_y * 10 * p.z_y / (10 * p.z_y - g.z_perm);
  EXPECT_NEAR(g.unloading_stiffness, secant, kAlgebra * secant);
}

}  // namespace
}  // namespace ivv
