// Tests of the closed-form linearized model (linear_model.h), on the paper's Table 1 scene
// (K_h, K_y, m) unless stated.
#include "closed_forms/linear_model.h"

#include <gtest/gtest.h>

#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>

#include "scene/input_error.h"
#include "scene/scene.h"

namespace ivv::closed_forms {
namespace {

// Closed forms evaluated in double precision: tens of roundings of ~1.1e-16 each.
constexpr double kRoundOff = 1e-13;
// docs/design.md §1 / the brief: the energy ledger and the impulse close to 1e-12 relative.
constexpr double kLedgerTol = 1e-12;

LinearModelInput paper_input(double v0, double zeta) {
  Scene s = paper_scene();
  s.velocity = v0;
  LinearModelInput in = linear_model_input(s, derive(s));
  in.zeta = zeta;
  return in;
}

TEST(LinearModel, PaperDashpotGivesZetaOfOneTenth) {
  // docs/design.md §1: with c = 11440 N s/m, zeta ~ 0.1. 11440 is given to four digits, so zeta is
  // 0.1 to within a unit of the fourth digit (5e-4 relative on c).
  constexpr double kFourDigits = 1e-4;
  const Scene s = paper_scene();
  EXPECT_NEAR(damping_ratio(s.mass, derive(s).K_y, 11440.0), 0.1, kFourDigits);
  EXPECT_EQ(damping_ratio(s.mass, derive(s).K_y, std::numeric_limits<double>::infinity()), 0.0);
}

TEST(LinearModel, UndampedRestitutionIsGammaOfEq20) {
  // Without a dashpot, loading is a half-quarter of a harmonic oscillation: z_m = v0/omega0
  // (eq 19); unloading from z_m about z_f at omega1 = omega0/gamma returns with speed
  // (z_m - z_f) omega1 = gamma^2 z_m omega0/gamma = gamma v0, so e = gamma (paper, below eq 18).
  for (double v0 : {0.5, 1.0, 5.0, 50.0}) {
    const LinearModelInput in = paper_input(v0, 0.0);
    const LinearImpact r = solve_linear_model(in);
    const double gamma2 = linear_gamma_squared_eq20(in.mass, in.K_h, in.K_y, v0);
    EXPECT_NEAR(r.e / std::sqrt(gamma2), 1.0, kRoundOff) << "v0 = " << v0;
    EXPECT_NEAR(r.z_max / undamped_linear_z_max(in.mass, in.K_y, v0), 1.0, kRoundOff);
    // No dashpot: alpha = z, so alpha_c = z_m at t_c = t_m, and t_m is a quarter period.
    EXPECT_EQ(r.alpha_max, r.z_max);
    EXPECT_EQ(r.t_alpha_max, r.t_max);
    EXPECT_NEAR(r.t_max * std::sqrt(in.K_y / in.mass), std::numbers::pi / 2, kRoundOff);
    // Unloading is a quarter period at omega1.
    EXPECT_NEAR((r.t_contact - r.t_max) * r.omega_unload, std::numbers::pi / 2, kRoundOff);
    EXPECT_EQ(r.W_v, 0.0);
  }
}

TEST(LinearModel, SmallDampingIsContinuousWithTheUndampedSolution) {
  // Every output is a smooth function of zeta through 0 with O(1) derivatives in the scaled
  // units (e.g. de/dzeta ~ -pi for a linear oscillator), so zeta = 1e-9 moves them by ~1e-9.
  constexpr double kZeta = 1e-9;
  constexpr double kFirstOrder = 1e-8;
  const LinearImpact a = solve_linear_model(paper_input(1.0, 0.0));
  const LinearImpact b = solve_linear_model(paper_input(1.0, kZeta));
  EXPECT_NEAR(b.e / a.e, 1.0, kFirstOrder);
  EXPECT_NEAR(b.z_max / a.z_max, 1.0, kFirstOrder);
  EXPECT_NEAR(b.t_contact / a.t_contact, 1.0, kFirstOrder);
  EXPECT_NEAR(b.alpha_max / a.alpha_max, 1.0, kFirstOrder);
  EXPECT_NEAR(b.t_alpha_max / a.t_alpha_max, 1.0, kFirstOrder);
  EXPECT_LT(b.W_v, kFirstOrder * b.energy_initial);
  EXPECT_LT(b.e, a.e);
}

TEST(LinearModel, EnergyLedgerCloses) {
  // (1/2) m v0^2 = (1/2) m alpha'_f^2 + W_p + W_v, W_v integrated independently (direct
  // exponential integrals for phases with damping ratio <= 0.5, phase identities above).
  for (double v0 : {1.0, 5.0, 30.0}) {
    for (double zeta : {0.0, 0.01, 0.1, 0.3, 0.45}) {
      const LinearImpact r = solve_linear_model(paper_input(v0, zeta));
      const double residual = r.energy_initial - r.energy_final - r.W_p - r.W_v;
      EXPECT_LT(std::abs(residual), kLedgerTol * r.energy_initial)
          << "v0 = " << v0 << ", zeta = " << zeta << ", zeta1 = " << r.zeta_unload;
    }
  }
}

TEST(LinearModel, ImpulseIsMomentumChange) {
  // integral F dt (direct exponential integrals / phase identities) = m v0 (1 + e).
  for (double v0 : {1.0, 5.0}) {
    for (double zeta : {0.0, 0.1, 0.3, 0.45}) {
      const LinearModelInput in = paper_input(v0, zeta);
      const LinearImpact r = solve_linear_model(in);
      EXPECT_NEAR(r.impulse / (in.mass * v0 * (1.0 + r.e)), 1.0, kLedgerTol)
          << "v0 = " << v0 << ", zeta = " << zeta;
    }
  }
}

TEST(LinearModel, TwoIntegrationRoutesAgreeAtTheirSwitch) {
  // Loading with zeta = 0.5 -/+ 1e-12 is integrated by the direct formula on one side and by
  // the phase identities on the other; W_v moves by O(1e-12) relative between the two.
  constexpr double kSwitch = 0.5;
  constexpr double kNudge = 1e-12;
  // At v0 = 1 m/s and zeta = 0.5: z_m = 0.546 v0/omega0 = 1.19e-4 m > 2.25 z_y = 8.8e-5 m
  // (inside the domain) and gamma = 0.85, so zeta1 = 0.59 < 1 and the impact separates.
  const LinearImpact below = solve_linear_model(paper_input(1.0, kSwitch * (1 - kNudge)));
  const LinearImpact above = solve_linear_model(paper_input(1.0, kSwitch * (1 + kNudge)));
  ASSERT_FALSE(below.captured);
  EXPECT_NEAR(above.W_v / below.W_v, 1.0, 1e3 * kNudge);
  EXPECT_NEAR(above.impulse / below.impulse, 1.0, 1e3 * kNudge);
}

TEST(LinearModel, StrongDampingCaptures) {
  // zeta1 = zeta/gamma >= 1: w = z - z_f decays without crossing zero, so F > 0 for all t
  // and the impactor comes to rest: e = 0, t_f = inf. Then all of E0 is dissipated, the whole
  // momentum is absorbed (impulse m v0), and alpha_c = z_f + y(inf) = z_f + m v0/c.
  // Strong damping lowers z_m (about v0/(2 zeta omega0) for large zeta), so the largest zeta
  // needs a fast impact to stay inside the domain z_m >= 2.25 z_y.
  struct Case {
    double zeta, v0;
  };
  for (const Case k : {Case{0.8, 5.0}, Case{1.0, 5.0}, Case{2.0, 5.0}, Case{50.0, 200.0}}) {
    const double zeta = k.zeta;
    const LinearModelInput in = paper_input(k.v0, zeta);
    const LinearImpact r = solve_linear_model(in);
    ASSERT_TRUE(r.captured) << zeta;
    EXPECT_EQ(r.e, 0.0);
    EXPECT_TRUE(std::isinf(r.t_contact));
    EXPECT_TRUE(std::isinf(r.t_alpha_max));
    EXPECT_NEAR((r.W_p + r.W_v) / r.energy_initial, 1.0, kLedgerTol) << zeta;
    EXPECT_NEAR(r.impulse / (in.mass * in.v0), 1.0, kLedgerTol) << zeta;
    const double omega0 = std::sqrt(in.K_y / in.mass);
    EXPECT_NEAR(r.alpha_max / (r.z_perm + 2.0 * zeta * in.v0 / omega0), 1.0, kRoundOff);
    // Far in time the state tends to (z_f, alpha_c) at rest. The slow unloading rate is
    // omega1/(zeta1 + sqrt(zeta1^2 - 1)); 60 of its time constants leave e^{-60} remainders
    // (times 60 for the critical case's s e^{-s}).
    const double zeta1 = r.zeta_unload;
    const double slow_rate = r.omega_unload / (zeta1 + std::sqrt(zeta1 * zeta1 - 1.0));
    const double late = r.t_max + 60.0 / slow_rate;
    const LinearState st = linear_model_state(in, r, late);
    EXPECT_EQ(st.phase, LinearState::Phase::unloading);
    EXPECT_NEAR(st.alpha / r.alpha_max, 1.0, 1e-12);
    EXPECT_GE(st.alpha_dot, 0.0);
    EXPECT_LT(st.F, 1e-12 * r.F_max);
  }
}

// The zeta at which zeta1 = zeta/gamma(zeta) = 1 for v0 (gamma depends on z_m, hence zeta).
double critical_unloading_zeta(double v0) {
  auto f = [v0](double zeta) {
    return solve_linear_model(paper_input(v0, zeta)).zeta_unload - 1.0;
  };
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      f, 0.05, 0.99, boost::math::tools::eps_tolerance<double>(50), iterations);
  return 0.5 * (bracket.first + bracket.second);
}

TEST(LinearModel, ContinuousThroughCriticalUnloadingDamping) {
  // On the underdamped side the separation time (pi - phi1)/omega_d1 -> inf as zeta1 -> 1,
  // with e ~ exp(-pi/sqrt(2(1 - zeta1))) -> 0, and alpha_c -> z_f + m v0/c: the capture
  // values. A relative step of 1e-10 in zeta changes the smooth outputs by ~1e-10.
  constexpr double kNudge = 1e-10;
  constexpr double kSmooth = 1e-8;
  const double zc = critical_unloading_zeta(5.0);
  const LinearImpact under = solve_linear_model(paper_input(5.0, zc * (1 - kNudge)));
  const LinearImpact over = solve_linear_model(paper_input(5.0, zc * (1 + kNudge)));
  EXPECT_FALSE(under.captured);
  EXPECT_TRUE(over.captured);
  EXPECT_LT(under.e, 1e-100);  // exp(-pi/sqrt(2e-10)) underflows to 0 in practice
  EXPECT_NEAR(under.alpha_max / over.alpha_max, 1.0, kSmooth);
  EXPECT_NEAR(under.W_v / over.W_v, 1.0, kSmooth);
  EXPECT_NEAR(under.W_p / over.W_p, 1.0, kSmooth);
  EXPECT_NEAR(under.z_max / over.z_max, 1.0, kSmooth);
  // The trajectory at a fixed time in unloading is continuous too.
  const double t = under.t_max + 3.0 / under.omega_unload;
  const LinearState a = linear_model_state(paper_input(5.0, zc * (1 - kNudge)), t);
  const LinearState b = linear_model_state(paper_input(5.0, zc * (1 + kNudge)), t);
  EXPECT_NEAR(a.alpha / b.alpha, 1.0, kSmooth);
  EXPECT_NEAR(a.F / b.F, 1.0, kSmooth);
}

TEST(LinearModel, ContinuousThroughCriticalLoadingDamping) {
  // zeta = 1 exactly uses the critical forms (t_m = 1/omega0, S = s e^{-as}); 1 -/+ 1e-12 use
  // the trigonometric and hyperbolic ones; all three agree to the step size.
  constexpr double kNudge = 1e-12;
  constexpr double kSmooth = 1e-9;
  const LinearImpact crit = solve_linear_model(paper_input(5.0, 1.0));
  for (double zeta : {1.0 - kNudge, 1.0 + kNudge}) {
    const LinearImpact r = solve_linear_model(paper_input(5.0, zeta));
    EXPECT_NEAR(r.t_max / crit.t_max, 1.0, kSmooth);
    EXPECT_NEAR(r.z_max / crit.z_max, 1.0, kSmooth);
    EXPECT_NEAR(r.W_v / crit.W_v, 1.0, kSmooth);
    const LinearState a = linear_model_state(paper_input(5.0, zeta), 0.5 * crit.t_max);
    const LinearState b = linear_model_state(paper_input(5.0, 1.0), 0.5 * crit.t_max);
    EXPECT_NEAR(a.z / b.z, 1.0, kSmooth);
    EXPECT_NEAR(a.alpha_dot / b.alpha_dot, 1.0, kSmooth);
  }
  // Critical loading: z_m = v0/(omega0 e).
  const LinearModelInput in = paper_input(5.0, 1.0);
  EXPECT_NEAR(crit.z_max / (in.v0 / (std::sqrt(in.K_y / in.mass) * std::numbers::e)), 1.0,
              kRoundOff);
}

TEST(LinearModel, TrajectoryHitsTheEventsOfTheSummary) {
  // The trajectory (state at t) and the summary come from different formulas; at the
  // summary's event times the trajectory must show the event.
  const LinearModelInput in = paper_input(1.0, 0.1);
  const LinearImpact r = solve_linear_model(in);
  const double v0 = in.v0;
  const LinearState at_m = linear_model_state(in, r, r.t_max);
  EXPECT_NEAR(at_m.z_dot / v0, 0.0, kRoundOff);
  EXPECT_NEAR(at_m.F / r.F_max, 1.0, kRoundOff);
  const LinearState at_c = linear_model_state(in, r, r.t_alpha_max);
  EXPECT_NEAR(at_c.alpha_dot / v0, 0.0, kRoundOff);
  EXPECT_NEAR(at_c.alpha / r.alpha_max, 1.0, kRoundOff);
  const double just_before = std::nextafter(r.t_contact, 0.0);
  const LinearState at_f = linear_model_state(in, r, just_before);
  EXPECT_NEAR(at_f.F / r.F_max, 0.0, kRoundOff);
  EXPECT_NEAR(at_f.alpha_dot / v0, -r.e, kRoundOff);
  EXPECT_NEAR(at_f.z / r.z_perm, 1.0, kRoundOff);
  const LinearState after = linear_model_state(in, r, 2.0 * r.t_contact);
  EXPECT_EQ(after.phase, LinearState::Phase::separated);
  EXPECT_EQ(after.F, 0.0);
  EXPECT_NEAR(after.y / r.y_final, 1.0, kRoundOff);
  // Paper: with damping the maximum displacement comes after the maximum force, z_m < alpha_c.
  EXPECT_GT(r.alpha_max, r.z_max);
  EXPECT_GT(r.t_alpha_max, r.t_max);
  EXPECT_LT(r.t_alpha_max, r.t_contact);
}

TEST(LinearModel, TrajectorySatisfiesTheEquationsOfMotion) {
  // m alpha'' = -F and c y' = F, checked by central differences of the closed-form alpha',
  // y and alpha. Step h = 1e-4 t_f: truncation h^2 f'''/6 ~ 1e-9 relative; round-off
  // eps/h ~ 1e-12. 1e-6 relative to the force scale F_max leaves margin.
  constexpr double kFiniteDifference = 1e-6;
  for (double zeta : {0.1, 0.45}) {
    const LinearModelInput in = paper_input(5.0, zeta);
    const LinearImpact r = solve_linear_model(in);
    const double c = std::sqrt(in.mass * in.K_y) / (2.0 * zeta);
    const double h = 1e-4 * r.t_contact;
    for (double fraction : {0.2, 0.5, 0.8, 1.3, 1.7}) {
      const double t = fraction * r.t_max;
      if (std::abs(t - r.t_max) < 2 * h || t + h >= r.t_contact) continue;
      const LinearState lo = linear_model_state(in, r, t - h);
      const LinearState mid = linear_model_state(in, r, t);
      const LinearState hi = linear_model_state(in, r, t + h);
      const double alpha_ddot = (hi.alpha_dot - lo.alpha_dot) / (2 * h);
      const double y_dot = (hi.y - lo.y) / (2 * h);
      const double alpha_dot = (hi.alpha - lo.alpha) / (2 * h);
      EXPECT_NEAR(in.mass * alpha_ddot / r.F_max, -mid.F / r.F_max, kFiniteDifference) << t;
      EXPECT_NEAR(c * y_dot / r.F_max, mid.F / r.F_max, kFiniteDifference) << t;
      EXPECT_NEAR(alpha_dot / in.v0, mid.alpha_dot / in.v0, kFiniteDifference) << t;
      EXPECT_NEAR(mid.alpha, mid.z + mid.y, kRoundOff * r.alpha_max);
    }
  }
}

TEST(LinearModel, RestitutionFallsWithDampingAndVelocity) {
  // Paper Fig. 14 trend (docs/design.md §3), in the closed form.
  double previous = 1.0;
  for (double zeta : {0.0, 0.05, 0.1, 0.2, 0.3}) {
    const double e = solve_linear_model(paper_input(1.0, zeta)).e;
    EXPECT_LT(e, previous) << zeta;
    previous = e;
  }
  previous = 1.0;
  for (double v0 : {0.5, 1.0, 2.0, 5.0, 10.0}) {
    const double e = solve_linear_model(paper_input(v0, 0.1)).e;
    EXPECT_LT(e, previous) << v0;
    previous = e;
  }
}

TEST(LinearModel, Eq21ApproachesEq20LikeTheNextBinomialTerm) {
  // (1 - q)^{2/3} = 1 - (2/3)q - (1/9)q^2 - (4/81)q^3 - ..., so eq 20 is
  // (2/3)q [1 + q/6 + (2/27)q^2 + ...] and eq21/eq20 - 1 = -q/6 - (5/108) q^2 + O(q^3).
  // Hence rel + q/6 is bounded by ~(5/108) q^2; 0.06 q^2 leaves room for the q^3 term at
  // q <= 0.3. q ~ v0^{-1/2}, so the relative difference halves when v0 quadruples.
  constexpr double kSecondOrderBound = 0.06;
  const LinearModelInput in = paper_input(1.0, 0.0);
  double previous = 0.0;
  for (double v0 : {10.0, 40.0, 160.0, 640.0}) {
    const double q = (in.K_y / in.K_h) * std::pow(in.K_y / (in.mass * v0 * v0), 0.25);
    ASSERT_LT(q, 0.3);
    const double eq20 = linear_gamma_squared_eq20(in.mass, in.K_h, in.K_y, v0);
    const double eq21 = linear_gamma_squared_eq21(in.mass, in.K_h, in.K_y, v0);
    const double rel = eq21 / eq20 - 1.0;
    EXPECT_LT(std::abs(rel + q / 6.0), kSecondOrderBound * q * q) << v0;
    if (previous != 0.0) {
      EXPECT_NEAR(rel / previous, 0.5, 0.05) << v0;
    }
    previous = rel;
  }
}

TEST(LinearModel, UndefinedBelowTwoAndAQuarterYieldDepths) {
  // Paper Table 1 at 0.1 m/s: z_m = v0 sqrt(m/K_y) = 2.19e-5 m < 2.25 z_y = 8.81e-5 m.
  const LinearModelInput in = paper_input(0.1, 0.0);
  try {
    solve_linear_model(in);
    FAIL() << "expected LinearizedLawUndefined";
  } catch (const LinearizedLawUndefined& err) {
    const std::string what = err.what();
    EXPECT_NE(what.find("linearized law undefined: z_m = "), std::string::npos) << what;
    EXPECT_NE(what.find("2.25 z_y"), std::string::npos) << what;
    EXPECT_LT(err.z_max(), err.z_min());
    const double z_y = derive(paper_scene()).z_y;
    EXPECT_NEAR(err.z_min() / (2.25 * z_y), 1.0, kRoundOff);
  }
  EXPECT_THROW(linear_gamma_squared_eq20(in.mass, in.K_h, in.K_y, 0.1), LinearizedLawUndefined);
  EXPECT_THROW(linear_model_state(in, 0.0), LinearizedLawUndefined);
  // At the boundary z_m = (K_y/K_h)^2 (undamped: v0 = omega0 (K_y/K_h)^2), z_f = 0 and
  // gamma = e = 1; just above, e is just below 1.
  const double v_edge = std::sqrt(in.K_y / in.mass) * (in.K_y / in.K_h) * (in.K_y / in.K_h);
  const LinearImpact edge = solve_linear_model(paper_input(v_edge * (1 + 1e-12), 0.0));
  EXPECT_NEAR(edge.e, 1.0, 1e-5);  // gamma^2 = 1 - (1 - q)^{2/3}, 1 - q ~ 5e-13
  EXPECT_THROW(solve_linear_model(paper_input(v_edge * (1 - 1e-9), 0.0)), LinearizedLawUndefined);
}

// The predicate answers what solve_linear_model would throw for, on both sides of the edge,
// damped and undamped, and is never an exception itself.
TEST(LinearModel, DefinedPredicateAgreesWithTheSolver) {
  const LinearModelInput base = paper_input(1.0, 0.0);
  const double v_edge =
      std::sqrt(base.K_y / base.mass) * (base.K_y / base.K_h) * (base.K_y / base.K_h);
  for (const double zeta : {0.0, 0.1, 0.5}) {
    for (const double f : {0.5, 1 - 1e-9, 1 + 1e-9, 1.1, 2.0, 100.0}) {
      const LinearModelInput in = paper_input(v_edge * f * (1 + 2 * zeta), zeta);
      bool solved = true;
      try {
        solve_linear_model(in);
      } catch (const LinearizedLawUndefined&) {
        solved = false;
      }
      EXPECT_EQ(linearized_law_defined(in), solved) << "zeta " << zeta << " v0/v_edge " << f;
    }
  }
  EXPECT_FALSE(linearized_law_defined(paper_input(0.1, 0.0)));
  EXPECT_TRUE(linearized_law_defined(paper_input(1.0, 0.1)));
}

TEST(LinearModel, RejectsBadInput) {
  LinearModelInput in = paper_input(1.0, 0.1);
  in.zeta = -0.1;
  EXPECT_THROW(solve_linear_model(in), InputError);
  in = paper_input(1.0, 0.1);
  in.mass = std::nan("");
  EXPECT_THROW(solve_linear_model(in), InputError);
  EXPECT_THROW(linear_model_state(paper_input(1.0, 0.1), -1.0), InputError);
}

TEST(LinearSpringDashpot, KelvinVoigtRestitution) {
  // x'' + 2 zeta w x' + w^2 x = 0 from x = 0, x' = v0 returns to x = 0 after half a damped
  // period pi/(w sqrt(1 - zeta^2)) with speed v0 exp(-zeta w t): e = exp(-pi zeta/sqrt(1-z^2)).
  EXPECT_EQ(linear_spring_dashpot_cor(0.0), 1.0);
  // Small zeta: e = 1 - pi zeta + (pi zeta)^2/2 + O(zeta^3).
  constexpr double kZeta = 1e-4;
  const double pz = std::numbers::pi * kZeta;
  EXPECT_NEAR(linear_spring_dashpot_cor(kZeta), 1.0 - pz + 0.5 * pz * pz, 1e-11);
  // zeta -> 1: e -> 0 continuously; at and above 1 no return (capture), 0.
  // exp(-pi (1 - 1e-6)/sqrt(2e-6)) = exp(-2221): below the smallest double.
  EXPECT_LT(linear_spring_dashpot_cor(1.0 - 1e-6), 1e-300);
  EXPECT_GT(linear_spring_dashpot_cor(0.9), 0.0);
  EXPECT_EQ(linear_spring_dashpot_cor(1.0), 0.0);
  EXPECT_EQ(linear_spring_dashpot_cor(3.0), 0.0);
  EXPECT_THROW(linear_spring_dashpot_cor(-1.0), InputError);
}

}  // namespace
}  // namespace ivv::closed_forms
