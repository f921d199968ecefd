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
//                           impact (a Kelvin-Voigt law k z + c zdot is not: F(0) = c v0); or,
//                           for a law that declares its onset force (an adhesive jump-in,
//                           LawProbe::onset_force), F(0) = the declared force, and
//                           static.continuity holds every other point to continuity
//   static.attractive       F >= 0 on loading and on unloading above the permanent set (a
//                           failure unless the law allows tension; reported either way)
//   static.breakpoints      F continuous at each declared kink (segment_end)
//   static.continuity       no jump anywhere, declared or not: loading on [0, z_scan] and
//                           unloading from three z_m are sampled densely (1000 intervals) and
//                           every interval whose force changes by more than 1e-12 F_ref is
//                           bisected down to adjacent doubles; a change that survives is a jump,
//                           reported with its z and the two one-sided values
//                           (verification/continuity_scan.h says what it cannot see). z_scan is
//                           beyond the grid's largest z_m: max(2 z_ref, 1.25 max z_m).
//   static.unloading_switch F continuous where unloading begins (z = z_m)
//   static.loading_monotone F non-decreasing in z on first loading
//   static.unloading_below  unloading at or below loading: no energy created by a cycle
//   static.stiffness        `stiffness` = dF/dz in every regime: automatic differentiation
//                           (Boost.Math autodiff) for laws templated on the scalar; not
//                           applicable to expression laws (their stiffness is a difference)
//   static.stored_energy    `stored_energy` = the integral of the unloading force (Gauss-Kronrod)
//   static.reloading        a cycle z_m -> z1 -> z_m below z_m creates no energy: unloading to
//                           z1 (zdot < 0), then reloading on the same unloading branch (zdot > 0,
//                           as the drivers do: a finite plate reloads the spring within one
//                           contact), the work put in on reloading is at least the work returned
//                           on unloading (1e-10 F_ref z_ref: the quadratures' error); a law whose
//                           reloading is softer than its unloading creates energy and fails
//   static.reloading_beyond reloading meets the loading curve at z_m without a jump, and beyond
//                           z_m loads on the first-loading curve (the history of z_m restored)
// Dynamic checks, over v0 (at least three decades) x damping (none and a dashpot, for laws
// independent of the rate), with the tightest reference available. A run that fails because
// the law is not defined there (LawDomainError, e.g. the linearized law below z_m = 2.25 z_y)
// in the reference and in every integrator alike is outside the law's domain: it is counted
// and named in the details, not judged; a law defined nowhere on the grid fails.
// A check that does not apply to the law, or a claim not made, is skipped with its reason.
// On a scene with a finite plate ([structure] length_x, length_y) the static checks run on the law
// as above, and the dynamic ones on the plate, by its own driver, at each grid velocity without a
// dashpot (verification/conformance_plate.cc): dynamic.energy (the ledger with the plate's
// vibration energy), dynamic.impulse (int F dt = m (v0 - alpha'_final)), dynamic.cor_range and
// dynamic.expected_cor on the final e, dynamic.integrators (the plate's two steppers against a
// tight reference); the COR definitions, the trends and the low-speed and capture claims are
// skipped with their reasons, and so is every dynamic check for a law the plate does not model.
//   dynamic.energy          the energy ledger closes
//   dynamic.cor_range       0 <= e <= 1
//   dynamic.cor_definitions Newton, Poisson and energetic CORs agree
//   dynamic.integrators     the integrators agree with the reference (mp50 when the law is
//                           templated on its scalar, else dp45 at rtol 1e-13, error estimated
//                           from its run at 1e-12): e, F_max, and t_contact for separated runs;
//                           a captured run (no rebound) has no contact time of its own (only
//                           the moment a capture criterion was met), so there e = 0 within
//                           the capture bound e_bound is compared instead, and a separated run
//                           whose e lies within another's capture bound agrees with it
//   dynamic.monotone_v0     e non-increasing in v0            (when claimed)
//   dynamic.monotone_damping e non-increasing in the damping  (when claimed)
//   dynamic.low_speed       e -> 1 as v0 -> 0                 (when claimed)
//   dynamic.increasing_v0   e non-decreasing in v0            (when claimed, adhesive laws)
//   dynamic.captured_below  captured below a stated speed     (when claimed)
//   dynamic.expected_cor    e against the COR the law claims  (when claimed), miss reported; a
//                           captured run against its interval [0, e_bound]
// Before a dynamic check blames the law, each run over its tolerance is repeated tighter
// (detail::Rechecks); an excess gone there is an IntegratorNote under the verdict, not a
// failure; one that persists fails the law.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "solver/plate/plate_impact.h"
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
  // The force the law declares at z = 0 on first loading [N] (law.h: onset_force), or nullopt.
  virtual std::optional<double> onset_force() const { return std::nullopt; }
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
  // One impact on the scene's finite plate (solver/plate/plate_impact.h); empty when the law
  // cannot run on one (a C++ law gets it from law_under_test_on_plate, conformance_plate_law.h).
  // Throws InputError, with the reason, for a law the plate does not model (rate-dependent, or with
  // tension: solver/plate/plate_law.h).
  std::function<PlateImpactResult(const Scene&, const PlateImpactOptions&)> simulate_plate;
  // One impact's trajectory (for the force-deformation loops of the result); may be empty.
  std::function<std::vector<TrajectoryPoint>(const Scene&, const IntegratorOptions&)> trajectory;
};

// What the law's author claims; each claim is a check.
struct Claims {
  bool cor_nonincreasing_in_v0 = true;
  // e non-decreasing in v0 (adhesive laws: captured at low speed, rebounding above); claimed in
  // place of cor_nonincreasing_in_v0 (both at once is a contradiction: run_conformance throws
  // InputError("--cor-increasing-in-v0"))
  bool cor_nondecreasing_in_v0 = false;
  bool cor_nonincreasing_in_damping = true;
  bool elastic_at_low_speed = false;
  // Captured (e = 0, no rebound) at every grid velocity below this speed [m/s], at every
  // damping; without a dashpot, rebounding at every grid velocity at or above it. nullopt: not
  // claimed. A claim no grid velocity lies below is not a claim checked: it fails.
  std::optional<double> captured_below;
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
  std::vector<double> zetas = {0.0, 0.1};  // damping ratios of the series dashpot; 0: none
                                           // (needs a scene with yield, where zeta is defined;
                                           // default_grid of a scene without yield: only 0; of a
                                           // scene with a [structure] and S_y: {0, its zeta})
  std::vector<double> dashpots;            // dashpot coefficients c [N s/m], besides the zetas
                                           // (any scene); rate-dependent laws run only with none
  IntegratorOptions options;               // of the integrators under comparison
  std::vector<IntegratorKind> integrators = {IntegratorKind::odeint_dopri5, IntegratorKind::dp45,
                                             IntegratorKind::gsl_rk8pd,
                                             IntegratorKind::odeint_rosenbrock4};
};

// How a check's tolerance bounds what it measured.
enum class Bound {
  at_most,  // passes when measured <= tolerance (a deviation, an error, a rise)
  at_least  // passes when measured >= tolerance (a lower bound, e.g. the smallest force)
};

struct Check {
  std::string id;
  bool passed = false;
  double measured = 0.0;   // what the check compares with its tolerance, in `unit`
  double reference = 0.0;  // what it would be for an exact law and solver, in `unit`
  double tolerance = 0.0;  // the bound on measured (see `bound`), in `unit`
  Bound bound = Bound::at_most;
  // The unit of measured, reference and tolerance: "-" (a pure number, e.g. a COR), or a scale
  // ("F_ref", "F_ref z_ref", "k_ref", "E0") whose SI value is `unit_si` in `si_unit`.
  std::string unit = "-";
  double unit_si = 1.0;  // one `unit` in SI (NaN for "-")
  std::string si_unit;   // "N", "J", "N/m" ("" for "-")
  // What was compared at the worst point, in SI: the law's (or integrator's) value and its
  // reference (e.g. F(0) = 114400 N against 0 N; delivered e against the claimed e).
  std::optional<double> value, reference_value;
  std::string value_unit;  // of value and reference_value ("N", "J", "-")
  std::string why;         // why the tolerance is what it is
  std::string detail;      // what was measured, where the worst case was
  // measured, reference and tolerance with their unit and SI value, for people:
  // "0.2529 F_ref (3180 N)", "<= 1e-12 F_ref (1.3e-08 N)"
  std::string measured_text() const;
  std::string reference_text() const;
  std::string tolerance_text() const;
  std::string line() const;  // "pass  static.onset  <detail> (measured ..., tolerance ...)"
};

// A check that did not run, and why (not applicable to this law, or not claimed).
struct Skipped {
  std::string id;
  std::string why;
};

struct CorPoint {
  double v0 = 0.0;
  double zeta = 0.0;  // damping ratio (0: no dashpot; NaN: not defined on a scene without yield)
  double c = std::numeric_limits<double>::infinity();  // dashpot [N s/m]; inf: no dashpot
  std::optional<double> e;                             // the reference run; nullopt when it failed
  std::optional<double> e_bound;                       // captured: the true e lies in [0, e_bound]
  std::optional<double> expected;                      // the claimed COR, when claimed
  std::string status;                                  // separated, captured, or the failure reason
  bool finite_plate = false;  // the scene's finite plate struck (e: the final COR)
  // "no dashpot", "zeta = 0.1", "c = 500 N s/m", "finite plate"
  std::string damping_label() const;
};

// One force-deformation loop of the reference run (plotted per law: a loop that encloses a
// negative area creates energy).
struct ForceLoop {
  double v0 = 0.0;           // [m/s]
  std::string damping;       // as CorPoint::damping_label
  std::vector<double> z, F;  // [m], [N]
};

// A difference that the integrator's accuracy explains, not the law: a dynamic check found it at
// the grid's settings, and it was gone when the run was repeated tighter (the integrator at
// 1/1000 of the grid's tolerances, the reference at a tighter tolerance), or it is the looseness
// of a capture bound on which both runs agree (e = 0). Reported under the verdict; it does not
// fail the law.
struct IntegratorNote {
  std::string check;         // the check that found it, e.g. "dynamic.integrators"
  std::string integrator;    // whose accuracy it is ("reference" for the reference run)
  double v0 = 0.0;           // [m/s]
  std::string damping;       // as CorPoint::damping_label
  double error = 0.0;        // what the check measured for this run at the grid's settings
  double tolerance = 0.0;    // the check's tolerance, in the same unit
  double error_tight = NAN;  // the same measure repeated tighter (NaN: not repeated)
  std::string detail;        // in words
  std::string line() const;  // "note  dynamic.integrators  dp45 at v0 = ..., : ..."
};

// The verdict of a law: every check that ran, every check skipped with its reason, the COR
// over the grid and a force-deformation loop. It reports itself, so that every front end (the
// command line, JSON, the HTML report, GoogleTest) prints the same words.
struct ConformanceResult {
  std::string law;
  std::string description;
  std::vector<Check> checks;
  std::vector<Skipped> skipped;
  std::vector<CorPoint> cor;
  std::vector<ForceLoop> loops;
  std::vector<IntegratorNote> notes;  // integrator accuracy, not the law's (see above)
  bool passed() const;
  std::string brief() const;  // one line: verdict, the checks passed, skipped, and failed
  // one line per check, then what was skipped and why, the integrator-accuracy notes, and the
  // e(v0) grid the trend checks used (one line per damping)
  std::string full() const;
  std::string cor_grid() const;  // that grid alone: "  no dashpot  v0 = 0.01: 1, 0.1: 0.98 ..."
  std::string notes_text() const;
  // e(v0) per damping with e = 1 and the claim; F(z) loops of the reference runs
  std::vector<verification::Plot> plots() const;
  const Check* find(std::string_view id) const;  // nullptr when it did not run
  const Skipped* find_skipped(std::string_view id) const;
};
using Report = ConformanceResult;  // the former name, kept for existing code

// {"verdict": "pass"|"fail", "brief", "law": {"name", "description"}, "checks": [{"id",
// "passed", "measured", "reference", "tolerance", "bound", "unit", "unit_si", "si_unit",
// "value", "reference_value", "value_unit", "why", "detail"}], "skipped": [{"id", "why"}],
// "not_applicable" (the same list under its former name), "cor": [{"v0", "zeta", "c", "e",
// "e_bound", "expected", "status"}]} (docs/design.md §5; NaN and absent values are null).
nlohmann::json to_json(const ConformanceResult& result);

ConformanceResult run_conformance(const LawUnderTest& law, const Claims& claims, const Grid& grid);

// A built-in law of the registry, or the expression law of a request (law, parameters and
// expression taken from `request`; scene, integrator and options ignored).
LawUnderTest registry_law(const SimulationRequest& request);

// The default grid on a scene (velocities empty: filled by run_conformance). Dampings: none,
// zeta = 0.1 when the scene has a yield strength (zeta is defined), and the scene's own dashpot
// when it gives one (a ratio, a coefficient, or a structure's coefficient).
Grid default_grid(const Scene& scene);

}  // namespace ivv::conformance
