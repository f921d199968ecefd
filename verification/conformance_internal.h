// Shared by the units of the conformance checks (not installed, not for law authors):
//   conformance_static.cc    the static checks (the law's equations, no integrator)
//   conformance_reloading.cc the static checks of reloading below z_m
//   conformance_dynamic.cc   the grid of impacts and the dynamic checks judged on it
//   conformance_result.cc    the result reporting itself (brief, full, plots, JSON)
//   conformance_registry.cc  the built-in and expression laws of the registry as laws under test
//   conformance_plate.cc     the dynamic checks on a finite plate
//   conformance.cc           run_conformance: the grid completed, then the checks in order
#pragma once

#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "solver/format.h"
#include "verification/conformance.h"

namespace ivv::conformance::detail {

// Rounding of a force formula in double, relative to the force scale F_ref: a few hundred ulps.
inline constexpr double kRounding = 1e-12;
inline constexpr const char* kRoundingWhy =
    "exact in exact arithmetic; 1e-12 F_ref allows the rounding of evaluating the formulas in "
    "double (a few hundred ulps)";
// Two exact derivatives (hand-written and autodiff) differ only by rounding, amplified by the
// conditioning of the formula; 1e-10 of the stiffness scale covers 1e6 ulps.
inline constexpr double kDerivative = 1e-10;
// The reference's error in e: mp50 ~1e-12 against closed forms; dp45 at rtol 1e-13 ~1e-10
// (global error N rtol over N <= 1000 steps). A rise of e above 1e-9 is the law's.
inline constexpr double kMonotone = 1e-9;

// Numbers in sentences: the one formatter (solver/format.h).
using ivv::fmt;

// The Hertz scales of a scene at velocity v: z_ref = (5 m v^2/(4 K_h))^{2/5} [m] (the undamped
// Hertz maximum compression), F_ref = K_h z_ref^{3/2} [N], k_ref = F_ref/z_ref [N/m], v [m/s].
struct Scales {
  double z = 0, F = 0, k = 0, v = 0;
};
Scales hertz_scales(const Scene& s, double v);

inline Check make_check(std::string id, double measured, double reference, double tolerance,
                        bool passed, std::string why, std::string detail) {
  Check c;
  c.id = std::move(id);
  c.passed = passed;
  c.measured = measured;
  c.reference = reference;
  c.tolerance = tolerance;
  c.why = std::move(why);
  c.detail = std::move(detail);
  return c;
}

// Advance a fresh probe along first loading to z (through every kink below z).
void load_to(LawProbe& probe, double z);

// "no dashpot", "zeta = 0.1", "c = 500 N s/m"
std::string damping_label(const Damping& d);

// The scene of one grid point: velocity v0 and the dashpot.
Scene at(const Scene& base, double v0, const Damping& damping);

// One grid point: the reference run and every integrator's run.
struct Run {
  double v0 = 0;
  Damping damping;
  double zeta = 0;  // the damping ratio (0: no dashpot; NaN: a coefficient on a scene without
                    // yield, where zeta is not defined)
  double c = std::numeric_limits<double>::infinity();  // the dashpot [N s/m]; inf: none
  ImpactResult reference;
  double reference_error = 0;  // estimate (double-precision reference only)
  std::vector<std::pair<IntegratorKind, ImpactResult>> runs;
};

// Every impact of the grid (the dampings a rate-dependent law cannot take are left out).
std::vector<Run> run_grid(const LawUnderTest& law, const Grid& grid);

// The runs of the grid repeated tighter, before a dynamic check blames the law for a difference
// (conformance.h: IntegratorNote): an integrator at 1/1000 of the grid's rtol and atol (not
// below 1e-13 and 1e-15, where double rounding takes over), the reference at a tolerance ten
// times tighter (mp50 at 1e-4 of its own; the double-precision reference, dp45 at rtol 1e-13,
// at 1e-14). Each run is repeated once, whichever checks ask (memoised).
class Rechecks {
 public:
  Rechecks(const LawUnderTest& law, const Grid& grid) : law_(law), grid_(grid) {}
  const ImpactResult& integrator(const Run& r, IntegratorKind k);
  const ImpactResult& reference(const Run& r);
  // "odeint-dopri5 at rtol 1e-13, atol 1e-15 against dp45 at rtol 1e-14"
  std::string settings(IntegratorKind k) const;
  IntegratorOptions tight_options(IntegratorKind k) const;
  IntegratorOptions tight_reference_options() const;

 private:
  const LawUnderTest& law_;
  const Grid& grid_;
  std::map<std::tuple<double, double, int>, ImpactResult> runs_;  // (v0, c, integrator)
};

// The static checks on the scene (velocity set to the grid's largest), in order; z_scan [m] is
// how far the discontinuity scan goes (beyond the largest z_m of the grid).
void static_checks(const LawUnderTest& law, const Scene& scene, double v_hi, double z_scan,
                   ConformanceResult& result);

// The reloading checks on the same scene (conformance_reloading.cc): a cycle z_m -> z1 -> z_m
// below z_m creates no energy, and reloading meets the loading curve at z_m.
void reloading_checks(const LawUnderTest& law, const Scene& scene, double v_hi,
                      ConformanceResult& result);

// The dynamic checks judged on the runs, in order.
void dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                    const std::vector<Run>& runs, ConformanceResult& result);

// On a finite plate (conformance_plate.cc): one velocity's runs of the plate driver.
struct PlatePoint {
  double v0 = 0;                  // [m/s]
  PlateImpactResult reference;    // dop853 at rtol 1e-12, atol 1e-14
  PlateImpactResult run, second;  // dop853 and odeint-dopri5 at the grid's tolerances (the
                                  // force recorded for the impulse)
  double truncation_error = 0;    // |e - e(cut-off/2)|/7 of `run` (0 when unknown)
};
struct PlateGrid {
  std::vector<PlatePoint> points;
  std::string refused;  // why the law does not run on the plate (empty: it runs)
};
Scene at_velocity(const Scene& base, double v0);
PlateGrid run_plate_grid(const LawUnderTest& law, const Grid& grid);
// The dynamic checks on the plate, and the ones that do not apply skipped with their reasons.
void plate_dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                          const PlateGrid& runs, ConformanceResult& result);

// "dp45 at v0 = 0.0001 m/s, no dashpot"
std::string run_label(const Run& r, std::string_view who);

// The claims on the trend of e (captured_below, cor_nondecreasing_in_v0), judged on the
// reference runs (conformance_claims.cc).
void adhesive_claim_checks(const Claims& claims, const Grid& grid, const std::vector<Run>& runs,
                           ConformanceResult& result);

}  // namespace ivv::conformance::detail
