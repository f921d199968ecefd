// The rows of a sweep's CSV: one line a point, in grid order (solver/sweep/sweep_grid.h).
//
// Columns: v0, zeta, one column per scene axis (named by its key, e.g. structure.thickness),
// then e, e_poisson, e_energetic, F_max, t_F_max, t_contact, z_max, alpha_max, z_perm,
// energy_residual, steps, route, integrator, status, reason; sweep_csv_columns() gives each
// with its unit. The inputs (v0, zeta, the axes) are in shortest round-trip form
// (std::to_chars: 0.1, not 0.10000000000000001; each reads back as the same double, so a row can
// be re-run exactly with `ivv simulate --v0 V --zeta Z`), results at 12 significant digits.
// route and integrator say what produced the row (ImpactResult::route, ::integrator): with
// --model auto and --integrator auto they differ from point to point. A failed row leaves
// every result column empty (never a plausible 0), keeps steps and gives the reason (quoted,
// RFC 4180).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "solver/result.h"
#include "solver/sweep/sweep_grid.h"

namespace ivv {

struct SweepColumn {
  std::string name;
  std::string unit;  // SI unit; "-" for a dimensionless number or a count; "" for a text column
};

// The columns of the CSV of a sweep over `axes` (none: the v0 x zeta grid), in order.
std::vector<SweepColumn> sweep_csv_columns(const std::vector<SceneAxis>& axes = {});
// "v0,zeta,...,reason\n"
std::string sweep_csv_header(const std::vector<SceneAxis>& axes = {});
// "v0 [m/s], zeta [-], ..., reason": the columns with their units, for --help and messages.
std::string sweep_csv_columns_text(const std::vector<SceneAxis>& axes = {});

// "v0,zeta,axis values,": the start of a point's row (a journal row read back must begin so).
std::string sweep_csv_inputs(const PointInputs& inputs);

// The input columns of every point of a grid, formatted once for the whole sweep: a point's are
// then copied, not formatted again (the two shortest round-trip numbers of a v0 x zeta row were
// ~1,100 of its ~5,800 instructions, callgrind on the 300 x 300 map). The same bytes as
// sweep_csv_inputs(point_inputs(request, index)); a sweep that keeps the scene's dashpot derives
// each point's zeta, so that column is formatted point by point. Refers to `request`, which must
// outlive it.
class SweepInputColumns {
 public:
  explicit SweepInputColumns(const SweepRequest& request);
  // Appends point `index`'s "v0,zeta,axis values," to `row`.
  void append(std::string& row, std::size_t index) const;

 private:
  // A value's text and its comma in a fixed slot (the shortest form of a double is at most 24
  // characters), copied whole: one append of a row's v0 and zeta instead of two (a string's
  // append of a few bytes was ~45 instructions, its memcpy a call; callgrind).
  struct Text {
    std::array<char, 32> chars;
    std::size_t size = 0;
  };
  static Text text(double x);

  const SweepRequest* request_;
  // per velocity, per zeta (none with the scene's dashpot), per value of each scene axis
  std::vector<Text> velocities_, zetas_;
  std::vector<std::vector<std::string>> axes_;
};

// Where the counts of a sweep (SweepCounts) find their facts in a row: the route and integrator
// names as offsets from the row's first character, and the status.
struct SweepRowFacts {
  std::size_t route = 0, route_size = 0, integrator = 0, integrator_size = 0;
  ImpactStatus status = ImpactStatus::failed;
};

// The result columns of a row, "e,...,reason\n", appended to `row`, whose row began at
// `row_start`: returns the row's facts (their offsets from `row_start`), known as it is written.
SweepRowFacts append_sweep_csv_results(std::string& row, std::size_t row_start,
                                       const ImpactResult& result);
// The row of a point (numbers by std::to_chars, solver/format.h), appended to `row`: no
// allocation once its capacity suffices.
void append_sweep_csv_row(std::string& row, const PointInputs& inputs, const ImpactResult& result);
std::string sweep_csv_row(const PointInputs& inputs, const ImpactResult& result);
// The same for a point of a v0 x zeta grid without scene axes.
std::string sweep_csv_row(double v0, double zeta, const ImpactResult& result);

// The index of column `name` in the CSV of a sweep with `axis_count` scene axes.
int sweep_csv_column_index(std::string_view name, std::size_t axis_count);

}  // namespace ivv
