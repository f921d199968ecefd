// The dashpot from the struck structure (docs/design.md §1), as a study (verification/study.h):
// computed once per process, judged by the structure.* cases (cases_structure.cc) and drawn by the
// report's section "Damping from the structure".
//
// Zener's problem (scene/structure.h, oracles/zener.h): the Hertz law in series with a
// dashpot, one dimensionless group lambda = m^{3/5} K_h^{2/5} v0^{1/5}/c. Its runs use the
// Hertz law on the shipped scene steel-ball-on-steel-plate's impactor and target
// (steel_ball_on_plate()), with the dashpot given as lambda (Damping::zener) or as a plate of
// thickness chosen for lambda (similarity), odeint-dopri5 at kTrendRtol (e to ~1e-11).
//
// The paper's impactor on a plate: Table 1's impactor and target (elastoplastic law), the
// dashpot that of a [0/90/0/90/0]s T300/934 plate with the paper's Table 1 ply data and density
// (E11 = 120 GPa, E22 = 7.9 GPa, G12 = 5.5 GPa, nu12 = 0.3, rho = 1580 kg/m^3) and Olsson's
// D* (scene/structure.h); --integrator auto at rtol 1e-10 (the thin plates are heavily
// damped, zeta up to ~60: rodas4 there).
#pragma once

#include <string>
#include <vector>

#include "oracles/zener.h"
#include "scene/scene.h"
#include "scene/structure.h"
#include "solver/simulate.h"

namespace ivv::verification {

// One impact in Zener's units: z* = (m v0^2/K_h)^{2/5}, time z*/v0, force K_h z*^{3/2}.
struct ZenerPoint {
  double lambda = 0.0;        // [-]
  double e = 0.0;             // Newton COR [-]
  double e_bound = 0.0;       // captured runs: the COR lies in [0, e_bound] [-]
  double contact_time = 0.0;  // t_f v0/z* [-]
  double peak_force = 0.0;    // F_max/(K_h z*^{3/2}) [-]
  bool separated = false;     // false: captured (e = 0 within e_bound)
  long steps = 0;             // accepted steps of the run
};

// A scene of the similarity set: a plate whose thickness gives the wanted lambda.
struct SimilarityPoint {
  std::string label;  // what differs, for people
  Scene scene;        // Damping::from_structure(plate)
  double E_star = 0.0, K_h = 0.0;
  double thickness = 0.0;  // h [m] that gives lambda
  ZenerPoint point;
};

struct ThicknessRow {
  double thickness = 0.0;  // h [m]
  double D_star = 0.0;     // [N m]
  double c = 0.0;          // [N s/m]
  double zeta = 0.0;       // [-]
  double e_1 = 0.0;        // e at 1 m/s (0: captured)
  double e_5 = 0.0;        // e at 5 m/s
};

struct StructureStudy {
  // Zener's curve: 41 log-spaced lambda from 1e-3 to 10, and the slope of 1 - e at small lambda
  std::vector<ZenerPoint> curve;
  double slope_quadrature = 0.0;       // a of 1 - e = a lambda (oracles/zener.h)
  std::vector<ZenerPoint> small;       // lambda = 1e-3, 2e-3, 4e-3
  double slope_richardson = 0.0;       // 2 g(1e-3) - g(2e-3), g = (1 - e)/lambda
  double slope_richardson_next = 0.0;  // 2 g(2e-3) - g(4e-3): its O(lambda^2) error is 4x
  std::vector<ZenerPoint> checked;     // lambda = 0.1, 0.5, 1.0, simulated
  std::vector<oracles::ZenerImpact> series_solution;  // the same lambda, oracles/zener.h
  std::vector<SimilarityPoint> similarity;            // lambda = 0.5 on four unlike scenes
  // the paper's impactor on the T300/934 plate
  Ply ply;                                   // Table 1 ply data
  std::vector<int> stacking;                 // [0/90/0/90/0]s
  double density = 0.0;                      // [kg/m^3]
  double d_star_per_h3 = 0.0;                // Olsson's D*/h^3 [N/m^2]
  double thickness_for_paper_zeta = 0.0;     // h at which the plate alone gives zeta = 0.1 [m]
  double zeta_at_that_thickness = 0.0;       // derive() of that scene: the check [-]
  std::vector<ThicknessRow> thickness_rows;  // 1 mm ... 50 mm
};

const StructureStudy& structure_study();

// The shipped scene's impactor and target (5 mm steel ball, steel target, 1 m/s) without a
// dashpot; the Hertz law runs on it.
Scene steel_ball_on_plate();
// Table 1 ply data and stacking of the paper's laminate (the paper's Table 1).
Ply paper_ply();
std::vector<int> paper_stacking();
inline constexpr double kPaperLaminateDensity = 1580.0;  // rho [kg/m^3], paper Table 1
// The paper scene with a T300/934 plate of thickness h as its dashpot.
Scene paper_on_laminate_plate(double thickness, double v0);

// One Hertz impact at lambda (scene: steel_ball_on_plate(), Damping::zener), in Zener's units.
ZenerPoint zener_point(double lambda, IntegratorKind integrator);
ZenerPoint zener_units(const Scene& s, const ImpactResult& r);

}  // namespace ivv::verification
