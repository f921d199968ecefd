#include "solver/steppers/dop853_lanes.h"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "scene/input_error.h"
#include "solver/steppers/dop853_lanes_run.h"

namespace ivv {
namespace {

// Each lane does the scalar step's operations in the same order on its own numbers: a vector
// add, multiply, divide and square root round each lane exactly as the scalar instruction does,
// and the compiler fuses a*b + c in the same places of the same expressions (per expression, the
// same on a vector as on a double). So the tolerance is zero: the same bits, NaN and the sign of
// zero included.
void expect_same_bits(double lanes, double scalar, const std::string& what) {
  EXPECT_EQ(std::bit_cast<std::uint64_t>(lanes), std::bit_cast<std::uint64_t>(scalar))
      << what << ": lanes " << lanes << ", scalar " << scalar;
}

void expect_same_state(const PaperLaneSystem::state_type& lanes,
                       const PaperLaneSystem::state_type& scalar, const std::string& what) {
  for (std::size_t m = 0; m < lanes.size(); ++m)
    expect_same_bits(lanes[m], scalar[m], what + "[" + std::to_string(m) + "]");
}

// Lane `i` of a lanes run against the scalar dop853 steps of the same unit from the same start.
void expect_lane_is_scalar(const LaneRunReport& lane, const LaneRunReport& scalar,
                           const std::string& lane_name, bool dense) {
  SCOPED_TRACE(lane_name);
  EXPECT_EQ(lane.result.ok, scalar.result.ok);
  EXPECT_EQ(lane.result.code, scalar.result.code);
  EXPECT_EQ(lane.result.reason, scalar.result.reason);
  EXPECT_EQ(lane.steps, scalar.steps);
  EXPECT_EQ(lane.rhs_evaluations, scalar.rhs_evaluations);  // the same attempts
  ASSERT_EQ(lane.t1_each.size(), scalar.t1_each.size());
  for (std::size_t s = 0; s < lane.t1_each.size(); ++s)  // each step's length: the controller
    expect_same_bits(lane.t1_each[s], scalar.t1_each[s], "t1 of step " + std::to_string(s));
  expect_same_bits(lane.t0, scalar.t0, "t0");
  expect_same_bits(lane.t1, scalar.t1, "t1");
  expect_same_state(lane.x0, scalar.x0, "x0");
  expect_same_state(lane.x1, scalar.x1, "x1");
  expect_same_state(lane.f1, scalar.f1, "f1");
  if (dense)
    for (std::size_t q = 0; q < lane.dense.size(); ++q)
      expect_same_state(lane.dense[q], scalar.dense[q], "dense " + std::to_string(q));
  ASSERT_TRUE(lane.error_norm.has_value());
  ASSERT_TRUE(lane.h_next.has_value());
  if (lane.result.ok) {
    EXPECT_LE(*lane.error_norm, 1.0);  // accepted: ||err|| <= 1
  }
}

IntegratorOptions paper_options() {
  IntegratorOptions opt;
  opt.rtol = opt.atol = 1e-8;  // the paper map's tolerance
  return opt;
}

// Both schedules (lanes in lockstep, or each lane on its own) against the scalar steps.
void compare_lanes_with_scalar(const std::array<LaneStart, kDop853Lanes>& starts,
                               const LaneRunOptions& run, const std::string& where = "") {
  const IntegratorOptions opt = paper_options();
  for (const LaneSchedule schedule : {LaneSchedule::lockstep, LaneSchedule::free}) {
    LaneRunOptions scheduled = run;
    scheduled.schedule = schedule;
    const LanesRunReport lanes = dop853_run_lanes(starts, opt, scheduled);
    for (std::size_t i = 0; i < kDop853Lanes; ++i) {
      const LaneRunReport scalar = dop853_run_scalar(starts[i], opt, run);
      expect_lane_is_scalar(lanes.lanes[i], scalar,
                            where + "lane " + std::to_string(i) +
                                (schedule == LaneSchedule::free ? " (free)" : " (lockstep)"),
                            run.dense_samples && scalar.result.ok);
    }
  }
}

using Branch = LanePlace::Branch;

// One lane on each branch of the law in one call: the lanes' force selects per lane.
TEST(Dop853Lanes, LanesOnDifferentBranchesEachMatchTheScalarStep) {
  ASSERT_TRUE(dop853_lanes_runnable());  // this machine has AVX2 and FMA (CI's too)
  const std::array<LaneStart, kDop853Lanes> starts = {
      paper_lane(1.0, 0.1, {Branch::hertz_loading, 0.6, 2.0, 0.9, 0.05}),
      paper_lane(1.0, 0.1, {Branch::plastic_loading, 1.7, 2.0, 0.5, 0.05}),
      paper_lane(1.0, 0.1, {Branch::plastic_unloading, 1.9, 2.5, -0.2, 0.05}),
      paper_lane(1.0, 0.1, {Branch::elastic_unloading, 0.4, 0.8, -0.7, 0.05}),
  };
  compare_lanes_with_scalar(starts, {.steps = 4, .dense_samples = true});
}

// Unloading far above yield (z_m = 2000 z_y: the cancellation's gain 30, past
// ElastoplasticLaw::kPlainUnloadingGain) takes the factored force; beside it a plain unloading
// lane and the loading branches, which then see the factored form computed and not taken.
TEST(Dop853Lanes, AFactoredUnloadingLaneBesidePlainOnesMatchesTheScalarStep) {
  const std::array<LaneStart, kDop853Lanes> starts = {
      paper_lane(10.0, 0.2, {Branch::plastic_unloading, 1990.0, 2000.0, -0.1, 0.01}),
      paper_lane(1.0, 0.1, {Branch::plastic_unloading, 1.9, 2.5, -0.2, 0.05}),
      paper_lane(1.0, 0.1, {Branch::hertz_loading, 0.6, 2.0, 0.9, 0.05}),
      paper_lane(1.0, 0.1, {Branch::plastic_loading, 1.7, 2.0, 0.5, 0.05}),
  };
  ASSERT_FALSE(starts[0].system.branch.plain_unloading);
  ASSERT_TRUE(starts[1].system.branch.plain_unloading);
  compare_lanes_with_scalar(starts, {.steps = 3, .dense_samples = true});
}

// The tension side of an unloading branch (z <= 0, past separation) beside a Hertz lane.
TEST(Dop853Lanes, TheTensionSideOfUnloadingMatchesTheScalarStep) {
  const std::array<LaneStart, kDop853Lanes> starts = {
      paper_lane(2.0, 0.2, {Branch::plastic_unloading, -0.05, 3.0, -0.6, 0.02}),
      paper_lane(2.0, 0.2, {Branch::hertz_loading, 0.2, 2.0, 0.95, 0.02}),
      paper_lane(2.0, 0.2, {Branch::elastic_unloading, -0.01, 0.5, -0.9, 0.02}),
      paper_lane(2.0, 0.2, {Branch::plastic_unloading, 0.3, 3.0, -0.5, 0.02}),
  };
  compare_lanes_with_scalar(starts, {.steps = 3, .dense_samples = true});
}

// Random valid lanes: the paper scene at v0 from 0.1 to 10 m/s (log) and zeta 0.01 to 1, each
// lane on a random branch at a random place, with first steps from 0.001 to 1 (many rejected:
// the lanes then wait for one another), several steps each.
TEST(Dop853Lanes, RandomLanesMatchTheScalarStepBitForBit) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int rejected_first_steps = 0;
  for (int batch = 0; batch < 150; ++batch) {
    std::array<LaneStart, kDop853Lanes> starts;
    for (LaneStart& s : starts) {
      const double v0 = 0.1 * std::pow(100.0, u(rng));
      const double zeta = 0.01 + 0.99 * u(rng);
      LanePlace at;
      at.branch = static_cast<Branch>(static_cast<int>(4 * u(rng)) % 4);
      at.z_max_over_z_y =
          at.branch == Branch::elastic_unloading ? 0.1 + 0.9 * u(rng) : 1.0 + 4.0 * u(rng);
      switch (at.branch) {
        case Branch::hertz_loading:
          at.z_over_z_y = u(rng);
          at.w = 0.05 + 0.95 * u(rng);
          break;
        case Branch::plastic_loading:
          at.z_over_z_y = 1.0 + 3.0 * u(rng);
          at.w = 0.05 + 0.9 * u(rng);
          break;
        default:  // unloading: below z_m, down to its tension side
          at.z_over_z_y = at.z_max_over_z_y * (1.05 * u(rng) - 0.05);
          at.w = -0.95 * u(rng);
          break;
      }
      at.h = 0.001 * std::pow(1000.0, u(rng));
      s = paper_lane(v0, zeta, at);
    }
    const LaneRunOptions run{.steps = 3, .dense_samples = true};
    compare_lanes_with_scalar(starts, run, "batch " + std::to_string(batch) + " ");
    for (const LaneStart& start : starts) {
      const LaneRunReport scalar = dop853_run_scalar(start, paper_options(), run);
      // more than 12 evaluations per step beyond start: some attempt was rejected
      if (scalar.rhs_evaluations > 1 + 12 * scalar.steps) ++rejected_first_steps;
    }
    if (testing::Test::HasFailure()) break;  // one batch's report is enough to read
  }
  EXPECT_GT(rejected_first_steps, 50);  // the lanes did wait for each other's retries
}

// A lane that cannot step (a NaN state: every attempt rejected until the step underflows) fails
// as the scalar stepper does, at its start, with the same code and message, while the lanes
// beside it step on unchanged (they computed their accepted step again meanwhile).
TEST(Dop853Lanes, AFailedLaneFailsAsTheScalarStepAndLeavesTheOthersAlone) {
  std::array<LaneStart, kDop853Lanes> starts = {
      paper_lane(1.0, 0.1, {Branch::hertz_loading, 0.6, 2.0, 0.9, 0.05}),
      paper_lane(1.0, 0.1, {Branch::plastic_loading, 1.7, 2.0, 0.5, 0.05}),
      paper_lane(1.0, 0.1, {Branch::plastic_unloading, 1.9, 2.5, -0.2, 0.05}),
      paper_lane(1.0, 0.1, {Branch::elastic_unloading, 0.4, 0.8, -0.7, 0.05}),
  };
  starts[1].x[PaperLaneSystem::Z] = std::numeric_limits<double>::quiet_NaN();
  const LanesRunReport lanes = dop853_run_lanes(starts, paper_options(), {.steps = 3});
  EXPECT_FALSE(lanes.lanes[1].result.ok);
  EXPECT_EQ(lanes.lanes[1].result.code, StepFailure::step_underflow);
  EXPECT_EQ(lanes.lanes[1].steps, 0);
  // the failing lane's ~20 attempts were computed in all four lanes
  EXPECT_GT(lanes.lane_attempts, lanes.useful_attempts);
  compare_lanes_with_scalar(starts, {.steps = 3, .dense_samples = true});
}

// The law's force in lanes (elastoplastic.h: force_lanes) against force() lane by lane, here in
// the baseline code of this test (SSE2: two lanes a vector; no fused multiply-add on either
// side), on every branch: the plain unloading (z_m = 2.5 z_y), the factored one (z_m = 2000 z_y,
// beside a plain lane), the elastic one; the pairs without a factored lane skip its formula.
TEST(ElastoplasticForceLanes, EachLaneIsTheScalarForceOnItsBranch) {
  using Lanes = LaneMath<2>;
  const std::array<LaneStart, 6> lanes = {
      paper_lane(1.0, 0.1, {Branch::hertz_loading, 0.6, 2.0, 0.9, 0.05}),
      paper_lane(3.0, 0.3, {Branch::plastic_loading, 1.7, 2.0, 0.5, 0.05}),
      paper_lane(0.5, 0.5, {Branch::plastic_unloading, 1.9, 2.5, -0.2, 0.05}),
      paper_lane(1.0, 0.1, {Branch::elastic_unloading, 0.4, 0.8, -0.7, 0.05}),
      paper_lane(10.0, 0.2, {Branch::plastic_unloading, 1990.0, 2000.0, -0.1, 0.01}),
      paper_lane(1.0, 0.1, {Branch::plastic_unloading, 1.9, 2.5, -0.2, 0.05}),
  };
  for (std::size_t pair = 0; pair < lanes.size(); pair += 2) {  // lanes 0 and 1, 2 and 3, ...
    ElastoplasticLaw::LaneBranches<Lanes> c;
    for (std::size_t i = 0; i < 2; ++i)
      c.set_lane(i, lanes[pair + i].system.law, lanes[pair + i].system.branch);
    for (const double scale : {-0.5, -1e-3, 0.0, 0.3, 1.0, 1.6, 3.0, 1980.0, 1999.0}) {
      Lanes::vector z{};
      for (std::size_t i = 0; i < 2; ++i) z[i] = scale * lanes[pair + i].system.law.z_y;
      const Lanes::vector F = ElastoplasticLaw::force_lanes<Lanes>(c, z);
      for (std::size_t i = 0; i < 2; ++i) {
        const PaperLaneSystem& sys = lanes[pair + i].system;
        expect_same_bits(
            F[i], sys.law.force(sys.branch, z[i], 0.0),
            "lane " + std::to_string(pair + i) + " at z/z_y = " + std::to_string(scale));
      }
    }
  }
}

TEST(Dop853Lanes, APaperLaneNeedsADashpot) {
  EXPECT_THROW(paper_lane(1.0, 0.0, {}), InputError);
  EXPECT_THROW(paper_lane(1.0, std::numeric_limits<double>::quiet_NaN(), {}), InputError);
  EXPECT_THROW(paper_lane(-1.0, 0.1, {}), InputError);
}

TEST(Dop853Lanes, RefusesFixedStepMode) {
  struct Law : ElastoplasticLaw {};
  IntegratorOptions opt;
  opt.fixed_step = true;
  using System = ImpactSystem<Law, true>;
  EXPECT_THROW((Dop853Lanes<System, LaneMath<2>>(opt)), std::invalid_argument);
}

}  // namespace
}  // namespace ivv
