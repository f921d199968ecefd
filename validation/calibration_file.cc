#include "validation/calibration_file.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "scene/input_error.h"
#include "scene/scene_json.h"
#include "validation/parameters.h"

namespace ivv::validation {
namespace {

using nlohmann::json;

json optional_number(const std::optional<double>& v) {
  return v ? json(*v) : json(nullptr);
}
json number_or_null(double v) {
  return std::isfinite(v) ? json(v) : json(nullptr);
}

json fit_json(const ParameterEstimate& p) {
  json j = {{"name", p.name},
            {"unit", p.unit},
            {"start", p.start},
            {"value", number_or_null(p.value)},
            {"standard_error", number_or_null(p.standard_error)},
            {"lower95", number_or_null(p.lower95)},
            {"upper95", number_or_null(p.upper95)},
            {"identifiable", p.identifiable},
            {"at_bound", p.at_bound},
            {"lower_bound", p.lower_bound},
            {"upper_bound", number_or_null(p.upper_bound)},
            {"profile95", nullptr},
            {"profile_differs", p.profile_differs}};
  if (p.profile95)
    j["profile95"] = {number_or_null(p.profile95->first), number_or_null(p.profile95->second)};
  return j;
}

// A field of the calibration file, or InputError naming it.
const json& field(const json& j, const std::string& name, const std::string& where) {
  if (!j.is_object() || !j.contains(name))
    throw InputError("--calibration", where + ": missing field '" + name + "'");
  return j.at(name);
}
double number(const json& j, const std::string& name, const std::string& where) {
  const json& v = field(j, name, where);
  if (!v.is_number())
    throw InputError("--calibration", where + ": field '" + name + "' must be a number");
  return v.get<double>();
}
std::optional<double> optional(const json& j, const std::string& name, const std::string& where) {
  const json& v = field(j, name, where);
  if (v.is_null()) return std::nullopt;
  return number(j, name, where);
}

}  // namespace

json calibration_json(const CalibrationProblem& problem, const CalibrationResult& r) {
  const CalibratedModel m = calibrated_model(problem, r);
  json j = {{"format", "ivv-calibration-1"},
            {"scene", scene_json(m.request.scene)},
            {"law", r.law},
            {"law_kind", std::string(to_string(m.request.law))},
            {"expression",
             {{"force", m.request.expression.force},
              {"unload", m.request.expression.unload},
              {"allow_tension", m.request.expression.allow_tension}}},
            {"parameters", json::object()},
            {"fit", json::array()},
            {"covariance", r.covariance},
            {"correlation", json::array()},
            {"chi2", r.chi2},
            {"dof", r.dof},
            {"points", r.points},
            {"p_value", optional_number(r.p_value)},
            {"sigma", json::object()},
            {"rtol", r.rtol},
            {"stated_error", r.stated_error},
            {"unidentifiable", r.unidentifiable},
            {"estimated_noise", r.estimated_noise},
            {"residuals", json::array()},
            {"data", {{"source", problem.data.source}, {"provenance", problem.data.provenance}}},
            {"solver_report", r.solver_report},
            {"notes", r.notes},
            {"determined", r.determined}};
  for (const auto& [name, value] : m.request.parameters) j["parameters"][name] = value;
  for (const auto& p : r.parameters) j["fit"].push_back(fit_json(p));
  for (const auto& row : r.correlation) {
    json jr = json::array();
    for (double v : row) jr.push_back(number_or_null(v));
    j["correlation"].push_back(jr);
  }
  for (Quantity q : kQuantities)
    j["sigma"][std::string(to_string(q))] = optional_number(r.sigma[static_cast<std::size_t>(q)]);
  for (const auto& x : r.residuals)
    j["residuals"].push_back({{"v0", x.v0},
                              {"quantity", std::string(to_string(x.quantity))},
                              {"measured", x.measured},
                              {"model", x.model},
                              {"uncertainty", x.uncertainty},
                              {"normalised", x.normalised},
                              {"line", x.line}});
  return j;
}

CalibratedModel calibrated_model(const CalibrationProblem& problem, const CalibrationResult& r) {
  CalibratedModel m;
  m.request = problem.request;
  m.law = r.law;
  m.covariance = r.covariance;
  m.sigma = r.sigma;
  for (const auto& p : r.parameters) {
    m.names.push_back(p.name);
    m.values.push_back(p.identifiable ? p.value : p.start);
    m.identifiable.push_back(p.identifiable);
    set_parameter(m.request, p.name, m.values.back());
  }
  return m;
}

namespace {

// A hand-edited calibration file is bad input where its covariance is not one. Tolerances:
// the writer's matrix is symmetric and positive semi-definite to round-off (~1e-15 relative
// of sqrt(C_ii C_jj) for the SVD pseudo-inverse, written with 17 digits); 1e-9 of that scale
// leaves six orders of magnitude for round-off and catches any edit that moves a band.
constexpr double kCovarianceRoundOff = 1e-9;

std::string number_text(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

[[noreturn]] void bad(const std::string& where, const std::string& message) {
  throw InputError("--calibration", where + ": " + message);
}

void check_shape(const CalibratedModel& m, const std::string& where) {
  const std::size_t p = m.names.size();
  if (p == 0) bad(where, "fit has no entries");
  if (m.covariance.size() != p)
    bad(where, "covariance must be " + std::to_string(p) + " x " + std::to_string(p) +
                   " (one row per fit entry)");
  for (const auto& row : m.covariance)
    if (row.size() != p) bad(where, "covariance rows must have " + std::to_string(p) + " entries");
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (m.names[k] == m.names[i])
        bad(where, "fit[" + std::to_string(i) + "] names '" + m.names[i] + "' again (fit[" +
                       std::to_string(k) + "]): one entry per parameter");
}

// Variances >= 0 (> 0 when identifiable), zero rows for unidentifiable entries, symmetry,
// |correlation| <= 1 and positive semi-definiteness, each named by entry.
void check_covariance(const CalibratedModel& m, const std::string& where) {
  const std::size_t p = m.names.size();
  const auto& C = m.covariance;
  auto entry = [&](std::size_t i, std::size_t k) {
    return "covariance[" + std::to_string(i) + "][" + std::to_string(k) + "] (" + m.names[i] +
           ", " + m.names[k] + ")";
  };
  for (std::size_t i = 0; i < p; ++i) {
    if (!m.identifiable[i]) {
      for (std::size_t k = 0; k < p; ++k)
        if (C[i][k] != 0 || C[k][i] != 0)
          bad(where, entry(i, k) + " is not 0, but fit[" + std::to_string(i) +
                         "] is marked identifiable: false (held at its start, not drawn)");
    } else if (!(C[i][i] > 0)) {
      bad(where, entry(i, i) + " = " + number_text(C[i][i]) +
                     ": the variance of an identifiable parameter must be > 0");
    }
  }
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t k = 0; k < i; ++k) {
      const double scale = std::sqrt(C[i][i] * C[k][k]);
      if (std::abs(C[i][k] - C[k][i]) > kCovarianceRoundOff * scale)
        bad(where, entry(i, k) + " differs from " + entry(k, i) + ": a covariance is symmetric");
      if (scale > 0 && std::abs(C[i][k]) > (1 + kCovarianceRoundOff) * scale)
        bad(where, entry(i, k) + " gives a correlation of " + number_text(C[i][k] / scale) +
                       ": must lie in [-1, 1]");
    }
  Eigen::MatrixXd R =
      Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(p), static_cast<Eigen::Index>(p));
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t k = 0; k < p; ++k)
      if (m.identifiable[i] && m.identifiable[k])
        R(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)) =
            C[i][k] / std::sqrt(C[i][i] * C[k][k]);
  const double lowest = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(R).eigenvalues().minCoeff();
  if (lowest < -kCovarianceRoundOff)
    bad(where,
        "covariance is not positive semi-definite (its correlation matrix has the "
        "eigenvalue " +
            number_text(lowest) + "): no distribution has it");
}

// A request's InputError in the file's words: the command-line flags a request's checks name
// (--force, --unload, --param NAME) are fields of the file here.
std::string file_field(const InputError& x) {
  const std::string& f = x.field();
  std::string what = x.what();
  std::string field = f;
  if (f == "--force" || f == "--unload")
    field = "expression." + f.substr(2);
  else if (f.rfind("--param ", 0) == 0)
    field = "parameters." + f.substr(8);
  if (field != f && what.rfind(f, 0) == 0) what = field + what.substr(f.size());
  return what;
}

// The law of the file: a built-in law by name, or the expression law.
void read_law(const json& j, const std::string& where, CalibratedModel& m) {
  const std::string kind = field(j, "law_kind", where).get<std::string>();
  const json& e = field(j, "expression", where);
  m.request.expression.force = field(e, "force", where + ".expression").get<std::string>();
  m.request.expression.unload = field(e, "unload", where + ".expression").get<std::string>();
  m.request.expression.allow_tension = field(e, "allow_tension", where + ".expression").get<bool>();
  if (kind == "expression") {
    m.request.law = LawKind::expression;
    m.law = m.request.expression.force;  // as calibrate prints it
  } else {
    try {
      m.request.law = parse_law(kind, "law_kind");
    } catch (const InputError& x) {
      bad(where, x.what());
    }
    m.request.expression = {};
    m.law = kind;  // law_kind decides; "law" is a label an edit may leave behind
  }
  for (const auto& [name, value] : field(j, "parameters", where).items())
    m.request.parameters[name] = value.get<double>();
}

void read_fit(const json& j, const std::string& where, CalibratedModel& m) {
  const json& fit = field(j, "fit", where);
  if (!fit.is_array()) bad(where, "fit must be an array");
  for (std::size_t i = 0; i < fit.size(); ++i) {
    const std::string at = where + ".fit[" + std::to_string(i) + "]";
    m.names.push_back(field(fit[i], "name", at).get<std::string>());
    m.identifiable.push_back(field(fit[i], "identifiable", at).get<bool>());
    m.values.push_back(m.identifiable.back() ? number(fit[i], "value", at)
                                             : number(fit[i], "start", at));
  }
  m.covariance = field(j, "covariance", where).get<std::vector<std::vector<double>>>();
  const json& sigma = field(j, "sigma", where);
  for (Quantity q : kQuantities)
    m.sigma[static_cast<std::size_t>(q)] = optional(sigma, std::string(to_string(q)), where);
}

}  // namespace

CalibratedModel read_calibration(const json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("format") || j["format"] != "ivv-calibration-1")
    bad(where,
        "not an ivv calibration file (format \"ivv-calibration-1\", written by ivv "
        "calibrate --json)");
  CalibratedModel m;
  try {
    m.request.scene = scene_from_json(field(j, "scene", where), "");
  } catch (const InputError& x) {
    if (x.field() == "--calibration") throw;
    bad(where, std::string("scene.") + x.what());  // the scene's own field, not a flag
  }
  try {
    read_law(j, where, m);
    read_fit(j, where, m);
  } catch (const json::exception& x) {
    bad(where, std::string("a field has the wrong type (") + x.what() + ")");
  }
  check_shape(m, where);
  check_covariance(m, where);
  try {
    const auto fittable = fittable_parameters(m.request);
    for (std::size_t i = 0; i < m.names.size(); ++i) {
      if (std::find(fittable.begin(), fittable.end(), m.names[i]) == fittable.end())
        bad(where, "fit[" + std::to_string(i) + "] names '" + m.names[i] +
                       "', not a parameter of this scene and law");
      set_parameter(m.request, m.names[i], m.values[i]);
    }
    m.request.auto_integrator = true;
    m.request.model = ModelKind::automatic;
    validate(m.request);
  } catch (const InputError& x) {
    if (x.field() == "--calibration") throw;
    bad(where, "with the fitted values applied, " + file_field(x));
  }
  return m;
}

CalibratedModel read_calibration_file(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("--calibration", "cannot read " + path.string());
  json j;
  try {
    in >> j;
  } catch (const json::exception& x) {
    throw InputError("--calibration", path.string() + " is not valid JSON: " + x.what());
  }
  return read_calibration(j, path.string());
}

}  // namespace ivv::validation
