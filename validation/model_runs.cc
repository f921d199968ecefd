#include "validation/model_runs.h"

#include <algorithm>

#include "solver/choice/model_choice.h"
#include "solver/parallel.h"
#include "validation/parameters.h"

namespace ivv::validation {

double calibration_rtol(double smallest_uncertainty) {
  return std::clamp(kIntegrationShare * smallest_uncertainty / kStatedErrorFactor, kTightestRtol,
                    1e-8);
}

std::vector<ModelPoint> run_model_points(const SimulationRequest& base,
                                         const std::vector<std::string>& names,
                                         std::span<const double> values,
                                         std::span<const double> velocities, int threads) {
  if (velocities.empty()) return {};
  SimulationRequest request = base;
  for (std::size_t i = 0; i < names.size(); ++i) set_parameter(request, names[i], values[i]);
  request.model = ModelKind::automatic;
  std::vector<SimulationRequest> points(velocities.size(), request);
  for (std::size_t i = 0; i < velocities.size(); ++i) points[i].scene.velocity = velocities[i];
  std::vector<ModelPoint> out(velocities.size());
  // One validation up front, so bad parameters are one InputError rather than an error per
  // worker (the velocities were checked when the data was read).
  validate(points.front());
  parallel_for(velocities.size(), threads, [&](std::size_t i) {
    const ValidatedRequest v(points[i]);
    const ModelDecision d = decide_model(v, RunOutput::result);
    out[i].result = run_model(v, d, nullptr);
    out[i].estimated_error = d.estimated_error;
  });
  return out;
}

}  // namespace ivv::validation
