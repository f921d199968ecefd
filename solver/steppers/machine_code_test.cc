#include "solver/steppers/machine_code.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "solver/consistency.h"
#include "solver/laws/energy_creating_hertz.h"
#include "solver/simulate.h"
#include "solver/simulate_law.h"

namespace ivv {
namespace {

// The paper impact (Table 1, 1 m/s, zeta 0.1) with dop853 at rtol = atol = 1e-8 in `code`.
SimulationRequest paper_request(LawKind law, MachineCode code) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = Damping::ratio(0.1);
  req.law = law;
  req.model = ModelKind::full;
  req.integrator = IntegratorKind::dop853;
  req.options.rtol = req.options.atol = 1e-8;
  req.options.machine_code = code;
  return req;
}

bool environment_forces_baseline() {
  const char* v = std::getenv("IVV_MACHINE_CODE");
  return v && std::string(v) == "baseline";
}

TEST(MachineCode, ABaselineRequestRunsTheBaselineCode) {
  EXPECT_EQ(machine_code_in_use(MachineCode::baseline), MachineCode::baseline);
}

TEST(MachineCode, TheFastestIsTheFmaCopyExactlyWhereTheCpuHasAvx2AndFma) {
  const bool copy = cpu_has_fma_clone() && !environment_forces_baseline();
  EXPECT_EQ(machine_code_in_use(MachineCode::fastest),
            copy ? MachineCode::fastest : MachineCode::baseline);
  EXPECT_EQ(machine_code_environment_problem(), "");
}

TEST(MachineCode, NamesItsCodes) {
  EXPECT_EQ(to_string(MachineCode::baseline), "baseline");
  EXPECT_EQ(to_string(MachineCode::fastest), "fastest");
  EXPECT_EQ(machine_code_description(MachineCode::fastest), "x86-64-v3 (AVX2, FMA)");
}

// The copy integrates the same equations by the same method: the same events and outcome, and
// e within the sum of the two runs' stated errors (accumulated_error_bound, the bound every
// run's ledger is held to). With a trajectory too: the observer is called from the copy.
class FmaCopy : public ::testing::TestWithParam<LawKind> {};

TEST_P(FmaCopy, AgreesWithTheBaselineWithinTheStatedErrors) {
  // without a copy (this CPU, or IVV_MACHINE_CODE=baseline) both requests run the same code:
  // then the two runs are the same bit for bit
  const bool copy = machine_code_in_use(MachineCode::fastest) == MachineCode::fastest;
  const SimulationRequest base_req = paper_request(GetParam(), MachineCode::baseline);
  const SimulationRequest fast_req = paper_request(GetParam(), MachineCode::fastest);
  std::vector<TrajectoryPoint> base_path, fast_path;
  const ImpactResult base = simulate(base_req, &base_path);
  const ImpactResult fast = simulate(fast_req, &fast_path);
  ASSERT_TRUE(base.ok()) << base.reason;
  ASSERT_TRUE(fast.ok()) << fast.reason;
  EXPECT_EQ(fast.status, base.status);
  ASSERT_EQ(fast.events.size(), base.events.size());
  for (std::size_t i = 0; i < base.events.size(); ++i)
    EXPECT_EQ(fast.events[i].kind, base.events[i].kind);
  const double stated = accumulated_error_bound(base.steps, base_req.options) +
                        accumulated_error_bound(fast.steps, fast_req.options);
  EXPECT_LE(std::abs(fast.e - base.e), copy ? stated : 0.0);
  // F_max in units of its own value, like e in units of v0
  EXPECT_LE(std::abs(fast.F_max - base.F_max), copy ? stated * base.F_max : 0.0);
  EXPECT_FALSE(fast_path.empty());
  // four samples a step in both (impact_driver.h): the same steps give the same count
  if (fast.steps == base.steps) {
    EXPECT_EQ(fast_path.size(), base_path.size());
  }
}

// A law derived from one that has a copy keeps its own members: the copy of the base law is not
// run in its place. Here the unloading force is 1.1 times Hertz's, which returns more energy
// (solver/laws/energy_creating_hertz.h).
using StifferUnloadingHertz = EnergyCreatingHertz;

TEST(FmaCopy, ALawDerivedFromACopiedLawRunsItsOwnMembers) {
  const SimulationRequest req = paper_request(LawKind::hertz, MachineCode::fastest);
  const HertzLaw hertz = HertzLaw::make({}, derive(req.scene));
  IntegratorOptions options = req.options;
  options.check_consistency = false;  // the derived law's ledger is not Hertz's
  const ImpactResult own =
      simulate(StifferUnloadingHertz{hertz}, req.scene, IntegratorKind::dop853, options);
  const ImpactResult base = simulate(hertz, req.scene, IntegratorKind::dop853, options);
  ASSERT_TRUE(own.ok()) << own.reason;
  ASSERT_TRUE(base.ok()) << base.reason;
  // 1.1 times the unloading force from the same z_max: e grows by about sqrt(1.1) (5 %); the two
  // codes differ by ~1e-13
  EXPECT_GT(own.e, base.e * 1.01);
}

INSTANTIATE_TEST_SUITE_P(PaperLaws, FmaCopy,
                         ::testing::Values(LawKind::elastoplastic, LawKind::hertz),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace ivv
