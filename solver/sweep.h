// A grid of impacts (v0 x zeta) run on all cores. Each point is an independent simulate();
// results come back in grid order (velocity-major) whatever the thread count.
#pragma once

#include <functional>
#include <vector>

#include "solver/simulate.h"

namespace ivv {

struct SweepRequest {
  SimulationRequest base;          // scene, law, integrator and options shared by every point
  std::vector<double> velocities;  // v0 [m/s]
  std::vector<double> zetas;       // damping ratios; 0 means no dashpot
  int threads = 0;                 // 0: all hardware threads
  // Called from worker threads (serialised) after each point: (points done, total).
  std::function<void(std::size_t, std::size_t)> progress;
};

struct SweepPoint {
  double v0 = 0.0;
  double zeta = 0.0;
  ImpactResult result;
};

// Throws InputError for an empty or invalid grid (naming --v0 or --zeta).
std::vector<SweepPoint> run_sweep(const SweepRequest& request);

// Grids: n points from lo to hi inclusive, linearly or logarithmically spaced.
std::vector<double> linear_grid(double lo, double hi, int n);
std::vector<double> log_grid(double lo, double hi, int n);

}  // namespace ivv
