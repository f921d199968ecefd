// simulate_batch (simulate_batch.h): impacts computed together, the paper's law with a dashpot in
// SIMD lanes, against simulate() of each request on its own.
#include "solver/simulate_batch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "solver/choice/model_choice.h"
#include "solver/consistency.h"
#include "solver/simulate_lanes.h"
#include "solver/steppers/machine_code.h"

namespace ivv {
namespace {

// The paper scene at v0 [m/s] and damping ratio zeta (0: no dashpot), `law`, rtol 1e-8.
SimulationRequest paper_point(double v0, double zeta, LawKind law = LawKind::elastoplastic) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = v0;
  req.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  req.law = law;
  req.model = ModelKind::automatic;  // as the command line runs it
  req.integrator = IntegratorKind::dop853;
  req.options.rtol = 1e-8;
  return req;
}

// a and b equal (both infinite: a captured impact's contact time), or within `relative` of b
bool close(double a, double b, double relative) {
  return a == b || std::abs(a - b) <= relative * std::abs(b);
}

bool in_lanes(const SimulationRequest& req) {
  return runs_in_lanes(ValidatedRequest(req));
}

std::vector<ImpactResult> batch(const std::vector<SimulationRequest>& requests) {
  std::vector<ValidatedRequest> validated;
  for (const SimulationRequest& req : requests) validated.emplace_back(req);
  std::vector<ImpactResult> results(requests.size());
  simulate_batch(validated, results);
  return results;
}

// Elastic (0.05, 0.1 m/s), plastic (1, 5 m/s) and captured (zeta 0.9 at low v0) impacts, with
// and without a dashpot: more points than lanes, so lanes are refilled as impacts end.
std::vector<SimulationRequest> mixed_grid() {
  std::vector<SimulationRequest> grid;
  for (double v0 : {0.05, 0.1, 0.3, 1.0, 5.0})
    for (double zeta : {0.0, 0.02, 0.1, 0.4, 0.9}) grid.push_back(paper_point(v0, zeta));
  return grid;
}

TEST(SimulateBatch, EachResultIsTheSingleRunsWithinTheTwoStatedErrors) {
  const std::vector<SimulationRequest> grid = mixed_grid();
  const std::vector<ImpactResult> together = batch(grid);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    SCOPED_TRACE("v0 " + std::to_string(grid[i].scene.velocity) + " m/s, zeta " +
                 std::to_string(grid[i].scene.damping.value));
    const ImpactResult one = simulate(grid[i]);
    const ImpactResult& r = together[i];
    ASSERT_TRUE(r.ok()) << r.reason;
    EXPECT_EQ(r.status, one.status);
    EXPECT_EQ(r.route, one.route);
    EXPECT_EQ(r.integrator, one.integrator);
    // each e is within its stated error of the exact one (solver/consistency.h)
    const double stated = accumulated_error_bound(r.steps, grid[i].options) +
                          accumulated_error_bound(one.steps, grid[i].options);
    EXPECT_LE(std::abs(r.e - one.e), stated);
    EXPECT_LE(std::abs(r.e_poisson - one.e_poisson), stated);
    // the contact time and peak force to the same relative accuracy, the events located on
    // interpolants of the same order
    EXPECT_TRUE(close(r.t_contact, one.t_contact, stated)) << r.t_contact << " " << one.t_contact;
    EXPECT_TRUE(close(r.F_max, one.F_max, stated)) << r.F_max << " " << one.F_max;
    EXPECT_EQ(r.events.size(), one.events.size());
    if (!in_lanes(grid[i])) {  // then the same code ran: the same bits
      EXPECT_EQ(r.e, one.e);
      EXPECT_EQ(r.steps, one.steps);
    }
  }
}

TEST(SimulateBatch, AnImpactsResultDoesNotDependOnTheOthersInItsBatch) {
  const std::vector<SimulationRequest> grid = mixed_grid();
  const std::vector<ImpactResult> together = batch(grid);
  for (const std::size_t i : {0UL, 7UL, 13UL, 24UL}) {
    const ImpactResult alone = batch({grid[i]})[0];
    EXPECT_EQ(alone.e, together[i].e) << i;
    EXPECT_EQ(alone.t_contact, together[i].t_contact) << i;
    EXPECT_EQ(alone.F_max, together[i].F_max) << i;
    EXPECT_EQ(alone.steps, together[i].steps) << i;
    EXPECT_EQ(alone.rhs_evaluations, together[i].rhs_evaluations) << i;
  }
}

TEST(SimulateBatch, CountsTheRightHandSidesAsTheScalarRunDoes) {
  // where the lanes take the scalar run's steps, they evaluate as many right-hand sides
  // (12 an attempt, 3 more on a step interpolated on, 1 at each start)
  const std::vector<SimulationRequest> grid = mixed_grid();
  const std::vector<ImpactResult> together = batch(grid);
  int same_steps = 0;
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const ImpactResult one = simulate(grid[i]);
    if (together[i].steps != one.steps) continue;
    ++same_steps;
    EXPECT_EQ(together[i].rhs_evaluations, one.rhs_evaluations) << i;
  }
  EXPECT_GT(same_steps, 10);
}

TEST(SimulateBatch, OnlyThePapersLawWithADashpotByDop853RunsInLanes) {
  // the paper's law with a dashpot does wherever the fastest machine code is this CPU's
  const bool fastest = machine_code_in_use(MachineCode::fastest) == MachineCode::fastest;
  EXPECT_EQ(in_lanes(paper_point(1.0, 0.1)), fastest && detail::dop853_lanes_impacts_runnable());
  EXPECT_FALSE(in_lanes(paper_point(1.0, 0.0)));  // no dashpot
  EXPECT_FALSE(in_lanes(paper_point(1.0, 0.1, LawKind::hertz)));
  SimulationRequest rk4 = paper_point(1.0, 0.1);
  rk4.model = ModelKind::full;
  rk4.integrator = IntegratorKind::rk4;
  SimulationRequest dopri5 = paper_point(1.0, 0.1);  // the library's default integrator
  dopri5.model = ModelKind::full;
  dopri5.integrator = IntegratorKind::odeint_dopri5;
  EXPECT_FALSE(in_lanes(dopri5));
  EXPECT_FALSE(in_lanes(rk4));
  SimulationRequest baseline = paper_point(1.0, 0.1);
  baseline.options.machine_code = MachineCode::baseline;
  EXPECT_FALSE(in_lanes(baseline));
  // the others in a batch are simulate()'s, bit for bit
  const std::vector<SimulationRequest> others = {paper_point(1.0, 0.1, LawKind::hertz), rk4,
                                                 baseline, paper_point(1.0, 0.0)};
  const std::vector<ImpactResult> together = batch(others);
  for (std::size_t i = 0; i < others.size(); ++i) {
    const ImpactResult one = simulate(others[i]);
    EXPECT_EQ(together[i].e, one.e) << i;
    EXPECT_EQ(together[i].rhs_evaluations, one.rhs_evaluations) << i;
    EXPECT_EQ(together[i].route, one.route) << i;
  }
}

TEST(SimulateBatch, ALaneThatReachesItsStepLimitFailsAsTheScalarRunDoes) {
  std::vector<SimulationRequest> grid = {paper_point(1.0, 0.1), paper_point(2.0, 0.2)};
  grid[0].options.max_steps = 2;
  grid[1].options.max_steps = 2;
  const std::vector<ImpactResult> together = batch(grid);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const ImpactResult one = simulate(grid[i]);
    EXPECT_EQ(together[i].status, ImpactStatus::failed);
    EXPECT_EQ(together[i].failure, FailureKind::step_limit);
    EXPECT_EQ(together[i].failure, one.failure);
    EXPECT_NE(together[i].reason.find("max_steps = 2"), std::string::npos) << together[i].reason;
  }
}

TEST(SimulateBatch, RequestsWithOtherOptionsRunInTheirOwnLanes) {
  std::vector<SimulationRequest> grid = {paper_point(1.0, 0.1), paper_point(1.0, 0.1),
                                         paper_point(3.0, 0.3)};
  grid[1].options.rtol = 1e-11;
  const std::vector<ImpactResult> together = batch(grid);
  const ImpactResult tight = batch({grid[1]})[0];
  EXPECT_EQ(together[1].e, tight.e);
  EXPECT_EQ(together[1].steps, tight.steps);
  EXPECT_GT(together[1].steps, together[0].steps);  // rtol 1e-11 takes more steps than 1e-8
}

TEST(SimulateBatch, TheLanesRunWhateverMachineCodeTheProcessUses) {
  // run_dop853_lanes called directly, so that builds whose fastest machine code is the
  // baseline (the sanitizer build turns the FMA copy off) run the lanes and their driver too:
  // the full model of each damped point of the grid, against simulate_full's dop853 run
  std::vector<SimulationRequest> grid;
  for (SimulationRequest req : mixed_grid()) {
    if (req.scene.damping.kind == Damping::Kind::none) continue;
    req.model = ModelKind::full;
    grid.push_back(req);
  }
  std::vector<ValidatedRequest> validated;
  for (const SimulationRequest& req : grid) validated.emplace_back(req);
  std::vector<ImpactResult> results(grid.size());
  std::vector<detail::LaneImpact> lanes;
  for (std::size_t i = 0; i < grid.size(); ++i) lanes.push_back({&validated[i], &results[i]});
  if (!detail::dop853_lanes_impacts_runnable()) {  // a CPU without the lanes' instructions
    EXPECT_THROW(detail::run_dop853_lanes(lanes), std::logic_error);
    return;
  }
  detail::run_dop853_lanes(lanes);
  for (std::size_t i = 0; i < grid.size(); ++i) {
    detail::finish_full(results[i], IntegratorKind::dop853);
    const ImpactResult one = detail::simulate_full(validated[i], IntegratorKind::dop853, nullptr);
    ASSERT_TRUE(results[i].ok()) << results[i].reason;
    EXPECT_EQ(results[i].status, one.status) << i;
    const double stated = accumulated_error_bound(results[i].steps, grid[i].options) +
                          accumulated_error_bound(one.steps, grid[i].options);
    EXPECT_LE(std::abs(results[i].e - one.e), stated) << i;
  }
}

TEST(SimulateBatch, RefusesSpansOfDifferentSizes) {
  const SimulationRequest req = paper_point(1.0, 0.1);
  std::vector<ValidatedRequest> validated{ValidatedRequest(req)};
  std::vector<ImpactResult> results(2);
  EXPECT_THROW(simulate_batch(validated, results), std::invalid_argument);
}

}  // namespace
}  // namespace ivv
