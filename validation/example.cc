#include "validation/example.h"

#include "scene/data_dir.h"
#include "scene/input_error.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"
#include "validation/synthetic.h"

namespace ivv::validation {
namespace {

std::filesystem::path shipped(const std::string& name) {
  for (const auto& dir : data_directories())
    if (std::filesystem::exists(dir / name)) return dir / name;
  throw InputError(name, "not found in the data directories (reference_data/, $IVV_DATA_DIR)");
}

CalibrationOptions fitting(std::vector<std::string> names, bool scan) {
  CalibrationOptions o;
  o.fit = std::move(names);
  o.scan = scan;
  return o;
}

// The other laws of the comparison, each with its own fitted parameters.
void rank(ShippedExample& x, const std::vector<double>& speeds) {
  SimulationRequest hertz = x.problem.request;
  hertz.law = LawKind::hertz;
  SimulationRequest hc = x.problem.request;
  hc.scene.damping = Damping::none();
  hc.law = LawKind::hunt_crossley;
  hc.parameters["mu"] = 0.1;
  const CalibrationProblem problems[] = {x.problem, {hertz, x.problem.data}, {hc, x.problem.data}};
  std::vector<CalibrationResult> fits{x.fit, calibrate(problems[1], fitting({"c"}, true)),
                                      calibrate(problems[2], fitting({"mu"}, true))};
  x.ranking = compare({"elastoplastic", "hertz + dashpot", "hunt-crossley"}, fits);
  for (const auto& m : x.ranking.models) {
    const std::size_t i = m.name == "elastoplastic" ? 0 : m.name == "hertz + dashpot" ? 1 : 2;
    std::vector<double> e;
    if (m.fit.ok) {
      const CalibratedModel cm = calibrated_model(problems[i], m.fit);
      for (const auto& p : run_model_points(cm.request, {}, {}, speeds, 0))
        e.push_back(p.result.ok() ? p.result.e : std::numeric_limits<double>::quiet_NaN());
    }
    x.ranking_curves.push_back(e);
  }
}

}  // namespace

const ShippedExample& shipped_example() {
  static const ShippedExample example = [] {
    ShippedExample x;
    x.problem.request.scene = load_scene("paper-damped");
    x.problem.request.auto_integrator = true;
    set_parameter(x.problem.request, "c", kExampleStartC);
    set_parameter(x.problem.request, "yield_strength", kExampleStartYield);
    x.problem.data = read_measured_data(shipped("calibration_example.csv"));
    x.fit = calibrate(x.problem, fitting({"c", "yield_strength"}, false));
    const auto speeds = log_velocities(0.3, 5.0, kExampleBandSpeeds);
    PredictionOptions o;
    o.samples = kExampleSamples;
    if (x.fit.ok) {
      const CalibratedModel m = calibrated_model(x.problem, x.fit);
      x.band = predict(m, speeds, o);
      x.holdout = read_measured_data(shipped("calibration_example_holdout.csv"));
      x.validation = compare_with_data(m, x.holdout, o);
    }
    rank(x, speeds);
    return x;
  }();
  return example;
}

}  // namespace ivv::validation
