#include "app/calibrate_command.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

#include "app/cli_args.h"
#include "app/command.h"
#include "reports/calibration_report.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "validation/calibration_file.h"
#include "validation/comparison.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"
#include "validation/prediction.h"
#include "validation/synthetic.h"

namespace ivv {
namespace {

using namespace validation;

std::vector<std::string> split_list(const std::vector<std::string>& items) {
  std::vector<std::string> out;
  for (const auto& item : items) {
    std::size_t start = 0;
    for (;;) {
      const auto comma = item.find(',', start);
      const std::string name = item.substr(start, comma - start);
      if (!name.empty()) out.push_back(name);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

// "NAME=LO:HI" items of --bounds.
std::map<std::string, Bounds> parse_bounds(const std::vector<std::string>& items) {
  std::map<std::string, Bounds> out;
  for (const auto& item : items) {
    const auto eq = item.find('='), colon = item.find(':', eq == std::string::npos ? 0 : eq);
    if (eq == std::string::npos || colon == std::string::npos)
      throw InputError("--bounds", "expected NAME=LO:HI, got '" + item + "'");
    const std::string name = item.substr(0, eq);
    out[name] = {parse_number(item.substr(eq + 1, colon - eq - 1), "--bounds " + name),
                 parse_number(item.substr(colon + 1), "--bounds " + name)};
  }
  return out;
}

// "NAME=VALUE" items of --start: each a finite number > 0 (a fit starts from one), named
// by --start and its name (not by --param or the scene field the value would land in).
std::map<std::string, double> parse_starts(const std::vector<std::string>& items) {
  std::map<std::string, double> out;
  for (const std::string& item : items) {
    const auto eq = item.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--start", "'" + item + "': expected NAME=VALUE, e.g. c=8000");
    const std::string name = item.substr(0, eq);
    const double value = parse_number(item.substr(eq + 1), "--start " + name);
    if (!(std::isfinite(value) && value > 0))
      throw InputError("--start " + name,
                       "must be a finite number > 0 (a fit starts from one), "
                       "got '" +
                           item.substr(eq + 1) + "'");
    if (!out.emplace(name, value).second) throw InputError("--start " + name, "given twice");
  }
  return out;
}

CalibrationProblem problem_for(const SimulationRequest& base, const MeasuredData& data,
                               const std::vector<std::string>& start) {
  CalibrationProblem p{base, data};
  for (const auto& [name, value] : parse_starts(start)) {
    parameter_info(p.request, name);  // throws naming the fittable parameters
    set_parameter(p.request, name, value);
  }
  return p;
}

// One law of --compare: its request and the --fit names it has.
std::pair<CalibrationProblem, CalibrationOptions> compared(const CalibrationProblem& main,
                                                           const CalibrationOptions& options,
                                                           const std::string& law,
                                                           const std::vector<std::string>& start) {
  CalibrationProblem p = main;
  CalibrationOptions o = options;
  o.fit.clear();
  o.bounds.clear();
  if (law != "expression") {
    p.request.law = parse_law(law, "--compare");
    p.request.expression = {};
  } else if (p.request.law != LawKind::expression) {
    throw InputError("--compare", "'expression' needs the law typed with --force");
  }
  if (p.request.law == LawKind::hunt_crossley) {
    p.request.scene.damping = Damping::none();
    p.request.parameters.try_emplace("mu", 0.1);
    o.scan = true;
  }
  const auto fittable = fittable_parameters(p.request);
  for (const auto& name : options.fit)
    if (std::find(fittable.begin(), fittable.end(), name) != fittable.end() &&
        !(p.request.law == LawKind::hunt_crossley && (name == "c" || name == "zeta")))
      o.fit.push_back(name);
  if (p.request.law == LawKind::hunt_crossley &&
      std::find(o.fit.begin(), o.fit.end(), "mu") == o.fit.end())
    o.fit.push_back("mu");
  if (o.fit.empty())
    throw InputError("--compare", "law '" + law + "' has none of the --fit parameters");
  for (const auto& [name, b] : options.bounds)
    if (std::find(o.fit.begin(), o.fit.end(), name) != o.fit.end()) o.bounds[name] = b;
  for (const auto& [name, value] : parse_starts(start))
    if (std::find(fittable.begin(), fittable.end(), name) != fittable.end())
      set_parameter(p.request, name, value);
  return {p, o};
}

}  // namespace

namespace {

struct ReportInputs {
  Prediction band;
  std::vector<std::vector<double>> curves;
};

// The report's band (40 speeds over the data's range, 2000 draws) and each ranked law's curve.
ReportInputs report_inputs(const CalibrationProblem& p, const CalibrationResult& fit,
                           const ModelRanking* ranking,
                           const std::vector<CalibrationProblem>& problems,
                           const std::vector<std::string>& names, int threads) {
  double lo = p.data.points.front().v0, hi = lo;
  for (const auto& m : p.data.points) lo = std::min(lo, m.v0), hi = std::max(hi, m.v0);
  const auto speeds = log_velocities(lo, hi, 40);
  ReportInputs r;
  PredictionOptions o;
  o.samples = 2000;
  o.threads = threads;
  r.band = predict(calibrated_model(p, fit), speeds, o);
  if (!ranking) return r;
  for (const auto& m : ranking->models) {
    std::vector<double> e;
    const auto i =
        static_cast<std::size_t>(std::find(names.begin(), names.end(), m.name) - names.begin());
    if (m.fit.ok && i < problems.size())
      for (const auto& pt :
           run_model_points(calibrated_model(problems[i], m.fit).request, {}, {}, speeds, threads))
        e.push_back(pt.result.ok() ? pt.result.e : std::numeric_limits<double>::quiet_NaN());
    r.curves.push_back(e);
  }
  return r;
}

// Progress of a long calibration on stderr: silent for the first 2 s (most fits end sooner),
// then at most one line every 5 s (a 1e5-row fit takes minutes, its profile intervals more),
// e.g. "ivv calibrate: fit, iteration 12 of at most 100 (41 s)". Not a sweep's ProgressLine:
// an iteration count has no rate or ETA.
std::function<void(std::string_view, std::size_t, std::size_t)> progress_lines() {
  using Clock = std::chrono::steady_clock;
  struct State {
    Clock::time_point start = Clock::now(), last{};
  };
  auto state = std::make_shared<State>();
  return [state](std::string_view stage, std::size_t done, std::size_t total) {
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - state->start).count();
    if (elapsed < 2.0 || std::chrono::duration<double>(now - state->last).count() < 5.0) return;
    state->last = now;
    std::cerr << "ivv calibrate: " << stage << (stage == "fit" ? ", iteration " : ", end ") << done
              << (stage == "fit" ? " of at most " : " of ") << total << " ("
              << static_cast<long>(elapsed) << " s)" << std::endl;
  };
}

}  // namespace

void add_calibrate_flags(CLI::App& cmd, CalibrateFlags& f) {
  cmd.add_option("--data", f.data,
                 "measured data: CSV with header v0,e[,u_e,F_max,u_F_max,t_contact,u_t_contact]; "
                 "'#' lines carry provenance")
      ->required();
  cmd.add_option("--fit", f.fit, "parameters to fit, NAME[,NAME...] (e.g. c,yield_strength)")
      ->required();
  cmd.add_option("--start", f.start, "start value NAME=VALUE of a fitted parameter (repeatable)");
  cmd.add_option("--bounds", f.bounds, "NAME=LO:HI (repeatable; default: positive)");
  cmd.add_flag("--scan", f.scan, "start from the best point of a coarse log grid");
  cmd.add_flag("--no-profile", f.no_profile, "skip the profile-likelihood intervals");
  cmd.add_option("--compare", f.compare,
                 "laws to fit to the same data and rank by AIC/BIC, e.g. "
                 "elastoplastic,hertz,hunt-crossley (`expression`: the --force law)");
  cmd.add_flag("--json", f.json, "print the calibration as JSON (the file ivv predict reads)");
  cmd.add_option("--out", f.out, "write the calibration JSON to this file");
  cmd.add_option("--report", f.report_dir, "write DIR/index.html for this calibration");
  app::add_threads_option(cmd, f.threads, "worker threads of the model runs (0 = all cores)");
}

int run_calibrate(const SimulationRequest& base, const CalibrateFlags& f,
                  const std::string& command_line) {
  if (f.threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
  // every output checked before any work: a directory, a FIFO or a missing directory for --out
  // would otherwise be found after the whole fit
  if (!f.out.empty()) resolve_output_path(f.out, "--out");
  if (!f.report_dir.empty()) reports::check_report_dir(f.report_dir);
  const MeasuredData data = read_measured_data(f.data);
  const CalibrationProblem problem = problem_for(base, data, f.start);
  CalibrationOptions options;
  options.fit = split_list(f.fit);
  options.bounds = parse_bounds(f.bounds);
  options.scan = f.scan;
  options.profile = !f.no_profile;
  options.threads = f.threads;
  options.progress = progress_lines();
  options.validate(problem.request);
  std::vector<std::pair<CalibrationProblem, CalibrationOptions>> others;
  for (const auto& law : split_list(f.compare))
    others.push_back(compared(problem, options, law, f.start));  // bad input before any fit
  const CalibrationResult fit = calibrate(problem, options);
  std::optional<ModelRanking> ranking;
  std::vector<CalibrationProblem> problems;
  std::vector<std::string> names;
  if (!others.empty()) {
    std::vector<CalibrationResult> fits;
    for (const auto& [p, o] : others) {
      names.push_back(p.request.law == LawKind::expression
                          ? "expression: " + p.request.expression.force
                          : std::string(to_string(p.request.law)));
      problems.push_back(p);
      fits.push_back(calibrate(p, o));
    }
    ranking = compare(names, fits);
  }
  const nlohmann::json j = fit.ok ? calibration_json(problem, fit) : nlohmann::json();
  if (f.json && fit.ok) std::cout << j.dump(2) << "\n";
  if (!f.json) {
    std::cout << fit.brief();
    for (const auto& s : fit.estimated_noise) std::cout << "  " << s << "\n";
    std::cout << "  " << fit.solver_report << "\n";
    if (ranking) std::cout << "\n" << ranking->table();
  }
  if (!fit.ok) {
    std::cerr << "ivv: failed: " << fit.failure << "\n";
    return 1;
  }
  if (!f.out.empty())
    write_file_atomically(
        f.out, [&](std::ostream& os) { os << j.dump(2) << "\n"; }, "--out");
  if (!f.report_dir.empty()) {
    const ReportInputs in =
        report_inputs(problem, fit, ranking ? &*ranking : nullptr, problems, names, f.threads);
    const reports::CalibrationView view{
        &problem, &fit, &in.band, nullptr, ranking ? &*ranking : nullptr, &in.curves};
    std::cerr << "report: " << reports::write_calibration_report(view, f.report_dir, command_line)
              << "\n";
  }
  return 0;
}

namespace {

// A parameter the calibration could not determine is held at its start value, which the data
// did not choose: said on stderr whatever the output format, never only in a JSON field.
void warn_held(const CalibratedModel& model) {
  for (std::size_t i = 0; i < model.names.size(); ++i)
    if (!model.identifiable[i])
      std::cerr << "ivv: warning: " << model.names[i]
                << " was not determined by the calibration data (UNIDENTIFIABLE); the prediction "
                   "holds it at its start value "
                << model.values[i]
                << ", which the data did not choose, and the band does not include its "
                   "uncertainty\n";
}

}  // namespace

void add_predict_flags(CLI::App& cmd, PredictFlags& f) {
  cmd.add_option("--calibration", f.calibration, "the calibration JSON (ivv calibrate --out)")
      ->required();
  auto* v0 = cmd.add_option("--v0", f.v0, "speeds LO:HI:N or a,b,c [m/s] for the band");
  auto* data = cmd.add_option(
      "--data", f.data, "held-back measurements (CSV as for calibrate): the V&V 20 comparison");
  v0->excludes(data);
  cmd.add_flag("--log", f.log, "log-spaced --v0 grid");
  cmd.add_option("--samples", f.samples, "Monte Carlo draws (default 10000)");
  // checked as text: CLI11 would wrap "-1" into 18446744073709551615 silently
  cmd.add_option("--seed", f.seed, "seed of the draws (default 1)")
      ->check(CLI::Validator(
          [](std::string& text) {
            return text.find('-') == std::string::npos
                       ? std::string()
                       : "must be an integer in [0, 2^64), got '" + text + "'";
          },
          "UINT64"));
  cmd.add_flag("--json", f.json, "print the band (and comparison) as JSON");
  app::add_threads_option(cmd, f.threads, "worker threads (0 = all cores)");
}

namespace {

void print_prediction(const CalibratedModel& model, const Prediction& band,
                      const ValidationComparison* vv) {
  std::cout << "model " << model.law << "; " << band.samples << " Monte Carlo draws (seed "
            << band.seed << ") over the fitted covariance";
  for (const auto& h : band.held)
    std::cout << "; " << h << " NOT DETERMINED, held at its start (band without its uncertainty)";
  std::cout << "\n";
  char line[200];
  if (!vv) {
    std::cout << "  v0 [m/s]        e    95 % band            u_input    u_num\n";
    for (const auto& b : band.points) {
      std::snprintf(line, sizeof line, "%10.4g %8.5f  [%8.5f, %8.5f]  %9.3g  %7.1e\n", b.v0,
                    b.e_nominal, b.e_lo, b.e_hi, b.u_input, b.u_num);
      std::cout << line;
    }
    return;
  }
  std::cout << "ASME V&V 20: E = S - D, u_val = sqrt(u_num^2 + u_input^2 + u_D^2)\n"
            << "  v0 [m/s]   S (model)  D (data)        E     u_val   |E|/u_val\n";
  for (const auto& p : vv->points) {
    std::snprintf(line, sizeof line, "%10.4g %10.5f %9.5f %+9.5f %9.3g %8.2f%s\n", p.v0, p.S, p.D,
                  p.E, p.u_val, std::abs(p.E) / p.u_val, p.exceeds ? "  > 2: model error" : "");
    std::cout << line;
  }
  std::cout << vv->summary() << "\n";
}

}  // namespace

int run_predict(const PredictFlags& f) {
  if (f.v0.empty() == f.data.empty())
    throw InputError("--v0",
                     "give the speeds of the band (--v0 LO:HI:N) or held-back data "
                     "(--data FILE), one of them");
  if (f.threads < 0) throw InputError("--threads", "must be >= 0 (0: all cores)");
  const CalibratedModel model = read_calibration_file(f.calibration);
  PredictionOptions o;
  o.samples = f.samples;
  o.seed = f.seed;
  o.threads = f.threads;
  o.validate();
  std::optional<ValidationComparison> vv;
  Prediction band;
  if (!f.data.empty()) {
    vv = compare_with_data(model, read_measured_data(f.data), o);
    band = vv->prediction;
  } else {
    const std::vector<double> speeds = parse_grid(f.v0, "--v0", spacing_of(f.log));
    for (double v : speeds)
      if (!(std::isfinite(v) && v > 0))
        throw InputError("--v0", "every speed must be a finite number > 0 m/s, got " +
                                     (std::ostringstream() << v).str());
    band = predict(model, speeds, o);
  }
  if (!band.ok()) {
    std::cerr << "ivv: failed: " << band.failures.front() << "\n";
    return 1;
  }
  warn_held(model);
  if (f.json)
    std::cout << prediction_json(band, vv ? &*vv : nullptr).dump(2) << "\n";
  else
    print_prediction(model, band, vv ? &*vv : nullptr);
  return 0;
}

}  // namespace ivv
