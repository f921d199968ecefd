// The impact's event table: which roots are active on a step, their directions and
// monotonicity, and that each root vanishes where its event is (impact_events.h).
#include "solver/driver/impact_events.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "solver/driver/impact_system.h"
#include "solver/laws/elastoplastic.h"
#include "solver/laws/hertz.h"
#include "solver/laws/hunt_crossley.h"
#include "solver/steppers/dop853.h"

namespace ivv {
namespace {

// Root values are sums of a few O(1) normalised terms: exact to a few ulps.
constexpr double kRootTolerance = 1e-15;

// Normalised units throughout (length = velocity = force scale = 1): K_h = 1, z_y = 0.25.
using Plastic = ImpactSystem<ElastoplasticLaw, true>;
Plastic plastic_system() {
  Plastic sys;
  sys.law = {1.0, 0.25, 1.5 * 0.5};
  sys.two_zeta = 0.2;
  return sys;
}

std::vector<EventKind> kinds(const ActiveEvents& a) {
  return {a.kinds.begin(), a.kinds.begin() + a.size()};
}

TEST(ImpactEvents, TableFollowsEventKindAndOnlyKinksAndMaxCompressionChangeTheBranch) {
  for (const ImpactEventRow& row : kImpactEvents) {
    EXPECT_EQ(event_row(row.kind).kind, row.kind);
    EXPECT_EQ(changes_branch(row.action),
              row.kind == EventKind::yield || row.kind == EventKind::max_compression);
  }
  EXPECT_EQ(event_row(EventKind::yield).direction, Direction::rising);
  EXPECT_EQ(event_row(EventKind::separation).action, EventAction::end_contact);
}

TEST(ImpactEvents, LoadingBelowYieldWatchesTheLawsKinkMaxCompressionAndMaxDisplacement) {
  Plastic sys = plastic_system();
  const Plastic::state_type x0{0.1, 0.9, 0.1, 0, 0, 0}, x1{0.2, 0.8, 0.2, 0, 0, 0};
  const ActiveEvents a = active_events(sys, EventsFound{}, x0, x1);
  EXPECT_EQ(kinds(a), (std::vector<EventKind>{EventKind::yield, EventKind::max_compression,
                                              EventKind::max_displacement}));
  // z' > 0 at both ends: z - z_y is monotone, no probing
  EXPECT_TRUE(a.roots.roots[0].monotone);
  // the yield root is z minus the segment end the law declares
  Plastic::state_type at_yield = x1;
  at_yield[Plastic::Z] = 0.25;
  EXPECT_NEAR(event_root(EventKind::yield, sys, at_yield), 0.0, kRootTolerance);
  EXPECT_LT(event_root(EventKind::yield, sys, x1), 0.0);  // pre-event side of a rising root
}

// The roots at a step's end read from the derivative the stepper computed there are the roots
// event_root evaluates, bit for bit, on every branch: loading below and above the kink,
// unloading (with and without a dashpot), and a law that allows tension (separation at z = 0).
template <class System>
void expect_roots_at_end_equal(const System& sys, const typename System::state_type& x) {
  typename System::state_type f{};
  sys(x, f, 0.0);
  for (const ImpactEventRow& row : kImpactEvents) {
    if (row.kind == EventKind::yield && !law_segment_end(sys.law, sys.branch)) continue;
    if (row.kind == EventKind::peak_force && !System::rate_dependent) continue;
    EXPECT_EQ(event_root_at(row.kind, sys, x, f), event_root(row.kind, sys, x))
        << to_string(row.kind);
  }
}

TEST(ImpactEvents, RootsAtAStepsEndFromItsDerivativeAreTheRootsBitForBit) {
  Plastic sys = plastic_system();
  const Plastic::state_type x{0.31, 0.47, 0.29, 0.2, 0.1, 0.03};
  expect_roots_at_end_equal(sys, x);  // loading, Hertzian
  law_next_segment(sys.law, sys.branch);
  expect_roots_at_end_equal(sys, x);  // loading, plastic
  law_begin_unloading(sys.law, sys.branch, 0.4);
  expect_roots_at_end_equal(sys, x);  // unloading
  ImpactSystem<ElastoplasticLaw, false> undamped;
  undamped.law = sys.law;
  law_begin_unloading(undamped.law, undamped.branch, 0.4);
  expect_roots_at_end_equal(undamped, {0.31, -0.2, 0.1, 0.05});
  ImpactSystem<HuntCrossleyLaw, false> hc;
  hc.law = {1.0, 0.2};
  hc.tension = true;
  expect_roots_at_end_equal(hc, {0.2, -0.3, 0.05, 0.04});
  hc.tension = false;
  expect_roots_at_end_equal(hc, {0.2, -0.3, 0.05, 0.04});
}

TEST(ImpactEvents, YieldIsProbedOnAStepThatAlsoReachesMaxCompression) {
  Plastic sys = plastic_system();
  // z' = w - 2 zeta F: at x1 the force 0.2^{1.5} = 0.089 with w = 0.001 gives z' < 0
  const Plastic::state_type x0{0.1, 0.5, 0.1, 0, 0, 0}, x1{0.2, 0.001, 0.2, 0, 0, 0};
  const ActiveEvents a = active_events(sys, EventsFound{}, x0, x1);
  ASSERT_EQ(a.kinds[0], EventKind::yield);
  EXPECT_FALSE(a.roots.roots[0].monotone);
}

TEST(ImpactEvents, UnloadingEndsAtSeparationOnceMaxDisplacementIsFound) {
  Plastic sys = plastic_system();
  law_next_segment(sys.law, sys.branch);  // yielded: the permanent set z_f > 0
  law_begin_unloading(sys.law, sys.branch, 0.5);
  ASSERT_GT(sys.branch.z_perm, 0.1);
  const Plastic::state_type x{0.6, -0.5, 0.45, 0, 0, 0};
  const ActiveEvents a = active_events(sys, EventsFound{true, false}, x, x);
  EXPECT_EQ(kinds(a), std::vector<EventKind>{EventKind::separation});
  EXPECT_TRUE(a.roots.roots[0].monotone);  // F falls with z on a rate-independent unloading
  Plastic::state_type at_perm = x;
  at_perm[Plastic::Z] = sys.branch.z_perm;
  EXPECT_NEAR(event_root(EventKind::separation, sys, at_perm), 0.0, kRootTolerance);
}

// A law that declares separates_at_z_perm (law.h) has the separation root z - z_perm: it must
// have the sign of the force on the unloading branch wherever the locator may evaluate it, from
// above z_m down past z = 0 onto the continuation. Points within rounding of the root (1e-12
// z_m, ~1e4 ulps of z_m, where the force's factored form and z - z_perm may round to opposite
// signs) are not judged.
template <class System>
void expect_separation_root_has_the_sign_of_the_force(const System& sys, const char* what) {
  const double z_m = sys.branch.z_max, z_f = sys.branch.z_perm;
  for (int k = -100; k <= 120; ++k) {
    const double z = z_m * k / 100.0;
    if (std::abs(z - z_f) <= 1e-12 * z_m) continue;
    typename System::state_type x{};
    x[System::has_dashpot ? System::Z : System::A] = z;
    x[System::W] = -0.3;
    const double g = event_root(EventKind::separation, sys, x), F = sys.force(x);
    EXPECT_EQ(g > 0, F > 0) << what << ", z = " << z << ": root " << g << ", force " << F;
    EXPECT_EQ(g < 0, F < 0) << what << ", z = " << z << ": root " << g << ", force " << F;
    EXPECT_EQ(g, z - z_f) << what << ", z = " << z;  // the set, not the force
  }
}

TEST(ImpactEvents, SeparationAtThePermanentSetHasTheSignOfTheForce) {
  static_assert(law_separates_at_z_perm<ElastoplasticLaw>() && law_separates_at_z_perm<HertzLaw>());
  static_assert(!law_separates_at_z_perm<HuntCrossleyLaw>());
  Plastic yielded = plastic_system();
  law_next_segment(yielded.law, yielded.branch);
  law_begin_unloading(yielded.law, yielded.branch, 0.5);
  ASSERT_GT(yielded.branch.z_perm, 0.1);
  expect_separation_root_has_the_sign_of_the_force(yielded, "elastoplastic, yielded");
  Plastic elastic = plastic_system();  // z_m below z_y: back down the Hertz curve, z_perm = 0
  law_begin_unloading(elastic.law, elastic.branch, 0.2);
  expect_separation_root_has_the_sign_of_the_force(elastic, "elastoplastic, elastic");
  ImpactSystem<HertzLaw, false> hertz;
  hertz.law = {1.0};
  law_begin_unloading(hertz.law, hertz.branch, 0.3);
  expect_separation_root_has_the_sign_of_the_force(hertz, "hertz");
}

TEST(ImpactEvents, RateDependentLawProbesPeakForceAndSeparation) {
  ImpactSystem<HuntCrossleyLaw, false> sys;
  sys.law = {1.0, 0.5};
  const ImpactSystem<HuntCrossleyLaw, false>::state_type x0{0.1, 0.9, 0, 0}, x1{0.2, 0.8, 0, 0};
  const ActiveEvents loading = active_events(sys, EventsFound{}, x0, x1);
  EXPECT_EQ(kinds(loading),
            (std::vector<EventKind>{EventKind::max_compression, EventKind::max_displacement,
                                    EventKind::peak_force}));
  EXPECT_FALSE(loading.roots.roots[2].monotone);
  law_begin_unloading(sys.law, sys.branch, 0.5);
  const ActiveEvents unloading = active_events(sys, EventsFound{true, true}, x0, x1);
  EXPECT_EQ(kinds(unloading), std::vector<EventKind>{EventKind::separation});
  EXPECT_FALSE(unloading.roots.roots[0].monotone);  // F = K z^{3/2} (1 + mu z') is not
}

// The locator interpolates only System::event_components (z and w) for the roots: every root,
// on the loading and the unloading branch, must give the same value when the other components
// are NaN.
template <class System>
void expect_roots_read_only_event_components(System sys, typename System::state_type x) {
  typename System::state_type only = x;
  for (std::size_t i = 0; i < only.size(); ++i)
    if (std::find(System::event_components.begin(), System::event_components.end(), i) ==
        System::event_components.end())
      only[i] = std::nan("");
  for (bool unloading : {false, true}) {
    if (unloading) law_begin_unloading(sys.law, sys.branch, 0.3);
    for (const ImpactEventRow& row : kImpactEvents) {
      if (row.kind == EventKind::yield && !law_segment_end(sys.law, sys.branch)) continue;
      EXPECT_EQ(event_root(row.kind, sys, only), event_root(row.kind, sys, x))
          << "event " << static_cast<int>(row.kind) << (unloading ? ", unloading" : ", loading");
    }
  }
}

TEST(ImpactEvents, RootsReadOnlyTheComponentsTheLocatorInterpolates) {
  expect_roots_read_only_event_components(plastic_system(), {0.1, 0.9, 0.2, 0.05, 0.04, 0.01});
  ImpactSystem<HuntCrossleyLaw, false> hc;
  hc.law = {1.0, 0.2};
  expect_roots_read_only_event_components(hc, {0.2, -0.3, 0.05, 0.04});
}

// dop853 forms only System::rhs_components of a stage's argument (dop853.h): the right-hand side
// must give the same derivatives, bit for bit, when every other component is NaN.
template <class System>
void expect_rhs_reads_only_rhs_components(System sys, typename System::state_type x) {
  typename System::state_type only = x;
  for (std::size_t i = 0; i < only.size(); ++i)
    if (std::find(System::rhs_components.begin(), System::rhs_components.end(), i) ==
        System::rhs_components.end())
      only[i] = std::nan("");
  for (bool unloading : {false, true}) {
    if (unloading) law_begin_unloading(sys.law, sys.branch, 0.3);
    typename System::state_type f{}, f_only{};
    sys(x, f, 0.0);
    sys(only, f_only, 0.0);
    for (std::size_t i = 0; i < f.size(); ++i)
      EXPECT_EQ(f_only[i], f[i]) << "component " << i << (unloading ? ", unloading" : "");
  }
}

TEST(ImpactSystem, RightHandSideReadsOnlyItsListedComponents) {
  expect_rhs_reads_only_rhs_components(plastic_system(), {0.1, 0.9, 0.2, 0.05, 0.04, 0.01});
  ImpactSystem<ElastoplasticLaw, false> undamped;
  undamped.law = plastic_system().law;
  expect_rhs_reads_only_rhs_components(undamped, {0.2, 0.7, 0.05, 0.04});
  ImpactSystem<HuntCrossleyLaw, false> hc;
  hc.law = {1.0, 0.2};
  expect_rhs_reads_only_rhs_components(hc, {0.2, -0.3, 0.05, 0.04});
}

// The same system without rhs_components: dop853 forms every component of a stage's argument.
struct EveryComponent {
  using value_type = double;
  using state_type = Plastic::state_type;
  Plastic sys = plastic_system();
  void operator()(const state_type& x, state_type& f, double t) const { sys(x, f, t); }
};

TEST(Dop853, StagesOfTheReadComponentsOnlyGiveTheSameStepsBitForBit) {
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;
  Dop853Stepper<Plastic> reduced(opt);
  Dop853Stepper<EveryComponent> full(opt);
  const Plastic sys = plastic_system();
  const EveryComponent every;
  const Plastic::state_type x0 = {0.01, 0.99, 0.01, 0.0, 0.0, 0.0};
  reduced.start(sys, 0.01, x0);
  full.start(every, 0.01, x0);
  for (int k = 0; k < 20; ++k) {  // on the loading branch
    ASSERT_TRUE(reduced.step(sys).ok);
    ASSERT_TRUE(full.step(every).ok);
    EXPECT_EQ(reduced.t1(), full.t1()) << "step " << k;
    for (std::size_t i = 0; i < x0.size(); ++i)
      EXPECT_EQ(reduced.x1()[i], full.x1()[i]) << "step " << k << ", component " << i;
    Plastic::state_type a{}, b{};
    const double t = 0.5 * (reduced.t0() + reduced.t1());
    reduced.interpolate(sys, t, a);
    full.interpolate(every, t, b);
    for (std::size_t i = 0; i < x0.size(); ++i)
      EXPECT_EQ(a[i], b[i]) << "dense output, step " << k << ", component " << i;
  }
}

}  // namespace
}  // namespace ivv
