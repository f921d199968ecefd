// Impacts integrated by dop853 in SIMD lanes (solver/steppers/dop853_lanes.h), one impact a lane,
// each driven by its own ImpactDriver (impact_driver.h) a step at a time:
//
//   every lane: load the next impact (set_up, then the driver's begin: onset series, first step)
//   repeat:     one attempt in every lane (Dop853Lanes::attempt)
//               a lane whose step is complete (accepted or failed): its driver's after_step
//               (events, restarts, capture, the end series) and limit_reached; a finished run
//               goes to finish(), and the lane takes the next impact
//   until no lane holds an impact.
//
// A lane's steps, events and end are its own: the lanes do not wait for one another except
// within one attempt, and a lane that finishes takes the next impact at once. What differs from
// running each impact by the scalar dop853 is the rounding of the stage arithmetic on vectors
// (fused multiply-adds where the unit contracts them), so each run agrees with the scalar one
// within the sum of the two runs' stated errors (the case cross.lanes.elastoplastic-map).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "solver/driver/impact_driver.h"
#include "solver/steppers/dop853_lane_stepper.h"
#include "solver/steppers/dop853_lanes.h"
#include "solver/steppers/integrator_options.h"

namespace ivv {

// Runs every job of `jobs` with `opt` in lanes of Lanes::width:
//   set_up(Job&, System&)                          the job's system (law, scales, 2 zeta)
//   finish(Job&, NormalisedRun<System>&&, System&) the finished run of the job
// Exceptions from either, or from a driver, propagate (jobs not finished then have no result).
template <class System, class Lanes, class Job, class SetUp, class Finish>
void run_impacts_in_lanes(std::span<Job> jobs, const IntegratorOptions& opt, SetUp&& set_up,
                          Finish&& finish) {
  using Stepper = Dop853Lanes<System, Lanes>;
  using Driver = ImpactDriver<Dop853LaneStepper<System, Lanes>, System>;
  constexpr std::size_t L = Lanes::width;
  struct Slot {
    System sys{};  // the driver and the lane hold its address
    std::optional<Driver> driver;
    Job* job = nullptr;
    // the event list of the lane's last finished run: the next run's list reuses its memory
    std::vector<typename NormalisedRun<System>::Event> event_storage;
  };
  Stepper lanes(opt);
  std::array<Slot, L> slots;
  std::size_t next = 0, busy = 0;
  // the slot's finished run to finish(); its event list's memory kept for the lane's next run
  // (finish may have moved it away: then the next run allocates its own)
  auto finish_run = [&](Slot& slot) {
    NormalisedRun<System> run = slot.driver->take_run();
    finish(*slot.job, std::move(run), slot.sys);
    slot.event_storage = std::move(run.events);
  };
  // the next job into lane i, until one needs a step; false when none is left (the lane stops)
  auto load = [&](std::size_t i) {
    Slot& slot = slots[i];
    while (next < jobs.size()) {
      slot.job = &jobs[next++];
      slot.sys = System{};
      set_up(*slot.job, slot.sys);
      lanes.begin_impact(i);
      slot.driver.emplace(slot.sys, opt, Dop853LaneStepper<System, Lanes>(lanes, i));
      slot.driver->reuse_event_storage(std::move(slot.event_storage));
      if (slot.driver->begin() == Driver::Next::step &&
          slot.driver->limit_reached() == Driver::Next::step)
        return true;
      finish_run(slot);
    }
    slot.job = nullptr;
    slot.driver.reset();
    lanes.stop(i);
    return false;
  };
  for (std::size_t i = 0; i < L; ++i)
    if (load(i)) ++busy;
  while (busy > 0) {
    const std::array<LaneAttempt, L> attempts = lanes.attempt();
    for (std::size_t i = 0; i < L; ++i) {
      const LaneAttempt::Kind kind = attempts[i].kind;
      if (kind != LaneAttempt::Kind::accepted && kind != LaneAttempt::Kind::failed) continue;
      Slot& slot = slots[i];
      if (slot.driver->after_step(lanes.step_result(i)) == Driver::Next::step &&
          slot.driver->limit_reached() == Driver::Next::step)
        continue;
      finish_run(slot);
      if (!load(i)) --busy;
    }
  }
}

}  // namespace ivv
