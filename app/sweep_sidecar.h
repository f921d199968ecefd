// The JSON sidecar beside every sweep CSV (grid.csv -> grid.json): what makes the CSV
// reproducible (scene, law, integrator, tolerances, the grid, ivv's version and commit) and
// the per-status counts of its rows, and the unit of every column of the CSV:
//   columns: {name: unit}   (SI; "-" dimensionless or a count; "" a text column)
//   grid: {order, points, v0, zeta, scene_dashpot, axes: [{key, unit, spec, log, count, values}]}
// A sweep to standard output (--out -) has no sidecar.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "solver/sweep/sweep.h"

namespace ivv {

struct GridSpec {
  std::string text;  // as typed (--v0 / --zeta / the RANGE of --set KEY=RANGE)
  bool log = false;
};

// Everything but the counts: also the description a resumed sweep must match. `axes` are the
// specs of req.axes, in order.
nlohmann::json sweep_inputs_json(const SweepRequest& req, const GridSpec& v0, const GridSpec& zeta,
                                 const std::vector<GridSpec>& axes = {});
// The whole sidecar.
nlohmann::json sweep_sidecar_json(const nlohmann::json& inputs, const SweepCounts& counts,
                                  const std::filesystem::path& csv, const std::string& command);
// grid.csv -> grid.json (any other name: NAME.json).
std::filesystem::path sidecar_path(const std::filesystem::path& csv);

// The project version (CMake) and the git commit at configure time ("unknown" outside git).
std::string ivv_version();
std::string ivv_commit();

}  // namespace ivv
