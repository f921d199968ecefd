// The capture criteria of capture.h, each on states chosen on either side of its threshold.
#include "solver/driver/capture.h"

#include <gtest/gtest.h>

#include "solver/driver/impact_system.h"
#include "solver/laws/elastoplastic.h"

namespace ivv {
namespace {

// Normalised units (length = velocity = force scale = 1): K_h = 1, z_y = 0.25, unloading from
// z_m = 0.5 after yield, so z_f = 0.119 and the slope floor k_f = 1.5 sqrt(z_f) = 0.52.
template <bool Dashpot>
ImpactSystem<ElastoplasticLaw, Dashpot> unloading(double two_zeta) {
  ImpactSystem<ElastoplasticLaw, Dashpot> sys;
  sys.law = {1.0, 0.25, 1.5 * 0.5};
  sys.two_zeta = two_zeta;
  law_next_segment(sys.law, sys.branch);
  law_begin_unloading(sys.law, sys.branch, 0.5);
  return sys;
}

// A state on the unloading branch at u = z - z_f above the permanent set, approaching at w.
template <class System>
typename System::state_type near_permanent_set(const System& sys, double u, double w) {
  typename System::state_type x{};
  x[System::A] = sys.branch.z_perm + u;
  x[System::W] = w;
  if constexpr (System::has_dashpot) x[System::Z] = sys.branch.z_perm + u;
  return x;
}

TEST(ExactCapture, InsideTheInvariantRegionByMoreThanTheErrorBoundIsExact) {
  // 2 zeta = 10: overdamped at z_f ((2 zeta k)^2 = 27 >= 4 k = 2.1), slow root s1 = 0.10
  const auto sys = unloading<true>(10.0);
  const IntegratorOptions opt;
  const auto inside = near_permanent_set(sys, 0.01, 0.5);  // w = 0.5 >= s1 u = 0.001
  EXPECT_EQ(exact_capture(sys, inside, 10, opt), std::optional<double>(0.0));
  EXPECT_EQ(capture_after_step(sys, inside, 10, opt), std::optional<double>(0.0));
  const auto outside = near_permanent_set(sys, 0.01, 0.0005);  // w < s1 u: may still turn back
  EXPECT_FALSE(exact_capture(sys, outside, 10, opt));
  IntegratorOptions off;
  off.exact_capture = false;
  EXPECT_FALSE(exact_capture(sys, inside, 10, off));
}

TEST(ExactCapture, UnderdampedAtThePermanentSetDoesNotApply) {
  const auto sys = unloading<true>(0.2);  // (2 zeta k)^2 = 0.011 < 4 k
  EXPECT_FALSE(exact_capture(sys, near_permanent_set(sys, 0.01, 0.5), 10, IntegratorOptions{}));
}

TEST(EnergyCapture, BoundIsTheAttainableReboundOrTheThreshold) {
  const auto sys = unloading<true>(0.2);
  const IntegratorOptions opt;  // capture_cor = 1e-9
  // at z_f the spring stores nothing: the attainable rebound is w itself
  EXPECT_EQ(energy_capture(sys, near_permanent_set(sys, 0.0, 1e-10), opt),
            std::optional<double>(opt.capture_cor));
  EXPECT_FALSE(energy_capture(sys, near_permanent_set(sys, 0.0, 1e-3), opt));
  EXPECT_FALSE(energy_capture(sys, near_permanent_set(sys, 0.01, 0.0), opt));  // U(z) > 0
}

TEST(CaptureAfterStep, AConservativeSystemIsNeverCaptured) {
  const auto sys = unloading<false>(0.0);  // no dashpot, rate-independent law
  EXPECT_FALSE(capture_after_step(sys, near_permanent_set(sys, 0.0, 0.0), 10, IntegratorOptions{}));
}

TEST(GrazingCapture, OnlyWithADashpotAndWithinTheAccumulatedErrorBound) {
  const IntegratorOptions opt;
  const double bound = accumulated_error_bound(100, opt);
  EXPECT_EQ(grazing_capture(true, 0.5 * bound, 100, opt), std::optional<double>(bound));
  EXPECT_FALSE(grazing_capture(true, 2 * bound, 100, opt));
  EXPECT_FALSE(grazing_capture(false, 0.5 * bound, 100, opt));
}

}  // namespace
}  // namespace ivv
