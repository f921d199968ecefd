// Exponential collocation for the plate impact (plate_impact.h): the modes and the impactor are
// advanced EXACTLY for a contact force that is a polynomial over the step, so the step is set by
// the smoothness of the force, not by the highest kept mode (an explicit Runge-Kutta method needs
// omega_max h <~ 5, its cost grows as the cut-off cubed).
//
// Equations (normalised, plate_system.h): alpha'' = -F, u_k'' + omega_k^2 u_k = g_k F, and the one
// nonlinearity, the scalar F = f(z_kin - C_res F), z_kin = alpha - sum_k u_k. On a step
// [t0, t0 + h] the force is replaced by its interpolating polynomial of degree P through the
// equispaced nodes theta_j = j/P (t = t0 + theta h), P(theta) = sum_i F_i l_i(theta), F_0 known
// (the force is continuous), F_1 .. F_P unknown. Each mode's response is then exact (Duhamel):
//   u(t) = u0 cos(omega t) + u0'/omega sin(omega t) + g sum_n c_n n! h^-n S_n(t),
// c_n the monomial coefficients of P in theta and S_n the response to s^n/n! from rest,
//   S_n(t) = t^(n+2) s_n(omega t)/n!,   s_n(x) = n! sum_k (-1)^k x^(2k)/(n + 2 + 2k)!,
// in closed form x^2 s_0 = 1 - cos x, x^2 s_1 = 1 - sin(x)/x, x^2 s_n = 1 - n (n-1) s_(n-2)
// (S_n'' = S_(n-2) and S_n'' + omega^2 S_n = t^n/n!); the forward recurrence is used for
// x >= kSeriesBelow (its error amplification prod n(n-1)/x^2 <= 1.3 there for P = 8); below it
// s_P and s_(P-1) come from the series (terms falling by x^2/((P+3)(P+4)) <= 0.12) and the rest
// from the recurrence run downwards, which damps errors by x^2/(n(n-1)) (x s_(-1) = sin x last,
// from x^2 s_1 = 1 - s_(-1)). The velocity is the same with S_(n-1) (S_n' = S_(n-1), S_(-1) =
// sin(omega t)/omega). The impactor is the case omega = 0, g = -1. This is the exponential
// collocation method of Hochbruck & Ostermann, Exponential integrators, Acta Numerica 19:209
// (2010), §2.3, applied to the one scalar that is not linear: equivalently, collocation for the
// Volterra equation F = f(z_free - int K F) (Brunner, Collocation Methods for Volterra Integral and
// Related Functional Equations, 2004, ch. 2).
//
// The collocation equations F_j = f(z_j - C_res F_j), z_j = z_kin(theta_j) = zfree_j + sum_i
// A(j, i) F_i, are P scalar equations: A(j, i) = -t_j^2 sum_n V(n, i) theta_j^n (s_n(0) +
// sum_k g_k s_n(omega_k t_j)) depends on h only, summed over the modes ONCE per step size. So the
// steps lie on a ladder h = 2^-j (normalised time) and each rung caches its tables (per mode:
// cos, sin of omega h and omega h/Q, and g_k s_n(omega_k h); reduced: A and the forced z_kin
// and rate at the Q probes); a step costs O(N (P + Q)) flops (the free motion at the probes, the
// end update) and a Newton solve of P unknowns, Jacobian I - diag(f'(z_j)) (A - C_res I). The
// free motion of a mode with omega h < kSeriesBelow (on the 5 mm ball at cut-off 20 every mode,
// at every rung: omega_max h <= 4.4) is summed over those modes first, as moments of the Taylor
// series of cos and sin, into one polynomial in theta (free_motion_of_slow_modes: ~2 flops per
// mode and term, at most kFreeTerms terms, where turning each mode's phase at the Q probes was
// ~9 flops per mode and probe); faster modes are turned at the probes as before. Callgrind, the
// ball with the oscillator at cut-off 20, rtol 1e-5, one impact (42 steps): the stepper's free
// motion 3.79M -> 1.25M instructions, the whole impact 12.9M -> 6.6M with the rest of this
// file's pairs and tables and plate_modes.cc's D_res.
//
// Error control: the embedded solution is the degree-(P-1) polynomial through nodes 0 .. P-1 of
// the same converged F; it differs from the full one by d_P = F_P - (its extrapolation to node
// P), the P-th difference of the nodal forces, less its rounding floor 2^P (the nodes' rounding:
// 64 eps f' |z| / (1 + f' C_res), z's scale |alpha| + |alpha' h| + sum |u_k|). The difference of
// the end state (alpha, alpha', w = sum u_k, w') is d_P times the rung's end rows of the last
// basis function, weighted by atol + rtol max(|old|, |new|) per component, max norm. For a smooth
// force that is O(h^(P+1)), so the next rung follows 0.9 err^(-1/(P+1)), clamped to [1/4, 4] (at
// most two rungs at a time), no growth after a rejection. The method itself is of order ~P + 2
// at the step ends (nine equispaced nodes integrate like Newton-Cotes' nine-point rule, exact to
// degree 9; measured order 11.4 in exponential_stepper_test.cc), so the estimate is conservative:
// on the shipped scenes at rtol 1e-8 e is within 1e-10 of DOP853 at rtol 1e-12. It is also
// sensitive to modes that ring in F faster than the step resolves (the P-th difference grows
// them by up to 2^P while their effect on the state falls as 1/omega): that, not the highest
// mode's stability, is what bounds the step on a plate. Onsets (F ~ t^(3/2) for Hertz) and
// separations (F clamped at 0) are not polynomial: the estimate rejects there and the step
// shrinks; the events are located by the driver. A Newton solve that does not converge in
// kNewtonIterations (to 1e-14 of F or the rounding floor) is a rejected step (four times
// smaller); a step below 1e-14 (1 + |t|) is StepFailure::step_underflow, and kMaxRejections
// rejections in a row StepFailure::attempts_exhausted: never a silent step.
//
// Dense output is exact for the polynomial force: interpolate() evaluates the Duhamel formula at
// any t (the phases by mode_phases.h: per-m and per-n rotations on a plate whose frequency
// separates, else sin and cos per mode); event_gap(t) gives z_kin and its rate, from the step's
// tables at the Q = 2P equispaced probes the event locator samples (the nodes and the midpoints
// between them, t0 + k (t1 - t0)/Q, recognised by their exact value; the driver asks for Q
// probes, kProbes) and by the same formula elsewhere, so every value the locator sees is the
// stepper's solution (the state interpolated at a located event is on the same side of it).
// Off the probes (the root finder's iterates) z_kin sums the Duhamel weights over the modes
// first, the slow modes' by their moments as at the probes, and applies the force's polynomial
// once: measured (callgrind, one impact) the 5 mm ball at cut-off 20 with the oscillator, rtol
// 1e-5, 15.3M instructions before this and the phases, 13.0M after; the drop-weight coupon at
// cut-off 40, rtol 1e-6, 121M and 104M; e moved by 7e-13 and 2e-13 (rounding, and the event
// times it moves).
//
// The Newton solve starts from the last step's force continued by its Taylor polynomial of
// degree 2 at the step's end (F' and F'' from that step's polynomial; after start(), where an
// event may have changed the branch, from F_0): measured on the drop-weight coupon at cut-off 40,
// rtol 1e-8, 2.14 iterations a solve against 2.67 from the constant F_0 (3979 solves; the
// second iteration is the one that confirms the first's update is below 1e-14 of F).
//
// Accuracy at loose tolerances: within rtol of DOP853 at rtol 1e-10 on both shipped scenes at
// cut-offs 10 .. 60, rtol 1e-6 and 1e-8, never farther than DOP853 at the same settings (measured
// at most 4e-10 in e; exponential_stepper_test.cc). It was off by up to 3.1e-4 (the coupon at
// rtol 1e-6) until a reload after a graze of z_m was located by the driver
// (plate_impact_driver.h, missed_reload): the error was the event's, not the stepper's.
// Not the default stepper yet, and not offered on the command line.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "solver/plate/mode_phases.h"
#include "solver/steppers/step_result.h"

namespace ivv {

// Two doubles in one SSE2 register (the GCC and Clang vector extension): the per-mode loops work
// on {u_k, u_k'} (the state's own layout) or on two terms at a time, since without -ffast-math
// the compiler does not reorder a sum into lanes itself.
using DoublePair = double __attribute__((vector_size(16)));

// Below this omega h the weights s_n come from their series (header).
inline constexpr double kSeriesBelow = 4.0;

// The series of duhamel_weights below kSeriesBelow, tabulated so that a term costs a
// multiplication (a division a term was most of a weight's cost): ratio[k][r] = 1/(a (a + 1)),
// a = n + 3 + 2 k, the ratio of term k + 1 to term k over -x^2 for n = P - 1 + r; first[r] =
// 1/((n + 1)(n + 2)), the first term.
inline constexpr int kDuhamelSeriesTerms = 60;
template <int P>
struct DuhamelSeries {
  std::array<DoublePair, kDuhamelSeriesTerms> ratio{};
  std::array<double, 2> first{};
};
template <int P>
constexpr DuhamelSeries<P> duhamel_series() {
  DuhamelSeries<P> t;
  auto ratio = [](int n, int k) {
    const double a = n + 3.0 + 2.0 * k;
    return 1.0 / (a * (a + 1.0));
  };
  for (int r = 0; r < 2; ++r)
    t.first[static_cast<std::size_t>(r)] = 1.0 / ((P + r) * (P + r + 1.0));  // n = P - 1 + r
  for (int k = 0; k < kDuhamelSeriesTerms; ++k)
    t.ratio[static_cast<std::size_t>(k)] = DoublePair{ratio(P - 1, k), ratio(P, k)};
  return t;
}

// s_(-1)(x) = sin(x)/x, then s_0(x) ... s_P(x) of the header, into s[0 .. P+1]; c, sn = cos x,
// sin x (read only for x >= kSeriesBelow).
template <int P>
void duhamel_weights(double x, double c, double sn, std::array<double, P + 2>& s) {
  static constexpr DuhamelSeries<P> kSeries = duhamel_series<P>();
  const double x2 = x * x;
  if (x < kSeriesBelow) {  // s_P, s_(P-1) by their series, then down: stable for x^2 < n(n-1)
    // both series at once, {s_(P-1), s_P} in one pair: the first has the larger term ratio and
    // the larger first term, so its sum is the last to converge
    DoublePair term = {kSeries.first[0], kSeries.first[1]}, sum = term;
    for (int k = 0; k < kDuhamelSeriesTerms && std::abs(term[0]) > 1e-18 * std::abs(sum[0]); ++k) {
      term *= -x2 * kSeries.ratio[static_cast<std::size_t>(k)];
      sum += term;
    }
    s[P] = sum[0], s[P + 1] = sum[1];
    // divided, not multiplied by a tabulated reciprocal: that extra rounding put s_(-1)(3.999)
    // 2.8e-16 off its 50-digit value, past the test's 2.5e-16 there
    for (int n = P; n >= 2; --n)
      s[static_cast<std::size_t>(n - 1)] =
          (1.0 - x2 * s[static_cast<std::size_t>(n + 1)]) / (n * (n - 1.0));
    s[0] = 1.0 - x2 * s[2];  // x^2 s_1 = 1 - s_(-1)
    return;
  }
  const double r2 = 1.0 / x2;
  s[0] = sn / x;
  s[1] = (1.0 - c) * r2;
  s[2] = (1.0 - s[0]) * r2;
  for (int n = 2; n <= P; ++n)
    s[static_cast<std::size_t>(n + 1)] =
        (1.0 - n * (n - 1.0) * s[static_cast<std::size_t>(n - 1)]) * r2;
}

// The monomial coefficients V(n, i) of the Lagrange basis l_i(theta) = sum_n V(n, i) theta^n on
// the nodes theta_j = j/P, by expanding the products (exact rational inputs, no Vandermonde solve).
template <int P>
std::array<std::array<double, P + 1>, P + 1> lagrange_monomials() {
  std::array<std::array<double, P + 1>, P + 1> V{};
  for (int i = 0; i <= P; ++i) {
    std::array<double, P + 1> poly{};  // coefficients of prod_{m != i} (theta - m/P)/((i - m)/P)
    poly[0] = 1.0;
    int deg = 0;
    for (int m = 0; m <= P; ++m) {
      if (m == i) continue;
      const double scale = static_cast<double>(P) / (i - m), root = static_cast<double>(m) / P;
      for (int d = deg + 1; d >= 0; --d)
        poly[static_cast<std::size_t>(d)] =
            scale * ((d > 0 ? poly[static_cast<std::size_t>(d - 1)] : 0.0) -
                     root * poly[static_cast<std::size_t>(d)]);
      ++deg;
    }
    for (int n = 0; n <= P; ++n)
      V[static_cast<std::size_t>(n)][static_cast<std::size_t>(i)] =
          poly[static_cast<std::size_t>(n)];
  }
  return V;
}

template <class System, int P = 8>
class PlateExponentialStepper {
  static_assert(P % 2 == 0 && P >= 2, "the embedded solution uses every second node");

 public:
  using state_type = std::vector<double>;
  static constexpr std::string_view name = "exponential";
  // The event locator's probes: the nodes and the midpoints between them (header); the tables
  // serve both.
  static constexpr int kProbesPerNode = 2;
  static constexpr int kProbes = kProbesPerNode * P;
  static constexpr int kNewtonIterations = 30;
  static constexpr int kMaxRejections = 60;
  static constexpr double kEstimateOrder = P + 1.0;
  static constexpr double kEps = 2.220446049250313e-16;

  PlateExponentialStepper(double rtol, double atol, double initial_dt)
      : rtol_(rtol), atol_(atol), first_rung_(rung_at_or_below(initial_dt)) {}

  void start(const System& sys, double t, const state_type& x) {
    if (modes_.omega.size() != sys.modes()) bind(sys);
    t0_ = t1_ = t;
    x0_ = x1_ = x;
    F_start_ = sys.force(z_kin(x));
    continued_ = false;  // an event may have changed the branch: F' jumps there
    if (F_start_ == 0.0 || rung_ < 0) rung_ = first_rung_;  // an onset: F ~ t^(3/2), start small
    grow_ok_ = true;
  }

  // No error control: every step is h = 2^-rung (convergence studies; a collocation that does
  // not converge is then a failed step, StepFailure::attempts_exhausted).
  void fix_step(int rung) { fixed_rung_ = rung; }

  StepResult step(const System& sys);
  void interpolate(const System& sys, double t, state_type& out) const;
  // {z_kin, z_kin'} at t in [t0, t1] (header).
  std::array<double, 2> event_gap(double t) const;

  double t0() const { return t0_; }
  double t1() const { return t1_; }
  const state_type& x0() const { return x0_; }
  const state_type& x1() const { return x1_; }
  long steps() const { return steps_; }
  long rejected() const { return rejected_; }
  long rungs_built() const { return static_cast<long>(rungs_.size()); }

  // The step size of rung j: 2^-j (normalised time).
  static double rung_step(int j) { return std::ldexp(1.0, -j); }
  static int rung_at_or_below(double h) {
    return static_cast<int>(std::ceil(-std::log2(std::max(h, 1e-300))));
  }

 private:
  using Row = std::array<double, P + 1>;  // one value per nodal force F_0 .. F_P
  // sum_k g_k omega_k^(2m), m = 0 .. kMoments - 1, over a prefix of the modes (by omega)
  static constexpr int kMoments = 24;
  using Moments = std::array<double, kMoments>;
  // kMomentSeries[n + 1][m]: the coefficient of x^(2m) in s_n(x), n = -1 .. P (the same terms
  // as duhamel_weights' series), tabulated: add_slow_modes sums them against the moments
  static constexpr std::array<Moments, P + 2> moment_series() {
    std::array<Moments, P + 2> c{};
    for (int n = -1; n <= P; ++n) {
      double term = n < 0 ? 1.0 : 1.0 / ((n + 1.0) * (n + 2.0));
      c[static_cast<std::size_t>(n + 1)][0] = term;
      for (int m = 1; m < kMoments; ++m) {
        const double a = n < 0 ? 2.0 * m : n + 1.0 + 2.0 * m;
        term *= -1.0 / (a * (a + 1.0));
        c[static_cast<std::size_t>(n + 1)][static_cast<std::size_t>(m)] = term;
      }
    }
    return c;
  }
  static constexpr std::array<Moments, P + 2> kMomentSeries = moment_series();
  // The free moments A_j, B_j of free_motion_of_slow_modes: at most this many terms, enough
  // for x = omega h up to kSeriesBelow (rung(): the first term left out is below
  // kFreeTruncation of the mode's amplitude, in deflection and rate)
  static constexpr int kFreeTerms = 20;
  static constexpr double kFreeTruncation = 1e-19;
  static constexpr std::array<double, 2 * kFreeTerms> inverse_factorials() {
    std::array<double, 2 * kFreeTerms> f{};
    double v = 1.0;
    for (int i = 0; i < 2 * kFreeTerms; ++i) {
      if (i > 0) v /= i;
      f[static_cast<std::size_t>(i)] = v;
    }
    return f;
  }
  static constexpr std::array<double, 2 * kFreeTerms> kInverseFactorial = inverse_factorials();
  // kFreeReach[J]: the largest x for which J terms are enough, x^(2J-1)/(2J-1)! <=
  // kFreeTruncation (the first term of the rate's series left out, relative to omega |u|; the
  // deflection's is smaller by x/(2J)); kFreeTerms are enough below kSeriesBelow
  inline static const std::array<double, kFreeTerms + 1> kFreeReach = [] {
    std::array<double, kFreeTerms + 1> reach{};
    for (int J = 1; J <= kFreeTerms; ++J)
      reach[static_cast<std::size_t>(J)] =
          std::pow(std::tgamma(2.0 * J) * kFreeTruncation, 1.0 / (2.0 * J - 1.0));
    return reach;
  }();
  struct Modes {
    std::vector<double> omega, inv_omega, gain;  // by increasing omega (plate_modes.h)
    std::vector<Moments> moments;                // moments[K]: over the modes k < K
    double compliance = 0.0;
  };
  struct Rung {
    double h = 0.0;
    // the modes k < slow have omega_k h < kSeriesBelow: at every probe their forced response is
    // in the moments' sum (add_slow_modes) and their free motion in the free moments
    // (free_motion)
    std::size_t slow = 0;
    int free_terms = 1;  // the free moments' terms the slow modes need (rung())
    // the modes k < terms_end[J] need at most J of them (terms_end[kFreeTerms] = slow)
    std::array<std::size_t, kFreeTerms + 1> terms_end{};
    std::vector<double> cos_h, sin_h, cos_q, sin_q;  // per mode: omega h, omega h/Q
    // per mode: what u and u' contribute to {u, u'} at the step's end, {cos, -omega sin} and
    // {sin/omega, cos} of omega h
    std::vector<DoublePair> turn_u, turn_v;
    std::vector<std::array<double, P + 2>> end_w;  // per mode: g_k s_n(omega_k h), n = -1 .. P
    std::array<Row, kProbes + 1> probe_z{}, probe_rate{};  // forced z_kin, rate at t = q h/Q
    Row alpha_end{}, alpha_rate_end{}, w_end{}, w_rate_end{};
  };

  static double z_kin(const state_type& x) {
    double w = 0.0;
    for (std::size_t i = 2; i + 1 < x.size(); i += 2) w += x[i];
    return x[0] - w;
  }
  void bind(const System& sys) {
    modes_ = {};
    modes_.moments.assign(1, Moments{});
    for (std::size_t k = 0; k < sys.modes(); ++k) {
      const double om = sys.omega(k);
      modes_.omega.push_back(om);
      modes_.inv_omega.push_back(1.0 / om);
      modes_.gain.push_back(sys.gain(k));
      Moments next = modes_.moments.back();
      double p = sys.gain(k);
      for (double& m : next) m += p, p *= om * om;
      modes_.moments.push_back(next);
    }
    modes_.compliance = sys.compliance();
    std::vector<std::array<int, 2>> lattice;  // none: every phase by sin and cos
    SeparableFrequency split;
    if constexpr (requires { sys.separable(); }) {
      for (std::size_t k = 0; k < sys.modes(); ++k) lattice.push_back(sys.lattice(k));
      split = sys.separable();
    }
    phases_ = ModePhases(modes_.omega, lattice, split);
    rungs_.clear();
  }
  const Rung& rung(int j);
  std::size_t add_slow_modes(double t, std::array<double, P + 2>& G) const;
  void build_probe_rows(Rung& r) const;
  void free_motion(const Rung& r);
  double free_motion_of_slow_modes(const Rung& r);
  std::array<double, 2> free_slow_at(double theta) const;
  bool solve_collocation(const System& sys, const Rung& r);
  double error_norm(const Rung& r) const;
  void advance(const Rung& r);
  // {z_kin, rate} at theta of the current step by the Duhamel formula (O(N) trigonometry).
  std::array<double, 2> gap_at(double theta) const;
  // The forced part of a response at theta of the step, from its Duhamel weights w = s_(-1) ..
  // s_P (duhamel_weights) at omega t: {t^2 sum_n c_n theta^n s_n, t sum_n n c_n theta^(n-1)
  // s_(n-1)} (displacement and rate, per unit gain; the rate's n = 0 term is c_0 s_(-1)).
  std::array<double, 2> forced_at(double theta, const std::array<double, P + 2>& w) const;

  inline static const std::array<std::array<double, P + 1>, P + 1> V_ = lagrange_monomials<P>();

  double rtol_, atol_;
  int first_rung_;
  int rung_ = -1;
  int fixed_rung_ = -1;  // >= 0: fix_step()
  bool grow_ok_ = true;
  Modes modes_;
  ModePhases phases_;                          // cos, sin of omega_k t for all k (mode_phases.h)
  mutable std::vector<double> cos_t_, sin_t_;  // scratch of gap_at and interpolate
  std::map<int, Rung> rungs_;
  double t0_ = 0.0, t1_ = 0.0, h_ = 0.0;
  state_type x0_, x1_, trial_;
  double z_magnitude_ = 0.0;
  double noise_ = 0.0;  // the largest nodal force's rounding floor (solve_collocation)  // |alpha|
                        // + |alpha' h| + sum |u_k|: z_kin's rounding scale
  double F_start_ = 0.0;  // the force at x1 (the next step's F_0)
  // F' and F'' at x1 from the last step's polynomial: the next collocation's first guess
  // (continued_ false after start(): an event may have changed the branch, the guess is F_0)
  double slope_ = 0.0, curvature_ = 0.0;
  bool continued_ = false;
  Row F_{};      // nodal forces of the current (last accepted) step
  Row coeff_{};  // its monomial coefficients c_n
  std::array<double, kProbes + 1> free_z_{}, free_rate_{};  // free motion at the probes
  // the slow modes' free deflection over the step, a polynomial in theta of this degree
  // (free_motion_of_slow_modes), and the step it was made for
  std::array<double, 2 * kFreeTerms> free_poly_{};
  int free_degree_ = -1;
  std::size_t free_slow_ = 0;  // the modes in it: k < free_slow_
  double free_h_ = 1.0;
  std::array<double, kProbes + 1> probe_z_{}, probe_rate_{};  // z_kin, rate there (accepted)
  long steps_ = 0, rejected_ = 0;
};

// The rung's tables (header), built at its first use.
template <class System, int P>
auto PlateExponentialStepper<System, P>::rung(int j) -> const Rung& {
  if (auto it = rungs_.find(j); it != rungs_.end()) return it->second;
  Rung& r = rungs_[j];
  r.h = rung_step(j);
  r.slow = static_cast<std::size_t>(
      std::lower_bound(modes_.omega.begin(), modes_.omega.end(), kSeriesBelow / r.h) -
      modes_.omega.begin());
  // the slow modes' free series: the modes k < terms_end[J] have x = omega_k h <= kFreeReach[J],
  // so that J terms are enough for them
  for (int J = 1; J <= kFreeTerms; ++J)
    r.terms_end[static_cast<std::size_t>(J)] =
        J == kFreeTerms
            ? r.slow
            : std::min(r.slow, static_cast<std::size_t>(std::upper_bound(modes_.omega.begin(),
                                                                         modes_.omega.end(),
                                                                         kFreeReach[J] / r.h) -
                                                        modes_.omega.begin()));
  r.free_terms = kFreeTerms;  // the fewest that every slow mode can do with
  while (r.free_terms > 1 && r.terms_end[static_cast<std::size_t>(r.free_terms - 1)] == r.slow)
    --r.free_terms;
  const std::size_t N = modes_.omega.size();
  r.cos_h.resize(N), r.sin_h.resize(N), r.cos_q.resize(N), r.sin_q.resize(N);
  r.end_w.resize(N);
  std::array<double, P + 2> s{}, s0{};
  duhamel_weights<P>(0.0, 1.0, 0.0, s0);
  auto rows = [&](const std::array<double, P + 2>& w, double g, double t, Row& du, Row& dv) {
    for (int i = 0; i <= P; ++i) {
      double u = 0.0, v = V_[0][i] * w[0];
      for (int n = 0; n <= P; ++n) {
        u += V_[n][i] * w[n + 1];
        if (n > 0) v += n * V_[n][i] * w[n];
      }
      du[i] = g * t * t * u;
      dv[i] = g * t * v;
    }
  };
  rows(s0, -1.0, r.h, r.alpha_end, r.alpha_rate_end);
  std::array<double, P + 2> sum{};  // sum_k g_k s_n(omega_k h)
  phases_.at(r.h, r.cos_h, r.sin_h);
  phases_.at(r.h / kProbes, r.cos_q, r.sin_q, r.slow);  // the probes turn the faster modes only
  r.turn_u.resize(N), r.turn_v.resize(N);
  for (std::size_t k = 0; k < N; ++k) {
    r.turn_u[k] = DoublePair{r.cos_h[k], -modes_.omega[k] * r.sin_h[k]};
    r.turn_v[k] = DoublePair{modes_.inv_omega[k] * r.sin_h[k], r.cos_h[k]};
  }
  for (std::size_t k = 0; k < N; ++k) {
    const double x = modes_.omega[k] * r.h;
    duhamel_weights<P>(x, r.cos_h[k], r.sin_h[k], s);
    for (int n = 0; n < P + 2; ++n) r.end_w[k][n] = modes_.gain[k] * s[n], sum[n] += r.end_w[k][n];
  }
  rows(sum, 1.0, r.h, r.w_end, r.w_rate_end);
  build_probe_rows(r);
  return r;
}

// G_n += sum_k g_k s_n(omega_k t) over the modes with omega_k t < kSeriesBelow by their series
// over the moments: no per-mode work (the same terms as duhamel_weights' series, summed over the
// modes first); returns the first mode not in the sum (the modes by increasing omega).
template <class System, int P>
std::size_t PlateExponentialStepper<System, P>::add_slow_modes(double t,
                                                               std::array<double, P + 2>& G) const {
  const auto K = static_cast<std::size_t>(
      std::lower_bound(modes_.omega.begin(), modes_.omega.end(), kSeriesBelow / t) -
      modes_.omega.begin());
  const Moments& mom = modes_.moments[K];
  Moments y{};  // t^(2m) times the m-th moment
  double tp = 1.0;
  for (int m = 0; m < kMoments; ++m, tp *= t * t)
    y[static_cast<std::size_t>(m)] = tp * mom[static_cast<std::size_t>(m)];
  for (int n = 0; n < P + 2; ++n) {
    const Moments& c = kMomentSeries[static_cast<std::size_t>(n)];
    double sum = 0.0;
    for (int m = 0; m < kMoments; ++m)
      sum += c[static_cast<std::size_t>(m)] * y[static_cast<std::size_t>(m)];
    G[static_cast<std::size_t>(n)] += sum;
  }
  return K;
}

// probe_z(q, i), probe_rate(q, i): the forced z_kin and its rate at t = q h/Q per unit F_i,
// summed over the modes (G_n = s_n(0) + sum_k g_k s_n(omega_k t) first, then the basis).
template <class System, int P>
void PlateExponentialStepper<System, P>::build_probe_rows(Rung& r) const {
  const std::size_t N = modes_.omega.size();
  std::array<std::array<double, P + 2>, kProbes + 1> G{};
  duhamel_weights<P>(0.0, 1.0, 0.0, G[0]);
  for (int q = 1; q <= kProbes; ++q) G[q] = G[0];
  for (int q = 1; q <= kProbes; ++q) add_slow_modes(r.h * q / kProbes, G[q]);
  std::array<double, P + 2> s{};
  for (std::size_t k = r.slow; k < N; ++k) {  // the slower ones are in the moments' sums
    double c = 1.0, sn = 0.0;
    const double om = modes_.omega[k];
    for (int q = 1; q <= kProbes; ++q) {
      const double cq = c * r.cos_q[k] - sn * r.sin_q[k];
      sn = sn * r.cos_q[k] + c * r.sin_q[k];
      c = cq;
      const double x = om * (r.h * q / kProbes);
      if (x < kSeriesBelow) continue;  // in the moments' sum above
      duhamel_weights<P>(x, c, sn, s);
      for (int n = 0; n < P + 2; ++n) G[q][n] += modes_.gain[k] * s[n];
    }
  }
  for (int q = 1; q <= kProbes; ++q) {
    const double theta = static_cast<double>(q) / kProbes, t = theta * r.h;
    for (int i = 0; i <= P; ++i) {
      double z = 0.0, v = V_[0][i] * G[q][0], pw = 1.0;
      for (int n = 0; n <= P; ++n) {
        z += V_[n][i] * pw * G[q][n + 1];
        if (n > 0) v += n * V_[n][i] * pw * G[q][n];
        pw *= theta;
      }
      r.probe_z[q][i] = -t * t * z;
      r.probe_rate[q][i] = -t * v;
    }
  }
}

// The free motion (F = 0 over the step) of alpha and the modes at the probes, into free_z_,
// free_rate_: the slow modes (k < r.slow) summed over the modes first into the polynomial
// free_poly_ (free_motion_of_slow_modes), the others by turning each mode's phase by omega h/Q
// per probe.
template <class System, int P>
void PlateExponentialStepper<System, P>::free_motion(const Rung& r) {
  std::array<double, kProbes + 1> w{}, wr{};
  const std::size_t N = modes_.omega.size();
  double mag = 0.0;
  for (std::size_t k = r.slow; k < N; ++k) {
    mag += std::abs(x0_[2 + 2 * k]);
    double re = x0_[2 + 2 * k], im = -x0_[3 + 2 * k] * modes_.inv_omega[k];  // u - i u'/omega
    const double cq = r.cos_q[k], sq = r.sin_q[k], om = modes_.omega[k];
    for (int q = 1; q <= kProbes; ++q) {
      const double re2 = re * cq - im * sq;
      im = re * sq + im * cq;
      re = re2;
      w[q] += re;
      wr[q] -= om * im;
    }
  }
  mag += free_motion_of_slow_modes(r);
  z_magnitude_ = mag + std::abs(x0_[0]) + std::abs(x0_[1]) * r.h;
  for (int q = 1; q <= kProbes; ++q) {
    const double theta = static_cast<double>(q) / kProbes, t = r.h * theta;
    const auto slow = free_slow_at(theta);
    free_z_[q] = x0_[0] + x0_[1] * t - (w[q] + slow[0]);
    free_rate_[q] = x0_[1] - (wr[q] + slow[1]);
  }
}

// free_poly_ of the modes k < r.slow (omega_k h < kSeriesBelow): their free deflection over the
// step, sum_k (u_k cos(x_k theta) + (u_k'/omega_k) sin(x_k theta)), x_k = omega_k h, by the
// Taylor series of cos and sin summed over the modes first,
//   sum_j (-1)^j [A_j theta^(2j)/(2j)! + B_j theta^(2j+1)/(2j+1)!],
//   A_j = sum_k u_k x_k^(2j),   B_j = h sum_k u_k' x_k^(2j),
// j < r.free_terms (rung()): 2 flops a mode and a term, where turning the phase at Q probes was
// 9 a mode and a probe. Returns sum_k |u_k| over these modes (z_kin's rounding scale).
template <class System, int P>
double PlateExponentialStepper<System, P>::free_motion_of_slow_modes(const Rung& r) {
  using Pair = DoublePair;  // {A_j, B_j}
  std::array<Pair, kFreeTerms> moments{};
  double mag = 0.0;
  for (std::size_t k = 0; k < r.slow; ++k) mag += std::abs(x0_[2 + 2 * k]);
  auto start = [&](std::size_t k, Pair& p, double& x2) {
    const double x = modes_.omega[k] * r.h;
    x2 = x * x;
    p = Pair{x0_[2 + 2 * k], x0_[3 + 2 * k]};
  };
  // modes [terms_end[J - 1], terms_end[J]) need J terms (rung()); four at a time, so that a
  // moment is loaded and stored once per four modes
  std::size_t k = 0;
  for (int J = 1; J <= kFreeTerms; ++J) {
    const std::size_t end = r.terms_end[static_cast<std::size_t>(J)];
    for (; k + 4 <= end; k += 4) {
      Pair p0, p1, p2, p3;
      double y0, y1, y2, y3;
      start(k, p0, y0), start(k + 1, p1, y1), start(k + 2, p2, y2), start(k + 3, p3, y3);
      for (int j = 0; j < J; ++j) {
        moments[static_cast<std::size_t>(j)] += (p0 + p1) + (p2 + p3);
        p0 *= y0, p1 *= y1, p2 *= y2, p3 *= y3;
      }
    }
    for (; k < end; ++k) {
      Pair p;
      double y;
      start(k, p, y);
      for (int j = 0; j < J; ++j) {
        moments[static_cast<std::size_t>(j)] += p;
        p *= y;
      }
    }
  }
  const int J = r.free_terms;
  free_poly_.fill(0.0);
  for (int j = 0; j < J; ++j) {
    const double sign = j % 2 == 0 ? 1.0 : -1.0;
    const auto i = static_cast<std::size_t>(2 * j);
    free_poly_[i] = sign * moments[static_cast<std::size_t>(j)][0] * kInverseFactorial[i];
    free_poly_[i + 1] =
        sign * r.h * moments[static_cast<std::size_t>(j)][1] * kInverseFactorial[i + 1];
  }
  free_degree_ = 2 * J - 1;
  free_h_ = r.h;
  free_slow_ = r.slow;
  return mag;
}

// {sum_k u_k, sum_k u_k'} of the slow modes at theta of the step, from free_poly_ (Horner).
template <class System, int P>
std::array<double, 2> PlateExponentialStepper<System, P>::free_slow_at(double theta) const {
  double w = 0.0, dw = 0.0;
  for (int i = free_degree_; i >= 0; --i) {
    dw = dw * theta + w;
    w = w * theta + free_poly_[static_cast<std::size_t>(i)];
  }
  return {w, dw / free_h_};
}

// Newton's method on F_j - f(z_j - C F_j) = 0, j = 1 .. P (header); false when it does not
// converge (the step is then rejected).
template <class System, int P>
bool PlateExponentialStepper<System, P>::solve_collocation(const System& sys, const Rung& r) {
  const double C = modes_.compliance;
  Row F = F_;
  for (int j = 1; j <= P; ++j) {  // the last step's force continued by its Taylor polynomial
    const double s = r.h * j / P;
    F[j] = F_[0] + (continued_ ? s * (slope_ + 0.5 * s * curvature_) : 0.0);
  }
  for (int it = 0; it < kNewtonIterations; ++it) {
    std::array<std::array<double, P + 1>, P> J{};  // J | -G, rows j = 1 .. P
    double scale = 0.0;
    std::array<double, P> noise{};  // F's rounding floor: f' times z's rounding, through 1 + f' C
    for (int j = 1; j <= P; ++j) {
      const auto& a = r.probe_z[kProbesPerNode * j];
      double z = free_z_[kProbesPerNode * j] - C * F[j];
      for (int i = 0; i <= P; ++i) z += a[i] * F[i];
      const double f = sys.law_force(z), df = sys.law_stiffness(z);
      if (!std::isfinite(f) || !std::isfinite(df)) return false;
      for (int l = 1; l <= P; ++l) J[j - 1][l - 1] = (l == j ? 1.0 + df * C : 0.0) - df * a[l];
      J[j - 1][P] = f - F[j];
      scale = std::max({scale, std::abs(F[j]), std::abs(f)});
      noise[j - 1] = 64.0 * kEps * std::abs(df) * z_magnitude_ / (1.0 + std::abs(df) * C);
    }
    for (int c = 0; c < P; ++c) {  // Gaussian elimination, partial pivoting
      int piv = c;
      for (int rr = c + 1; rr < P; ++rr)
        if (std::abs(J[rr][c]) > std::abs(J[piv][c])) piv = rr;
      std::swap(J[c], J[piv]);
      if (J[c][c] == 0.0) return false;
      for (int rr = c + 1; rr < P; ++rr) {
        const double m = J[rr][c] / J[c][c];
        for (int cc = c; cc <= P; ++cc) J[rr][cc] -= m * J[c][cc];
      }
    }
    bool converged = true;
    for (int c = P - 1; c >= 0; --c) {
      double v = J[c][P];
      for (int cc = c + 1; cc < P; ++cc) v -= J[c][cc] * J[cc][P];
      J[c][P] = v / J[c][c];
      F[c + 1] += J[c][P];
      if (!std::isfinite(F[c + 1])) return false;
      converged = converged && std::abs(J[c][P]) <= 1e-14 * scale + noise[c];
    }
    if (converged) {
      F_ = F;
      noise_ = *std::max_element(noise.begin(), noise.end());
      return true;
    }
  }
  return false;
}

// max over alpha, alpha', w, w' at the end of |full - embedded|/(atol + rtol max(|old|, |new|)).
template <class System, int P>
double PlateExponentialStepper<System, P>::error_norm(const Rung& r) const {
  Row d{};  // F minus the degree-(P-1) interpolant of nodes 0 .. P-1: nonzero at node P only
  double ext = 0.0;
  for (int i = 0; i < P; ++i) {
    double l = 1.0;
    for (int m = 0; m < P; ++m)
      if (m != i) l *= static_cast<double>(P - m) / (i - m);
    ext += l * F_[i];
  }
  // less its rounding floor: the P-th difference of F grows the nodes' noise by 2^P
  const double dP = F_[P] - ext;
  d[P] = std::copysign(std::max(0.0, std::abs(dP) - std::ldexp(noise_ + kEps * std::abs(F_[P]), P)),
                       dP);
  auto dot = [&](const Row& row) {
    double s = 0.0;
    for (int i = 0; i <= P; ++i) s += row[i] * d[i];
    return s;
  };
  auto dot_f = [&](const Row& row) {
    double s = 0.0;
    for (int i = 0; i <= P; ++i) s += row[i] * F_[i];
    return s;
  };
  double w0 = 0.0, wr0 = 0.0;
  for (std::size_t i = 2; i + 1 < x0_.size(); i += 2) w0 += x0_[i], wr0 += x0_[i + 1];
  // w = alpha - z_kin: the free part from the probes' free motion, then the forced part
  const double w1 = x0_[0] + x0_[1] * r.h - free_z_[kProbes] + dot_f(r.w_end);
  const double wr1 = x0_[1] - free_rate_[kProbes] + dot_f(r.w_rate_end);
  const double a1 = x0_[0] + x0_[1] * r.h + dot_f(r.alpha_end);
  const double v1 = x0_[1] + dot_f(r.alpha_rate_end);
  const std::array<double, 4> est{dot(r.alpha_end), dot(r.alpha_rate_end), dot(r.w_end),
                                  dot(r.w_rate_end)};
  const std::array<double, 4> old{x0_[0], x0_[1], w0, wr0}, now{a1, v1, w1, wr1};
  double err = 0.0;
  for (int c = 0; c < 4; ++c)
    err = std::max(
        err, std::abs(est[c]) / (atol_ + rtol_ * std::max(std::abs(old[c]), std::abs(now[c]))));
  return err;
}

// The accepted step: every mode's end state, the probes' values, the monomial coefficients.
template <class System, int P>
void PlateExponentialStepper<System, P>::advance(const Rung& r) {
  const std::size_t N = modes_.omega.size();
  double d1 = 0.0, d2 = 0.0;  // dF/dtheta, d2F/dtheta2 at theta = 1
  for (int n = 0; n <= P; ++n) {
    double c = 0.0;
    for (int i = 0; i <= P; ++i) c += V_[n][i] * F_[i];
    coeff_[n] = c;
    d1 += n * c, d2 += n * (n - 1.0) * c;
  }
  slope_ = d1 / r.h, curvature_ = d2 / (r.h * r.h);
  continued_ = true;
  std::array<double, P + 2> cu{}, cv{};  // the forced end state = h^2 sum cu w, h sum cv w
  cv[0] = coeff_[0];
  for (int n = 0; n <= P; ++n) cu[n + 1] = r.h * r.h * coeff_[n];
  for (int n = 1; n <= P; ++n) cv[n] = n * coeff_[n];
  for (int n = 0; n <= P; ++n) cv[n] *= r.h;
  trial_.resize(x0_.size());
  // per mode, in SSE2 pairs: {u, u'} turned by the rung's {cos, -omega sin}, {sin/omega, cos},
  // plus the forced part {h^2 sum cu w, h sum cv w} summed two weights at a time
  std::array<DoublePair, (P + 2) / 2> cu2, cv2;
  for (int i = 0; i < (P + 2) / 2; ++i)
    cu2[i] = DoublePair{cu[2 * i], cu[2 * i + 1]}, cv2[i] = DoublePair{cv[2 * i], cv[2 * i + 1]};
  for (std::size_t k = 0; k < N; ++k) {
    const double u = x0_[2 + 2 * k], v = x0_[3 + 2 * k];
    const double* w = r.end_w[k].data();
    DoublePair au{}, av{};
    for (int i = 0; i < (P + 2) / 2; ++i) {
      DoublePair wp;
      std::memcpy(&wp, w + 2 * i, sizeof wp);
      au += cu2[i] * wp, av += cv2[i] * wp;
    }
    const DoublePair f = DoublePair{au[0], av[0]} + DoublePair{au[1], av[1]};
    const DoublePair next = u * r.turn_u[k] + v * r.turn_v[k] + f;
    std::memcpy(&trial_[2 + 2 * k], &next, sizeof next);
  }
  double fa = 0.0, fva = 0.0;
  for (int i = 0; i <= P; ++i) fa += r.alpha_end[i] * F_[i], fva += r.alpha_rate_end[i] * F_[i];
  trial_[0] = x0_[0] + x0_[1] * r.h + fa;
  trial_[1] = x0_[1] + fva;
  for (int q = 1; q <= kProbes; ++q) {
    double z = free_z_[q], v = free_rate_[q];
    for (int i = 0; i <= P; ++i) z += r.probe_z[q][i] * F_[i], v += r.probe_rate[q][i] * F_[i];
    probe_z_[q] = z, probe_rate_[q] = v;
  }
  h_ = r.h;
  t1_ = t0_ + r.h;
  std::swap(x1_, trial_);
}

template <class System, int P>
StepResult PlateExponentialStepper<System, P>::step(const System& sys) {
  t0_ = t1_;
  x0_ = x1_;
  const double F_start = F_start_;
  for (int rejections = 0;; ++rejections) {
    if (rejections >= kMaxRejections)
      return StepResult::failure(StepFailure::attempts_exhausted,
                                 "exponential: " + std::to_string(kMaxRejections) +
                                     " rejected attempts at t = " + std::to_string(t0_));
    if (fixed_rung_ >= 0) rung_ = fixed_rung_;
    const Rung& r = rung(rung_);
    if (r.h < 1e-14 * (1.0 + std::abs(t0_)))
      return StepResult::failure(StepFailure::step_underflow,
                                 "exponential: step " + std::to_string(r.h) +
                                     " below 1e-14 (1 + |t|) at t = " + std::to_string(t0_) +
                                     (sys.failure().empty() ? "" : " (" + sys.failure() + ")"));
    F_.fill(0.0);
    F_[0] = F_start;
    free_motion(r);
    if (fixed_rung_ >= 0 && !solve_collocation(sys, r))
      return StepResult::failure(StepFailure::attempts_exhausted,
                                 "exponential: the collocation equations did not converge at the "
                                 "fixed step " +
                                     std::to_string(r.h) + " at t = " + std::to_string(t0_));
    if (fixed_rung_ < 0 && !solve_collocation(sys, r)) {
      ++rejected_, rung_ += 2, grow_ok_ = false;
      continue;
    }
    const double err = fixed_rung_ >= 0 ? 0.0 : error_norm(r);
    if (!(err <= 1.0)) {
      ++rejected_, grow_ok_ = false;
      const double fac = std::isfinite(err)
                             ? std::clamp(0.9 * std::pow(err, -1.0 / kEstimateOrder), 0.25, 0.5)
                             : 0.25;
      rung_ += static_cast<int>(std::ceil(-std::log2(fac)));
      continue;
    }
    advance(r);
    F_start_ = F_[P];
    ++steps_;
    const double fac =
        std::clamp(0.9 * std::pow(std::max(err, 1e-300), -1.0 / kEstimateOrder), 1.0, 4.0);
    if (grow_ok_) rung_ -= static_cast<int>(std::floor(std::log2(fac)));
    grow_ok_ = true;
    return StepResult::success();
  }
}

template <class System, int P>
std::array<double, 2> PlateExponentialStepper<System, P>::forced_at(
    double theta, const std::array<double, P + 2>& w) const {
  const double t = theta * h_;
  double u = 0.0, v = coeff_[0] * w[0], pw = 1.0;
  for (int n = 0; n <= P; ++n) {
    u += coeff_[n] * pw * w[n + 1];
    if (n > 0) v += n * coeff_[n] * pw * w[n];
    pw *= theta;
  }
  return {t * t * u, t * v};
}

// {z_kin, rate} at theta of the current step by the Duhamel formula: the free motion of alpha
// and every mode, and the forced part once from G_n = s_n(0) + sum_k g_k s_n(omega_k t) (the
// forced response is linear in the weights; the slow modes' share by the moments, as at the
// probes), not per mode.
template <class System, int P>
std::array<double, 2> PlateExponentialStepper<System, P>::gap_at(double theta) const {
  const double t = theta * h_;
  std::array<double, P + 2> G{}, s{};
  duhamel_weights<P>(0.0, 1.0, 0.0, G);
  const std::size_t K = add_slow_modes(t, G);
  // the free motion: the slow modes' from their polynomial, the others' by their phases
  auto [w, wr] = free_slow_at(theta);
  phases_.at(t, cos_t_, sin_t_, free_slow_);
  for (std::size_t k = free_slow_; k < modes_.omega.size(); ++k) {
    const double om = modes_.omega[k], c = cos_t_[k], sn = sin_t_[k];
    const double u = x0_[2 + 2 * k], v = x0_[3 + 2 * k];
    w += u * c + v * modes_.inv_omega[k] * sn;
    wr += -u * om * sn + v * c;
    if (k < K) continue;  // in G by the moments
    duhamel_weights<P>(om * t, c, sn, s);
    for (int n = 0; n < P + 2; ++n) G[n] += modes_.gain[k] * s[n];
  }
  const auto f = forced_at(theta, G);
  return {x0_[0] + x0_[1] * t - w - f[0], x0_[1] - wr - f[1]};
}

template <class System, int P>
std::array<double, 2> PlateExponentialStepper<System, P>::event_gap(double t) const {
  if (t == t1_) return {probe_z_[kProbes], probe_rate_[kProbes]};
  const double theta = (t - t0_) / h_;
  const long q = std::lround(theta * kProbes);
  if (q >= 1 && q < kProbes && t == t0_ + (t1_ - t0_) * static_cast<double>(q) / kProbes)
    return {probe_z_[q], probe_rate_[q]};
  return gap_at(theta);
}

template <class System, int P>
void PlateExponentialStepper<System, P>::interpolate(const System&, double t,
                                                     state_type& out) const {
  out.resize(x0_.size());
  if (t == t1_) {
    out = x1_;
    return;
  }
  if (t == t0_) {
    out = x0_;
    return;
  }
  const double theta = (t - t0_) / h_, tt = theta * h_;
  std::array<double, P + 2> s{};
  duhamel_weights<P>(0.0, 1.0, 0.0, s);
  const auto fa = forced_at(theta, s);
  out[0] = x0_[0] + x0_[1] * tt - fa[0];
  out[1] = x0_[1] - fa[1];
  phases_.at(tt, cos_t_, sin_t_);
  for (std::size_t k = 0; k < modes_.omega.size(); ++k) {
    const double om = modes_.omega[k], x = om * tt, c = cos_t_[k], sn = sin_t_[k];
    const double u = x0_[2 + 2 * k], v = x0_[3 + 2 * k];
    duhamel_weights<P>(x, c, sn, s);
    const auto f = forced_at(theta, s);
    out[2 + 2 * k] = u * c + v * modes_.inv_omega[k] * sn + modes_.gain[k] * f[0];
    out[3 + 2 * k] = -u * om * sn + v * c + modes_.gain[k] * f[1];
  }
}

}  // namespace ivv
