// Restitution studies (see verification/study.h): computed once per process, judged by the
// published-trend cases (cases_trends.cc) and drawn by the report's restitution section
// (reports/restitution.h). Every study here runs the Table 1 scene of the paper
// (paper_scene(), elastoplastic law unless said) with the integrator and tolerance stated on
// it; velocities in m/s, e (Newton COR) dimensionless.
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv::verification {

// Integrator of the trend studies: odeint-dopri5 at rtol 1e-12, atol 1e-14 (normalised
// state). The global error of e is at most N rtol over the N < 1000 steps of these contacts:
// e to ~1e-11, below every threshold the cases apply.
inline constexpr double kTrendRtol = 1e-12;
inline constexpr double kTrendAtol = 1e-14;
SimulationRequest trend_request(const Scene& s, LawKind law = LawKind::elastoplastic);
// One trend run; throws std::runtime_error (naming `what`) unless it separates.
ImpactResult trend_run(const Scene& s, LawKind law, const std::string& what);

// (15/8)^{1/8} (v0/v_y)^{-1/4}: the high-velocity asymptote of the undamped elastoplastic COR.
// For v0 >> v_y the plastic leg dominates, d = z_m - z_y ~ v0 sqrt(m/K_y), F_m ~ K_y d,
// E0 ~ K_y d^2/2, and the unloading Hertz arc is nearly straight over the small rebound
// z_m - z_f ~ 2 F_m/(3 K_h sqrt(z_m)), so W_u ~ F_m^2/(3 K_h sqrt(z_m)) and
// e^2 = W_u/E0 ~ 2 K_y/(3 K_h sqrt(d)) = sqrt(z_y/d). With K_y/m = (15/8) v_y^2/z_y^2 (from the
// definitions of K_y and v_y) this is e ~ (15/8)^{1/8} (v0/v_y)^{-1/4} = 1.0819 (v0/v_y)^{-1/4}
// (the nonlinear counterpart of the paper's eq. 21). The first neglected term is of relative
// order (v0/v_y)^{-1/2}.
double undamped_cor_asymptote(double velocity_ratio);

// ---- the undamped COR against v0/v_y and its local slope: the one slope computation ---------

struct UndampedCorRow {
  double ratio = 0.0;               // v0/v_y [-]
  double e_closed_form = 0.0;       // oracles::solve_undamped_elastoplastic (1 below v_y) [-]
  double e_simulated = 0.0;         // trend_run, no dashpot [-]
  double slope_closed_form = 0.0;   // d ln e/d ln v0 of the closed form, central difference [-]
  double slope_simulated = 0.0;     // the same of the simulations [-]
  double e_thornton = 0.0;          // oracles::thornton_cor(v_y/v0), Thornton's V_y = v_y [-]
  double asymptote = 0.0;           // undamped_cor_asymptote(ratio) [-]
  double thornton_asymptote = 0.0;  // oracles::thornton_asymptote(v_y/v0): 1.185 r^{1/4} [-]
  bool tabulated = false;           // one of the report's table rows (kSlopeTableRatios)
};

struct UndampedCorStudy {
  double v_yield = 0.0;              // v_y of the Table 1 scene [m/s]
  double log_step = 0.0;             // h: slopes are central differences over v0 (1 +- h) [-]
  std::vector<UndampedCorRow> rows;  // ascending ratio; slopes NaN where v0 (1 - h) <= v_y
  // the closed form and Thornton's formula on 200 log-spaced ratios 0.5 ... 1e4 (curves)
  std::vector<double> curve_ratio, curve_e_closed_form, curve_e_thornton;
  // The row at `ratio` (relative match 1e-9); throws std::out_of_range if there is none.
  const UndampedCorRow& at(double ratio) const;
};

// Table 1 scene without dashpot, odeint-dopri5 at kTrendRtol. Rows: 0.5 and 0.7 v_y (elastic),
// 49 log-spaced ratios 1 ... 1e4, and the table ratios 1.5, 3, 10, 15, 30, 100, 1e3, 1e4; each
// with e at v0 and at v0 (1 +- 1e-3) for the slopes (the simulated slope's error is
// 2 x 1e-11 / (2 x 1e-3 e) < 1e-7; the truncation error of the difference, h^2 e'''/6, ~1e-7).
const UndampedCorStudy& undamped_cor_study();

// ---- e(v0, zeta) above yield: the monotone map ------------------------------------------------

struct CorMapStudy {
  std::vector<double> ratio;           // v0/v_y, 30 log-spaced in [1.5, 100]
  std::vector<double> zeta;            // 0 ... 0.25 (10 values)
  std::vector<std::vector<double>> e;  // e[i_zeta][i_ratio]
};
// Table 1 scene, damping ratio zeta, odeint-dopri5 at kTrendRtol. Up to zeta = 0.25: beyond
// ~0.3 the unloading damping zeta/gamma reaches 1 at the grid's high velocities and the impact
// is captured (e = 0, no longer strictly decreasing). Fails (StudyError) if a point does not
// separate.
const CorMapStudy& cor_map_study();

// ---- e against zeta at fixed v0, up to capture ------------------------------------------------

struct CorZetaStudy {
  std::vector<double> velocities;               // 0.1, 1, 5 m/s
  std::vector<double> zetas;                    // 30 log-spaced in [0.01, 10]
  std::vector<std::vector<ImpactResult>> runs;  // runs[i_v0][i_zeta]
  // the linearized closed form (eqs 22-25) on 120 log-spaced zeta in [0.01, 10]; NaN where
  // the linearized law is undefined (loading stops below 2.25 z_y)
  std::vector<double> linear_zetas;
  std::vector<std::vector<double>> linear_e;  // linear_e[i_v0][i]
};
// Table 1 scene, elastoplastic, odeint-dopri5 at its defaults (rtol 1e-10): strong damping is
// stiff (zeta = 10) and the default is what a user runs. A failed run is kept (status failed,
// with its reason) for the case to report.
const CorZetaStudy& cor_zeta_study();

// ---- the Hunt-Crossley damping maps mu(e) ---------------------------------------------------

struct DampingMapPoint {
  double e_target = 0.0;
  double mu = 0.0;         // the map's mu at v0 = 1 m/s [s/m]
  double e_exact = 0.0;    // closed_forms::delivered_cor (exact relation, Lambert W)
  double e_table = 0.0;    // reference_data/hunt_crossley_mu_maps.csv e_delivered
  ImpactResult simulated;  // Hunt-Crossley, K = K_h, no dashpot, v0 = 1 m/s
};
struct DampingMapCurve {
  std::string name, formula;
  std::vector<DampingMapPoint> points;  // the table's rows for this map, ascending e_target
  std::vector<double> curve_target, curve_e_exact;  // 97 targets in [0.02, 0.98]
};
// One per closed_forms::damping_maps(); simulated with odeint-dopri5 at kTrendRtol. A run that does
// not separate is kept (the case names it).
const std::vector<DampingMapCurve>& damping_map_study();

}  // namespace ivv::verification
