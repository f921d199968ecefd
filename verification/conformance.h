// Conformance checks of a contact law: is it sound, and does it deliver what it claims?
//
// One implementation behind three front ends: `ivv check-law` (an expression law typed on the
// command line), the C++ API below (any type modelling ivv::ContactLaw, through
// verification/conformance_law.h), and a GoogleTest suite a downstream project instantiates
// for its own law (verification/conformance_gtest.h). The worked examples of examples/ run
// through it in the verification battery.
//
// Static checks (no integrator), on the scene's Hertz scales z_ref = (5 m v0^2/(4 K_h))^{2/5}
// at the grid's largest v0:
//   static.onset            F(0, zdot = v0) = 0 on first loading: the force is continuous at
//                           impact (a Kelvin-Voigt law k z + c zdot is not: F(0) = c v0)
//   static.attractive       F >= 0 on loading and on unloading above the permanent set (a
//                           failure unless the law allows tension; reported either way)
//   static.breakpoints      F continuous at each declared kink (segment_end)
//   static.unloading_switch F continuous where unloading begins (z = z_m)
//   static.loading_monotone F non-decreasing in z on first loading
//   static.unloading_below  unloading at or below loading: no energy created by a cycle
//   static.stiffness        `stiffness` = dF/dz in every regime: automatic differentiation
//                           (Boost.Math autodiff) for laws templated on the scalar; not
//                           applicable to expression laws (their stiffness is a difference)
//   static.stored_energy    `stored_energy` = the integral of the unloading force (Gauss-Kronrod)
// Dynamic checks, over v0 (at least three decades) x damping (none and a dashpot, for laws
// independent of the rate), with the tightest reference available:
//   dynamic.energy          the energy ledger closes
//   dynamic.cor_range       0 <= e <= 1
//   dynamic.cor_definitions Newton, Poisson and energetic CORs agree
//   dynamic.integrators     the integrators agree with the reference (mp50 when the law is
//                           templated on its scalar, else dp45 at rtol 1e-13, error estimated
//                           from its run at 1e-12)
//   dynamic.monotone_v0     e non-increasing in v0            (when claimed)
//   dynamic.monotone_damping e non-increasing in the damping  (when claimed)
//   dynamic.low_speed       e -> 1 as v0 -> 0                 (when claimed)
//   dynamic.expected_cor    e against the COR the law claims  (when claimed), miss reported
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/simulate.h"
#include "verification/plot_data.h"

namespace ivv::conformance {

// A law on one scene, evaluated in double, with its history (loading -> unloading).
class LawProbe {
 public:
  virtual ~LawProbe() = default;
  virtual double force(double z, double zdot) const = 0;           // [N]
  virtual double stiffness(double z, double zdot) const = 0;       // [N/m]
  virtual double rate_stiffness(double z, double zdot) const = 0;  // [N s/m]
  // dF/dz and dF/dzdot by automatic differentiation of the law on the current branch, or
  // nullopt for a law not templated on its scalar.
  virtual std::optional<std::pair<double, double>> autodiff_slopes(double z, double zdot) const = 0;
  virtual std::optional<double> segment_end() const = 0;  // [m]
  virtual void next_segment() = 0;
  virtual void begin_unloading(double z_max) = 0;  // may throw LawDomainError
  virtual double permanent_set() const = 0;        // z_f [m] once unloading
  virtual double stored_energy(double z) const = 0;
  virtual bool stored_energy_is_quadrature() const = 0;  // true: comparing it proves nothing
  virtual void reset() = 0;                              // back to first loading
};

// A law as the checks see it (type-erased; the simulation inside stays templated).
struct LawUnderTest {
  std::string name;
  std::string description;  // the equations, for people
  bool rate_dependent = false;
  bool allows_tension = false;
  bool runs_in_reference = true;  // templated on its scalar: mp50 can run it
  std::function<std::unique_ptr<LawProbe>(const Scene&)> probe;
  std::function<ImpactResult(const Scene&, IntegratorKind, const IntegratorOptions&)> simulate;
};

// What the law's author claims; each claim is a check.
struct Claims {
  bool cor_nonincreasing_in_v0 = true;
  bool cor_nonincreasing_in_damping = true;
  bool elastic_at_low_speed = false;
  // The COR the law is meant to deliver at v0 (no dashpot), and how it was given. It must be a
  // finite number in [0, 1] at every grid velocity: run_conformance throws
  // InputError("--expect-cor") before any run otherwise.
  std::function<double(double v0)> expected_cor;
  std::string expected_cor_text;
  // Allowed |e - expected|. Default: 1e-9, ten times the reference's error of e (mp50 ~1e-12
  // against closed forms; dp45 at rtol 1e-13 ~1e-10, N rtol over N <= 1000 steps), the same
  // bound as the monotonicity checks: a larger miss is the law's, not the integrator's. A claim
  // that is itself approximate (a fitted or truncated formula) states its own accuracy.
  double cor_tolerance = 1e-9;
  std::string cor_tolerance_reason =
      "10x the reference's error of e (mp50 ~1e-12; dp45 at rtol 1e-13 ~1e-10): a larger miss "
      "is the law's";
};

struct Grid {
  Scene scene;                     // materials, mass, radius; velocity and damping are set below
  std::vector<double> velocities;  // v0 [m/s]; empty: 7 points log-spaced over three decades,
                                   // 0.01 to 10 times the scene's v0
  std::vector<double> zetas = {0.0, 0.1};  // 0: no dashpot (rate-dependent laws: only 0;
                                           // default_grid of a scene without yield: only 0;
                                           // of a scene with a [structure] (and S_y): {0, the
                                           // scene's zeta})
  IntegratorOptions options;               // of the integrators under comparison
  std::vector<IntegratorKind> integrators = {IntegratorKind::odeint_dopri5, IntegratorKind::dp45,
                                             IntegratorKind::gsl_rk8pd,
                                             IntegratorKind::odeint_rosenbrock4};
};

struct Check {
  std::string id;
  bool passed = false;
  double measured = 0.0;
  double reference = 0.0;
  double tolerance = 0.0;
  std::string why;     // why the tolerance is what it is
  std::string detail;  // what was measured, where the worst case was
};

struct CorPoint {
  double v0 = 0.0, zeta = 0.0;
  std::optional<double> e;         // the reference run; nullopt when it failed
  std::optional<double> expected;  // the claimed COR, when claimed
  std::string status;              // separated, captured, or the failure reason
};

struct Report {
  std::string law;
  std::string description;
  std::vector<Check> checks;
  std::vector<std::pair<std::string, std::string>> not_applicable;  // id, why
  std::vector<CorPoint> cor;
  bool passed() const;
  std::string brief() const;  // one line: verdict and the failed checks
  std::string full() const;   // one line per check, then what was not applicable
  std::vector<verification::Plot> plots() const;  // e(v0) per damping, with the claim
};

// {"verdict": "pass"|"fail", "law": {"name", "description"}, "checks": [{"id", "passed",
// "measured", "reference", "tolerance", "why", "detail"}], "not_applicable": [{"id", "why"}],
// "cor": [{"v0", "zeta", "e", "expected", "status"}]} (SPEC §5; NaN and absent values are null).
nlohmann::json to_json(const Report& report);

Report run_conformance(const LawUnderTest& law, const Claims& claims, const Grid& grid);

// A built-in law of the registry, or the expression law of a request (law, parameters and
// expression taken from `request`; scene, integrator and options ignored).
LawUnderTest registry_law(const SimulationRequest& request);

// The default grid on a scene (velocities empty: filled by run_conformance).
Grid default_grid(const Scene& scene);

}  // namespace ivv::conformance
