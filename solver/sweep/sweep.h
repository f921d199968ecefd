// A grid of impacts: v0 x zeta x any scene values. Each point is an independent simulate();
// the grid, its order and its validation are solver/sweep/sweep_grid.h, the CSV rows
// solver/sweep/sweep_csv.h, the streamed and journalled output solver/sweep/sweep_sink.h.
//
// Two ways to run a grid:
// - run_sweep(): in memory, for studies that want the ImpactResults (reports, cases, Python).
// - SweepSink + run_sweep_points() (sweep_sink.h): streamed to a CSV for large studies, with a
//   journal that --resume continues from, or to standard output.
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"
#include "solver/sweep/sweep_csv.h"
#include "solver/sweep/sweep_grid.h"
#include "solver/sweep/sweep_sink.h"

namespace ivv {

struct SweepPoint {
  double v0 = 0.0;
  double zeta = 0.0;
  std::vector<double> axes;  // the scene axes' values (SweepRequest::axes order)
  ImpactResult result;
};

// Validates, then runs every point on request.threads workers. A point whose simulate()
// throws ends the sweep with std::runtime_error naming the point (v0, zeta, the axes).
std::vector<SweepPoint> run_sweep(const SweepRequest& request);

// Runs point `index` and returns its CSV row. A throwing simulate() becomes std::runtime_error
// naming the point.
std::string run_sweep_point(const SweepRequest& request, std::size_t index);

}  // namespace ivv
