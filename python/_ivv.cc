// ivv._ivv: the compiled half of the Python module `ivv` (python/ivv/__init__.py is the other).
// Every number it returns is computed by the libraries the command line uses, and every JSON
// it returns is built by the same library function as the CLI's --json (reports/impact_json.h,
// verification/conformance.h), converted to Python objects as it is: no field is listed twice.
// The C++ work runs with the GIL released; a sweep checks for Ctrl-C while it runs.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <future>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "oracles/expression_functions.h"
#include "reports/impact_json.h"
#include "scene/data_dir.h"
#include "scene/input_error.h"
#include "scene/scene_values.h"
#include "solver/plate/plate_run.h"
#include "solver/request_options.h"
#include "solver/sweep/sweep.h"
#include "validation/calibration.h"
#include "validation/calibration_file.h"
#include "validation/measured_data.h"
#include "validation/parameters.h"
#include "validation/prediction.h"
#include "verification/check_law_request.h"
#include "verification/conformance.h"

namespace py = pybind11;

namespace ivv::python {
namespace {

// ---- JSON -> Python ----------------------------------------------------------------------

// A JSON value as the Python object json.loads would give, except that numbers keep what the
// library computed: a NaN or an infinity (null in the CLI's JSON) stays a float.
py::object to_python(const nlohmann::json& j) {
  switch (j.type()) {
    case nlohmann::json::value_t::null:
      return py::none();
    case nlohmann::json::value_t::boolean:
      return py::bool_(j.get<bool>());
    case nlohmann::json::value_t::number_integer:
      return py::int_(j.get<long long>());
    case nlohmann::json::value_t::number_unsigned:
      return py::int_(j.get<unsigned long long>());
    case nlohmann::json::value_t::number_float:
      return py::float_(j.get<double>());
    case nlohmann::json::value_t::string:
      return py::str(j.get_ref<const std::string&>());
    case nlohmann::json::value_t::array: {
      py::list list;
      for (const auto& item : j) list.append(to_python(item));
      return list;
    }
    case nlohmann::json::value_t::object: {
      py::dict dict;
      for (const auto& [key, value] : j.items()) dict[py::str(key)] = to_python(value);
      return dict;
    }
    default:
      return py::none();  // binary and discarded values never occur in ivv's JSON
  }
}

// ---- keyword arguments -------------------------------------------------------------------

// The value of `key` in `d`, or nothing when it is absent or None.
template <class T>
std::optional<T> get(const py::dict& d, const char* key) {
  if (!d.contains(key) || d[key].is_none()) return std::nullopt;
  return d[key].cast<T>();
}

// Raises TypeError for a keyword that is not one of `known` (what Python does for a function).
void reject_unknown(const py::dict& d, const std::vector<std::string>& known, const char* what) {
  for (const auto& item : d) {
    const auto key = item.first.cast<std::string>();
    if (std::find(known.begin(), known.end(), key) == known.end())
      throw py::type_error(std::string(what) + " got an unexpected keyword argument '" + key + "'");
  }
}

// ---- scenes --------------------------------------------------------------------------------

// A scene as ivv.scene() gives it: the loaded scene with every override applied and validated,
// and the overrides the command line has flags for (v0, zeta, c, lambda, no_dashpot), which a
// request applies again so that its messages name the flag as the CLI's do.
struct PyScene {
  std::string source;
  Scene scene;
  RequestOptions overrides;
};

// The keywords of ivv.scene() that are the CLI's overrides (a request applies them again).
const std::vector<std::string> kFlagOverrides = {"v0", "zeta", "c", "lambda_", "no_dashpot"};

// The scene value a keyword of ivv.scene() (or a scene axis of ivv.sweep()) names: a key of
// scene/scene_values.h with an underscore for its dot (structure_thickness, target_mass, ...),
// or one of the short names mass, radius and yield_strength. Empty for any other keyword.
std::string scene_key(const std::string& keyword) {
  if (keyword == "mass") return "impactor.mass";
  if (keyword == "radius") return "impactor.radius";
  if (keyword == "yield_strength") return "target.yield_strength";
  const std::size_t underscore = keyword.find('_');
  if (underscore == std::string::npos) return "";
  std::string key = keyword;
  key[underscore] = '.';
  return find_scene_value(key) ? key : "";
}

// Every keyword of ivv.scene(): the CLI's overrides, then the scene's values.
std::vector<std::string> scene_keywords() {
  std::vector<std::string> names = kFlagOverrides;
  for (const char* alias : {"mass", "radius", "yield_strength"}) names.emplace_back(alias);
  for (const SceneValueInfo& v : scene_values()) {
    std::string name(v.key);
    name[name.find('.')] = '_';
    names.push_back(name);
  }
  return names;
}

// The scene values among the keywords, set through scene/scene_values.h (None leaves an optional
// value out); a message names the keyword as typed.
void override_scene_values(Scene& scene, const py::dict& kw) {
  for (const auto& item : kw) {
    const auto keyword = item.first.cast<std::string>();
    const std::string key = scene_key(keyword);
    if (key.empty()) continue;
    try {
      if (item.second.is_none())
        clear_scene_value(scene, key);
      else
        set_scene_value(scene, key, item.second.cast<double>());
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(keyword, what.substr(std::min(what.size(), e.field().size() + 2)));
    }
  }
}

PyScene load(const std::string& source, const py::dict& kw) {
  reject_unknown(kw, scene_keywords(), "scene()");
  PyScene s{source, load_scene(source), {}};
  override_scene_values(s.scene, kw);
  RequestOptions& o = s.overrides;
  o.scene = source;
  o.v0 = get<double>(kw, "v0");
  o.zeta = get<double>(kw, "zeta");
  o.c = get<double>(kw, "c");
  o.lambda = get<double>(kw, "lambda_");
  o.no_dashpot = get<bool>(kw, "no_dashpot").value_or(false);
  const int dashpots = o.zeta.has_value() + o.c.has_value() + o.lambda.has_value() + o.no_dashpot;
  if (dashpots > 1)
    throw InputError(o.zeta ? "--zeta" : "--c",
                     "give one of zeta, c, lambda_ and no_dashpot (they all set the dashpot)");
  if (has_finite_plate(s.scene)) refuse_dashpot_and_integrator_flags(o);  // as simulate does
  s.scene = to_scene(s.scene, o);
  return s;
}

py::object scene_dict(const PyScene& s) {
  return to_python(scene_json(s.scene, derive(s.scene)));
}

// ---- requests ------------------------------------------------------------------------------

const std::vector<std::string> kModelArgs = {
    "law",    "integrator", "model",  "rtol",          "atol", "dt",    "max_steps",
    "params", "force",      "unload", "allow_tension", "hc_k", "hc_mu", "model_tol"};

// The options of a request on `s`: its overrides, and the law, integrator and tolerances of
// `kw` (the keywords of ivv.simulate), checked as the command line checks its flags.
RequestOptions request_options(const PyScene& s, const py::dict& kw, const char* what) {
  reject_unknown(kw, kModelArgs, what);
  RequestOptions o = s.overrides;
  o.law = get<std::string>(kw, "law").value_or("elastoplastic");
  o.integrator = get<std::string>(kw, "integrator").value_or("auto");
  o.model = get<std::string>(kw, "model").value_or("auto");
  o.rtol = get<double>(kw, "rtol");
  o.atol = get<double>(kw, "atol");
  o.dt = get<double>(kw, "dt");
  o.model_tolerance = get<double>(kw, "model_tol");
  o.max_steps = get<long>(kw, "max_steps");
  if (o.max_steps && *o.max_steps < 1)
    throw InputError("--max-steps", "must be an integer >= 1, got " + std::to_string(*o.max_steps));
  o.hc_k = get<double>(kw, "hc_k");
  o.hc_mu = get<double>(kw, "hc_mu");
  if (auto p = get<std::map<std::string, double>>(kw, "params"))
    o.parameters = LawParameters(p->begin(), p->end());
  const auto force = get<std::string>(kw, "force");
  const auto unload = get<std::string>(kw, "unload");
  for (const auto& [text, flag] : {std::pair{&force, "--force"}, std::pair{&unload, "--unload"}})
    if (*text && text->value().find_first_not_of(" \t") == std::string::npos)
      throw InputError(flag, "is empty; give the force [N] as an expression, e.g. 'K_h*z^1.5'");
  o.expression = {force.value_or(""), unload.value_or(""),
                  get<bool>(kw, "allow_tension").value_or(false)};
  return o;
}

// ---- simulate ------------------------------------------------------------------------------

// The trajectory as numpy columns named as `ivv simulate --trajectory` names its CSV columns.
py::dict trajectory_columns(const std::vector<TrajectoryPoint>& samples) {
  struct Column {
    const char* name;
    double TrajectoryPoint::*member;
  };
  static constexpr Column columns[] = {{"t", &TrajectoryPoint::t},
                                       {"alpha", &TrajectoryPoint::alpha},
                                       {"alpha_dot", &TrajectoryPoint::alpha_dot},
                                       {"y", &TrajectoryPoint::y},
                                       {"z", &TrajectoryPoint::z},
                                       {"F", &TrajectoryPoint::force},
                                       {"tau", &TrajectoryPoint::tau},
                                       {"alpha_bar", &TrajectoryPoint::alpha_bar},
                                       {"F_bar", &TrajectoryPoint::force_bar}};
  py::dict out;
  for (const Column& c : columns) {
    py::array_t<double> a(static_cast<py::ssize_t>(samples.size()));
    auto v = a.mutable_unchecked<1>();
    for (std::size_t i = 0; i < samples.size(); ++i) v(i) = samples[i].*(c.member);
    out[c.name] = std::move(a);
  }
  return out;
}

// (the simulate --json object, the trajectory columns or None)
py::tuple simulate(const PyScene& s, const py::dict& kw, bool trajectory) {
  if (has_finite_plate(s.scene)) {  // its modes, and the model it needs (ivv simulate's)
    if (trajectory)
      throw InputError("trajectory",
                       "not written for a finite plate yet (its state is the "
                       "impactor and every kept mode)");
    const RequestOptions o = request_options(s, kw, "simulate()");
    PlateRun run;
    {
      py::gil_scoped_release release;
      run = run_plate_simulation(s.scene, o);
    }
    return py::make_tuple(to_python(plate_simulation_json(run)), py::none());
  }
  SimulationRequest req = to_request(s.scene, request_options(s, kw, "simulate()"));
  std::vector<TrajectoryPoint> samples;
  SimulationRun run;
  {
    py::gil_scoped_release release;
    run = run_simulation(std::move(req), trajectory ? &samples : nullptr);
  }
  // as `ivv simulate` does: a law used outside its domain is bad input
  if (run.result.failure == FailureKind::law_domain) throw InputError("--law", run.result.reason);
  py::object traj = py::none();
  if (trajectory && run.result.ok()) traj = trajectory_columns(samples);
  return py::make_tuple(to_python(simulation_json(run)), traj);
}

// ---- sweep ---------------------------------------------------------------------------------

// run_sweep() on a worker thread while this thread, the GIL released, looks every 50 ms for a
// signal Python wants handled (Ctrl-C): then no new point starts, the points in flight finish,
// and KeyboardInterrupt (or what the handler raised) propagates.
std::vector<SweepPoint> run_interruptible(SweepRequest& req) {
  std::atomic<bool> stop{false};
  req.stop = &stop;
  std::vector<SweepPoint> points;
  {
    py::gil_scoped_release release;
    auto job = std::async(std::launch::async, [&req] { return run_sweep(req); });
    while (job.wait_for(std::chrono::milliseconds(50)) != std::future_status::ready) {
      if (stop) continue;
      py::gil_scoped_acquire acquire;
      if (PyErr_CheckSignals() != 0) stop = true;  // the exception is set; raised below
    }
    points = job.get();
  }
  if (stop) throw py::error_already_set();
  return points;
}

py::array_t<double> numbers(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

// The columns of the sweep CSV (solver/sweep/sweep.h, sweep_csv_header()) from the results the CSV
// is written from: a failed point has NaN where the CSV leaves its result columns empty.
py::dict sweep_columns(const SweepRequest& req, const std::vector<SweepPoint>& points) {
  static const char* const result_names[] = {
      "e",         "e_poisson", "e_energetic", "F_max",  "t_F_max",
      "t_contact", "z_max",     "alpha_max",   "z_perm", "energy_residual"};
  const std::size_t n = points.size();
  std::vector<double> v0(n), zeta(n);
  std::vector<std::vector<double>> axes(req.axes.size(), std::vector<double>(n));
  std::vector<std::vector<double>> results(std::size(result_names), std::vector<double>(n));
  py::array_t<long long> steps(static_cast<py::ssize_t>(n));
  auto steps_out = steps.mutable_unchecked<1>();
  py::list route, integrator, status, reason;
  for (std::size_t i = 0; i < n; ++i) {
    const ImpactResult& r = points[i].result;
    v0[i] = points[i].v0;
    zeta[i] = points[i].zeta;
    for (std::size_t k = 0; k < axes.size(); ++k) axes[k][i] = points[i].axes[k];
    const double values[] = {r.e,         r.e_poisson, r.e_energetic, r.F_max,  r.t_F_max,
                             r.t_contact, r.z_max,     r.alpha_max,   r.z_perm, r.energy.residual};
    for (std::size_t k = 0; k < std::size(result_names); ++k)
      results[k][i] = r.ok() ? values[k] : std::nan("");
    steps_out(i) = static_cast<long long>(r.steps);
    route.append(r.route);
    integrator.append(r.integrator);
    status.append(to_string(r.status));
    reason.append(!r.reason.empty() || r.ok() ? r.reason : "failed without a reason");
  }
  py::dict out;
  out["v0"] = numbers(v0);
  out["zeta"] = numbers(zeta);
  for (std::size_t k = 0; k < axes.size(); ++k) out[py::str(req.axes[k].key)] = numbers(axes[k]);
  for (std::size_t k = 0; k < std::size(result_names); ++k)
    out[result_names[k]] = numbers(results[k]);
  out["steps"] = steps;
  out["route"] = route;
  out["integrator"] = integrator;
  out["status"] = status;
  out["reason"] = reason;
  return out;
}

// `ivv sweep` over v0 x zeta (zeta None: every point keeps the scene's own dashpot) x the scene
// axes, each (key, values) as `--set KEY=...` (scene/scene_values.h).
py::dict sweep(const PyScene& s, const std::vector<double>& v0,
               const std::optional<std::vector<double>>& zeta, int threads, const py::dict& kw,
               const std::vector<std::pair<std::string, std::vector<double>>>& axes) {
  SweepRequest req;
  req.base = to_sweep_base(s.scene, request_options(s, kw, "sweep()"));
  req.velocities = v0;
  if (zeta)
    req.zetas = *zeta;
  else if (req.base.scene.damping.kind != Damping::Kind::none)
    req.scene_dashpot = true;
  else
    throw InputError("--zeta",
                     "required: the scene has no dashpot of its own (LO:HI:N or a,b,c; 0 = no "
                     "dashpot)");
  for (const auto& [key, values] : axes) req.axes.push_back({key, values});
  req.threads = threads;
  validate(req);
  const std::vector<SweepPoint> points = run_interruptible(req);
  return sweep_columns(req, points);
}

// ---- check-law -----------------------------------------------------------------------------

// The grid's axes and the claims of `ivv check-law`, from the keywords of ivv.check_law.
conformance::CheckLawAsk check_law_ask(const py::dict& kw) {
  conformance::CheckLawAsk ask;
  ask.velocities = get<std::vector<double>>(kw, "v0");
  ask.zetas = get<std::vector<double>>(kw, "zeta");
  ask.dashpots = get<std::vector<double>>(kw, "c");
  ask.elastic_at_low_speed = get<bool>(kw, "elastic_at_low_speed").value_or(false);
  ask.monotone = get<bool>(kw, "monotone").value_or(true);
  ask.cor_increasing_in_v0 = get<bool>(kw, "cor_increasing_in_v0").value_or(false);
  ask.captured_below = get<double>(kw, "captured_below");
  ask.expect_cor = get<std::string>(kw, "expect_cor").value_or("");
  ask.cor_tolerance = get<double>(kw, "cor_tolerance");
  return ask;
}

const std::vector<std::string> kCheckArgs = {"v0",
                                             "zeta",
                                             "c",
                                             "expect_cor",
                                             "cor_tolerance",
                                             "name",
                                             "elastic_at_low_speed",
                                             "monotone",
                                             "cor_increasing_in_v0",
                                             "captured_below",
                                             "onset_force"};

// The verdict with every check: the object `ivv check-law --json` prints.
py::object check_law(const PyScene& s, const py::dict& kw, const py::dict& checks) {
  reject_unknown(checks, kCheckArgs, "check_law()");
  if (!get<std::string>(kw, "force") && !get<std::string>(kw, "law") && !kw.contains("params") &&
      !get<double>(kw, "hc_k") && !get<double>(kw, "hc_mu"))
    throw InputError("--force",
                     "give the law to check: --force EXPR, or --law NAME (`ivv laws` lists them)");
  RequestOptions options = request_options(s, kw, "check_law()");
  conformance::declare_onset_force(options, get<std::string>(checks, "onset_force"));
  const SimulationRequest req = to_check_law_request(s.scene, options);
  const conformance::CheckLawAsk ask = check_law_ask(checks);
  const conformance::Grid grid = conformance::check_law_grid(req, ask);
  const conformance::Claims claims =
      conformance::check_law_claims(req, ask, oracles::expression_functions());
  conformance::LawUnderTest law = conformance::registry_law(req);
  if (auto name = get<std::string>(checks, "name"); name && !name->empty()) law.name = *name;
  nlohmann::json j;
  {
    py::gil_scoped_release release;
    j = conformance::check_law_json(conformance::run_conformance(law, claims, grid), req, claims);
  }
  return to_python(j);
}

// ---- calibrate and predict -----------------------------------------------------------------

// Measured data: a file (`path`), or the same CSV as text (ivv.calibrate's columns, written
// by the Python side with every digit of its floats).
validation::MeasuredData measured_data(const py::dict& kw) {
  if (auto text = get<std::string>(kw, "data_text"))
    return validation::parse_measured_data(*text, "<data>");
  return validation::read_measured_data(kw["data"].cast<std::string>());
}

void check_threads(int threads) {
  if (threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
}

// `ivv calibrate`: the fit of `fit` (with start values and bounds) to the measured data. The
// problem is built as app/calibrate_command.cc builds it (start values through set_parameter).
py::dict calibrate(const PyScene& s, const py::dict& kw, const py::dict& fit_kw) {
  validation::CalibrationProblem problem{to_request(s.scene, request_options(s, kw, "calibrate()")),
                                         measured_data(fit_kw)};
  for (const auto& [name, value] : get<std::map<std::string, double>>(fit_kw, "start")
                                       .value_or(std::map<std::string, double>{})) {
    validation::parameter_info(problem.request, name);  // throws naming the fittable ones
    validation::set_parameter(problem.request, name, value);
  }
  validation::CalibrationOptions options;
  options.fit = fit_kw["fit"].cast<std::vector<std::string>>();
  using Range = std::pair<double, double>;
  for (const auto& [name, range] :
       get<std::map<std::string, Range>>(fit_kw, "bounds").value_or(std::map<std::string, Range>{}))
    options.bounds[name] = {range.first, range.second};
  options.scan = get<bool>(fit_kw, "scan").value_or(false);
  options.profile = get<bool>(fit_kw, "profile").value_or(true);
  options.threads = get<int>(fit_kw, "threads").value_or(0);
  check_threads(options.threads);
  options.validate(problem.request);
  validation::CalibrationResult fit;
  {
    py::gil_scoped_release release;
    fit = validation::calibrate(problem, options);
  }
  py::dict out;
  out["ok"] = fit.ok;
  out["failure"] = fit.failure;
  out["brief"] = fit.brief();
  out["json"] = py::none();
  if (fit.ok) out["json"] = validation::calibration_json(problem, fit).dump();
  return out;
}

// `ivv predict`: the calibration (its JSON text, or a file) over speeds, or against held-back
// data (ASME V&V 20).
py::dict predict(const py::dict& kw) {
  const validation::CalibratedModel model =
      kw.contains("calibration_text")
          ? validation::read_calibration(
                nlohmann::json::parse(kw["calibration_text"].cast<std::string>()), "<calibration>")
          : validation::read_calibration_file(kw["calibration"].cast<std::string>());
  validation::PredictionOptions o;
  o.samples = get<int>(kw, "samples").value_or(10000);
  o.seed = get<std::uint64_t>(kw, "seed").value_or(1);
  o.threads = get<int>(kw, "threads").value_or(0);
  check_threads(o.threads);
  o.validate();
  const auto v0 = get<std::vector<double>>(kw, "v0");
  const bool with_data = kw.contains("data") || kw.contains("data_text");
  if (v0.has_value() == with_data)
    throw InputError("--v0",
                     "give the speeds of the band (--v0 LO:HI:N) or held-back data "
                     "(--data FILE), one of them");
  std::optional<validation::MeasuredData> data;
  if (with_data) data = measured_data(kw);
  std::optional<validation::ValidationComparison> vv;
  validation::Prediction band;
  {
    py::gil_scoped_release release;
    if (data) {
      vv = validation::compare_with_data(model, *data, o);
      band = vv->prediction;
    } else {
      band = validation::predict(model, *v0, o);
    }
  }
  py::dict out;
  out["ok"] = band.ok();
  out["failure"] = band.ok() ? std::string() : band.failures.front();
  out["json"] = to_python(validation::prediction_json(band, vv ? &*vv : nullptr));
  return out;
}

// ---- the module ----------------------------------------------------------------------------

void translate_input_error(py::module_& m) {
  static py::exception<InputError> exc(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      py::object error = py::reinterpret_borrow<py::object>(exc.ptr())(e.what());
      error.attr("field") = e.field();
      PyErr_SetObject(exc.ptr(), error.ptr());
    }
  });
}

}  // namespace
}  // namespace ivv::python

PYBIND11_MODULE(_ivv, m) {
  using namespace ivv::python;
  m.doc() = "The compiled half of the Python module ivv (use `import ivv`, not this module).";
  m.attr("__version__") = IVV_VERSION;
  translate_input_error(m);
  py::class_<PyScene>(m, "_Scene")
      .def_readonly("source", &PyScene::source)
      .def("to_dict", &scene_dict,
           "The scene and its derived parameters (`ivv scene show --json`).");
  m.def("_load_scene", &load, py::arg("source"), py::arg("overrides"));
  m.def("_simulate", &simulate, py::arg("scene"), py::arg("options"), py::arg("trajectory"));
  m.def("_sweep", &sweep, py::arg("scene"), py::arg("v0"), py::arg("zeta"), py::arg("threads"),
        py::arg("options"), py::arg("axes"));
  m.def("_scene_key", &scene_key, py::arg("keyword"));
  m.def("_scene_values", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const ivv::SceneValueInfo& v : ivv::scene_values())
      out.emplace_back(std::string(v.key), std::string(v.unit));
    return out;
  });
  m.def("_check_law", &check_law, py::arg("scene"), py::arg("options"), py::arg("checks"));
  m.def("_calibrate", &calibrate, py::arg("scene"), py::arg("options"), py::arg("fit"));
  m.def("_predict", &predict, py::arg("options"));
  m.def(
      "_add_data_directory", [](const std::string& dir) { ivv::add_data_directory(dir); },
      py::arg("directory"));
  m.def("_data_directories", [] {
    std::vector<std::string> out;
    for (const auto& d : ivv::data_directories()) out.push_back(d.string());
    return out;
  });
}
