// Heap allocations per impact on the hot path (none beyond the result's own), counted by replacing
// the global operator new in this test binary and running simulate() without a trajectory.
//
// The bound: an impact returns ImpactResult, whose `events` vector must own its storage, and
// the driver keeps its own event list in normalised units (reserved once for every event an
// impact can have); so a hand-written stepper costs exactly these two allocations per impact
// and nothing per step or per right-hand-side evaluation. Library steppers are listed with
// what their libraries allocate (GSL allocates its driver per impact; odeint's steppers on
// std::array state allocate nothing).
#include <gtest/gtest.h>

#include "solver/simulate.h"

// counted_allocations.cc: the global operator new replaced by one that counts
long heap_allocations_so_far();

namespace ivv {
namespace {

long allocations_of_one_impact(IntegratorKind k, double zeta) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  req.integrator = k;
  const ImpactResult warm = simulate(req);  // first-call statics (tables, error handlers)
  EXPECT_TRUE(warm.separated()) << warm.reason;
  const long before = heap_allocations_so_far();
  const ImpactResult r = simulate(req);
  const long n = heap_allocations_so_far() - before;
  EXPECT_TRUE(r.separated()) << r.reason;
  return n;
}

// ImpactResult::events and the driver's own event list: two allocations, independent of the
// number of steps (so none per step or per evaluation).
constexpr long kPerImpact = 2;

TEST(Allocations, HandWrittenSteppersAllocateOnlyTheEventLists) {
  for (IntegratorKind k : {IntegratorKind::dop853, IntegratorKind::dp45, IntegratorKind::rk4,
                           IntegratorKind::odeint_dopri5, IntegratorKind::rodas4}) {
    for (double zeta : {0.0, 0.1}) {
      EXPECT_EQ(allocations_of_one_impact(k, zeta), kPerImpact)
          << to_string(k) << " zeta = " << zeta;
    }
  }
}

TEST(Allocations, DoNotGrowWithTheNumberOfSteps) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = Damping::ratio(0.1);
  for (IntegratorKind k : {IntegratorKind::dop853, IntegratorKind::rodas4}) {
    req.integrator = k;
    for (double rtol : {1e-6, 1e-13}) {
      req.options.rtol = req.options.atol = rtol;
      simulate(req);
      const long before = heap_allocations_so_far();
      const ImpactResult r = simulate(req);
      EXPECT_EQ(heap_allocations_so_far() - before, kPerImpact)
          << to_string(k) << " rtol " << rtol << ", " << r.steps << " steps";
    }
  }
}

// The stiff scene the implicit rodas4 is for (zeta = 100, captured): still only the event
// lists, however many steps (the Jacobian, the LU and the stages live in the stepper).
TEST(Allocations, RodasOnTheStiffSceneAllocatesOnlyTheEventLists) {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = Damping::ratio(100.0);
  req.integrator = IntegratorKind::rodas4;
  for (double rtol : {1e-6, 1e-10}) {
    req.options.rtol = req.options.atol = rtol;
    simulate(req);
    const long before = heap_allocations_so_far();
    const ImpactResult r = simulate(req);
    EXPECT_EQ(r.status, ImpactStatus::captured) << r.reason;
    EXPECT_EQ(heap_allocations_so_far() - before, kPerImpact)
        << "rtol " << rtol << ", " << r.steps << " steps";
  }
}

}  // namespace
}  // namespace ivv
