// Dop853 in SIMD lanes: L independent impacts advanced by one dop853 attempt each in one call,
// every lane with its own system (law parameters, branch, 2 zeta, scales), time, state and step
// size, the stage arithmetic and the right-hand side done on vectors of L doubles (GCC vector
// extensions; AVX2 for L = 4 where the unit is compiled for it: dop853_lanes.cc).
//
// The method is dop853.h's (Hairer's DOP853 tableau, its error norm and dense output, the one
// controller of step_controller.h), written for lanes: stage I of every lane is
//   k_I = f(x0 + h sum_j a[I][j] k_j)   (the components the system's right-hand side reads)
// with x0, k_j and h vectors of L lanes, then x1 = x0 + h sum_j b_j k_j, f(x1) (FSAL) and
//   ||err|| = sum5 |h| / sqrt(n (sum5 + 0.01 sum3))     per lane (dop853.h's header)
// in the same order of operations as Dop853Stepper, so that where the compiler forms the same
// fused multiply-adds (it does so per expression, the same way on a vector as on a double) each
// lane's x1, stages, error norm and next step are the scalar step's to the last bit
// (dop853_lanes_test.cc compares them lane by lane). After the attempt each lane is judged by its
// own StepController: accepted (t1 = t0 + h, the next h), rejected (h shrinks, the lane tries
// again in the next call) or failed (t1 = t0, x1 = x0: the scalar stepper's failure).
//
// A lane whose step is complete while others still retry computes its accepted attempt again with
// the same h from the same x0 (bit for bit the same stages, so nothing it holds changes) instead
// of blending: the lockstep's cost is that idle lane, counted in LaneCounts::lane_attempts.
//
// The system in lanes: Dop853Lanes<System, Lanes> runs ImpactSystemLanes<System, Lanes> (below),
// the impact equations of solver/driver/impact_system.h with the law's force in lanes
// (Law::force_lanes, Law::LaneBranches: a law capability; ElastoplasticLaw has it). The system is
// autonomous (the right-hand side does not read tau), which the lanes rely on: a lane's stage
// times are not formed.
//
// The driver: solver/driver/lanes_driver.h runs one impact a lane, each through its own
// ImpactDriver with the lane seen as the scalar stepper (dop853_lane_stepper.h); events, restarts
// and a lane that finishes taking the next impact are the driver's. Fixed-step mode
// (IntegratorOptions::fixed_step) is not supported: the constructor refuses it. A lane's step is
// read (x0, x1, f1, interpolate) before the next attempt(), which begins that lane's next step in
// the same stage arrays.
//
// Measured (callgrind, this unit as built, the four paper states of bench/benchmarks.cc, net of
// the lanes' start): nine steps a lane driven by attempt() (lanes busy in 43 of 44
// lane-attempts), 612 instructions a lane-step in lanes against 1,237 for the scalar
// Dop853Stepper (0.49); in lockstep, three steps a lane (13 of 16 lane-attempts useful), 702
// against 1,156 (0.61). Compiled with contraction into fused multiply-adds, as the FMA copy is
// (not bit for bit then), 540 against 1,054 (0.51) and 621 against 991 (0.63). A call of
// attempt() costs about two scalar attempts: the stage sums are the same instructions on four
// lanes, the force computes every branch's formula, and each lane's controller and bookkeeping
// stay scalar (~15 % of the call).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <stdexcept>
#include <string_view>
#include <type_traits>
#include <utility>

#include "solver/steppers/dop853.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_controller.h"
#include "solver/steppers/step_result.h"

namespace ivv {

// The arithmetic of L lanes of doubles (GCC vector extensions): what Law::force_lanes and
// Dop853Lanes use beyond + - * / and comparisons. sqrt is correctly rounded per lane, as
// std::sqrt: here by SSE2's sqrtpd two lanes at a time on x86-64 (a lane of a formula that is not
// selected may take the root of a negative number; std::sqrt there would call libm to set errno,
// ~40 instructions a lane), the scalar root lane by lane elsewhere; a policy for a wider unit
// (dop853_lanes.cc: vsqrtpd with AVX) hides it with its own.
template <std::size_t L>
struct LaneVectors;  // the vector types of L lanes (the attribute's size cannot depend on L)
template <>
struct LaneVectors<2> {
  typedef double vector __attribute__((vector_size(16)));
  typedef long mask __attribute__((vector_size(16)));  // what comparing two vectors gives
};
template <>
struct LaneVectors<4> {
  typedef double vector __attribute__((vector_size(32)));
  typedef long mask __attribute__((vector_size(32)));
};
template <>
struct LaneVectors<8> {
  typedef double vector __attribute__((vector_size(64)));
  typedef long mask __attribute__((vector_size(64)));
};

template <std::size_t L>
struct LaneMath {
  static constexpr std::size_t width = L;
  using vector = typename LaneVectors<L>::vector;
  using mask = typename LaneVectors<L>::mask;  // all ones in a lane where true

  [[gnu::always_inline]] static vector broadcast(double v) { return vector{} + v; }
  [[gnu::always_inline]] static vector sqrt(vector v) {
    vector r{};
#if defined(__x86_64__)
    using pair = typename LaneVectors<2>::vector;
    for (std::size_t i = 0; i < L; i += 2) {
      const pair q = __builtin_ia32_sqrtpd(pair{v[i], v[i + 1]});
      r[i] = q[0];
      r[i + 1] = q[1];
    }
#else
    for (std::size_t i = 0; i < L; ++i) r[i] = __builtin_sqrt(v[i]);
#endif
    return r;
  }
  // |v| by clearing the sign bit, as fabs
  [[gnu::always_inline]] static vector abs(vector v) {
    return reinterpret_cast<vector>(reinterpret_cast<mask>(v) & static_cast<long>(~(1UL << 63)));
  }
  [[gnu::always_inline]] static vector select(mask m, vector yes, vector no) {
    return m ? yes : no;
  }
  // whether m is true in any lane
  [[gnu::always_inline]] static bool any(mask m) {
    bool r = false;
    for (std::size_t i = 0; i < L; ++i) r = r || m[i] != 0;
    return r;
  }
  // std::max(a, b) lane by lane: (a < b) ? b : a, NaN included
  [[gnu::always_inline]] static vector max(vector a, vector b) {
    return select(a < b, b, a);
  }
};

// A law that gives its force in lanes (elastoplastic.h: LaneBranches and force_lanes).
template <class Law, class Lanes>
concept law_has_force_lanes = requires(const typename Law::template LaneBranches<Lanes>& c,
                                       const typename Lanes::vector& z) {
  { Law::template force_lanes<Lanes>(c, z) } -> std::same_as<typename Lanes::vector>;
};

// The impact equations of ImpactSystem (solver/driver/impact_system.h) for L impacts at once:
//   a' = w,  w' = -F,  z' = w - 2 zeta F (dashpot),  J' = F,  Wa' = F w,  Wv' = 2 zeta F^2
// with F = law.force(branch, length z) / force_scale lane by lane, each lane's law, branch,
// length, 1/force_scale and 2 zeta its own (set_lane from the lane's system). The operations
// are ImpactSystem::operator()'s in the same order.
template <class System, class Lanes>
requires law_has_force_lanes<typename System::law_type, Lanes>
struct ImpactSystemLanes {
  using Law = typename System::law_type;
  using V = typename Lanes::vector;
  static constexpr std::size_t N = System::N;
  using state_type = std::array<V, N>;
  static constexpr std::array<std::size_t, 2> rhs_components = System::rhs_components;

  typename Law::template LaneBranches<Lanes> law;
  V length{};               // v0/omega0 [m]
  V inverse_force_scale{};  // 1/(m v0 omega0) [1/N]
  V two_zeta{};             // 2 zeta (dashpot only)

  void set_lane(std::size_t i, const System& sys) {
    law.set_lane(i, sys.law, sys.branch);
    length[i] = sys.length;
    inverse_force_scale[i] = sys.inverse_force_scale;
    two_zeta[i] = sys.two_zeta;
  }

  [[gnu::always_inline]] void operator()(const state_type& x, state_type& dxdt) const {
    constexpr std::size_t A = System::A, W = System::W, J = System::J, WA = System::WA;
    const V z = System::has_dashpot ? x[System::Z] : x[A];
    const V force_N = Law::template force_lanes<Lanes>(law, length * z);
    const V F = force_N * inverse_force_scale;
    dxdt[A] = x[W];
    dxdt[W] = -F;
    if constexpr (System::has_dashpot) {
      dxdt[System::Z] = x[W] - (two_zeta * inverse_force_scale) * force_N;  // as z_rate_of
      dxdt[System::WV] = two_zeta * F * F;
    }
    dxdt[J] = F;
    dxdt[WA] = F * x[W];
  }
};

// What one call of Dop853Lanes::attempt() did in a lane.
struct LaneAttempt {
  enum class Kind {
    idle,      // no impact in the lane, or its step was complete before the call
    retry,     // rejected: the lane tries again with the smaller h in the next call
    accepted,  // the step is complete: t1 = t0 + h, x1, the stages of its dense output
    failed,    // the step failed (code): t1 = t0, x1 = x0, as the scalar stepper leaves it
  };
  Kind kind = Kind::idle;
  double error_norm = 0;  // ||err|| of the attempt (dop853.h's norm), the controller's input
  StepFailure code = StepFailure::none;
};

// Work done, for the benchmark: attempts in lanes that needed them, and lane-attempts computed
// (L per call, the idle lanes' included).
struct LaneCounts {
  long useful_attempts = 0;
  long lane_attempts = 0;
};

template <class System, class Lanes>
class Dop853Lanes {
 public:
  using T = double;
  using V = typename Lanes::vector;
  using M = typename Lanes::mask;
  using state_type = typename System::state_type;
  using Rhs = ImpactSystemLanes<System, Lanes>;
  using lane_state = typename Rhs::state_type;
  static constexpr std::size_t L = Lanes::width;
  static constexpr std::size_t N = System::N;
  // the method's name in a failure's message: the scalar stepper's (the same method and message)
  static constexpr std::string_view name = Dop853Stepper<System>::name;
  static constexpr int error_exponent = Dop853Stepper<System>::error_exponent;
  static_assert(std::is_same_v<typename System::value_type, double>, "lanes of doubles");

  explicit Dop853Lanes(const IntegratorOptions& opt)
      : rtol_(opt.rtol),
        atol_(opt.atol),
        initial_dt_(opt.initial_dt),
        h_(Lanes::broadcast(opt.initial_dt)) {
    if (opt.fixed_step)
      throw std::invalid_argument("dop853 in lanes: fixed_step is not supported (adaptive only)");
  }

  // Lane i holds the impact of `sys` from (t, x): its law, branch and scales are read now (call
  // again after the branch changes, as the driver restarts a scalar stepper), f(t, x) is
  // evaluated by the scalar system, as Dop853Stepper::start does. `sys` must outlive the lane.
  [[gnu::flatten]] void start(std::size_t i, const System& sys, T t, const state_type& x) {
    sys_[i] = &sys;
    rhs_.set_lane(i, sys);
    t1_[i] = t;
    state_type f{};
    sys(x, f, t);
    for (std::size_t m = 0; m < N; ++m) {
      x1_[m][i] = x[m];
      k_[12][m][i] = f[m];
    }
    ends_[i].x1 = x;
    ends_[i].f1 = f;
    fresh_[i] = true;
    stepping_[i] = false;
    failed_[i] = false;
    // the other lanes' dense stages stay valid (each lane's are its own numbers); lane i has
    // no step to interpolate on until its next is accepted, which prepares them again
  }
  // Lane i begins a new impact, as a new Dop853Stepper would: its steps counted from 0, the
  // step to try first IntegratorOptions::initial_dt; then start() it.
  void begin_impact(std::size_t i) {
    steps_[i] = 0;
    h_[i] = initial_dt_;
  }
  // The step lane i tries first (Dop853Stepper::propose_step).
  void propose_step(std::size_t i, T h) { h_[i] = h; }
  // Lane i holds no impact: it computes, nothing it computes is read (its accessors then read
  // numbers of no meaning until start()).
  void stop(std::size_t i) { sys_[i] = nullptr; }

  // One attempt in every lane that holds an impact: a lane whose last step is complete (or that
  // was just started) begins its next step; the others retry. What happened, per lane.
  [[gnu::flatten]] std::array<LaneAttempt, L> attempt() {
    return attempt_lanes({.begin_completed = true});
  }

  // One step in every lane that holds an impact: attempts until each is accepted or failed (a
  // lane done early computes its accepted attempt again meanwhile, header), as
  // Dop853Stepper::step() in each lane. StepResult per lane (ok for a lane without an impact).
  [[gnu::flatten]] std::array<StepResult, L> step() {
    std::array<StepResult, L> out{};
    for (bool first = true;; first = false) {
      attempt_lanes({.begin_completed = first});
      bool busy = false;
      for (std::size_t i = 0; i < L; ++i) busy = busy || (sys_[i] && stepping_[i]);
      if (!busy) break;
    }
    for (std::size_t i = 0; i < L; ++i) {
      if (!sys_[i] || !failed_[i]) continue;
      restore_start(i);  // the rounds after the failure computed in the lane with h = 0
      out[i] = failure(i);
    }
    return out;
  }

  // Lane i's last step [t0, t1] (or its start), as Dop853Stepper's accessors.
  T t0(std::size_t i) const { return t0_[i]; }
  T t1(std::size_t i) const { return t1_[i]; }
  T h(std::size_t i) const { return h_[i]; }  // the step to try next
  long steps(std::size_t i) const { return steps_[i]; }
  const state_type& x0(std::size_t i) const { return ends_[i].x0; }
  const state_type& x1(std::size_t i) const { return ends_[i].x1; }
  const state_type& f1(std::size_t i) const { return ends_[i].f1; }
  // What lane i's last complete step returned (Dop853Stepper::step's StepResult).
  StepResult step_result(std::size_t i) const {
    return failed_[i] ? failure(i) : StepResult::success();
  }
  // ||err|| of lane i's last attempt (the controller's input)
  T last_error_norm(std::size_t i) const { return norm_[i]; }
  const LaneCounts& counts() const { return counts_; }

  // Lane i's continuous extension on its last accepted step at t (dop853.h's formula, the same
  // operations): the three extra stages and the coefficients are computed once for all lanes
  // on the first call after a step (prepare_dense).
  void interpolate(std::size_t i, T t, state_type& out) const {
    interpolate(i, t, out, all_components<N>());
  }
  // The components listed in `which` only (the rest of `out` untouched), as
  // Dop853Stepper::interpolate(sys, t, out, which). The first call on lane i after its step adds
  // the three extra stages to its system's count of right-hand sides, as the scalar stepper's
  // first interpolation on a step does.
  template <std::size_t K>
  void interpolate(std::size_t i, T t, state_type& out,
                   const std::array<std::size_t, K>& which) const {
    if (!dense_ready_) prepare_dense();
    if (!dense_read_[i]) {
      dense_read_[i] = true;
      sys_[i]->rhs_evaluations += 3;
    }
    const T th = (t - t0_[i]) / (t1_[i] - t0_[i]), s1 = 1 - th;
    for (const std::size_t m : which) {
      auto r = [&](std::size_t q) { return r_[q][m][i]; };
      const T inner = r(3) + th * (r(4) + s1 * (r(5) + th * r(6)));
      out[m] = x0_[m][i] + th * (r(0) + s1 * (r(1) + th * (r(2) + s1 * inner)));
    }
  }

 private:
  struct AttemptOptions {
    bool begin_completed = true;  // lanes whose step is complete begin their next step
  };
  [[gnu::flatten]] std::array<LaneAttempt, L> attempt_lanes(AttemptOptions opt) {
    if (opt.begin_completed) begin_steps();
    advance();
    const V norm = error_norm();
    std::array<LaneAttempt, L> out{};
    counts_.lane_attempts += L;
    for (std::size_t i = 0; i < L; ++i) {
      if (!sys_[i] || !stepping_[i]) continue;
      ++counts_.useful_attempts;
      sys_[i]->rhs_evaluations += 12;  // stages 1-11 and f(x1), as the scalar attempt
      norm_[i] = norm[i];
      out[i] = judge(i, norm[i]);
    }
    dense_ready_ = false;
    dense_read_ = {};
    return out;
  }

  // Lane i back at the start of its failed step: x1 = x0, f(x1) = k0 (the scalar's failure).
  void restore_start(std::size_t i) {
    for (std::size_t m = 0; m < N; ++m) {
      x1_[m][i] = x0_[m][i];
      k_[12][m][i] = k_[0][m][i];
    }
    keep_ends(i);
  }

  // Lane i's x0, x1 and f1 copied out of the vectors where its step is complete, failed or
  // started, so that the driver's many reads of them (roots, capture, the end series) are
  // references, as the scalar stepper's (gathered at each read, they cost the map's driver
  // ~4 % more instructions than the scalar stepper's, callgrind).
  void keep_ends(std::size_t i) { ends_[i] = {lane(x0_, i), lane(x1_, i), lane(k_[12], i)}; }

  static state_type lane(const lane_state& v, std::size_t i) {
    state_type x{};
    for (std::size_t m = 0; m < N; ++m) x[m] = v[m][i];
    return x;
  }

  // Lanes whose last step is complete begin the next: t0 = t1, x0 = x1, k0 = f(x1) (FSAL).
  [[gnu::always_inline]] void begin_steps() {
    M begin{};
    bool any = false;
    for (std::size_t i = 0; i < L; ++i) {
      if (!sys_[i] || stepping_[i]) continue;
      if (!fresh_[i] && !done_[i]) continue;
      begin[i] = -1;
      any = true;
      t0_[i] = t1_[i];
      control_[i].begin();
      stepping_[i] = true;
      fresh_[i] = done_[i] = failed_[i] = false;
    }
    if (!any) return;
    for (std::size_t m = 0; m < N; ++m) {
      x0_[m] = Lanes::select(begin, x1_[m], x0_[m]);
      k_[0][m] = Lanes::select(begin, k_[12][m], k_[0][m]);
    }
  }

  // The controller's verdict on lane i's attempt (AdaptiveStepState::judge_attempt's rules).
  LaneAttempt judge(std::size_t i, T norm) {
    const T h = h_[i];
    T next{};
    const StepVerdict verdict = control_[i].template judge<error_exponent>(h, norm, t0_[i], next);
    h_[i] = next;
    if (verdict.action == StepVerdict::Action::retry) return {LaneAttempt::Kind::retry, norm};
    stepping_[i] = false;
    done_[i] = true;
    if (verdict.action == StepVerdict::Action::accept) {
      h_done_[i] = h;
      t1_[i] = t0_[i] + h;
      ++steps_[i];
      keep_ends(i);
      return {LaneAttempt::Kind::accepted, norm};
    }
    // a failed step leaves the lane at its start (the other lanes' x1 and k12 kept)
    failed_[i] = true;
    failure_code_[i] = verdict.failure;
    h_done_[i] = 0;
    t1_[i] = t0_[i];
    restore_start(i);
    return {LaneAttempt::Kind::failed, norm, verdict.failure};
  }

  [[gnu::flatten]] StepResult failure(std::size_t i) const {
    return StepResult::failure(
        failure_code_[i],
        step_failure_message(name, failure_code_[i], t0_[i], rtol_, control_[i].attempts()));
  }

  // The step length each lane computes with: its trial h while stepping, else the h of its
  // completed step (the same stages again; 0 after a failure or without an impact).
  [[gnu::always_inline]] V lane_h() const {
    V h = h_;
    for (std::size_t i = 0; i < L; ++i)
      if (!sys_[i] || !stepping_[i]) h[i] = sys_[i] && !failed_[i] ? h_done_[i] : 0.0;
    return h;
  }

  // sum_j w[j] k_j[m] over the listed j, left to right (dop853.h's weighted)
  template <std::size_t... J>
  [[gnu::always_inline]] V weighted(const double* w, std::size_t m) const {
    return (... + (w[J] * k_[J][m]));
  }
  // Stage I of every lane (dop853.h's stage: only the components the right-hand side reads, each
  // by dop853_stage_argument, the newest stage added last and alone).
  template <std::size_t I, std::size_t... J>
  [[gnu::always_inline]] void stage(const V& h) const {
    lane_state tmp{};
    for (const std::size_t m : Rhs::rhs_components)
      tmp[m] = dop853_stage_argument<I, J...>(x0_[m], h, k_, m);
    rhs_(tmp, k_[I]);
  }

  [[gnu::always_inline]] void advance() {
    const V h = lane_h();
    hv_ = h;
    stage<1, 0>(h);
    stage<2, 0, 1>(h);
    stage<3, 0, 2>(h);
    stage<4, 0, 2, 3>(h);
    stage<5, 0, 3, 4>(h);
    stage<6, 0, 3, 4, 5>(h);
    stage<7, 0, 3, 4, 5, 6>(h);
    stage<8, 0, 3, 4, 5, 6, 7>(h);
    stage<9, 0, 3, 4, 5, 6, 7, 8>(h);
    stage<10, 0, 3, 4, 5, 6, 7, 8, 9>(h);
    stage<11, 0, 3, 4, 5, 6, 7, 8, 9, 10>(h);
    for (std::size_t m = 0; m < N; ++m)
      x1_[m] = x0_[m] + h * weighted<0, 5, 6, 7, 8, 9, 10, 11>(dop853_tableau::a[12], m);
    rhs_(x1_, k_[12]);
  }

  // ||err|| of every lane's attempt (dop853.h's error_norm, the same operations).
  [[gnu::always_inline]] V error_norm() const {
    using namespace dop853_tableau;
    const V h = hv_;
    V sum5{}, sum3{};
    for (std::size_t m = 0; m < N; ++m) {
      const V sk = atol_ + rtol_ * Lanes::max(Lanes::abs(x0_[m]), Lanes::abs(x1_[m]));
      const V e5m = weighted<0, 5, 6, 7, 8, 9, 10, 11>(e5, m) / sk;
      const V e3m = ((a[12][0] - bhh[0]) * k_[0][m] + a[12][5] * k_[5][m] + a[12][6] * k_[6][m] +
                     a[12][7] * k_[7][m] + (a[12][8] - bhh[8]) * k_[8][m] + a[12][9] * k_[9][m] +
                     a[12][10] * k_[10][m] + (a[12][11] - bhh[11]) * k_[11][m]) /
                    sk;
      sum5 += e5m * e5m;
      sum3 += e3m * e3m;
    }
    V deno = sum5 + 0.01 * sum3;
    deno = Lanes::select(deno <= V{}, Lanes::broadcast(1.0), deno);
    return Lanes::select(h < V{}, -h, h) * sum5 / Lanes::sqrt(static_cast<double>(N) * deno);
  }

  // The continuous extension's three extra stages of every lane's last step, with h = t1 - t0
  // as dop853.h's (not the attempt's h: t0 + h - t0 need not be h).
  // Then the coefficients r of every component of every lane (dop853.h's prepare_dense, the same
  // operations), once a step for all lanes: an interpolation is then the polynomial's value
  // only (the event locator interpolates a step up to a dozen times).
  void prepare_dense() const {
    using dop853_tableau::d;
    V h{};
    for (std::size_t i = 0; i < L; ++i) h[i] = t1_[i] - t0_[i];
    stage<13, 0, 6, 7, 8, 9, 10, 11, 12>(h);
    stage<14, 0, 5, 6, 7, 10, 11, 12, 13>(h);
    stage<15, 0, 5, 6, 7, 8, 12, 13, 14>(h);
    for (std::size_t m = 0; m < N; ++m) {
      const V dx = x1_[m] - x0_[m];
      const V bspl = h * k_[0][m] - dx;
      r_[0][m] = dx;
      r_[1][m] = bspl;
      r_[2][m] = dx - h * k_[12][m] - bspl;
      for (std::size_t q = 0; q < 4; ++q)
        r_[3 + q][m] = h * weighted<0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15>(d[q], m);
    }
    dense_ready_ = true;
  }

  double rtol_, atol_, initial_dt_;
  V h_;        // the step each lane tries next
  V hv_{};     // the lengths of the attempt just computed
  Rhs rhs_{};  // the lanes' systems
  lane_state x0_{}, x1_{};
  // k_[0..11] the stages, k_[12] = f(t1, x1), k_[13..15] the dense output's extra stages
  mutable std::array<lane_state, 16> k_{};
  mutable std::array<lane_state, 7> r_{};  // the continuous extension's coefficients
  mutable bool dense_ready_ = false;
  mutable std::array<bool, L> dense_read_{};  // lane i's last step interpolated on
  std::array<const System*, L> sys_{};
  std::array<T, L> t0_{}, t1_{}, h_done_{}, norm_{};
  struct Ends {
    state_type x0{}, x1{}, f1{};
  };
  std::array<Ends, L> ends_{};  // each lane's, as keep_ends() left them
  std::array<StepController<T>, L> control_{};
  std::array<StepFailure, L> failure_code_{};
  std::array<long, L> steps_{};
  std::array<bool, L> fresh_{}, stepping_{}, done_{}, failed_{};
  LaneCounts counts_{};
};

}  // namespace ivv
