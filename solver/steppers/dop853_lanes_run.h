// Dop853 in lanes (dop853_lanes.h) on the paper's system, the elastoplastic law with a series
// dashpot, compiled in dop853_lanes.cc for AVX2 + FMA where the build compiles the FMA copy
// (fma_copy.h: IVV_FMA_COPY), beside the scalar Dop853Stepper of the same unit and the same
// machine code: the lane-by-lane comparison (dop853_lanes_test.cc) and the benchmark
// (bench/benchmarks.cc) run these two side by side.
//
// These are the lanes' bare steps, for the comparison and the benchmark; the impacts of a sweep
// run in lanes through the driver (solver/driver/lanes_driver.h, solver/simulate_batch.h).
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "solver/driver/impact_system.h"
#include "solver/laws/elastoplastic.h"
#include "solver/steppers/integrator_options.h"
#include "solver/steppers/step_result.h"

namespace ivv {

using PaperLaneSystem = ImpactSystem<ElastoplasticLaw, true>;
inline constexpr std::size_t kDop853Lanes = 4;  // doubles in an AVX2 register

// Where one lane's impact is: its system (law, branch, scales), tau, state and first step.
struct LaneStart {
  PaperLaneSystem system;
  double tau = 0;
  PaperLaneSystem::state_type x{};
  double h = 0;  // the step to try first (Dop853Stepper::propose_step)
};

// How the lanes are driven: Dop853Lanes::step() (every lane's step complete before any begins
// its next: a lane done early waits) or attempt() (a lane begins its next step as soon as its
// last is complete, as a driver in lanes would; a lane done with its steps then idles).
enum class LaneSchedule { lockstep, free };

struct LaneRunOptions {
  int steps = 1;              // steps per lane (a lane that fails stops there)
  bool dense_samples = true;  // interpolate the last step at theta = 1/4, 1/2, 3/4
  LaneSchedule schedule = LaneSchedule::lockstep;  // lanes only
};

// What the steps of one lane left, as the scalar stepper's accessors give it.
struct LaneRunReport {
  StepResult result;            // of the last step taken
  long steps = 0;               // accepted
  std::vector<double> t1_each;  // t1 after each step taken
  double t0 = 0, t1 = 0;
  PaperLaneSystem::state_type x0{}, x1{}, f1{};
  long rhs_evaluations = 0;  // the system's count (start and every attempt)
  std::array<PaperLaneSystem::state_type, 3> dense{};  // at theta = 1/4, 1/2, 3/4 (if asked)
  // lanes only (the scalar stepper does not expose them): the last attempt's error norm
  // (dop853.h's ||err||) and the step to try next
  std::optional<double> error_norm;
  std::optional<double> h_next;
};

struct LanesRunReport {
  std::array<LaneRunReport, kDop853Lanes> lanes;
  long useful_attempts = 0;  // attempts the lanes needed
  long lane_attempts = 0;    // lane-attempts computed (4 per call, idle lanes included)
};

// Where a paper-scene lane starts (paper_lane): on which branch of the elastoplastic law, at
// which spring deformation and velocity, with which first step.
struct LanePlace {
  enum class Branch { hertz_loading, plastic_loading, elastic_unloading, plastic_unloading };
  Branch branch = Branch::hertz_loading;
  double z_over_z_y = 0.5;      // z / z_y (may be <= 0 on an unloading branch: its tension side)
  double z_max_over_z_y = 2.0;  // z_m / z_y of an unloading branch (< 1 elastic, > 1 plastic)
  double w = 0.5;               // normalised impactor velocity alpha'/v0
  double h = 0.05;              // first step to try [normalised time]
};

// The paper scene (Table 1) at v0 [m/s] and damping ratio zeta, its system set up as the dop853
// run sets it (yield scales), the branch of `at` (begin_unloading from z_m for an unloading one),
// and a state consistent with the equations: z and w as given, J = 1 - w and
// Wa = (1 - w^2)/2 (exact integrals of J' = F = -w'), a = z + 2 zeta J (y' = 2 zeta F), and
// Wv = Wa less the energy the spring holds (at least 0; the ledger less the plastic work).
// Throws InputError naming damping.zeta unless zeta > 0, and as validate(scene) does for v0.
LaneStart paper_lane(double v0, double zeta, const LanePlace& at);

// Whether this process can run the lanes: false only where dop853_lanes.cc is compiled for AVX2
// + FMA and the CPU lacks them (cpu_has_fma_clone()).
bool dop853_lanes_runnable();

// The four impacts of `lanes` in lanes, run.steps steps each (Dop853Lanes::step()), and their
// reports. Throws std::logic_error where !dop853_lanes_runnable().
LanesRunReport dop853_run_lanes(const std::array<LaneStart, kDop853Lanes>& lanes,
                                const IntegratorOptions& options, const LaneRunOptions& run);
// The same for one impact with the scalar Dop853Stepper of the same unit.
LaneRunReport dop853_run_scalar(const LaneStart& lane, const IntegratorOptions& options,
                                const LaneRunOptions& run);

}  // namespace ivv
