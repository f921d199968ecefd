// Dormand-Prince 8(5,3) ("DOP853"): Hairer, Norsett & Wanner, Solving Ordinary Differential
// Equations I (2nd ed., Springer 1993), §II.5 (the method, after Prince & Dormand, J. Comput.
// Appl. Math. 7:67, 1981) and §II.6 (the dense output), written from the tableau; shares no code
// with odeint or GSL.
//
// Coefficients: the constants of Hairer's Fortran code DOP853 (version of 2004, file dop853.f,
// http://www.unige.ch/~hairer/software.html): nodes C2..C16, stages A(i,j), weights B(j), the
// error weights BHH(j) and ER(j), the dense-output vectors D4j..D7j, as printed there to 30
// significant digits (the same numbers scipy's dop853_coefficients.py reproduces). Indices here
// count from 0: stage i of this file is stage i+1 of the book.
//
// The method: 12 stages give an eighth-order solution x1 = x0 + h sum_j b_j k_j (b_j = a[12][j]);
// the 13th evaluation f(t0 + h, x1) is the first stage of the next step (FSAL). Error, as in
// DOP853, from two embedded estimates of orders 5 and 3 (sk_i = atol + rtol max(|x0_i|, |x1_i|)):
//   err5_i = h sum_j e5_j k_j,   err3_i = h sum_j (b_j - bhh_j) k_j
//   ||err|| = sum_i (err5_i/sk_i)^2 / sqrt(n (sum_i (err5_i/sk_i)^2 + 0.01 sum_i (err3_i/sk_i)^2))
// which behaves as h^8 for small h and is never smaller than the fifth-order estimate would say
// where the third-order one is large. Accepted when ||err|| <= 1; next step
// h clamp(0.9 ||err||^{-1/8}, 0.2, 5), no growth right after a rejection: the one controller of
// step_controller.h (Hairer's DOP853 clamps at [1/3, 6]; ivv uses one clamp for every stepper).
//
// Dense output (order 7): three more stages (c = 0.1, 0.2, 7/9) computed only when an
// interpolation is asked for on a step, then with theta = (t - t0)/h, s1 = 1 - theta:
//   x(t0 + theta h) = x0 + theta (r1 + s1 (r2 + theta (r3 + s1 (r4 + theta (r5 + s1 (r6 +
//                     theta r7))))))
//   r1 = x1 - x0, r2 = h k0 - r1, r3 = r1 - h k12 - r2, r_{4+q} = h sum_j d[q][j] k_j.
// The extension is linear in x0, x1 and the stages, so a linear functional L of the state (a sum
// of components) has its own seven coefficients L(r_i) = the same formulas over L(x0), L(x1),
// L(k_j): dense_functionals() computes those from the 16 stage values of L, without the r's of
// every component (the plate's event locator reads z = alpha - sum u_k of ~1000 components).
// With IntegratorOptions::fixed_step the error control is off and h = dt (convergence studies).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <string_view>
#include <utility>

#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"
#include "solver/steppers/step_state.h"

namespace ivv {

namespace dop853_tableau {
// nodes c_i (stage i at t0 + c_i h); stages 0-11 the method, 12 = f(t0 + h, x1) (FSAL),
// 13-15 the extra stages of the dense output
inline constexpr double c[16] = {
    0.0,
    0.526001519587677318785587544488e-01,
    0.789002279381515978178381316732e-01,
    0.118350341907227396726757197510,
    0.281649658092772603273242802490,
    0.333333333333333333333333333333,
    0.25,
    0.307692307692307692307692307692,
    0.651282051282051282051282051282,
    0.6,
    0.857142857142857142857142857142,
    1.0,
    1.0,
    0.1,
    0.2,
    0.777777777777777777777777777778,
};
// a[i][j]: stage i from stages j < i; row 12 holds the eighth-order weights b_j
inline constexpr double a[16][16] = {
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {5.26001519587677318785587544488e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {1.97250569845378994544595329183e-2, 5.91751709536136983633785987549e-2, 0, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0},
    {2.95875854768068491816892993775e-2, 0, 8.87627564304205475450678981324e-2, 0, 0, 0, 0, 0, 0, 0,
     0, 0, 0, 0, 0, 0},
    {2.41365134159266685502369798665e-1, 0, -8.84549479328286085344864962717e-1,
     9.24834003261792003115737966543e-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.7037037037037037037037037037e-2, 0, 0, 1.70828608729473871279604482173e-1,
     1.25467687566822425016691814123e-1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.7109375e-2, 0, 0, 1.70252211019544039314978060272e-1, 6.02165389804559606850219397283e-2,
     -1.7578125e-2, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {3.70920001185047927108779319836e-2, 0, 0, 1.70383925712239993810214054705e-1,
     1.07262030446373284651809199168e-1, -1.53194377486244017527936158236e-2,
     8.27378916381402288758473766002e-3, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {6.24110958716075717114429577812e-1, 0, 0, -3.36089262944694129406857109825,
     -8.68219346841726006818189891453e-1, 2.75920996994467083049415600797e1,
     2.01540675504778934086186788979e1, -4.34898841810699588477366255144e1, 0, 0, 0, 0, 0, 0, 0, 0},
    {4.77662536438264365890433908527e-1, 0, 0, -2.48811461997166764192642586468,
     -5.90290826836842996371446475743e-1, 2.12300514481811942347288949897e1,
     1.52792336328824235832596922938e1, -3.32882109689848629194453265587e1,
     -2.03312017085086261358222928593e-2, 0, 0, 0, 0, 0, 0, 0},
    {-9.3714243008598732571704021658e-1, 0, 0, 5.18637242884406370830023853209,
     1.09143734899672957818500254654, -8.14978701074692612513997267357,
     -1.85200656599969598641566180701e1, 2.27394870993505042818970056734e1,
     2.49360555267965238987089396762, -3.0467644718982195003823669022, 0, 0, 0, 0, 0, 0},
    {2.27331014751653820792359768449, 0, 0, -1.05344954667372501984066689879e1,
     -2.00087205822486249909675718444, -1.79589318631187989172765950534e1,
     2.79488845294199600508499808837e1, -2.85899827713502369474065508674,
     -8.87285693353062954433549289258, 1.23605671757943030647266201528e1,
     6.43392746015763530355970484046e-1, 0, 0, 0, 0, 0},
    {5.42937341165687622380535766363e-2, 0, 0, 0, 0, 4.45031289275240888144113950566,
     1.89151789931450038304281599044, -5.8012039600105847814672114227,
     3.1116436695781989440891606237e-1, -1.52160949662516078556178806805e-1,
     2.01365400804030348374776537501e-1, 4.47106157277725905176885569043e-2, 0, 0, 0, 0},
    {5.61675022830479523392909219681e-2, 0, 0, 0, 0, 0, 2.53500210216624811088794765333e-1,
     -2.46239037470802489917441475441e-1, -1.24191423263816360469010140626e-1,
     1.5329179827876569731206322685e-1, 8.20105229563468988491666602057e-3,
     7.56789766054569976138603589584e-3, -8.298e-3, 0, 0, 0},
    {3.18346481635021405060768473261e-2, 0, 0, 0, 0, 2.83009096723667755288322961402e-2,
     5.35419883074385676223797384372e-2, -5.49237485713909884646569340306e-2, 0, 0,
     -1.08347328697249322858509316994e-4, 3.82571090835658412954920192323e-4,
     -3.40465008687404560802977114492e-4, 1.41312443674632500278074618366e-1, 0, 0},
    {-4.28896301583791923408573538692e-1, 0, 0, 0, 0, -4.69762141536116384314449447206,
     7.68342119606259904184240953878, 4.06898981839711007970213554331,
     3.56727187455281109270669543021e-1, 0, 0, 0, -1.39902416515901462129418009734e-3,
     2.9475147891527723389556272149, -9.15095847217987001081870187138, 0},
};
// bhh_j: the third-order weights enter the error estimate as b_j - bhh_j (Hairer's ERR2)
inline constexpr double bhh[12] = {
    0.244094488188976377952755905512,   0, 0, 0, 0, 0, 0, 0, 0.733846688281611857341361741547, 0, 0,
    0.220588235294117647058823529412e-1};
// e5_j: b_j minus the fifth-order weights (Hairer's ER1 ... ER12)
inline constexpr double e5[12] = {0.1312004499419488073250102996e-1,
                                  0,
                                  0,
                                  0,
                                  0,
                                  -0.1225156446376204440720569753e1,
                                  -0.4957589496572501915214079952,
                                  0.1664377182454986536961530415e1,
                                  -0.3503288487499736816886487290,
                                  0.3341791187130174790297318841,
                                  0.8192320648511571246570742613e-1,
                                  -0.2235530786388629525884427845e-1};
// d[r][j]: the dense output's coefficient vectors r = 4 ... 7 (Hairer's D4j ... D7j)
inline constexpr double d[4][16] = {
    {-0.84289382761090128651353491142e1, 0, 0, 0, 0, 0.56671495351937776962531783590,
     -0.30689499459498916912797304727e1, 0.23846676565120698287728149680e1,
     0.21170345824450282767155149946e1, -0.87139158377797299206789907490,
     0.22404374302607882758541771650e1, 0.63157877876946881815570249290,
     -0.88990336451333310820698117400e-1, 0.18148505520854727256656404962e2,
     -0.91946323924783554000451984436e1, -0.44360363875948939664310572000e1},
    {0.10427508642579134603413151009e2, 0, 0, 0, 0, 0.24228349177525818288430175319e3,
     0.16520045171727028198505394887e3, -0.37454675472269020279518312152e3,
     -0.22113666853125306036270938578e2, 0.77334326684722638389603898808e1,
     -0.30674084731089398182061213626e2, -0.93321305264302278729567221706e1,
     0.15697238121770843886131091075e2, -0.31139403219565177677282850411e2,
     -0.93529243588444783865713862664e1, 0.35816841486394083752465898540e2},
    {0.19985053242002433820987653617e2, 0, 0, 0, 0, -0.38703730874935176555105901742e3,
     -0.18917813819516756882830838328e3, 0.52780815920542364900561016686e3,
     -0.11573902539959630126141871134e2, 0.68812326946963000169666922661e1,
     -0.10006050966910838403183860980e1, 0.77771377980534432092869265740,
     -0.27782057523535084065932004339e1, -0.60196695231264120758267380846e2,
     0.84320405506677161018159903784e2, 0.11992291136182789328035130030e2},
    {-0.25693933462703749003312586129e2, 0, 0, 0, 0, -0.15418974869023643374053993627e3,
     -0.23152937917604549567536039109e3, 0.35763911791061412378285349910e3,
     0.93405324183624310003907691704e2, -0.37458323136451633156875139351e2,
     0.10409964950896230045147246184e3, 0.29840293426660503123344363579e2,
     -0.43533456590011143754432175058e2, 0.96324553959188282948394950600e2,
     -0.39177261675615439165231486172e2, -0.14972683625798562581422125276e3},
};
}  // namespace dop853_tableau

// Component m of stage I's argument, x0 + h sum_j a[I][j] k_j (x0 its x0, k the stages), with the
// newest stage (the last of J, I - 1 in every row) added last and alone:
//   (x0 + h sum_{older j} a[I][j] k_j) + (h a[I][last]) k_last.
// All but one multiply-add is then formed while stage I - 1 is being computed, so the chain an
// explicit step waits on (a stage's z -> its force -> its derivative -> the next stage's z) holds
// one multiply-add here instead of two (the sum's last term, then x0 + h sum). One function for
// the scalar stepper and the lanes (dop853_lanes.h), which must round alike.
template <std::size_t I, std::size_t... J, class V, class H, class Stages>
[[gnu::always_inline]] inline V dop853_stage_argument(const V& x0, const H& h, const Stages& k,
                                                      std::size_t m) {
  constexpr std::array<std::size_t, sizeof...(J)> js{J...};
  constexpr std::size_t n = js.size();
  const double* w = dop853_tableau::a[I];
  const V newest = (h * w[js[n - 1]]) * k[js[n - 1]][m];
  if constexpr (n == 1) {
    return x0 + newest;
  } else {
    const V older = [&]<std::size_t... P>(std::index_sequence<P...>) {
      return (... + (w[js[P]] * k[js[P]][m]));
    }
    (std::make_index_sequence<n - 1>{});
    return (x0 + h * older) + newest;
  }
}

template <class System>
class Dop853Stepper : public AdaptiveStepState<System> {
 public:
  using state_type = typename System::state_type;
  using T = typename System::value_type;
  static constexpr std::string_view name = "dop853";
  static constexpr bool dense_output = true;
  static constexpr int order = 8;
  static constexpr int error_exponent = 8;  // Hairer's: the norm behaves as h^8 (header)
  static constexpr bool implicit = false;
  static constexpr bool fixed_step = false;  // adaptive; IntegratorOptions::fixed_step turns it off
  static constexpr bool fixed_step_mode = true;
  static constexpr bool reference = false;
  // the paper scene at default settings, relative error of e against mp50: held to the 1e-9 of
  // the other explicit pairs (integrators_test.cc re-measures every row)
  static constexpr double measured_relative_error = 1e-9;
  static constexpr std::string_view description =
      "hand-written Dormand-Prince 8(5,3) (DOP853) from Hairer's tableau, 7th-order dense output: "
      "the 1e-8 to 1e-13 range";

  explicit Dop853Stepper(const IntegratorOptions& opt) : AdaptiveStepState<System>(opt) {}

  void start(const System& sys, T t, const state_type& x) {
    t1_ = t;
    x1_ = x;
    size_like(x0_, x);
    for (state_type& k : k_) size_like(k, x);
    for (state_type& r : r_) size_like(r, x);
    size_like(tmp_, x);
    sys(x1_, k_[12], t1_);
    dense_ready_ = false;
    stages_ready_ = false;
  }

  // Flattened: the step sits at GCC's inlining budget, where the right-hand side was called out
  // of line from some stages; flattened, all of it is inlined into the step (callgrind, paper
  // scene at 1e-8: the step 13,951 -> 13,012 instructions per impact, results bit for bit the
  // same; always_inline on the step instead had cost 12 %).
  [[gnu::flatten]] StepResult step(const System& sys) {
    t0_ = t1_;
    x0_ = x1_;
    k_[0] = k_[12];
    dense_ready_ = false;
    stages_ready_ = false;
    this->begin_attempts();
    for (;;) {
      const T h = h_;
      advance(sys, h);
      const AttemptOutcome<T> outcome{error_norm(h)};
      if (auto done = this->template judge_attempt<error_exponent>(name, h, outcome)) {
        if (!done->ok) k_[12] = k_[0];  // f at the restored x1 = x0
        return *done;
      }
    }
  }

  void interpolate(const System& sys, T t, state_type& out) const {
    if (!dense_ready_) prepare_dense(sys);
    size_like(out, x1_);
    const T th = (t - t0_) / (t1_ - t0_);
    for (std::size_t m = 0; m < x1_.size(); ++m) out[m] = dense(th, m);
  }
  // f(t1, x1) on the law's present branch (the next step's first stage, FSAL)
  const state_type& f1() const { return k_[12]; }
  // the stages the continuous extension's r's weigh (d[q][j] != 0, with k0 and k12)
  static constexpr std::array<std::size_t, 12> kDenseStages{0,  5,  6,  7,  8,  9,
                                                            10, 11, 12, 13, 14, 15};
  // K linear functionals at once, L(state) -> std::array<T, K> (each L_i(a x + b y) = a L_i(x)
  // + b L_i(y)), of the continuous extension on the last step: for each, {L(x0), L(r1), ...,
  // L(r7)} (header), to evaluate by dense_value(). One pass of L over each stage; the extra
  // stages are computed once per step, the r's of the components not.
  template <std::size_t K, class Functionals>
  std::array<std::array<T, 8>, K> dense_functionals(const System& sys, Functionals&& L) const {
    using dop853_tableau::d;
    if (!stages_ready_) prepare_dense_stages(sys);
    const T h = t1_ - t0_;
    std::array<std::array<T, K>, 16> lk{};
    for (const std::size_t j : kDenseStages) lk[j] = L(k_[j]);
    const std::array<T, K> l0 = L(x0_), l1 = L(x1_);
    std::array<std::array<T, 8>, K> out{};
    for (std::size_t i = 0; i < K; ++i) {
      const T dx = l1[i] - l0[i], bspl = h * lk[0][i] - dx;
      std::array<T, 8>& c = out[i];
      c = {l0[i], dx, bspl, dx - h * lk[12][i] - bspl, 0, 0, 0, 0};
      for (std::size_t q = 0; q < 4; ++q) {
        T sum = 0;
        for (const std::size_t j : kDenseStages) sum += d[q][j] * lk[j][i];
        c[4 + q] = h * sum;
      }
    }
    return out;
  }
  // One functional, L(state) -> T.
  template <class Functional>
  std::array<T, 8> dense_functional(const System& sys, Functional&& L) const {
    return dense_functionals<1>(sys,
                                [&](const state_type& x) { return std::array<T, 1>{L(x)}; })[0];
  }
  // The functional's value at t on the last step from dense_functional()'s coefficients.
  T dense_value(const std::array<T, 8>& c, T t) const {
    const T th = (t - t0_) / (t1_ - t0_), s1 = 1 - th;
    return c[0] +
           th * (c[1] +
                 s1 * (c[2] + th * (c[3] + s1 * (c[4] + th * (c[5] + s1 * (c[6] + th * c[7]))))));
  }

  // The components listed in `which` only (the rest of `out` untouched): the event locator's
  // root functions read two of the six (ImpactSystem::event_components).
  template <std::size_t K>
  void interpolate(const System& sys, T t, state_type& out,
                   const std::array<std::size_t, K>& which) const {
    if (!dense_ready_) prepare_dense(sys);
    const T th = (t - t0_) / (t1_ - t0_);
    for (const std::size_t m : which) out[m] = dense(th, m);
  }

 private:
  using Base = AdaptiveStepState<System>;
  using Base::accept;
  using Base::atol_;
  using Base::fixed_;
  using Base::h_;
  using Base::rtol_;
  using Base::t0_;
  using Base::t1_;
  using Base::x0_;
  using Base::x1_;

  // Component m of the continuous extension at theta = (t - t0)/h (prepare_dense done).
  T dense(T th, std::size_t m) const {
    const T s1 = 1 - th;
    return x0_[m] +
           th * (r_[0][m] +
                 s1 * (r_[1][m] +
                       th * (r_[2][m] +
                             s1 * (r_[3][m] + th * (r_[4][m] + s1 * (r_[5][m] + th * r_[6][m]))))));
  }

  // sum_j w[j] k_j[m] over the listed j, left to right (the tableau's non-zero entries only)
  template <std::size_t... J>
  T weighted(const double* w, std::size_t m) const {
    return (... + (w[J] * k_[J][m]));
  }
  // Stage I: k_I = f(t0 + c_I h, x0 + h sum_j a[I][j] k_j), J the non-zero columns of row I.
  // A system that lists the components its right-hand side reads (System::rhs_components:
  // ImpactSystem's z and w of six) gets only those of the argument formed; the others are
  // zero, never read. The stages' derivatives, x1, the error and the dense output are as
  // before, bit for bit. Where the right-hand side is inlined the compiler drops most of the
  // unread components itself; the rest (the dense output's stages above all) was 1.1 % of the
  // paper map's instructions (callgrind, 60 x 60 map: 239.0M before, 236.3M after).
  template <std::size_t I, std::size_t... J>
  void stage(const System& sys, T h) const {
    using dop853_tableau::a;
    // a fixed-size argument is a local (kept in registers); a run-time-sized one the member
    auto run = [&](state_type& tmp) {
      if constexpr (requires { System::rhs_components; }) {
        for (const std::size_t m : System::rhs_components)
          tmp[m] = dop853_stage_argument<I, J...>(x0_[m], h, k_, m);
      } else {
        const std::size_t n = x0_.size();
        for (std::size_t m = 0; m < n; ++m)
          tmp[m] = dop853_stage_argument<I, J...>(x0_[m], h, k_, m);
      }
      sys(tmp, k_[I], t0_ + dop853_tableau::c[I] * h);
    };
    if constexpr (requires(state_type & v) { v.resize(0); }) {
      run(tmp_);
    } else {
      state_type tmp{};
      run(tmp);
    }
  }

  // The twelve stages of a step of length h, the eighth-order solution x1 and f(t0 + h, x1).
  // advance and error_norm are forced inline into step(): as separate calls the same
  // instructions ran 15-25 % slower (a driver micro-benchmark, dop853 at rtol 1e-10,
  // elastoplastic with dashpot, medians of 8-15 alternated runs: 183 against 143-147 us under
  // load; callgrind counts equal), as in the single function they replace.
  [[gnu::always_inline]] void advance(const System& sys, T h) {
    stage<1, 0>(sys, h);
    stage<2, 0, 1>(sys, h);
    stage<3, 0, 2>(sys, h);
    stage<4, 0, 2, 3>(sys, h);
    stage<5, 0, 3, 4>(sys, h);
    stage<6, 0, 3, 4, 5>(sys, h);
    stage<7, 0, 3, 4, 5, 6>(sys, h);
    stage<8, 0, 3, 4, 5, 6, 7>(sys, h);
    stage<9, 0, 3, 4, 5, 6, 7, 8>(sys, h);
    stage<10, 0, 3, 4, 5, 6, 7, 8, 9>(sys, h);
    stage<11, 0, 3, 4, 5, 6, 7, 8, 9, 10>(sys, h);
    for (std::size_t m = 0; m < x0_.size(); ++m)
      x1_[m] = x0_[m] + h * weighted<0, 5, 6, 7, 8, 9, 10, 11>(dop853_tableau::a[12], m);
    sys(x1_, k_[12], t0_ + h);
  }

  // ||err|| of the step of length h just advanced (the comment at the top of this file).
  [[gnu::always_inline]] T error_norm(T h) const {
    using namespace dop853_tableau;
    const std::size_t n = x0_.size();
    T sum5 = 0, sum3 = 0;
    for (std::size_t m = 0; m < n; ++m) {
      using std::abs;
      using std::max;
      const T sk = atol_ + rtol_ * max(abs(x0_[m]), abs(x1_[m]));
      const T e5m = weighted<0, 5, 6, 7, 8, 9, 10, 11>(e5, m) / sk;
      const T e3m = ((a[12][0] - bhh[0]) * k_[0][m] + a[12][5] * k_[5][m] + a[12][6] * k_[6][m] +
                     a[12][7] * k_[7][m] + (a[12][8] - bhh[8]) * k_[8][m] + a[12][9] * k_[9][m] +
                     a[12][10] * k_[10][m] + (a[12][11] - bhh[11]) * k_[11][m]) /
                    sk;
      sum5 += e5m * e5m;
      sum3 += e3m * e3m;
    }
    using std::sqrt;
    T deno = sum5 + T(0.01) * sum3;
    if (deno <= 0) deno = 1;
    return (h < 0 ? -h : h) * sum5 / sqrt(T(n) * deno);
  }

  // The three extra stages of the continuous extension, once per step and only for steps that
  // are interpolated (most steps of an impact are not).
  void prepare_dense_stages(const System& sys) const {
    const T h = t1_ - t0_;
    stage<13, 0, 6, 7, 8, 9, 10, 11, 12>(sys, h);
    stage<14, 0, 5, 6, 7, 10, 11, 12, 13>(sys, h);
    stage<15, 0, 5, 6, 7, 8, 12, 13, 14>(sys, h);
    stages_ready_ = true;
  }
  // The extra stages and the coefficient vectors r of every component.
  void prepare_dense(const System& sys) const {
    using dop853_tableau::d;
    const T h = t1_ - t0_;
    if (!stages_ready_) prepare_dense_stages(sys);
    for (std::size_t m = 0; m < x0_.size(); ++m) {
      const T dx = x1_[m] - x0_[m];
      const T bspl = h * k_[0][m] - dx;
      r_[0][m] = dx;
      r_[1][m] = bspl;
      r_[2][m] = dx - h * k_[12][m] - bspl;
      for (std::size_t q = 0; q < 4; ++q)
        r_[3 + q][m] = h * weighted<0, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15>(d[q], m);
    }
    dense_ready_ = true;
  }

  // k_[0..11] the stages, k_[12] = f(t1, x1), k_[13..15] the dense output's extra stages
  mutable std::array<state_type, 16> k_{};
  mutable std::array<state_type, 7> r_{};
  mutable bool dense_ready_ = false;
  mutable bool stages_ready_ = false;  // k_[13..15] of the last step
  mutable state_type tmp_{};           // a stage's argument
};

}  // namespace ivv
