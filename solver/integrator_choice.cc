#include "solver/integrator_choice.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "solver/format.h"

namespace ivv {
namespace {

// Undamped maximum compression [m] of the elastoplastic (and, below yield, Hertz) curve, by
// energy (SPEC §2): an upper bound on z_m with a dashpot.
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

// Without a yield strength (zeta and z_y are NaN there, issue 21 item 6) the law runs in the
// Hertz scales: the loading time 1/omega = z_mH/v0 and the stiffness at the undamped Hertz
// maximum compression z_mH, 1.5 K_h sqrt(z_mH), so S = 1.5 K_h z_mH^{3/2}/(c v0), the same
// measure (relaxation rate K/c times the loading time) in the law's own scales.
double hertz_stiffness_ratio(const Scene& s, const DerivedParameters& p) {
  const double z_mH = std::pow(1.25 * p.effective_mass * s.velocity * s.velocity / p.K_h, 0.4);
  return 1.5 * p.K_h * z_mH * std::sqrt(z_mH) / (p.c * s.velocity);
}

}  // namespace

double stiffness_ratio(const Scene& scene, const DerivedParameters& p) {
  // validate() refuses a dashpot for a law that carries its own damping
  if (!p.has_dashpot()) return 0.0;
  if (!p.has_yield()) return hertz_stiffness_ratio(scene, p);
  return 2.0 * p.zeta * std::max(1.0, std::sqrt(undamped_z_max(scene, p) / p.z_y));
}

IntegratorKind auto_integrator(const Scene& scene, const DerivedParameters& p) {
  return stiffness_ratio(scene, p) > kStiffnessThreshold ? IntegratorKind::rodas4
                                                         : IntegratorKind::dop853;
}

IntegratorChoice choose_integrator(const SimulationRequest& req) {
  IntegratorChoice c;
  const DerivedParameters p = derive(req.scene);
  const bool dashpot = p.has_dashpot();
  if (dashpot && !p.has_yield()) {
    c.stiffness_ratio = stiffness_ratio(req.scene, p);
    c.reasons.push_back(
        "stiffness ratio S = 1.5 K_h z_mH^{3/2}/(c v0) = " + fmt3(c.stiffness_ratio) +
        " (dashpot relaxation rate at the Hertz maximum compression z_mH over "
        "the loading rate v0/z_mH: the scene has no yield strength)");
  } else if (dashpot) {
    const double k_max = std::max(1.0, std::sqrt(undamped_z_max(req.scene, p) / p.z_y));
    c.stiffness_ratio = stiffness_ratio(req.scene, p);
    c.reasons.push_back("stiffness ratio S = 2 zeta k_max = 2 x " + fmt3(p.zeta) + " x " +
                        fmt3(k_max) + " = " + fmt3(c.stiffness_ratio) +
                        " (dashpot relaxation rate over the loading rate; k_max = "
                        "sqrt(z_m/z_y) from the undamped z_m)");
  } else {
    c.reasons.push_back(law_info(req.law).rate_dependent
                            ? std::string(law_info(req.law).name) +
                                  " carries its own damping, no dashpot: not stiff (S = 0)"
                            : "no dashpot: not stiff (S = 0)");
  }
  c.integrator = auto_integrator(req.scene, p);
  const bool implicit = traits(c.integrator).implicit;
  if (implicit) {
    c.reasons.push_back("S > " + fmt3(kStiffnessThreshold) +
                        ": stiff, an explicit method would be held to |h lambda| = O(1) by "
                        "stability; implicit rodas4 (Rosenbrock 4(3), L-stable, dense output)");
  } else {
    c.reasons.push_back("S <= " + fmt3(kStiffnessThreshold) +
                        ": not stiff; the eighth-order explicit dop853 (dense output) needs "
                        "the fewest evaluations at rtol " +
                        fmt3(req.options.rtol));
  }
  const double factor = implicit ? kAutoErrorFactorImplicit : kAutoErrorFactorExplicit;
  c.estimated_error = factor * req.options.rtol;
  c.reasons.push_back("estimated error of e (in v0), F_max, z_max, and of t_f times e: " +
                      fmt3(factor) + " rtol = " + fmt3(c.estimated_error) +
                      " (the global error of " + std::string(to_string(c.integrator)) +
                      " measured on the paper grid, the Hertz law and the stiff scene, checked "
                      "by the autochoice cases)");
  return c;
}

}  // namespace ivv
