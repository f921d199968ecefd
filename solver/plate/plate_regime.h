// Which model a plate impact needs (docs/design.md §1 "A finite plate"): the full plate against
// the three cheaper models of the same impact, each measured, and the regime named after the
// cheapest one within a stated tolerance.
//
// The models of a sphere striking a finite plate, cheapest first:
//   half-space      the target is rigid behind the contact spring: no dashpot, no plate
//                   (the scene with [damping] none; a closed form for the paper's laws);
//   infinite-plate  the paper's idealisation: the plate radiates flexural waves that never
//                   come back, a dashpot c = 8 sqrt(rho h D*) in series with the spring (D*
//                   Olsson's effective stiffness of a laminate, scene/structure.h);
//   quasi-static    the plate bends statically: the contact law in series with the plate's
//                   static stiffness 1/C_static at the impact point, no plate inertia (the
//                   "two-spring" model: z = alpha - C_static F, m alpha'' = -F);
//   full            the plate's modes (plate_impact.h): reflections, reloading, repeated contacts.
//
// Error of a model against the full plate: err = max(|e_model - e_full|, |F_model/F_full - 1|),
// e in units of v0 (as every estimated error of e in ivv) and F_max relative. The regime is the
// first model in the order above with err <= tolerance; "plate-dynamics" when none is. The
// errors are measured (every model run, at the run's rtol), never assumed from a threshold.
//
// The groups that tell the models apart, reported beside the measured choice:
//   mass_ratio          m / (rho h a b), impactor over plate;
//   wave_return_time    2 d/c_g at the contact's frequency (plate_modes.h), against the full
//                       plate's first contact time;
//   relative_stiffness  lambda = k_c C_static: the contact's stiffness over the plate's static
//                       stiffness, k_c = F_max/z_max of the half-space impact (secant) — large:
//                       the plate is the softer spring and bends; small: the contact governs;
//   zeta_plate          the paper's damping ratio of the infinite plate's dashpot,
//                       sqrt(m K_y)/(2 c) with c = 8 sqrt(rho h D*) (Christoforou & Yigit's
//                       loss factor zeta_w of the infinite plate has the same form with their
//                       linearised contact stiffness in place of K_y; NaN without a yield
//                       strength, where K_y is not defined);
//   zener_lambda        Zener's inelasticity parameter of the infinite plate,
//                       m^{3/5} K_h^{2/5} v0^{1/5}/c (the Hertz law's one group).
// The published criteria, printed for comparison and not used in the choice:
//   Olsson's mass criterion (R. Olsson, "Mass criterion for wave controlled impact response of
//   composite plates", Composites A 31 (2000) 879-887): mass ratio below 0.23, a small-mass,
//   wave-controlled impact (the infinite plate); above 2, a large-mass, quasi-static one;
//   Christoforou & Yigit ("Characterization of impact in composite plates", Compos. Struct. 43
//   (1998) 15-24): the impact is infinite-plate-like for large zeta_w and quasi-static for small
//   zeta_w with the relative stiffness deciding between the plate's and the contact's spring.
// ivv's groups differ from those papers' in their stiffness: its k_c is the secant of the
// scene's own law at the half-space's peak, not a linearised Hertz stiffness; its regimes are
// measured, not read off their diagrams.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "solver/laws/expression.h"
#include "solver/plate/plate_impact.h"

namespace ivv {

enum class PlateModel { half_space, infinite_plate, quasi_static, full };
// "half-space", "infinite-plate", "quasi-static", "full"
std::string_view to_string(PlateModel m);
// The accepted --model names for a finite plate: "auto" gives nullopt, the four names above
// their model; any other name is bad input (InputError("--model", ...)).
std::optional<PlateModel> parse_plate_model(const std::string& name);

// The scene of a cheaper model: half-space (no dashpot), infinite plate (the same plate
// without its lengths, edges, impact point and dropped_modes; laminate D's as Olsson's D* in
// bending_stiffness). The quasi-static model keeps the finite plate and runs without modes.
Scene half_space_scene(const Scene& finite);
Scene infinite_plate_scene(const Scene& finite);

struct PlateModelOutcome {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  PlateModel model = PlateModel::full;
  bool ok = false;
  std::string reason;        // why it failed (empty when ok)
  double e = nan;            // final COR
  double F_max = nan;        // [N]
  double t_contact = nan;    // first contact [s]
  double z_max = nan;        // largest spring deformation [m]
  double error = nan;        // against the full plate (header), NaN for the full plate itself
  double error_e = nan;      // |e - e_full|, units of v0
  double error_F = nan;      // |F_max/F_full - 1|
  long rhs_evaluations = 0;  // its cost (0 for a closed form)
};

struct PlateRegime {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  double tolerance = nan;                 // the stated tolerance of the choice
  double mass_ratio = nan;                // impactor over plate
  double wave_return_time = nan;          // [s]
  double contact_time = nan;              // the full plate's first contact [s]
  double relative_stiffness = nan;        // lambda = k_c C_static
  double zeta_plate = nan;                // the infinite plate's damping ratio
  double c_plate = nan;                   // 8 sqrt(rho h D*) [N s/m]
  double zener_lambda = nan;              // m^{3/5} K_h^{2/5} v0^{1/5}/c_plate
  std::vector<PlateModelOutcome> models;  // half-space, infinite-plate, quasi-static, full
  std::string regime;  // "half-space", "infinite-plate", "quasi-static", "plate-dynamics"
  std::string olsson;  // the mass criterion's class, for comparison
  std::vector<std::string> reasons;  // the choice in words

  const PlateModelOutcome& outcome(PlateModel m) const;
  // The cheapest model within the tolerance (the full plate when none is).
  PlateModel chosen() const;
  // The regime's name at another tolerance, from the measured errors (no new run).
  std::string regime_at(double other_tolerance) const;
  // The first cheaper model (in the header's order) within `t` of the full plate, else full.
  PlateModel cheapest_within(double t) const;
};

// The default tolerance of the choice: 1e-3 in e (units of v0) and relative in F_max. Tighter
// than a drop-weight rig measures either (a few per cent), loose enough that the infinite plate
// answers a plate whose waves do not return during the contact.
inline constexpr double kPlateModelTolerance = 1e-3;

// What the models share: the finite-plate scene, the law and its parameters, the tolerances.
struct PlateImpactSpec {
  const Scene& scene;
  LawKind law;
  const LawParameters& parameters;
  const PlateImpactOptions& options;              // rtol, atol for every model
  const ExpressionLawSpec* expression = nullptr;  // law == expression: the typed law
};

// Runs the three cheaper models of the spec, measures each against `full` (the full plate's
// run of the same spec, which must be ok), and names the regime.
PlateRegime plate_regime(const PlateImpactSpec& spec, const PlateImpactResult& full,
                         double tolerance = kPlateModelTolerance);

// Olsson's class of a mass ratio: "small-mass (wave-controlled)" below 0.23, "large-mass
// (quasi-static)" above 2, "intermediate" between.
std::string olsson_mass_class(double mass_ratio);

}  // namespace ivv
