// The grid of a sweep: which impacts it holds, in which order, and the one validation of it.
//
// A sweep is the product of its axes: the impact velocities v0, the damping ratios zeta (or the
// scene's own dashpot at every point), then any number of scene values (SceneAxis: a key of
// scene/scene_values.h, e.g. structure.thickness or impactor.mass, with its values). Points are
// numbered row-major in that order, the last axis varying fastest:
//   index = ((iv * n_zeta + iz) * n_1 + i_1) * n_2 + i_2 ...
// (without scene axes: iv * n_zeta + iz, velocity-major), and results always come back in that
// order, whatever the thread count, the number of MPI ranks or the interruptions.
//
// Grids typed as LO:HI:N (linear_grid, log_grid) hold the values the user typed: see below.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv {

// One scene value varied over a sweep: `key` a key of scene/scene_values.h ("structure.thickness"),
// `values` in its unit. Every point of the sweep sets that key of the base scene to its value.
struct SceneAxis {
  std::string key;
  std::vector<double> values;
};

struct SweepRequest {
  SimulationRequest base;          // scene, law, integrator and options shared by every point
  std::vector<double> velocities;  // v0 [m/s]
  std::vector<double> zetas;       // damping ratios; 0 means no dashpot
  // Every point keeps the base scene's own dashpot (a [structure], lambda or c) instead of a
  // zeta of the grid: `zetas` must then be empty, the zeta axis has one value, and the zeta
  // column of a row is the point's derived zeta (nan without a yield strength).
  bool scene_dashpot = false;
  std::vector<SceneAxis> axes;  // scene values varied after v0 and zeta (at most kMaxSceneAxes)
  int threads = 0;              // 0: all hardware threads
  // run_sweep only: called from worker threads (serialised) after each point: (done, total).
  std::function<void(std::size_t, std::size_t)> progress;
  // run_sweep only: once true, no new point is started and run_sweep returns after the points
  // in flight; the points never started keep a default ImpactResult (the caller asked to stop
  // and knows it: the Python module's Ctrl-C).
  const std::atomic<bool>* stop = nullptr;
};

// The largest grid accepted: 1e8 points (a CSV of ~25 GB). Checked before anything is
// allocated, so a mistyped grid is bad input, not std::bad_alloc.
inline constexpr double kMaxSweepPoints = 1e8;
// Scene axes of one sweep at most: validate() checks every corner of the grid (2^axes points).
inline constexpr std::size_t kMaxSceneAxes = 8;

// The one validation of a sweep, called by every entry point before any work: the grid is
// non-empty, of at most kMaxSweepPoints points, v0 finite > 0, zeta finite >= 0, each scene
// axis a known key (scene/scene_values.h) given once, with finite values, and every point a
// valid SimulationRequest. A law that carries its own rate dependence (hunt-crossley) with a
// series dashpot (zeta > 0) is rejected naming --zeta, as `ivv simulate` rejects it. Throws
// InputError naming the flag: --v0, --zeta, or "--set KEY" for a scene axis.
//
// "Every point valid" without validating each of up to 1e8 points: each value of each axis is
// validated with the other axes at their first value (the range checks of single inputs), and
// each corner of the grid (every axis at its smallest or its largest value) is validated: the
// checks that involve several inputs at once (the derived parameters and scales representable in
// double, an impact point inside the plate) are monotone in each input, so their worst case
// over the grid's box lies on one of its corners.
void validate(const SweepRequest& request);

std::size_t point_count(const SweepRequest& request);
// Where point `index` lies on the grid: the indices of its velocity and of its zeta (0 when every
// point keeps the scene's dashpot) and the mixed-radix index of its scene axes' values (the last
// axis fastest: axis k's value index is (axes / (n_{k+1} n_{k+2} ...)) % n_k).
struct GridPosition {
  std::size_t velocity = 0, zeta = 0, axes = 0;
};
GridPosition grid_position(const SweepRequest& request, std::size_t index);
// The simulation request of point `index`.
SimulationRequest point_request(const SweepRequest& request, std::size_t index);
// Makes `r` point `index`'s request, the same as point_request(request, index), where `r` is
// request.base or was made a point of the same grid by an earlier call. Without scene axes
// points differ only in v0 and the dashpot, so only these are assigned: a worker keeps one
// request for all its points instead of copying the base request a point (the copy and its
// destruction were ~300 instructions of a map point). With scene axes the base is copied.
void assign_point_request(const SweepRequest& request, std::size_t index, SimulationRequest& r);

// The validated request of each point of a grid, with what its points share made once for the
// grid. On a v0 x zeta grid (no scene axes, the zetas of the grid, no finite plate) a point's
// derived parameters come from one VelocityDampingDerivation of the base scene (scene/scene.h)
// and v0^{1/5} kept per velocity, instead of derive() of the point's scene (its square roots and
// three powers were ~570 instructions of a point of the 300 x 300 map, callgrind); on any other
// grid each point's scene is derived (ValidatedRequest::grid_point). The same parameters either
// way, to the bit (sweep_test.cc). Refers to `request`, a grid validate() accepted, which must
// outlive it.
class SweepPointRequests {
 public:
  explicit SweepPointRequests(const SweepRequest& request);
  // derive(point.scene) for `point` = point `index`'s request (assign_point_request made it).
  DerivedParameters derived(std::size_t index, const SimulationRequest& point) const;
  // Point `index`'s validated request, referring to `point` (which must outlive it).
  ValidatedRequest validated(std::size_t index, const SimulationRequest& point) const;
  // Whether the grid's points share the base scene's derivation (a v0 x zeta grid, above).
  bool shares_derivation() const { return shared_.has_value(); }

 private:
  const SweepRequest* request_;
  std::optional<VelocityDampingDerivation> shared_;
  std::vector<double> velocity_factors_;  // zener_velocity_factor of each velocity
};

// The inputs of point `index` as its CSV row gives them: v0, zeta (the scene dashpot's derived
// zeta when request.scene_dashpot), then each scene axis's value.
struct PointInputs {
  double v0 = 0.0;
  double zeta = 0.0;
  std::vector<double> axes;  // in request.axes order
};
PointInputs point_inputs(const SweepRequest& request, std::size_t index);

// Grids of n points from lo to hi inclusive.
//
// linear_grid: the values a user means by typing LO:HI:N. The naive lo + i (hi - lo)/(n - 1)
// gives 0.30000000000000004 for the fourth point of 0:1:11 and 1.0000000000000002-like ends, so
// that a CSV reader's `v0 == 0.3` finds nothing. Instead, in exact decimal arithmetic:
//   lo and hi are read as the shortest decimals that round-trip to them (std::to_chars):
//     lo = L 10^s, hi = H 10^s with integers L, H on their common scale s;
//   the step (H - L)/(n - 1) 10^s is a finite decimal when n - 1 divides (H - L) 10^j for some
//     j >= 0: take the smallest such j (the step's decimal precision: 10^(s - j));
//   point i is then the decimal (L 10^j + i (H - L) 10^j/(n - 1)) 10^(s - j), converted to the
//     double nearest to it (std::from_chars), exactly as if the user had typed it.
// So 0.1:1:10 gives 0.1, 0.2, ..., 1 and 0:1:5 gives 0, 0.25, 0.5, 0.75, 1: each the double
// nearest to its decimal, within a few ulps of the naive value. Where the step has no finite
// decimal (0:1:4, steps of 1/3; 0.05:20:100), or the integers would pass 10^18 (endpoints many
// decades apart, or too many digits), the naive formula is kept, with lo and hi exact.
std::vector<double> linear_grid(double lo, double hi, int n);
// log_grid: exp(log lo + i (log hi - log lo)/(n - 1)), with both endpoints exactly lo and hi
// (exp(log lo) may differ from lo by an ulp). Interior points have no decimal form to keep.
std::vector<double> log_grid(double lo, double hi, int n);

}  // namespace ivv
