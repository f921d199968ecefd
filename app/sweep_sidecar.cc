#include "app/sweep_sidecar.h"

#include "reports/impact_json.h"
#include "scene/scene_values.h"

namespace ivv {

std::string ivv_version() {
  return IVV_VERSION;
}
std::string ivv_commit() {
  return IVV_GIT_COMMIT;
}

namespace {
// The values themselves for grids of reasonable size; a LO:HI:N spec reproduces any grid.
constexpr std::size_t kListedValues = 10000;

nlohmann::json grid_json(const std::vector<double>& values, const GridSpec& spec) {
  nlohmann::json j = {{"spec", spec.text}, {"log", spec.log}, {"count", values.size()}};
  if (values.size() <= kListedValues) j["values"] = values;
  return j;
}

// The scene axes: each key with its unit, its spec as typed and its values.
nlohmann::json axes_json(const SweepRequest& req, const std::vector<GridSpec>& specs) {
  nlohmann::json axes = nlohmann::json::array();
  for (std::size_t k = 0; k < req.axes.size(); ++k) {
    const SceneValueInfo* info = find_scene_value(req.axes[k].key);
    nlohmann::json axis = grid_json(req.axes[k].values, k < specs.size() ? specs[k] : GridSpec{});
    axis["key"] = req.axes[k].key;
    axis["unit"] = info ? std::string(info->unit) : std::string();
    axes.push_back(std::move(axis));
  }
  return axes;
}

nlohmann::json columns_json(const SweepRequest& req) {
  nlohmann::json columns = nlohmann::json::object();
  for (const SweepColumn& c : sweep_csv_columns(req.axes)) columns[c.name] = c.unit;
  return columns;
}

}  // namespace

nlohmann::json sweep_inputs_json(const SweepRequest& req, const GridSpec& v0, const GridSpec& zeta,
                                 const std::vector<GridSpec>& axes) {
  const SimulationRequest& b = req.base;
  nlohmann::json tol = {{"rtol", b.options.rtol},
                        {"atol", b.options.atol},
                        {"max_steps", b.options.max_steps},
                        {"capture_cor", b.options.capture_cor}};
  if (traits(b.integrator).fixed_step) tol["dt"] = b.options.fixed_dt();
  nlohmann::json j = {
      {"scene", scene_json(b.scene, derive(b.scene))},
      {"law", to_string(b.law)},
      {"integrator",
       b.auto_integrator ? std::string("auto") : std::string(to_string(b.integrator))},
      {"model", to_string(b.model)},
      {"tolerances", tol},
      {"grid",
       {{"order",
         "row-major over v0, zeta, then each axis in order (the last fastest): row = 1 + "
         "((iv * zeta.count + iz) * axes[0].count + i0) * axes[1].count + i1 ..."},
        {"points", point_count(req)},
        {"v0", grid_json(req.velocities, v0)},
        {"zeta", grid_json(req.zetas, zeta)},
        // true: no zeta grid, every point keeps the scene's own dashpot ([structure], lambda
        // or c); the zeta column is each point's derived zeta
        {"scene_dashpot", req.scene_dashpot},
        {"axes", axes_json(req, axes)}}},
      {"columns", columns_json(req)},
  };
  j["law_details"] = law_json(b);
  return j;
}

nlohmann::json sweep_sidecar_json(const nlohmann::json& inputs, const SweepCounts& counts,
                                  const std::filesystem::path& csv, const std::string& command) {
  nlohmann::json j = inputs;
  j["csv"] = csv.filename().string();
  j["ivv"] = {{"version", ivv_version()}, {"commit", ivv_commit()}};
  j["command"] = command;
  j["counts"] = {{"separated", counts.separated},
                 {"captured", counts.captured},
                 {"failed", counts.failed},
                 {"routes", counts.routes},
                 {"integrators", counts.integrators}};
  return j;
}

std::filesystem::path sidecar_path(const std::filesystem::path& csv) {
  std::filesystem::path p = csv;
  return p.extension() == ".csv" ? p.replace_extension(".json") : p += ".json";
}

}  // namespace ivv
