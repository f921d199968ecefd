#include "validation/calibration.h"

#include <ceres/ceres.h>
#include <glog/logging.h>

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <boost/math/tools/roots.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "scene/input_error.h"
#include "validation/model_runs.h"
#include "validation/parameters.h"

namespace ivv::validation {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A positive parameter's default lower bound: 1e-6 of its start (it may not reach 0, where the
// model is undefined); an estimate on it is reported as at_bound.
constexpr double kDefaultLowerFactor = 1e-6;
// Directions with s_k below this fraction of s_max are numerically null (the pseudo-inverse of
// the correlation matrix drops them): round-off of a Jacobian with ~1e-10 relative accuracy.
constexpr double kNullDirection = 1e-12;
// A parameter with this share of an unresolved direction (|V_jk| >= 0.1, the share at which
// join_names names it in the combination) moves with that combination: unidentifiable.
constexpr double kCombinationShare = 0.01;
// The scan evaluates 5^p points; beyond 3 parameters (125 points, each a run of every data
// velocity) it costs more than the fit it starts.
constexpr std::size_t kScanMaxParameters = 3;

// One residual: impact `point`, quantity `q`.
struct Entry {
  std::size_t point;
  Quantity q;
};

double model_value(const ImpactResult& r, Quantity q) {
  switch (q) {
    case Quantity::e:
      return r.e;
    case Quantity::F_max:
      return r.F_max;
    case Quantity::t_contact:
      return r.t_contact;
  }
  return kNaN;
}

using Progress = std::function<void(std::string_view, std::size_t, std::size_t)>;

// The least-squares problem in x = theta / theta0, all parameters, with per-quantity sigma for
// quantities without stated uncertainties.
class Model {
 public:
  Model(const CalibrationProblem& problem, std::vector<std::string> names, int threads)
      : problem_(problem), names_(std::move(names)), threads_(threads) {
    for (const auto& p : problem.data.points) velocities_.push_back(p.v0);
    for (std::size_t i = 0; i < problem.data.points.size(); ++i)
      for (Quantity q : kQuantities)
        if (problem.data.points[i].value[static_cast<std::size_t>(q)]) entries_.push_back({i, q});
    for (Quantity q : kQuantities) {
      const auto qi = static_cast<std::size_t>(q);
      if (!problem.data.has_quantity[qi] || problem.data.has_uncertainty[qi]) continue;
      double mean = 0;
      for (const auto& e : entries_)
        if (e.q == q) mean += std::abs(*problem.data.points[e.point].value[qi]);
      mean /= static_cast<double>(problem.data.count(q));
      sigma_[qi] = mean > 0 ? mean / 100 : 0.01;  // a start; estimated after the first fit
    }
  }

  std::size_t residual_count() const { return entries_.size(); }
  const std::array<double, 3>& sigmas() const { return sigma_; }
  void set_sigmas(const std::array<double, 3>& sigma) { sigma_ = sigma; }
  std::size_t parameter_count() const { return names_.size(); }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<Entry>& entries() const { return entries_; }
  bool sigma_estimated(Quantity q) const { return sigma_[static_cast<std::size_t>(q)] > 0; }
  double& sigma(Quantity q) { return sigma_[static_cast<std::size_t>(q)]; }
  double sigma(Quantity q) const { return sigma_[static_cast<std::size_t>(q)]; }
  long evaluations() const { return evaluations_; }

  double uncertainty(const Entry& e) const {
    const auto qi = static_cast<std::size_t>(e.q);
    return sigma_[qi] > 0 ? sigma_[qi] : *problem_.data.points[e.point].uncertainty[qi];
  }

  // Model runs at theta; nullopt when a run failed or the parameters are invalid.
  std::optional<std::vector<ModelPoint>> run(const std::vector<double>& theta) const {
    evaluations_ += static_cast<long>(velocities_.size());
    try {
      auto points = run_model_points(problem_.request, names_, theta, velocities_, threads_);
      for (std::size_t i = 0; i < points.size(); ++i)
        if (!points[i].result.ok()) {
          last_failure_ = at(theta) + ", v0 = " + std::to_string(velocities_[i]) +
                          " m/s: " + points[i].result.reason;
          return std::nullopt;
        }
      return points;
    } catch (const std::exception& e) {
      last_failure_ = at(theta) + ": " + e.what();
      return std::nullopt;
    }
  }

  Progress progress;  // CalibrationOptions::progress (may be empty)

  // Why the last model run that failed failed ("" if none did): a failed fit names it.
  const std::string& last_failure() const { return last_failure_; }

  bool residuals(const std::vector<double>& theta, double* r) const {
    const auto points = run(theta);
    if (!points) return false;
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      const Entry& e = entries_[k];
      const double d = *problem_.data.points[e.point].value[static_cast<std::size_t>(e.q)];
      r[k] = (model_value((*points)[e.point].result, e.q) - d) / uncertainty(e);
      // A captured impact has t_contact = inf: an evaluation Ceres cannot use. Said so (false)
      // rather than handed over: a trial step into capture is then rejected like any failed
      // step, and a start in capture moves to the scan (fit()); handed over, Ceres stopped the
      // fit and dumped its residual block to the log.
      if (!std::isfinite(r[k])) {
        last_failure_ = at(theta) + ", v0 = " + std::to_string(velocities_[e.point]) +
                        " m/s: the model's " + std::string(to_string(e.q)) + " is not finite" +
                        (e.q == Quantity::t_contact ? " (captured: no rebound)" : "");
        return false;
      }
    }
    return true;
  }

  const CalibrationProblem& problem() const { return problem_; }

 private:
  const CalibrationProblem& problem_;
  std::vector<std::string> names_;
  int threads_;
  std::vector<double> velocities_;
  std::vector<Entry> entries_;
  std::array<double, 3> sigma_{};  // > 0: estimated sigma of that quantity
  mutable std::atomic<long> evaluations_{0};
  // Ceres evaluates residuals on one thread (Solver::Options::num_threads = 1, the default);
  // the impacts of one evaluation run in parallel inside run_model_points.
  mutable std::string last_failure_;

  std::string at(const std::vector<double>& theta) const {
    std::ostringstream os;
    os.precision(6);
    os << "at";
    for (std::size_t j = 0; j < theta.size(); ++j)
      os << (j ? ", " : " ") << names_[j] << " = " << theta[j];
    return os.str();
  }
};

// Ceres' view: p parameter blocks of size 1, x_j = theta_j / theta0_j.
struct CostFunctor {
  const Model* model;
  std::vector<double> theta0;
  bool operator()(double const* const* x, double* r) const {
    std::vector<double> theta(theta0.size());
    for (std::size_t j = 0; j < theta.size(); ++j) theta[j] = theta0[j] * x[j][0];
    return model->residuals(theta, r);
  }
};

using Cost = ceres::DynamicNumericDiffCostFunction<CostFunctor, ceres::CENTRAL>;

struct Scaled {
  std::vector<double> theta0;        // theta = theta0 * x
  std::vector<double> lower, upper;  // bounds on theta
};

// A Ceres problem over x (p blocks of size 1, x = 1 at theta0); `fixed` blocks held constant.
struct CeresProblem {
  std::vector<double> x;
  ceres::Problem problem;
  CeresProblem(const Model& model, const Scaled& s, const std::vector<bool>& fixed)
      : x(s.theta0.size(), 1.0) {
    ceres::NumericDiffOptions nd;
    nd.relative_step_size = kRelativeStep;
    auto* cost = new Cost(new CostFunctor{&model, s.theta0}, ceres::TAKE_OWNERSHIP, nd);
    for (std::size_t j = 0; j < x.size(); ++j) cost->AddParameterBlock(1);
    cost->SetNumResiduals(static_cast<int>(model.residual_count()));
    std::vector<double*> blocks;
    for (auto& v : x) blocks.push_back(&v);
    problem.AddResidualBlock(cost, nullptr, blocks);
    for (std::size_t j = 0; j < x.size(); ++j) {
      problem.SetParameterLowerBound(&x[j], 0, s.lower[j] / s.theta0[j]);
      if (std::isfinite(s.upper[j]))
        problem.SetParameterUpperBound(&x[j], 0, s.upper[j] / s.theta0[j]);
      if (!fixed.empty() && fixed[j]) problem.SetParameterBlockConstant(&x[j]);
    }
  }
};

// Ceres logs through glog to stderr ("Terminating: Residual and Jacobian evaluation failed.",
// dumps of residual blocks): words for Ceres' developers, not for ivv's users, who get every
// failure from the Summary in calibrate's own words. Below FATAL, its log is switched off once.
void silence_ceres_log() {
  static const bool silenced = [] {
    FLAGS_minloglevel = google::GLOG_FATAL;
    return true;
  }();
  (void)silenced;
}

ceres::Solver::Options solver_options(int max_iterations) {
  silence_ceres_log();
  ceres::Solver::Options o;
  o.linear_solver_type = ceres::DENSE_QR;
  o.max_num_iterations = max_iterations;
  // Convergence far below what the data resolve: a relative change of the cost of 1e-12, of
  // a parameter of 1e-10 (the recovery case needs the estimate to the integration error).
  o.function_tolerance = 1e-12;
  o.parameter_tolerance = 1e-10;
  o.gradient_tolerance = 1e-14;
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  return o;
}

// Reports the fit's iterations to CalibrationOptions::progress.
class FitProgress : public ceres::IterationCallback {
 public:
  FitProgress(const Progress& progress, int max_iterations)
      : progress_(progress), max_(static_cast<std::size_t>(max_iterations)) {}
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& s) override {
    progress_("fit", static_cast<std::size_t>(s.iteration), max_);
    return ceres::SOLVER_CONTINUE;
  }

 private:
  const Progress& progress_;
  std::size_t max_;
};

// Minimises over the free parameters from theta0; returns theta at the minimum.
std::pair<std::vector<double>, ceres::Solver::Summary> solve(const Model& model, const Scaled& s,
                                                             const std::vector<bool>& fixed,
                                                             int max_iterations) {
  CeresProblem cp(model, s, fixed);
  ceres::Solver::Summary summary;
  ceres::Solver::Options options = solver_options(max_iterations);
  FitProgress progress(model.progress, max_iterations);
  if (model.progress && fixed.empty()) options.callbacks.push_back(&progress);  // the fit proper
  ceres::Solve(options, &cp.problem, &summary);
  std::vector<double> theta(s.theta0.size());
  for (std::size_t j = 0; j < theta.size(); ++j) theta[j] = s.theta0[j] * cp.x[j];
  return {theta, summary};
}

double chi2_at(const Model& model, const std::vector<double>& theta) {
  std::vector<double> r(model.residual_count());
  if (!model.residuals(theta, r.data())) return std::numeric_limits<double>::infinity();
  double c = 0;
  for (double v : r) c += v * v;
  return c;
}

}  // namespace

namespace {

Scaled scaled_problem(const CalibrationProblem& problem, const CalibrationOptions& options) {
  Scaled s;
  for (const auto& name : options.fit) {
    const double start = parameter_value(problem.request, name);
    if (!(std::isfinite(start) && start > 0))
      throw InputError("--fit", name + " starts at " + std::to_string(start) +
                                    "; a fit starts from a finite value > 0 (give one with "
                                    "--param or in the scene)");
    ParameterInfo info = parameter_info(problem.request, name);
    double lo = std::max(info.lower, kDefaultLowerFactor * start), hi = info.upper;
    if (auto it = options.bounds.find(name); it != options.bounds.end()) {
      lo = it->second.lower > 0 ? it->second.lower : lo;
      hi = it->second.upper;
    }
    if (!(start >= lo && start <= hi))
      throw InputError("--bounds " + name, "the start value " + std::to_string(start) +
                                               " lies outside [" + std::to_string(lo) + ", " +
                                               std::to_string(hi) + "]");
    s.theta0.push_back(start);
    s.lower.push_back(lo);
    s.upper.push_back(hi);
  }
  return s;
}

// The coarse scan: the best point of a log grid of factors around the start, within bounds.
std::vector<double> scan_start(const Model& model, const Scaled& s) {
  const double factors[] = {0.1, 0.31622776601683794, 1.0, 3.1622776601683795, 10.0};
  const std::size_t p = s.theta0.size();
  std::size_t combos = 1;
  for (std::size_t j = 0; j < p; ++j) combos *= 5;
  std::vector<double> best = s.theta0;
  double best_chi2 = chi2_at(model, best);
  for (std::size_t c = 0; c < combos; ++c) {
    std::vector<double> theta(p);
    std::size_t k = c;
    bool inside = true;
    for (std::size_t j = 0; j < p; ++j, k /= 5) {
      theta[j] = s.theta0[j] * factors[k % 5];
      inside = inside && theta[j] >= s.lower[j] && theta[j] <= s.upper[j];
    }
    if (!inside) continue;
    const double c2 = chi2_at(model, theta);
    if (c2 < best_chi2) best_chi2 = c2, best = theta;
  }
  return best;
}

// sigma_q^2 = sum r^2 / (n_q (1 - p/n)) in data units, for each quantity whose sigma is estimated.
bool estimate_noise(Model& model, const std::vector<double>& theta) {
  std::vector<double> r(model.residual_count());
  if (!model.residuals(theta, r.data())) return false;
  const double n = static_cast<double>(r.size()), p = static_cast<double>(model.parameter_count());
  for (Quantity q : kQuantities) {
    if (!model.sigma_estimated(q)) continue;
    double sum = 0, nq = 0;
    for (std::size_t k = 0; k < r.size(); ++k)
      if (model.entries()[k].q == q) sum += std::pow(r[k] * model.sigma(q), 2), nq += 1;
    const double s2 = sum / (nq * std::max(1e-12, 1 - p / n));
    // exact data (sum = 0) would give sigma = 0: keep a floor far below any real scatter
    model.sigma(q) = std::max(std::sqrt(s2), 1e-12 * model.sigma(q));
  }
  return true;
}

// J = d r / d ln theta at theta (the problem rebuilt around theta).
std::optional<Eigen::MatrixXd> jacobian(const Model& model, const std::vector<double>& theta) {
  Scaled around{theta, std::vector<double>(theta.size(), 0.0),
                std::vector<double>(theta.size(), std::numeric_limits<double>::infinity())};
  for (std::size_t j = 0; j < theta.size(); ++j) around.lower[j] = 1e-300;
  CeresProblem cp(model, around, {});
  ceres::CRSMatrix crs;
  double cost = 0;
  if (!cp.problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, &crs))
    return std::nullopt;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(crs.num_rows, crs.num_cols);
  for (int row = 0; row < crs.num_rows; ++row)
    for (int k = crs.rows[row]; k < crs.rows[row + 1]; ++k) J(row, crs.cols[k]) = crs.values[k];
  return J;
}

// Ceres' covariance of ln theta at theta, dropping `null_rank` directions.
std::optional<Eigen::MatrixXd> ceres_covariance(const Model& model,
                                                const std::vector<double>& theta, int null_rank,
                                                std::string& why) {
  Scaled around{theta, std::vector<double>(theta.size(), 1e-300),
                std::vector<double>(theta.size(), std::numeric_limits<double>::infinity())};
  CeresProblem cp(model, around, {});
  ceres::Covariance::Options o;
  o.algorithm_type = ceres::DENSE_SVD;
  o.null_space_rank = null_rank;
  ceres::Covariance covariance(o);
  std::vector<const double*> blocks;
  for (const auto& v : cp.x) blocks.push_back(&v);
  if (!covariance.Compute(blocks, &cp.problem)) {
    why =
        "Ceres Covariance::Compute failed: the Jacobian is rank deficient beyond the "
        "unidentifiable directions dropped (" +
        std::to_string(null_rank) + ")";
    return std::nullopt;
  }
  const auto p = static_cast<Eigen::Index>(theta.size());
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> c(p, p);
  covariance.GetCovarianceMatrix(blocks, c.data());
  return Eigen::MatrixXd(c);
}

std::string join_names(const std::vector<std::string>& names, const Eigen::VectorXd& v) {
  std::ostringstream os;
  os.precision(3);
  bool first = true;
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    if (std::abs(v(j)) < 0.1) continue;
    os << (first ? "" : (v(j) < 0 ? " - " : " + ")) << (first && v(j) < 0 ? "-" : "");
    if (std::abs(v(j)) < 0.9995) os << std::abs(v(j)) << " ";
    os << "ln " << names[static_cast<std::size_t>(j)];
    first = false;
  }
  return os.str();
}

}  // namespace

namespace {

// Profile chi^2 at theta_j = value (others re-fitted from `theta`), minus the target.
struct Profile {
  const Model& model;
  const Scaled& s;
  std::vector<double> theta;  // warm start, updated
  std::size_t j;
  double target;  // chi2_min + t^2
  int max_iterations;
  std::vector<bool> held;  // unidentifiable parameters: held at the estimate
  double operator()(double log_value) {
    std::vector<double> t = theta;
    t[j] = std::exp(log_value);
    if (theta.size() > 1) {
      Scaled around = s;
      around.theta0 = t;
      std::vector<bool> fixed = held;
      fixed[j] = true;
      auto solved = solve(model, around, fixed, max_iterations).first;
      if (std::isfinite(chi2_at(model, solved))) theta = solved, t = solved;
    }
    return chi2_at(model, t) - target;
  }
};

// One end of the profile interval in direction `sign`; NaN when the profile stays below the
// threshold up to the bound (or 2^6 standard errors).
double profile_end(Profile profile, double log_hat, double se_log, double bound, double sign) {
  double a = log_hat, b = log_hat;
  double fb = -1;
  for (double k = 1; k <= 64 && fb < 0; k *= 2) {
    a = b;
    b = log_hat + sign * k * se_log;
    if (sign * (b - std::log(bound)) > 0) b = std::log(bound);
    fb = profile(b);
    if (fb < 0 && b == std::log(bound)) return kNaN;
  }
  if (fb < 0) return kNaN;
  std::uintmax_t iterations = 30;
  const auto root =
      boost::math::tools::toms748_solve(profile, std::min(a, b), std::max(a, b),
                                        boost::math::tools::eps_tolerance<double>(20), iterations);
  return std::exp(0.5 * (root.first + root.second));
}

void profile_intervals(const Model& model, const Scaled& s, const std::vector<double>& theta,
                       double chi2_min, double t, CalibrationResult& out, int max_iterations) {
  std::size_t ends = 0, done = 0;
  for (const auto& pe : out.parameters) ends += pe.identifiable && !pe.at_bound ? 2 : 0;
  for (std::size_t j = 0; j < theta.size(); ++j) {
    ParameterEstimate& pe = out.parameters[j];
    if (!pe.identifiable || pe.at_bound) continue;
    if (model.progress) model.progress("profile intervals", done, ends);
    const double se_log = pe.standard_error / pe.value;
    std::vector<bool> held(theta.size());
    for (std::size_t k = 0; k < theta.size(); ++k) held[k] = !out.parameters[k].identifiable;
    Profile prof{model, s, theta, j, chi2_min + t * t, max_iterations, held};
    const double lo = profile_end(prof, std::log(pe.value), se_log, s.lower[j], -1);
    if (model.progress) model.progress("profile intervals", ++done, ends);
    const double hi = profile_end(prof, std::log(pe.value), se_log, s.upper[j], +1);
    if (model.progress) model.progress("profile intervals", ++done, ends);
    pe.profile95 = std::make_pair(lo, hi);
    pe.profile_differs =
        !std::isfinite(lo) || !std::isfinite(hi) ||
        std::abs(lo - pe.lower95) > kProfileDisagreement * (pe.value - pe.lower95) ||
        std::abs(hi - pe.upper95) > kProfileDisagreement * (pe.upper95 - pe.value);
  }
}

// Identifiability by the SVD of J = d r / d ln theta; returns the number of dropped directions
// and fills identifiable flags, sentences and the correlation matrix.
//
// A direction k with 1/s_k > kUnidentifiable is dropped. Whether a parameter j is
// unidentifiable with it depends on whether J resolves the direction at all:
//   - resolved (s_k above the resolution s_res below): its variance there is V_jk^2 / s_k^2,
//     summed over every resolved direction; j is unidentifiable when the sum exceeds
//     kUnidentifiable^2;
//   - unresolved (s_k <= s_res, including s_k = 0 for a parameter without any effect): the
//     direction is a combination the data do not see, and V_jk / s_k means nothing (0/0 for an
//     exactly null direction, which once made every parameter unidentifiable beside one without
//     effect; noise over noise for a column of integration error). j is unidentifiable when it
//     has a share V_jk^2 >= kCombinationShare in such a direction: it moves with it.
// s_res: each entry of J carries an integration error of at most kIntegrationShare /
// kRelativeStep = 1e-2 (validation/model_runs.h: runs within 1e-5 u, central differences of
// relative step 1e-3), so a direction of J with singular value below 1e-2 sqrt(n) cannot be told
// from none; and never below the SVD's own round-off, kNullDirection s_max.
int identifiability(const Eigen::MatrixXd& J, const std::vector<std::string>& names,
                    CalibrationResult& out) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeFullV);
  const Eigen::VectorXd sv = svd.singularValues();
  const Eigen::MatrixXd V = svd.matrixV();
  const auto p = V.rows();
  const double smax = sv.size() ? sv(0) : 0.0;
  const double s_res = std::max(kIntegrationShare / kRelativeStep * std::sqrt(double(J.rows())),
                                kNullDirection * smax);
  Eigen::MatrixXd pinv = Eigen::MatrixXd::Zero(p, p);     // over numerically non-null directions
  Eigen::VectorXd var_log = Eigen::VectorXd::Zero(p);     // over resolved directions
  Eigen::VectorXd unresolved = Eigen::VectorXd::Zero(p);  // share in unresolved directions
  int dropped = 0;
  for (Eigen::Index k = 0; k < p; ++k) {
    const double s = k < sv.size() ? sv(k) : 0.0;
    const bool resolved = s > s_res;
    for (Eigen::Index j = 0; j < p; ++j)
      (resolved ? var_log(j) : unresolved(j)) += V(j, k) * V(j, k) / (resolved ? s * s : 1.0);
    if (s > kNullDirection * smax) pinv += V.col(k) * V.col(k).transpose() / (s * s);
    if (resolved && 1.0 / s <= kUnidentifiable) continue;
    ++dropped;
    out.unidentifiable.push_back(resolved
                                     ? "the data determine " + join_names(names, V.col(k)) +
                                           " only to a standard error of " +
                                           std::to_string(1.0 / s) + " (unidentifiable combination)"
                                     : "the data do not determine " + join_names(names, V.col(k)) +
                                           " (no effect within the resolution of the model runs)");
  }
  out.correlation.assign(static_cast<std::size_t>(p),
                         std::vector<double>(static_cast<std::size_t>(p)));
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < p; ++j)
      out.correlation[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] =
          pinv(i, j) / std::sqrt(pinv(i, i) * pinv(j, j));
  for (Eigen::Index j = 0; j < p; ++j)
    out.parameters[static_cast<std::size_t>(j)].identifiable =
        std::sqrt(var_log(j)) <= kUnidentifiable && unresolved(j) < kCombinationShare;
  return dropped;
}

}  // namespace

namespace {

void fill_residuals(const Model& model, const std::vector<ModelPoint>& points,
                    CalibrationResult& out) {
  out.chi2 = 0;
  out.stated_error = 0;
  for (const auto& p : points) out.stated_error = std::max(out.stated_error, p.estimated_error);
  for (const Entry& e : model.entries()) {
    const Measurement& m = model.problem().data.points[e.point];
    Residual r;
    r.v0 = m.v0;
    r.quantity = e.q;
    r.measured = *m.value[static_cast<std::size_t>(e.q)];
    r.model = model_value(points[e.point].result, e.q);
    r.uncertainty = model.uncertainty(e);
    r.normalised = (r.model - r.measured) / r.uncertainty;
    r.line = m.line;
    out.chi2 += r.normalised * r.normalised;
    out.residuals.push_back(r);
  }
}

void fill_estimates(const std::vector<double>& theta, const Scaled& s, const Eigen::MatrixXd& cov,
                    double t, CalibrationResult& out) {
  const std::size_t p = theta.size();
  out.covariance.resize(p);
  for (auto& row : out.covariance) row.assign(p, 0.0);
  for (std::size_t i = 0; i < p; ++i)
    for (std::size_t j = 0; j < p; ++j)
      if (out.parameters[i].identifiable && out.parameters[j].identifiable)
        out.covariance[i][j] =
            theta[i] * theta[j] * cov(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
  for (std::size_t j = 0; j < theta.size(); ++j) {
    ParameterEstimate& pe = out.parameters[j];
    pe.lower_bound = s.lower[j];
    pe.upper_bound = s.upper[j];
    pe.at_bound = theta[j] <= s.lower[j] * (1 + 1e-9) || theta[j] >= s.upper[j] * (1 - 1e-9);
    if (!pe.identifiable) {
      pe.value = pe.standard_error = pe.lower95 = pe.upper95 = kNaN;
      continue;
    }
    const auto jj = static_cast<Eigen::Index>(j);
    pe.value = theta[j];
    pe.standard_error = theta[j] * std::sqrt(std::max(0.0, cov(jj, jj)));
    // linearised in ln theta, where J was taken: a positive parameter's interval stays
    // positive (theta +- t SE can go below 0 when SE is comparable to theta)
    const double se_log = std::sqrt(std::max(0.0, cov(jj, jj)));
    pe.lower95 = pe.value * std::exp(-t * se_log);
    pe.upper95 = pe.value * std::exp(t * se_log);
  }
}

bool converged(const ceres::Solver::Summary& summary) {
  return summary.termination_type == ceres::CONVERGENCE;
}

struct FitOutcome {
  std::vector<double> theta;
  ceres::Solver::Summary summary;
  std::string note;  // how the start was found when it was not the request's
};

// The fit from s.theta0, with the noise re-estimated once where it is not stated (the second
// solve starts at the first's minimum and must converge too).
FitOutcome fit_from(Model& model, const Scaled& s, const CalibrationOptions& options,
                    bool noise_estimated) {
  FitOutcome out;
  std::tie(out.theta, out.summary) = solve(model, s, {}, options.max_iterations);
  if (noise_estimated && converged(out.summary) && estimate_noise(model, out.theta)) {
    Scaled again = s;
    again.theta0 = out.theta;
    std::tie(out.theta, out.summary) = solve(model, again, {}, options.max_iterations);
    estimate_noise(model, out.theta);
  }
  return out;
}

// The fit: from the request's start (or the scan's, with options.scan). When Ceres does not
// converge from the request's start (NO_CONVERGENCE: the iteration limit, typically a start in
// a flat or distant region), the fit starts again once from the best point of the coarse scan,
// with the noise estimate reset, and says so. A fit that still did not converge is returned as
// it is; calibrate() turns it into a failure.
FitOutcome fit(Model& model, Scaled& s, const CalibrationOptions& options, bool noise_estimated) {
  const std::array<double, 3> sigma_start = model.sigmas();
  if (options.scan) s.theta0 = scan_start(model, s);
  FitOutcome out = fit_from(model, s, options, noise_estimated);
  if (converged(out.summary) || options.scan || s.theta0.size() > kScanMaxParameters) return out;
  const std::string first = out.summary.message;
  model.set_sigmas(sigma_start);
  s.theta0 = scan_start(model, s);
  out = fit_from(model, s, options, noise_estimated);
  out.note = "Ceres did not converge from the given start (" + first +
             "); the fit was started again from the best point of a coarse scan (as --scan)";
  return out;
}

// Bad input named by its data row, before any fit: a v0 the scene cannot run (1e308 m/s
// overflows its scales: validate()'s own check at the slowest and the fastest row, the scales
// being powers of v0) and a stated uncertainty below what the model resolves
// (kSmallestResolvableUncertainty; e absolute, the others relative).
void check_rows(const CalibrationProblem& problem) {
  SimulationRequest r = problem.request;
  validate(r);  // the request itself, at the scene's v0: its own fields named
  const auto [slowest, fastest] =
      std::minmax_element(problem.data.points.begin(), problem.data.points.end(),
                          [](const Measurement& a, const Measurement& b) { return a.v0 < b.v0; });
  for (const Measurement* m : {&*slowest, &*fastest}) {
    r.scene.velocity = m->v0;
    try {
      validate(r);
    } catch (const InputError& e) {
      std::ostringstream os;
      os << "the impact at v0 = " << m->v0 << " m/s cannot be modelled with this scene ("
         << e.what() << ")";
      throw InputError(problem.data.source + ":" + std::to_string(m->line) + ":v0", os.str());
    }
  }
  for (const auto& m : problem.data.points) {
    const std::string row = problem.data.source + ":" + std::to_string(m.line) + ":";
    for (Quantity q : kQuantities) {
      const auto qi = static_cast<std::size_t>(q);
      if (!m.value[qi] || !m.uncertainty[qi]) continue;
      const double u = q == Quantity::e ? *m.uncertainty[qi] : *m.uncertainty[qi] / *m.value[qi];
      if (!(u >= kSmallestResolvableUncertainty)) {
        std::ostringstream os;
        os << "must be >= " << kSmallestResolvableUncertainty
           << (q == Quantity::e ? "" : " of the value")
           << ", the smallest uncertainty the model's integration error stays far below (got "
           << *m.uncertainty[qi] << ")";
        throw InputError(row + "u_" + std::string(to_string(q)), os.str());
      }
    }
  }
}

}  // namespace

double smallest_relative_uncertainty(const MeasuredData& data) {
  double u = std::numeric_limits<double>::infinity();
  for (const auto& m : data.points)
    for (Quantity q : kQuantities) {
      const auto qi = static_cast<std::size_t>(q);
      if (!m.value[qi] || !m.uncertainty[qi]) continue;
      // e is already in units of v0; F_max and t_contact relative to their value
      u = std::min(u, q == Quantity::e ? *m.uncertainty[qi] : *m.uncertainty[qi] / *m.value[qi]);
    }
  bool all_stated = true;
  for (Quantity q : kQuantities)
    all_stated = all_stated && (!data.has_quantity[static_cast<std::size_t>(q)] ||
                                data.has_uncertainty[static_cast<std::size_t>(q)]);
  return all_stated && std::isfinite(u) ? u : std::min(u, kDefaultSmallestUncertainty);
}

const ParameterEstimate* CalibrationResult::find(const std::string& name) const {
  for (const auto& p : parameters)
    if (p.name == name) return &p;
  return nullptr;
}

void CalibrationOptions::validate(const SimulationRequest& request) const {
  check_fit_names(request, fit);
  for (const auto& [name, b] : bounds) {
    if (std::find(fit.begin(), fit.end(), name) == fit.end())
      throw InputError("--bounds", "bounds for '" + name + "', which is not fitted (--fit)");
    if (!(b.lower >= 0 && b.upper > b.lower && !std::isnan(b.upper)))
      throw InputError("--bounds " + name, "must be LO:HI with 0 <= LO < HI");
  }
  if (max_iterations < 1) throw InputError("max_iterations", "must be >= 1");
}

namespace {

// The parameters as the result lists them, before the fit: name, unit, start.
std::vector<ParameterEstimate> parameter_list(const CalibrationProblem& problem,
                                              const CalibrationOptions& options, const Scaled& s) {
  std::vector<ParameterEstimate> out;
  for (std::size_t j = 0; j < s.theta0.size(); ++j) {
    const ParameterInfo info = parameter_info(problem.request, options.fit[j]);
    ParameterEstimate pe;
    pe.name = info.name;
    pe.unit = info.unit;
    pe.start = s.theta0[j];
    out.push_back(pe);
  }
  return out;
}

std::string termination_name(const ceres::Solver::Summary& summary) {
  return ceres::TerminationTypeToString(summary.termination_type);
}

// An estimated noise needs residuals left over: with n <= p (or no degrees of freedom once the
// determined directions are counted) the fitted parameters can absorb every residual, sigma is
// 0/0, and every standard error built on it is undefined. Returns the failure, or "".
std::string undefined_noise(const Model& model, const std::vector<double>& theta,
                            const CalibrationResult& out) {
  if (out.dof > 0 && model.residual_count() > model.parameter_count()) return "";
  std::ostringstream os;
  os.precision(6);
  os << "the noise of";
  for (Quantity q : kQuantities)
    if (model.sigma_estimated(q)) os << " " << to_string(q);
  os << " is not stated (no u_ column) and would be estimated from the residuals, but "
     << model.residual_count() << " residuals leave " << std::max(out.dof, 0)
     << " degrees of freedom for " << model.parameter_count()
     << " fitted parameters: the noise is undefined, and so is every standard error and "
        "interval. The values that fit the data:";
  for (std::size_t j = 0; j < theta.size(); ++j)
    os << (j ? ", " : " ") << model.names()[j] << " = " << theta[j];
  os << ". State the uncertainty (a u_e column) or add measurements";
  return os.str();
}

// A start for the dashpot when c or zeta is fitted and the scene has none. Zener's lambda =
// m*^{3/5} K_h^{2/5} v0^{1/5} / c spans, from 0.01 to 100, dashpots from negligible (e within
// about 1 % of the undamped) to strong enough for capture, whatever the law: the c of each of
// these 9 lambdas (log-spaced) at the data's median v0 is tried with the other parameters at
// their starts, and the best chi^2 sets the scene's dashpot. Returns the note saying so, or ""
// when there was nothing to do or no candidate ran (then the start stays missing and the fit
// is refused with the reason).
std::string start_dashpot_from_scan(CalibrationProblem& problem,
                                    const CalibrationOptions& options) {
  const auto fitted = [&](const char* n) {
    return std::find(options.fit.begin(), options.fit.end(), n) != options.fit.end();
  };
  if (problem.request.scene.damping.kind != Damping::Kind::none || !(fitted("c") || fitted("zeta")))
    return "";
  std::vector<double> v0;
  for (const auto& m : problem.data.points) v0.push_back(m.v0);
  std::nth_element(v0.begin(), v0.begin() + static_cast<long>(v0.size() / 2), v0.end());
  const double median = v0[v0.size() / 2];
  validate(problem.request.scene);
  const DerivedParameters d = derive(problem.request.scene);
  const Model model(problem, {"c"}, options.threads);
  double best_c = 0, best_chi2 = std::numeric_limits<double>::infinity(), best_lambda = 0;
  for (int k = -4; k <= 4; ++k) {
    const double lambda = std::pow(10.0, 0.5 * k);
    const double c = dashpot_for_zener_lambda(d.effective_mass, d.K_h, median, lambda);
    const double chi2 = chi2_at(model, {c});
    if (chi2 < best_chi2) best_chi2 = chi2, best_c = c, best_lambda = lambda;
  }
  if (!(best_c > 0)) return "";
  problem.request.scene.damping = Damping::coefficient(best_c);
  std::ostringstream os;
  os.precision(4);
  os << "the scene has no dashpot to start from: the fit started at c = " << best_c
     << " N s/m (Zener's lambda = " << best_lambda << " at v0 = " << median
     << " m/s), the best of a coarse scan over lambda = 0.01 .. 100";
  return os.str();
}

// Standard errors, intervals, the noise and the chi-square test at the converged theta.
// Returns false with out.failure set when they cannot be computed.
bool fill_uncertainty(const Model& model, const Scaled& s, const std::vector<double>& theta,
                      const CalibrationOptions& options, CalibrationResult& out) {
  bool noise_estimated = false;
  for (Quantity q : kQuantities) noise_estimated = noise_estimated || model.sigma_estimated(q);
  const auto J = jacobian(model, theta);
  if (!J) {
    out.failure = "the Jacobian could not be evaluated at the estimate (a model run failed)";
    return false;
  }
  const int dropped = identifiability(*J, options.fit, out);
  const int p = static_cast<int>(theta.size());
  out.determined = p - dropped;
  out.dof = out.points - out.determined;
  if (noise_estimated) out.failure = undefined_noise(model, theta, out);
  if (!out.failure.empty()) return false;
  double t = 1.959963984540054;  // two-sided 95 % normal quantile
  if (noise_estimated) t = boost::math::quantile(boost::math::students_t(out.dof), 0.975);
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(p, p);
  if (dropped < p) {
    const auto c = ceres_covariance(model, theta, dropped, out.failure);
    if (!c) return false;
    cov = *c;
  }
  fill_estimates(theta, s, cov, t, out);
  for (Quantity q : kQuantities)
    if (model.sigma_estimated(q)) {
      out.sigma[static_cast<std::size_t>(q)] = model.sigma(q);
      out.estimated_noise.push_back(std::string(to_string(q)) +
                                    ": sigma = " + std::to_string(model.sigma(q)) + " " +
                                    std::string(unit(q)) + ", estimated from the residuals");
    }
  if (!noise_estimated && out.dof > 0)
    out.p_value =
        boost::math::cdf(boost::math::complement(boost::math::chi_squared(out.dof), out.chi2));
  const bool profiled = std::any_of(out.parameters.begin(), out.parameters.end(),
                                    [](const auto& pe) { return pe.identifiable && !pe.at_bound; });
  if (options.profile && profiled) {
    const auto start = std::chrono::steady_clock::now();
    const long before = model.evaluations();
    profile_intervals(model, s, theta, out.chi2, t, out, options.max_iterations);
    std::ostringstream os;
    os.precision(3);
    os << "profile intervals: " << model.evaluations() - before << " impacts run in "
       << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
       << " s (--no-profile skips them)";
    out.notes.push_back(os.str());
  }
  return true;
}

}  // namespace

CalibrationResult calibrate(const CalibrationProblem& given, const CalibrationOptions& options) {
  options.validate(given.request);
  check_rows(given);
  CalibrationProblem problem = given;
  problem.request.options.rtol = calibration_rtol(smallest_relative_uncertainty(given.data));
  CalibrationResult out;
  out.law = problem.request.law == LawKind::expression
                ? problem.request.expression.force
                : std::string(to_string(problem.request.law));
  out.rtol = problem.request.options.rtol;
  if (const std::string note = start_dashpot_from_scan(problem, options); !note.empty())
    out.notes.push_back(note);
  Model model(problem, options.fit, options.threads);
  model.progress = options.progress;
  Scaled s = scaled_problem(problem, options);
  out.parameters = parameter_list(problem, options, s);
  bool noise_estimated = false;
  for (Quantity q : kQuantities) noise_estimated = noise_estimated || model.sigma_estimated(q);
  const FitOutcome f = fit(model, s, options, noise_estimated);
  out.solver_report = f.summary.BriefReport();
  if (!f.note.empty()) out.notes.push_back(f.note);
  out.points = static_cast<int>(model.residual_count());
  const auto points = converged(f.summary) ? model.run(f.theta) : std::nullopt;
  if (!converged(f.summary) || !points) {
    out.failure = "the fit did not converge (Ceres: " + termination_name(f.summary) + ", " +
                  f.summary.message +
                  "), so its end point is no estimate; start elsewhere (--start, --scan) or "
                  "narrow the --bounds";
    if (!model.last_failure().empty())
      out.failure += ". The last model run that failed: " + model.last_failure();
    if (converged(f.summary)) out.failure = "a model run failed at the fit's end point";
  } else {
    fill_residuals(model, *points, out);
    out.ok = fill_uncertainty(model, s, f.theta, options, out);
  }
  out.model_evaluations = static_cast<int>(model.evaluations());
  return out;
}

std::string CalibrationResult::brief() const {
  std::ostringstream os;
  os.precision(6);
  if (!ok) return "calibration failed: " + failure + "\n";
  os << "law " << law << ": chi^2 = " << chi2 << " on " << dof << " dof";
  if (p_value)
    os << " (p = " << *p_value << ")";
  else if (!estimated_noise.empty())
    os << " (noise estimated from the residuals: no chi^2 test)";
  else
    os << " (no degrees of freedom left: no chi^2 test)";
  os << '\n';
  for (const auto& p : parameters) {
    os << "  " << p.name << " [" << p.unit << "] = ";
    if (!p.identifiable) {
      os << "UNIDENTIFIABLE\n";
      continue;
    }
    os << p.value << " +- " << p.standard_error << "  (95 %: " << p.lower95 << " .. " << p.upper95
       << ")";
    if (p.at_bound) os << " AT BOUND";
    if (p.profile_differs && p.profile95) {
      // an end the profile never reached within the bounds is no number
      const auto end = [](double v) {
        std::ostringstream e;
        e.precision(6);
        if (std::isfinite(v))
          e << v;
        else
          e << "unbounded";
        return e.str();
      };
      os << "  profile 95 %: " << end(p.profile95->first) << " .. " << end(p.profile95->second);
    }
    os << '\n';
  }
  for (const auto& u : unidentifiable) os << "  " << u << '\n';
  for (const auto& n : notes) os << "  note: " << n << '\n';
  return os.str();
}

}  // namespace ivv::validation
