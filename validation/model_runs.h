// The model evaluations of a calibration or a prediction: one request, a set of parameter
// values, a list of impact velocities; each impact runs with --model auto
// (solver/choice/model_choice.h: a closed form where one exists, the integrator otherwise) on the
// project's one parallel loop (solver/parallel.h), results in velocity order whatever the
// thread count.
//
// The tolerance rule (runs tight enough that the integration error is far below
// the data's noise). --model auto states the error it commits in e (in units of v0, as a
// stated bound: closed forms 1e-14, integrated routes 200-300 rtol,
// solver/choice/integrator_choice.h). A calibration asks for
//     stated error <= kIntegrationShare * u_min,   kIntegrationShare = 1e-5,
// u_min the smallest standard uncertainty of the data (relative for F_max and t_contact), i.e.
// rtol = 1e-5 u_min / 300, clamped to [1e-13, 1e-8]. Central differences of step h (relative,
// kRelativeStep = 1e-3) then carry an error from the integration of at most
// 2 * 1e-5 u / (2 h) = 1e-2 u per unit relative change of a parameter: 1 % of one standard
// uncertainty, so derivatives (and the covariance built from them) are unaffected at the
// level the data can see; the truncation error of the central difference, h^2/6 relative
// (~2e-7), is smaller still. Without stated uncertainties the rule uses u_min = 1e-3 (below
// any COR scatter reported for drop tests), i.e. rtol = 3.3e-11.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv::validation {

inline constexpr double kIntegrationShare = 1e-5;
inline constexpr double kRelativeStep = 1e-3;
inline constexpr double kStatedErrorFactor = 300.0;  // stated error <= 300 rtol (implicit)
inline constexpr double kDefaultSmallestUncertainty = 1e-3;
inline constexpr double kTightestRtol = 1e-13;  // the clamp of the rule (double's round-off)
// The smallest standard uncertainty for which the rule holds at the tightest rtol:
// 300 * 1e-13 / 1e-5 = 3e-6 (in e; relative for F_max and t_contact). Below it the integration
// error is no longer negligible against the data, and a fit would read it as signal.
inline constexpr double kSmallestResolvableUncertainty =
    kStatedErrorFactor * kTightestRtol / kIntegrationShare;

// The rtol of the rule above for the smallest relative standard uncertainty of the data.
double calibration_rtol(double smallest_uncertainty);

struct ModelPoint {
  ImpactResult result;
  double estimated_error = 0.0;  // --model auto's stated error of e (units of v0)
};

// `base` with parameters names[i] = values[i], run at each velocity (model auto, `threads`
// workers; 0 = all). A request that fails validation throws InputError; an impact that fails
// comes back with result.status == failed and its reason.
std::vector<ModelPoint> run_model_points(const SimulationRequest& base,
                                         const std::vector<std::string>& names,
                                         std::span<const double> values,
                                         std::span<const double> velocities, int threads);

}  // namespace ivv::validation
