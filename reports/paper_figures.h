// Section 2 of the report: the paper's Figs 2-14, drawn from the paper study
// (verification/study_paper.h), the same runs the trend.paper.* cases judge. Nothing here
// simulates: it formats.
//
//   Figs 2-7   force history and force-displacement hysteresis at v0 = 0.1, 1 and 5 m/s with
//              c = 11440 N s/m (zeta ~ 0.1): the nonlinear elastoplastic model, the linearized
//              model in closed form (undefined at 0.1 m/s, said in the caption) and Hunt-Crossley
//              fitted to the same F_max and e (K and mu printed in the caption).
//   Fig 8      yield strength S_y varied, force history (c held at 11440 N s/m).
//   Fig 9      impactor mass varied, force history (c held at 11440 N s/m).
//   Figs 10-11 normalised F_bar against tau and against alpha_bar, several v0, zeta = 0.1
//              (with the spring deformation z_bar as a companion panel to Fig 11).
//   Figs 12-13 the same for several zeta at v0 = 1 m/s.
//   Fig 14     COR against v0 for several zeta.
// Figs 2-13 are labelled illustrations (force histories), with the cases that judge the paper's
// claims about them; Fig 14 is the measurement of trend.paper.fig14-cor-falls-with-zeta.
// The paper's own fitted Hunt-Crossley values are withheld; nothing here uses them.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"

namespace ivv::reports {

// Throws verification::StudyError if the paper study failed. Order: 2-13, then the two
// spring-deformation companions of Figs 11 and 13 side by side, then 14.
std::vector<Figure> paper_figures(const SectionOptions& options);

// HTML: the Table 1 scene with its derived parameters (K_h, z_y, K_y, omega0, v_y) and the
// damping ratio of c = 11440 N s/m, for the section's introduction.
std::string paper_parameters_html();

}  // namespace ivv::reports
