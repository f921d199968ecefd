// Section 3 of the report: restitution trends.
//
//   * COR of the undamped elastoplastic model against v0/v_y on log-log axes (closed form of
//     oracles/undamped_elastoplastic.h as the curve, simulate() as points), with its v0^{-1/4}
//     asymptote, and a table of the local slope d ln e / d ln v0.
//     The asymptote: for v0 >> v_y the plastic leg dominates, d = z_m - z_y ~ v0 sqrt(m/K_y),
//     F_m ~ K_y d, E0 ~ K_y d^2/2, and the unloading Hertz arc is nearly straight over the
//     small rebound z_m - z_f ~ 2 F_m/(3 K_h sqrt(z_m)), so W_u ~ F_m^2/(3 K_h sqrt(z_m)) and
//     e^2 = W_u/E0 ~ 2 K_y/(3 K_h sqrt(d)) = sqrt(z_y/d). With K_y/m = (15/8) v_y^2/z_y^2
//     (from the definitions of K_y and v_y) this is
//       e ~ (15/8)^{1/8} (v0/v_y)^{-1/4} = 1.0819 (v0/v_y)^{-1/4}.
//   * COR against zeta at fixed v0 (simulated; the linearized closed form beside it).
//   * Thornton's (1997) curve beside the model, both against v0/v_y.
//   * The Hunt-Crossley damping maps mu(e): the e each one delivers against its target.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"

namespace ivv::reports {

// (15/8)^{1/8} (v0/v_y)^{-1/4}: the high-velocity asymptote of the undamped elastoplastic COR.
double undamped_cor_asymptote(double velocity_ratio);

struct SlopeRow {
  double velocity_ratio = 0.0;     // v0/v_y [-]
  double e = 0.0;                  // closed-form COR [-]
  double slope_closed_form = 0.0;  // d ln e / d ln v0 of the closed form [-]
  double slope_simulated = 0.0;    // the same from simulate() (odeint-dopri5, rtol 1e-12)
  double e_over_asymptote = 0.0;   // e / undamped_cor_asymptote [-]
};

struct DampingMapRow {
  std::string name, formula;
  std::vector<double> delivered;  // at RestitutionSection::map_targets
};

struct RestitutionSection {
  std::vector<Figure> figures;
  std::vector<SlopeRow> slopes;
  double log_step = 0.0;  // relative velocity step of the central differences [-]
  std::vector<double> map_targets;
  std::vector<DampingMapRow> maps;
};

// Throws std::runtime_error if a simulation it needs fails.
RestitutionSection restitution_section(const SectionOptions& options);

}  // namespace ivv::reports
