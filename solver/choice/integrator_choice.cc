#include "solver/choice/integrator_choice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "solver/format.h"

namespace ivv {
namespace {

// Undamped maximum compression [m] of the elastoplastic (and, below yield, Hertz) curve, by
// energy (docs/design.md §2): an upper bound on z_m with a dashpot.
double undamped_z_max(const Scene& s, const DerivedParameters& p) {
  const double E0 = 0.5 * p.effective_mass * s.velocity * s.velocity;
  const double sqrt_zy = std::sqrt(p.z_y);
  const double E_y = 0.4 * p.K_h * p.z_y * p.z_y * sqrt_zy;
  if (E0 <= E_y) return std::pow(1.25 * p.effective_mass * s.velocity * s.velocity / p.K_h, 0.4);
  const double b = p.K_h * p.z_y * sqrt_zy;  // (K_y/2) d^2 + b d = E0 - E_y
  const double d = (-b + std::sqrt(b * b + 2.0 * p.K_y * (E0 - E_y))) / p.K_y;
  return p.z_y + d;
}

// Three significant digits: enough for a reason, short enough to read (solver/format.h).
std::string fmt3(double v) {
  return fmt(v, 3);
}

// Without a yield strength (zeta and z_y are NaN there, and a ratio built on them chose dop853
// for chung-ooi-2-aluminium, hertz, c = 1 N s/m, which ran out of steps) the law runs in the
// Hertz scales: the loading time 1/omega = z_mH/v0 and the stiffness at the undamped Hertz
// maximum compression z_mH, 1.5 K_h sqrt(z_mH), so S = 1.5 K_h z_mH^{3/2}/(c v0), the same
// measure (relaxation rate K/c times the loading time) in the law's own scales.
double hertz_stiffness_ratio(const Scene& s, const DerivedParameters& p) {
  const double z_mH = std::pow(1.25 * p.effective_mass * s.velocity * s.velocity / p.K_h, 0.4);
  return 1.5 * p.K_h * z_mH * std::sqrt(z_mH) / (p.c * s.velocity);
}

// Undamped maximum compression [m] in the scene's own scales (Hertz without a yield strength).
double undamped_z(const Scene& s, const DerivedParameters& p) {
  if (p.has_yield()) return undamped_z_max(s, p);
  return std::pow(1.25 * p.effective_mass * s.velocity * s.velocity / p.K_h, 0.4);
}

// The compression [m] at which the loading curve carries `force`: Hertz below the yield force,
// the linear elastic-plastic branch above it (Hertz alone without a yield strength).
double compression_at_force(const DerivedParameters& p, double force) {
  const double hertz = std::cbrt((force / p.K_h) * (force / p.K_h));
  if (!p.has_yield()) return hertz;
  const double F_y = p.K_h * p.z_y * std::sqrt(p.z_y);
  return force <= F_y ? hertz : p.z_y + (force - F_y) / p.K_y;
}

// z_f^{3/2} [m^1.5] of the permanent set z_f of the elastoplastic unloading curve from z_m (0
// below yield).
double permanent_set_three_halves(const DerivedParameters& p, double z_m) {
  if (!p.has_yield() || !(z_m > p.z_y)) return 0.0;
  const double s = z_m * std::sqrt(z_m) - p.z_y * std::sqrt(p.z_y) - p.K_y / p.K_h * (z_m - p.z_y);
  return s > 0 ? s : 0.0;
}

// Permanent set z_f [m] of the elastoplastic unloading curve from z_m (0 below yield).
double permanent_set(const DerivedParameters& p, double z_m) {
  const double s = permanent_set_three_halves(p, z_m);
  return s > 0 ? std::cbrt(s * s) : 0.0;
}

// capture.h criterion 1 expected at z_m: the elastoplastic unloading slope at the permanent set,
// K_f = 1.5 K_h sqrt(z_f), overdamped by the dashpot, K_f m >= 4 c^2, with z_f > 0. As written,
// with z_f = permanent_set(p, z_m).
bool overdamped_at_permanent_set(const DerivedParameters& p, double z_m) {
  const double z_f = permanent_set(p, z_m);
  const double K_f = 1.5 * p.K_h * std::sqrt(z_f);
  return z_f > 0 && K_f * p.effective_mass >= 4.0 * p.c * p.c;
}

// The same decision without the cube root of z_f (~125 instructions of a map's point,
// callgrind), where it is clear: with s = z_f^{3/2} (permanent_set_three_halves), sqrt(z_f) =
// s^{1/3}, so K_f m >= 4 c^2 is s >= T^3, T = 4 c^2/(1.5 K_h m). The two sides as computed here and
// as overdamped_at_permanent_set() computes them are each within ~1e-14 of their exact values, so
// where s/T^3 is more than kClearMargin away from 1 (and every quantity a normal double) both
// give the exact answer; nearer (or with a subnormal, infinite or NaN part) the written form
// decides. The same decision at every z_m (integrator_choice_test.cc, at the boundary too).
constexpr double kClearMargin = 1e-9;
bool overdamped_at_permanent_set_fast(const DerivedParameters& p, double z_m) {
  const double s = permanent_set_three_halves(p, z_m);
  if (!(s > 0)) return false;  // z_f = 0
  const double T = 4.0 * p.c * p.c / (1.5 * p.K_h * p.effective_mass);
  const double ratio = s / (T * T * T);
  if (std::isnormal(s * s) && std::isnormal(T * T * T) && std::isfinite(ratio)) {
    if (ratio > 1.0 + kClearMargin) return true;
    if (ratio < 1.0 - kClearMargin) return false;
  }
  return overdamped_at_permanent_set(p, z_m);
}

// The cost model's powers of tol = rtol / kCostReferenceRtol, which depend on rtol alone: kept for
// the last rtol asked on this thread, since a sweep asks the same one at every point (the three
// pow calls were ~360 instructions of a 300 x 300 map's point, callgrind). The same numbers as
// computing them every time.
struct TolerancePowers {
  double explicit_steps, implicit_steps, dashpot_growth;  // tol^(-1/8), tol^(-1/4), tol^(-0.2)
};
const TolerancePowers& tolerance_powers(double rtol) {
  thread_local double last_rtol = std::numeric_limits<double>::quiet_NaN();
  thread_local TolerancePowers powers{};
  if (!(rtol == last_rtol)) {
    const double tol = rtol / kCostReferenceRtol;
    powers = {std::pow(tol, -1.0 / kCostOrderExplicit), std::pow(tol, -1.0 / kCostOrderImplicit),
              std::pow(tol, -kDashpotImplicitOrder)};
    last_rtol = rtol;
  }
  return powers;
}

}  // namespace

IntegratorCosts estimate_integrator_costs(const Scene& scene, const DerivedParameters& p,
                                          LawKind law, double rtol) {
  IntegratorCosts k;
  const TolerancePowers& powers = tolerance_powers(rtol);
  k.steps_explicit = kAccuracyStepsExplicit * powers.explicit_steps;
  k.steps_implicit = kAccuracyStepsImplicit * powers.implicit_steps;
  // validate() refuses a dashpot for a law that carries its own damping
  if (p.has_dashpot()) {
    const double m = p.effective_mass, v0 = scene.velocity;
    const double z_undamped = undamped_z(scene, p);
    k.z_max = std::min(z_undamped, compression_at_force(p, p.c * v0));
    k.relaxation_rate = 1.5 * p.K_h * std::sqrt(k.z_max) / p.c;
    k.dashpot_time = m / p.c;
    k.dashpot_over_loading = k.dashpot_time * v0 / z_undamped;
    // capture.h criterion 1: the elastoplastic unloading slope floor K_f = 1.5 K_h sqrt(z_f)
    // overdamped by the dashpot, (K_f/c)^2 >= 4 K_f/m
    k.early_capture = law == LawKind::elastoplastic && overdamped_at_permanent_set_fast(p, k.z_max);
    if (k.early_capture) {
      k.steps_implicit *= kEarlyCaptureImplicitFactor;
    } else {
      k.steps_explicit += 3.0 * k.relaxation_rate * k.dashpot_time / kStabilityBoundExplicit;
      k.steps_implicit *= 1.0 + kDashpotImplicitFactor * powers.dashpot_growth *
                                    std::min(1.0, k.dashpot_over_loading / kDashpotSaturation);
    }
  }
  k.us_explicit = kMicrosecondsPerStepExplicit * k.steps_explicit;
  k.us_implicit = kMicrosecondsPerStepImplicit * k.steps_implicit;
  return k;
}

double stiffness_ratio(const Scene& scene, const DerivedParameters& p) {
  // validate() refuses a dashpot for a law that carries its own damping
  if (!p.has_dashpot()) return 0.0;
  if (!p.has_yield()) return hertz_stiffness_ratio(scene, p);
  return 2.0 * p.zeta * std::max(1.0, std::sqrt(undamped_z_max(scene, p) / p.z_y));
}

IntegratorKind auto_integrator(const SimulationRequest& request, const DerivedParameters& p) {
  const IntegratorCosts k =
      estimate_integrator_costs(request.scene, p, request.law, request.options.rtol);
  return k.us_implicit < k.us_explicit ? IntegratorKind::rodas4 : IntegratorKind::dop853;
}

IntegratorChoice choose_integrator(const SimulationRequest& req) {
  IntegratorChoice c;
  const DerivedParameters p = derive(req.scene);
  c.stiffness_ratio = stiffness_ratio(req.scene, p);
  c.costs = estimate_integrator_costs(req.scene, p, req.law, req.options.rtol);
  const IntegratorCosts& k = c.costs;
  const double rtol = req.options.rtol;
  c.reasons.push_back("accuracy alone at rtol " + fmt3(rtol) + ": dop853 ~" +
                      fmt3(kAccuracyStepsExplicit) + " (rtol/1e-8)^(-1/8), rodas4 ~" +
                      fmt3(kAccuracyStepsImplicit) + " (rtol/1e-8)^(-1/4) steps per impact");
  if (!p.has_dashpot()) {
    c.reasons.push_back(law_info(req.law).rate_dependent
                            ? std::string(law_info(req.law).name) +
                                  " carries its own damping, no dashpot: not stiff"
                            : "no dashpot: not stiff");
  } else {
    c.reasons.push_back(
        "damped maximum compression z_m ~ " + fmt3(k.z_max) +
        " m (the undamped one, or less where the loading curve reaches the force c v0 a "
        "dashpot moving at v0 can carry); relaxation rate K(z_m)/c = " +
        fmt3(k.relaxation_rate) + " 1/s over the dashpot time m/c = " + fmt3(k.dashpot_time) +
        " s");
    if (k.early_capture)
      c.reasons.push_back(
          "capture expected at the start of unloading (z_m above yield and the unloading "
          "slope at the permanent set overdamped by the dashpot): the slow creep towards z_f "
          "is not integrated, so neither method pays for the dashpot's stiffness");
    else
      c.reasons.push_back(
          "dop853 is held by stability to |h lambda| <= B = " + fmt3(kStabilityBoundExplicit) +
          " while the dashpot controls the motion: 3 (K/c)(m/c) / B = " +
          fmt3(3.0 * k.relaxation_rate * k.dashpot_time / kStabilityBoundExplicit) +
          " more dop853 steps");
  }
  c.reasons.push_back("estimated cost: dop853 " + fmt3(k.steps_explicit) + " steps ~ " +
                      fmt3(k.us_explicit) + " us, rodas4 " + fmt3(k.steps_implicit) + " steps ~ " +
                      fmt3(k.us_implicit) + " us");
  c.integrator = auto_integrator(req, p);
  const bool implicit = traits(c.integrator).implicit;
  if (implicit)
    c.reasons.push_back(
        "rodas4 (Rosenbrock 4(3), L-stable, dense output) is the cheaper: the dashpot "
        "relaxation would hold dop853 to stability-limited steps");
  else
    c.reasons.push_back(
        "dop853 (explicit eighth order, dense output) is the cheaper: its steps are set by "
        "accuracy, not by the stability of the dashpot relaxation");
  const double factor = implicit ? kAutoErrorFactorImplicit : kAutoErrorFactorExplicit;
  c.estimated_error = factor * rtol;
  c.reasons.push_back("estimated error of e (in v0), F_max, z_max, and of t_f times e: " +
                      fmt3(factor) + " rtol = " + fmt3(c.estimated_error) +
                      " (the global error of " + std::string(to_string(c.integrator)) +
                      " measured on the paper grid, the Hertz law and the stiff scene, checked "
                      "by the autochoice cases)");
  return c;
}

}  // namespace ivv
