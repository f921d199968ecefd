// The one step controller (step_controller.h): its rules alone, then every error-controlled
// stepper written here through one generic test (as Boost.Odeint tests its steppers over a
// type list): the declared order, the tolerance met, the failure codes and the restored state,
// and the same numbers from a run-time-sized state as from a fixed-size one.
#include "solver/steppers/step_controller.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "solver/steppers/dop853.h"
#include "solver/steppers/dp45.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/rodas.h"

namespace ivv {
namespace {

// dp45's exponent
struct Control : StepController<double> {
  StepVerdict judge(double h, double norm, double t0, double& next) {
    return StepController<double>::judge<5>(h, norm, t0, next);
  }
};

TEST(StepController, AcceptsAtNormOneAndGrowsByTheOptimalFactor) {
  Control c;
  c.begin();
  double next = 0;
  const StepVerdict v = c.judge(1.0, 0.5, 0.0, next);
  EXPECT_EQ(v.action, StepVerdict::Action::accept);
  EXPECT_DOUBLE_EQ(next, 0.9 * std::pow(0.5, -0.2));
}

TEST(StepController, ClampsGrowthAtFiveAndShrinkAtOneFifth) {
  Control c;
  c.begin();
  double next = 0;
  c.judge(1.0, 0.0, 0.0, next);  // a zero error estimate
  EXPECT_EQ(next, 5.0);
  c.begin();
  c.judge(1.0, 1e-30, 0.0, next);
  EXPECT_EQ(next, 5.0);
  c.begin();
  EXPECT_EQ(c.judge(1.0, 1e30, 0.0, next).action, StepVerdict::Action::retry);
  EXPECT_EQ(next, 0.2);
}

TEST(StepController, DoesNotGrowRightAfterARejection) {
  Control c;
  c.begin();
  double next = 0;
  EXPECT_EQ(c.judge(1.0, 4.0, 0.0, next).action, StepVerdict::Action::retry);
  const double h = next;
  EXPECT_EQ(c.judge(h, 1e-6, 0.0, next).action, StepVerdict::Action::accept);
  EXPECT_EQ(next, h);  // the optimal factor would be 5
  c.begin();           // the next step may grow again
  c.judge(h, 1e-6, 0.0, next);
  EXPECT_EQ(next, 5 * h);
}

TEST(StepController, ANonFiniteNormShrinksTheStepByFive) {
  Control c;
  c.begin();
  double next = 0;
  EXPECT_EQ(c.judge(1.0, std::numeric_limits<double>::quiet_NaN(), 0.0, next).action,
            StepVerdict::Action::retry);
  EXPECT_EQ(next, 0.2);
  EXPECT_EQ(c.judge(0.2, std::numeric_limits<double>::infinity(), 0.0, next).action,
            StepVerdict::Action::retry);
  EXPECT_DOUBLE_EQ(next, 0.04);
}

TEST(StepController, NamesAnUnderflowAndExhaustedAttempts) {
  Control c;
  c.begin();
  double next = 0;
  const StepVerdict under = c.judge(2e-14, 1e10, 100.0, next);  // needs h < 1e-14 (1 + 100)
  EXPECT_EQ(under.action, StepVerdict::Action::fail);
  EXPECT_EQ(under.failure, StepFailure::step_underflow);

  c.begin();
  double h = 1.0;
  StepVerdict v;
  int attempts = 0;
  do {  // an error estimate that stays just above 1 however small the step
    v = c.judge(h, 1.0001, 0.0, next);
    h = next;
    ++attempts;
  } while (v.action == StepVerdict::Action::retry);
  EXPECT_EQ(v.failure, StepFailure::attempts_exhausted);
  EXPECT_EQ(attempts, StepControl::max_attempts);
  EXPECT_EQ(to_string(v.failure), "attempts_exhausted");
}

// Uncoupled linear oscillators x_k'' = -omega_k^2 x_k, state (x_1, v_1, ..., x_K, v_K):
// x_k = cos(omega_k t), v_k = -omega_k sin(omega_k t) from x_k = 1, v_k = 0. The flow is an
// isometry in the energy norm, so local errors add up without growth. `poison_after`: the
// right-hand side is NaN past that time (a law's domain left), for the failure tests.
template <class State>
struct Oscillators {
  using value_type = double;
  using state_type = State;
  static constexpr std::size_t N = 6;  // rodas4's fixed size (the array instantiations)
  static constexpr std::array<double, 3> omega = {1.0, 2.5, 7.0};
  double poison_after = std::numeric_limits<double>::infinity();

  static State initial() {
    State x{};
    if constexpr (requires { x.resize(N); }) x.resize(N);
    for (std::size_t k = 0; k < 3; ++k) x[2 * k] = 1.0;
    return x;
  }
  void operator()(const State& x, State& dxdt, double t) const {
    const double nan = t > poison_after ? std::numeric_limits<double>::quiet_NaN() : 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      dxdt[2 * k] = x[2 * k + 1] + nan;
      dxdt[2 * k + 1] = -omega[k] * omega[k] * x[2 * k];
    }
  }
  template <class Jacobian>
  void jacobian(const State&, Jacobian& J) const {
    for (std::size_t k = 0; k < 3; ++k) {
      J(2 * k, 2 * k + 1) = 1.0;
      J(2 * k + 1, 2 * k) = -omega[k] * omega[k];
    }
  }
  static double max_error(const State& x, double t) {
    double worst = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      worst = std::max(worst, std::abs(x[2 * k] - std::cos(omega[k] * t)));
      worst =
          std::max(worst, std::abs(x[2 * k + 1] + omega[k] * std::sin(omega[k] * t)) / omega[k]);
    }
    return worst;
  }
};

using ArraySystem = Oscillators<std::array<double, 6>>;

template <class Stepper>
class ErrorControlledStepper : public ::testing::Test {};
using Steppers = ::testing::Types<Dp45Stepper<ArraySystem>, Dop853Stepper<ArraySystem>,
                                  Rodas4Stepper<ArraySystem>>;
TYPED_TEST_SUITE(ErrorControlledStepper, Steppers);

// Integrates to t_end with the stepper; returns the error at the end and the accepted steps.
template <class Stepper>
std::pair<double, long> integrate(const ArraySystem& sys, const IntegratorOptions& opt,
                                  double t_end) {
  Stepper stepper(opt);
  stepper.start(sys, 0.0, ArraySystem::initial());
  while (stepper.t1() < t_end) {
    if (!opt.fixed_step) stepper.propose_step(std::min(opt.initial_dt, t_end - stepper.t1()));
    const StepResult r = stepper.step(sys);
    if (!r.ok) ADD_FAILURE() << r.reason;
    if (!r.ok) break;
  }
  return {ArraySystem::max_error(stepper.x1(), stepper.t1()), stepper.steps()};
}

// The order each stepper declares, observed with fixed steps h and h/2 over t in [0, 2]
// (error ~ C h^p, so log2 of the ratio is p; 0.3 allows the next term of the expansion).
TYPED_TEST(ErrorControlledStepper, ConvergesAtItsDeclaredOrder) {
  const ArraySystem sys;
  const int p = TypeParam::order;
  // steps whose error is far above roundoff and within the asymptotic range for this order
  const double h = p >= 8 ? 0.2 : 0.02;
  IntegratorOptions coarse, fine;
  coarse.fixed_step = fine.fixed_step = true;
  coarse.dt = h;
  fine.dt = h / 2;
  const double e1 = integrate<TypeParam>(sys, coarse, 2.0).first;
  const double e2 = integrate<TypeParam>(sys, fine, 2.0).first;
  EXPECT_NEAR(std::log2(e1 / e2), p, 0.3) << TypeParam::name << ": " << e1 << " -> " << e2;
}

// With error control the local error of each accepted step is at most rtol (|x| <= omega here,
// atol = rtol); the flow does not amplify errors, so the global error is at most their sum,
// steps x rtol x max|x| (7, the largest omega). Two tolerances, to see it follows rtol.
TYPED_TEST(ErrorControlledStepper, MeetsItsToleranceSummedOverTheSteps) {
  const ArraySystem sys;
  for (const double rtol : {1e-6, 1e-9}) {
    IntegratorOptions opt;
    opt.rtol = opt.atol = rtol;
    opt.initial_dt = 1e-3;
    const auto [error, steps] = integrate<TypeParam>(sys, opt, 10.0);
    EXPECT_LE(error, steps * rtol * 7.0) << TypeParam::name << " rtol " << rtol;
    EXPECT_GT(steps, 0);
  }
}

// A right-hand side that turns NaN at t = 0.5: the steps close in on it until the one that
// would reach it is below 1e-14 (1 + t): step_underflow, named, the stepper left at its start.
TYPED_TEST(ErrorControlledStepper, FailsWithACodeAndRestoresTheState) {
  ArraySystem sys;
  sys.poison_after = 0.5;
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;
  opt.initial_dt = 0.05;
  TypeParam stepper(opt);
  stepper.start(sys, 0.0, ArraySystem::initial());
  StepResult r;
  for (int k = 0; k < 10000 && r.ok; ++k) r = stepper.step(sys);
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.code, StepFailure::step_underflow) << r.reason;
  EXPECT_NE(r.reason.find(TypeParam::name), std::string::npos) << r.reason;
  EXPECT_EQ(stepper.t1(), stepper.t0());
  EXPECT_EQ(stepper.x1(), stepper.x0());
  EXPECT_LT(stepper.t1(), 0.5);
  EXPECT_GT(stepper.t1(), 0.5 - 1e-6);
}

// The explicit steppers with a std::vector state (the finite plate's run-time size) take the
// same steps to the same bits as with std::array: the controller and the stages are generic.
template <template <class> class Stepper>
void expect_same_run_for_vector_state() {
  using VectorSystem = Oscillators<std::vector<double>>;
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;
  opt.initial_dt = 1e-3;
  Stepper<ArraySystem> a(opt);
  Stepper<VectorSystem> v(opt);
  a.start(ArraySystem{}, 0.0, ArraySystem::initial());
  v.start(VectorSystem{}, 0.0, VectorSystem::initial());
  for (int k = 0; k < 50; ++k) {
    ASSERT_TRUE(a.step(ArraySystem{}).ok);
    ASSERT_TRUE(v.step(VectorSystem{}).ok);
  }
  ASSERT_EQ(v.x1().size(), 6u);
  EXPECT_EQ(a.t1(), v.t1());
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(a.x1()[i], v.x1()[i]) << i;
  std::array<double, 6> ai{};
  std::vector<double> vi;
  const double mid = 0.5 * (a.t0() + a.t1());
  a.interpolate(ArraySystem{}, mid, ai);
  v.interpolate(VectorSystem{}, mid, vi);
  ASSERT_EQ(vi.size(), 6u);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(ai[i], vi[i]) << i;
}

TEST(ErrorControlledStepperState, Dp45RunsAVectorStateAsAnArray) {
  expect_same_run_for_vector_state<Dp45Stepper>();
}
TEST(ErrorControlledStepperState, Dop853RunsAVectorStateAsAnArray) {
  expect_same_run_for_vector_state<Dop853Stepper>();
}

// dense_functional() is the continuous extension of a linear functional of the state (the plate's
// z = alpha - sum u_k): at every point of a step it equals the functional of the interpolated
// state, the same sums in another order, to rounding (a few ulp of the terms' magnitude, 1e-14
// with room for the six components' sum).
TEST(ErrorControlledStepperState, Dop853DenseFunctionalIsTheFunctionalOfTheInterpolant) {
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;
  opt.initial_dt = 1e-3;
  Dop853Stepper<ArraySystem> st(opt);
  st.start(ArraySystem{}, 0.0, ArraySystem::initial());
  auto L = [](const std::array<double, 6>& x) { return x[0] - x[2] + 2.0 * x[4] - 0.5 * x[5]; };
  for (int k = 0; k < 20; ++k) {
    ASSERT_TRUE(st.step(ArraySystem{}).ok);
    const std::array<double, 8> c = st.dense_functional(ArraySystem{}, L);
    for (double th : {0.0, 0.1, 0.37, 0.5, 0.93, 1.0}) {
      const double t = st.t0() + th * (st.t1() - st.t0());
      std::array<double, 6> x{};
      st.interpolate(ArraySystem{}, t, x);
      double scale = 0.0;
      for (double v : x) scale += std::abs(v);
      EXPECT_NEAR(st.dense_value(c, t), L(x), 1e-14 * scale) << "step " << k << ", theta " << th;
    }
  }
}

}  // namespace
}  // namespace ivv
