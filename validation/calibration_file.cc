#include "validation/calibration_file.h"

#include <fstream>

#include "scene/input_error.h"
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

json scene_json(const Scene& s) {
  const char* kinds[] = {"none", "ratio", "coefficient"};
  return {
      {"name", s.name},
      {"mass", s.mass},
      {"radius", s.radius},
      {"impactor_youngs_modulus", s.impactor_youngs_modulus},
      {"impactor_poisson_ratio", s.impactor_poisson_ratio},
      {"target_youngs_modulus", number_or_null(s.target_youngs_modulus)},
      {"target_poisson_ratio", s.target_poisson_ratio},
      {"yield_strength", optional_number(s.yield_strength)},
      {"target_radius", optional_number(s.target_radius)},
      {"target_mass", optional_number(s.target_mass)},
      {"velocity", s.velocity},
      {"damping", {{"kind", kinds[static_cast<int>(s.damping.kind)]}, {"value", s.damping.value}}}};
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

Scene read_scene(const json& j, const std::string& where) {
  Scene s;
  s.name = field(j, "name", where).get<std::string>();
  s.mass = number(j, "mass", where);
  s.radius = number(j, "radius", where);
  s.impactor_youngs_modulus = number(j, "impactor_youngs_modulus", where);
  s.impactor_poisson_ratio = number(j, "impactor_poisson_ratio", where);
  s.target_youngs_modulus =
      optional(j, "target_youngs_modulus", where).value_or(std::numeric_limits<double>::infinity());
  s.target_poisson_ratio = number(j, "target_poisson_ratio", where);
  s.yield_strength = optional(j, "yield_strength", where);
  s.target_radius = optional(j, "target_radius", where);
  s.target_mass = optional(j, "target_mass", where);
  s.velocity = number(j, "velocity", where);
  const json& d = field(j, "damping", where);
  const std::string kind = field(d, "kind", where + ".damping").get<std::string>();
  const double value = number(d, "value", where + ".damping");
  if (kind == "ratio")
    s.damping = Damping::ratio(value);
  else if (kind == "coefficient")
    s.damping = Damping::coefficient(value);
  else if (kind != "none")
    throw InputError("--calibration", where + ".damping.kind must be none, ratio or coefficient");
  validate(s);
  return s;
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
            {"solver_report", r.solver_report}};
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

CalibratedModel read_calibration(const json& j, const std::string& where) {
  if (!j.is_object() || !j.contains("format") || j["format"] != "ivv-calibration-1")
    throw InputError("--calibration",
                     where +
                         ": not an ivv calibration file (format "
                         "\"ivv-calibration-1\", written by ivv calibrate --json)");
  CalibratedModel m;
  try {
    m.request.scene = read_scene(field(j, "scene", where), where + ".scene");
    m.request.law = parse_law(field(j, "law_kind", where).get<std::string>(), where + ".law_kind");
    m.law = field(j, "law", where).get<std::string>();
    const json& e = field(j, "expression", where);
    m.request.expression.force = field(e, "force", where).get<std::string>();
    m.request.expression.unload = field(e, "unload", where).get<std::string>();
    m.request.expression.allow_tension = field(e, "allow_tension", where).get<bool>();
    for (const auto& [name, value] : field(j, "parameters", where).items())
      m.request.parameters[name] = value.get<double>();
    for (const auto& p : field(j, "fit", where)) {
      m.names.push_back(field(p, "name", where + ".fit").get<std::string>());
      m.identifiable.push_back(field(p, "identifiable", where + ".fit").get<bool>());
      m.values.push_back(m.identifiable.back() ? number(p, "value", where + ".fit")
                                               : number(p, "start", where + ".fit"));
    }
    m.covariance = field(j, "covariance", where).get<std::vector<std::vector<double>>>();
    const json& sigma = field(j, "sigma", where);
    for (Quantity q : kQuantities)
      m.sigma[static_cast<std::size_t>(q)] = optional(sigma, std::string(to_string(q)), where);
  } catch (const json::exception& x) {
    throw InputError("--calibration", where + ": a field has the wrong type (" + x.what() + ")");
  }
  const std::size_t p = m.names.size();
  if (p == 0 || m.covariance.size() != p)
    throw InputError("--calibration", where + ": covariance must be " + std::to_string(p) + " x " +
                                          std::to_string(p) + " (one row per fit entry)");
  for (const auto& row : m.covariance)
    if (row.size() != p)
      throw InputError("--calibration",
                       where + ": covariance rows must have " + std::to_string(p) + " entries");
  for (std::size_t i = 0; i < p; ++i) set_parameter(m.request, m.names[i], m.values[i]);
  m.request.auto_integrator = true;
  m.request.model = ModelKind::automatic;
  validate(m.request);
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
