// The calibration file (`ivv calibrate --json`, read by `ivv predict --calibration`): the
// fitted model in full, so a prediction needs nothing else.
//
// JSON object, format "ivv-calibration-1":
//   scene       the scene in its one JSON form (scene/scene_json.h: every input, any dashpot
//               kind or [structure], and the derived values), with the fitted values applied
//   law         the law as calibrate printed it (the expression for a typed law); law_kind
//               the law's name ("expression" for a typed law: it decides, an edited law is
//               read as law_kind says), expression {force, unload, allow_tension},
//               parameters {NAME: value} (--param, fitted values applied)
//   fit         [{name, unit, start, value, standard_error, lower95, upper95, identifiable,
//               at_bound, lower_bound, upper_bound, profile95 (or null)}] (value null when
//               unidentifiable: the model file then carries the start value)
//   covariance  p x p [unit_i unit_j] (zero rows for unidentifiable parameters)
//   correlation p x p
//   chi2, dof, p_value (null when the noise was estimated), sigma {e, F_max, t_contact} (the
//   estimated sigmas, null when stated), rtol, stated_error, unidentifiable [sentences],
//   residuals [{v0, quantity, measured, model, uncertainty, normalised, line}],
//   data {source, provenance [lines]}, solver_report, notes [how the fit got there: a restart
//   from the scan, a dashpot started from a scan, the profile intervals' cost], determined (the
//   directions the data determine: the k of --compare)
// Reading checks the format tag and every field it needs: InputError("--calibration", ...)
// naming the field otherwise. A hand-edited file is bad input, naming the entry, when its
// covariance is not one: a negative variance (or a zero one for an identifiable parameter),
// an asymmetric matrix, |correlation| > 1, a matrix that is not positive semi-definite, a
// non-zero row for an entry marked identifiable: false, or a parameter named twice or not
// a parameter of the file's scene and law.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "validation/calibration.h"

namespace ivv::validation {

nlohmann::json calibration_json(const CalibrationProblem& problem, const CalibrationResult& result);

// A fitted model as prediction needs it.
struct CalibratedModel {
  SimulationRequest request;  // fitted values applied (unidentifiable ones at their start)
  std::vector<std::string> names;
  std::vector<double> values;
  std::vector<bool> identifiable;
  std::vector<std::vector<double>> covariance;
  std::array<std::optional<double>, 3> sigma;  // estimated noise per quantity, if any
  std::string law;
};

CalibratedModel calibrated_model(const CalibrationProblem& problem,
                                 const CalibrationResult& result);
CalibratedModel read_calibration(const nlohmann::json& j, const std::string& source);
CalibratedModel read_calibration_file(const std::filesystem::path& path);

}  // namespace ivv::validation
