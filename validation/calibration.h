// Calibration of a contact model to measured restitution: weighted
// nonlinear least squares by Ceres Solver, with the parameter covariance, identifiability,
// and the chi-square test of the fit.
//
// Model and residuals. For impact i at velocity v0_i and each quantity q measured there
// (e, and F_max, t_contact when the file has them), the residual is
//     r_iq = (S_q(v0_i; theta) - D_iq) / u_iq,
// S the model (validation/model_runs.h: --model auto, at the tolerance rule stated there),
// D the measurement and u_iq its stated standard uncertainty. A quantity without a u_ column
// gets one standard deviation sigma_q for all its points, estimated from the residuals
// (sigma_q^2 = sum_i r_iq^2 / (n_q (1 - p/n)), starting from sigma_q = mean |D_q| / 100 and
// re-fitted once with the estimate); the result says so, and the chi-square test is then not
// a test (chi^2/dof = 1 by construction) and no p-value is given.
//
// The fit: theta = theta0 * x, Ceres minimises (1/2) sum r^2 over x with Levenberg-Marquardt,
// derivatives by central differences (DynamicNumericDiffCostFunction, CENTRAL, relative step
// kRelativeStep), bounds per parameter (positive by default, validation/parameters.h), started
// from the request's values or, with `scan`, from the best point of a coarse log grid
// (factors 10^{-1, -1/2, 0, 1/2, 1} around the start, within bounds, up to 3 parameters).
// A dashpot fitted (c or zeta) on a scene without one starts from a coarse scan over Zener's
// lambda = 0.01 .. 100 at the data's median v0 (the result's notes say where).
//
// Uncertainty. At the estimate, J = d r / d ln theta (the problem rebuilt around the estimate,
// so x = theta/theta_hat). With the SVD J = U S V^T, the linearised standard error of
// ln theta_j is sqrt(sum_k V_jk^2 / s_k^2) over the directions J resolves (s_k above the
// integration error of J, 1e-2 sqrt(n): validation/model_runs.h). A direction below that, and
// an exactly null one (a parameter with no effect on the data), is a combination the data do
// not see: the parameters with a share V_jk^2 >= 0.01 in it are unidentifiable with it, and
// the others are untouched (dividing by s_k there gave 0/0 for every parameter).
// A parameter whose standard error of ln theta
// exceeds kUnidentifiable = 1 is UNIDENTIFIABLE: its 95 % interval would span more than a
// factor exp(1.96) ~ 7 either way, so the data cannot determine even its order of magnitude;
// it gets no value, standard error or interval. The directions with 1/s_k > kUnidentifiable are
// dropped from the covariance (Ceres Covariance, DENSE_SVD, null_space_rank = their number):
// the other parameters' errors are conditional on the unidentifiable combinations. The
// correlation matrix is that of the pseudo-inverse over every direction with
// s_k > 1e-12 s_max, so two parameters only their combination determines show +-1.
// The dof are n minus the determined directions (p minus those dropped), which is also the k
// of the information criteria (validation/comparison.h).
// 95 % intervals: linearised in ln theta, theta_hat exp(+-t SE_ln) with SE_ln = SE/theta_hat
// (t = 1.96 with stated uncertainties, Student t with those dof when sigma is estimated), so a
// positive parameter's interval stays positive; to first order in SE_ln it is theta_hat +- t SE.
// Profile-likelihood intervals (the parameter fixed, the others re-fitted, the ends where chi^2
// rises by the same t^2) are computed for every identifiable parameter and reported where they
// differ from the linearised ends by more than 10 % of the linearised half-width.
//
// Noise without degrees of freedom: a sigma estimated from the residuals needs n > p (and
// n > the determined directions). Without them the parameters can absorb every residual, sigma
// is 0/0 and no standard error exists: that is a failure naming the values that fit the data,
// never an interval of zero width.
//
// Cost: the profile intervals re-fit the other parameters at every trial value of each one
// (about 2 x 10 re-fits per parameter); the result's notes state the model runs and the time
// they took, and CalibrationOptions::profile = false (--no-profile) skips them.
//
// Success: Ceres converged (termination CONVERGENCE) and the covariance was computed. When
// Ceres stops without converging from the request's start (NO_CONVERGENCE: the iteration
// limit), the fit starts once more from the coarse scan (up to 3 parameters) and the result
// says so in `notes`. Failure of the solver or of the covariance is CalibrationResult::failure
// with Ceres' own words, never a number that looks like an estimate.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/simulate.h"
#include "validation/measured_data.h"

namespace ivv::validation {

inline constexpr double kUnidentifiable = 1.0;        // SE of ln theta beyond which: unidentifiable
inline constexpr double kProfileDisagreement = 0.10;  // report the profile interval beyond this

struct Bounds {
  double lower = 0.0;  // lower is exclusive when 0 (positive parameters)
  double upper = 0.0;
};

struct CalibrationOptions {
  std::vector<std::string> fit;          // parameter names (validation/parameters.h)
  std::map<std::string, Bounds> bounds;  // overrides of the default bounds
  bool scan = false;                     // coarse scan for the start
  bool profile = true;                   // profile-likelihood intervals
  int threads = 0;                       // model runs in parallel (0: all cores)
  int max_iterations = 100;
  // Called as the work goes: ("fit", Ceres iteration, max_iterations) after each iteration of
  // the fit, ("profile intervals", ends done, ends in all) after each end of a profile
  // interval (each end is a root search of re-fits, the costliest stage on large data).
  std::function<void(std::string_view stage, std::size_t done, std::size_t total)> progress;
  // Throws InputError naming the flag (--fit, --bounds) when invalid for this request.
  void validate(const SimulationRequest& request) const;
};

struct ParameterEstimate {
  std::string name, unit;
  double start = 0.0;
  double lower_bound = 0.0, upper_bound = 0.0;
  bool identifiable = true;
  bool at_bound = false;  // the estimate sits on a bound: its interval is one-sided at best
  // NaN when unidentifiable:
  double value = 0.0;
  double standard_error = 0.0;
  double lower95 = 0.0, upper95 = 0.0;  // linearised in ln theta
  // Profile-likelihood interval, when it was computed (NaN end: the profile did not reach the
  // threshold within the bounds).
  std::optional<std::pair<double, double>> profile95;
  bool profile_differs = false;  // by more than kProfileDisagreement of the half-width
};

struct Residual {
  double v0 = 0.0;
  Quantity quantity = Quantity::e;
  double measured = 0.0, model = 0.0, uncertainty = 0.0;
  double normalised = 0.0;  // (model - measured) / uncertainty
  int line = 0;             // data file line
};

struct CalibrationResult {
  std::string law;  // the law's name, or the expression
  bool ok = false;
  std::string failure;  // why, when !ok
  std::vector<ParameterEstimate> parameters;
  std::vector<std::vector<double>> correlation;  // p x p
  // Covariance of theta [unit_i unit_j], identifiable parameters only (zero rows and columns
  // for the unidentifiable ones, which prediction holds at their start values).
  std::vector<std::vector<double>> covariance;
  std::vector<std::string> unidentifiable;  // sentences naming parameters and combinations
  double chi2 = 0.0;
  int points = 0;                              // residuals (n)
  int determined = 0;                          // directions the data determine (rank of J)
  int dof = 0;                                 // n - determined
  std::optional<double> p_value;               // absent when a sigma was estimated
  std::vector<std::string> estimated_noise;    // e.g. "e: sigma = 0.0123 estimated from residuals"
  std::array<std::optional<double>, 3> sigma;  // per Quantity: the estimated sigma, if any
  std::vector<Residual> residuals;
  double rtol = 0.0;               // the tolerance rule's choice (validation/model_runs.h)
  double stated_error = 0.0;       // the largest stated integration error of e at the estimate
  int model_evaluations = 0;       // impacts run
  std::string solver_report;       // Ceres Summary::BriefReport()
  std::vector<std::string> notes;  // how the fit got there, when not the plain way (a restart)

  double chi2_per_dof() const { return dof > 0 ? chi2 / dof : 0.0; }
  const ParameterEstimate* find(const std::string& name) const;
  std::string brief() const;  // one paragraph for people
};

struct CalibrationProblem {
  SimulationRequest request;  // scene, law (or expression), integrator; v0 ignored
  MeasuredData data;
};

// The u_min of the tolerance rule (validation/model_runs.h): the smallest stated uncertainty
// (e absolute, F_max and t_contact relative), kDefaultSmallestUncertainty where a quantity's
// uncertainty is not stated.
double smallest_relative_uncertainty(const MeasuredData& data);

// Runs the fit (the request's rtol replaced by the tolerance rule's). InputError for bad options or
// a request that cannot start (named flag).
CalibrationResult calibrate(const CalibrationProblem& problem, const CalibrationOptions& options);

}  // namespace ivv::validation
