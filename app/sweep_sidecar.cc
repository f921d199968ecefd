#include "app/sweep_sidecar.h"

#include "reports/impact_json.h"

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
}  // namespace

nlohmann::json sweep_inputs_json(const SweepRequest& req, const GridSpec& v0,
                                 const GridSpec& zeta) {
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
       {{"order", "velocity-major: row = 1 + iv * zeta.count + iz"},
        {"points", point_count(req)},
        {"v0", grid_json(req.velocities, v0)},
        {"zeta", grid_json(req.zetas, zeta)},
        // true: no zeta grid, every point keeps the scene's own dashpot ([structure], lambda
        // or c); the zeta column is each point's derived zeta
        {"scene_dashpot", req.scene_dashpot}}},
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
