#include "verification/work_precision.h"

#include "closed_forms/linear_model.h"
#include "solver/steppers/machine_code.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <thread>

// The CMake build type, set by verification/CMakeLists.txt.
#ifndef IVV_BUILD_TYPE
#define IVV_BUILD_TYPE ""
#endif

namespace ivv::verification {
namespace {

double floored(double error) {
  return error == 0.0 ? kErrorFloor : error;
}

double relative_error(double x, double reference) {
  const double diff = std::abs(x - reference);
  return floored(reference == 0.0 ? diff : diff / std::abs(reference));
}

double median(std::vector<double> v) {
  const std::size_t n = v.size();
  std::nth_element(v.begin(), v.begin() + n / 2, v.end());
  const double upper = v[n / 2];
  if (n % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(v.begin(), v.begin() + n / 2));
}

// The point's request: `base` with the integrator and its accuracy setting replaced.
SimulationRequest point_request(const SimulationRequest& base, IntegratorKind kind,
                                double tolerance) {
  SimulationRequest req = base;
  req.integrator = kind;
  req.options.check_consistency = false;  // the study measures the error itself
  if (traits(kind).fixed_step) {
    req.options.dt = tolerance;
  } else {
    req.options.rtol = tolerance;
    req.options.atol = tolerance;  // the state is normalised to O(1): atol = rtol
    req.options.fixed_step = false;
  }
  return req;
}

WorkPrecisionPoint measure_point(const SimulationRequest& req, double tolerance,
                                 const ImpactResult& ref, const WorkPrecisionOptions& opt) {
  using Clock = std::chrono::steady_clock;
  WorkPrecisionPoint pt;
  pt.tolerance = tolerance;
  std::vector<double> seconds;
  ImpactResult r;
  const auto study_start = Clock::now();
  do {
    const auto t0 = Clock::now();
    r = simulate(req);
    seconds.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
    if (!r.ok()) break;  // a failure is not worth timing again
  } while (static_cast<int>(seconds.size()) < opt.min_repeats ||
           std::chrono::duration<double>(Clock::now() - study_start).count() <
               opt.min_seconds_per_point);
  pt.seconds_per_impact = median(seconds);
  pt.repeats = static_cast<int>(seconds.size());
  pt.steps = r.steps;
  pt.rhs_evaluations = r.rhs_evaluations;
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  pt.error_e = pt.error_F_max = pt.error_t_contact = nan;
  if (!r.ok()) {
    pt.reason = r.reason.empty() ? "integration failed" : r.reason;
    return pt;
  }
  if (r.status != ref.status) {
    pt.reason = "ended " + std::string(to_string(r.status)) + ", the reference " +
                std::string(to_string(ref.status));
    return pt;
  }
  pt.ok = true;
  pt.error_e = relative_error(r.e, ref.e);
  pt.error_F_max = relative_error(r.F_max, ref.F_max);
  pt.error_t_contact = relative_error(r.t_contact, ref.t_contact);
  return pt;
}

std::string compiler_name() {
#if defined(__clang__)
  return std::string("clang ") + __VERSION__;
#elif defined(__GNUC__)
  return std::string("GCC ") + __VERSION__;
#else
  return __VERSION__;
#endif
}

// Least-squares slope of log(y) on log(x).
double fitted_slope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double lx = std::log(x[i]), ly = std::log(y[i]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace

MachineInfo describe_machine() {
  MachineInfo m;
  m.cpu_model = "unknown";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    const auto first = line.find_first_not_of(" \t", colon + 1);
    if (first != std::string::npos) m.cpu_model = line.substr(first);
    break;
  }
  m.logical_cores = static_cast<int>(std::thread::hardware_concurrency());
  m.compiler = compiler_name();
  m.build_type = std::string(IVV_BUILD_TYPE).empty() ? "unspecified" : IVV_BUILD_TYPE;
  m.machine_code = machine_code_description(machine_code_in_use(MachineCode::fastest));
  return m;
}

WorkPrecisionStudy measure_work_precision(const std::string& label, const SimulationRequest& base,
                                          const WorkPrecisionOptions& options) {
  validate(base);
  WorkPrecisionStudy study;
  study.label = label;
  study.base = base;
  study.machine = describe_machine();

  SimulationRequest ref_req = base;
  ref_req.integrator = IntegratorKind::mp50;
  study.reference = simulate(ref_req);
  if (!study.reference.ok())
    throw std::runtime_error("work-precision study '" + label +
                             "': the mp50 reference failed: " + study.reference.reason);

  std::size_t total = 0;
  for (IntegratorKind k : options.integrators)
    total += (traits(k).fixed_step ? options.rk4_steps : options.rtols).size();
  std::size_t done = 0;
  for (IntegratorKind k : options.integrators) {
    WorkPrecisionSeries s;
    s.integrator = k;
    for (double tol : traits(k).fixed_step ? options.rk4_steps : options.rtols) {
      const SimulationRequest req = point_request(base, k, tol);
      validate(req);
      s.points.push_back(measure_point(req, tol, study.reference, options));
      if (options.progress) options.progress(++done, total);
    }
    study.series.push_back(std::move(s));
  }
  return study;
}

OrderStudy measure_order(const SimulationRequest& base, IntegratorKind kind,
                         const std::vector<double>& settings, double error_floor) {
  if (base.law != LawKind::linearized)
    throw std::invalid_argument("measure_order: the closed form needs LawKind::linearized");
  const closed_forms::LinearImpact exact = closed_forms::solve_linear_model(
      closed_forms::linear_model_input(base.scene, derive(base.scene)));
  if (exact.captured)
    throw std::invalid_argument("measure_order: the closed form is a capture (no COR)");
  if (!traits(kind).fixed_step_mode)
    throw std::invalid_argument("measure_order: " + std::string(to_string(kind)) +
                                " has no fixed-step mode");
  OrderStudy study;
  study.integrator = kind;
  std::vector<double> x, y;
  for (double setting : settings) {
    SimulationRequest req = base;
    req.integrator = kind;
    req.options.dt = setting;
    req.options.fixed_step = true;
    req.options.check_consistency = false;  // deliberately coarse steps: the error is measured
    const ImpactResult r = simulate(req);
    if (!r.separated()) {
      std::ostringstream os;
      os << "measure_order: " << to_string(kind) << " at " << setting << " ended "
         << to_string(r.status) << (r.reason.empty() ? "" : ": ") << r.reason;
      throw std::runtime_error(os.str());
    }
    const double err = relative_error(r.e, exact.e);
    study.settings.push_back(setting);
    study.steps.push_back(static_cast<double>(r.steps));
    study.errors_e.push_back(err);
    const bool fit = err >= error_floor;
    study.fitted.push_back(fit);
    if (fit) {
      x.push_back(setting);
      y.push_back(err);
    }
  }
  if (x.size() < 2)
    throw std::runtime_error("measure_order: fewer than two points above the error floor for " +
                             std::string(to_string(kind)));
  study.observed_order = fitted_slope(x, y);
  return study;
}

ConvergenceStudy measure_convergence(const SimulationRequest& base, IntegratorKind kind,
                                     std::vector<double> dts, EventLocation events) {
  const bool locate_events = events == EventLocation::located;
  if (base.law != LawKind::linearized)
    throw std::invalid_argument("measure_convergence: the closed form needs LawKind::linearized");
  if (!traits(kind).fixed_step_mode)
    throw std::invalid_argument("measure_convergence: the integrator needs a fixed-step mode");
  if (dts.size() < 2 ||
      std::all_of(dts.begin(), dts.end(), [&](double dt) { return dt == dts[0]; }))
    throw std::invalid_argument("measure_convergence: needs at least two distinct dts");

  const closed_forms::LinearImpact exact = closed_forms::solve_linear_model(
      closed_forms::linear_model_input(base.scene, derive(base.scene)));
  if (exact.captured)
    throw std::invalid_argument("measure_convergence: the closed form is a capture (no COR)");
  ConvergenceStudy study;
  study.integrator = kind;
  study.events_located = locate_events;
  for (double dt : dts) {
    SimulationRequest req = base;
    req.integrator = kind;
    req.options.dt = dt;
    req.options.fixed_step = true;
    req.options.locate_events = locate_events;
    req.options.check_consistency = false;  // deliberately coarse steps: the error is measured
    const ImpactResult r = simulate(req);
    if (!r.separated()) {
      std::ostringstream os;
      os << "measure_convergence: " << to_string(kind) << " at dt = " << dt << " ended "
         << to_string(r.status) << (r.reason.empty() ? "" : ": ") << r.reason;
      throw std::runtime_error(os.str());
    }
    study.steps.push_back(dt);
    study.errors_e.push_back(relative_error(r.e, exact.e));
    study.errors_t_contact.push_back(relative_error(r.t_contact, exact.t_contact));
  }
  study.fitted_order = fitted_slope(study.steps, study.errors_e);
  study.fitted_order_t_contact = fitted_slope(study.steps, study.errors_t_contact);
  return study;
}

}  // namespace ivv::verification
