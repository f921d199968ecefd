// Section 3 of the report: restitution trends, drawn from the restitution studies
// (verification/study_restitution.h), the data the trend.* cases judge. Nothing here simulates
// or evaluates a closed form: it formats.
//
//   * COR of the undamped elastoplastic model against v0/v_y on log-log axes (closed form as the
//     curve, simulations as points) with its v0^{-1/4} asymptote
//     (verification::undamped_cor_asymptote), and a table of the local slope d ln e / d ln v0:
//     cases trend.cor-undamped-simulated-is-closed-form, trend.cor-slope-*,
//     trend.cor-undamped-asymptote.
//   * COR against zeta at fixed v0 (simulated; the linearized closed form beside it): case
//     trend.cor-falls-with-zeta-to-capture.
//   * Thornton's (1997) curve beside the model, both against v0/v_y: trend.thornton-*.
//   * The Hunt-Crossley damping maps mu(e): the e each one delivers against its target, exact
//     relation and simulations: trend.hunt-crossley-map.*.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"
#include "verification/study_restitution.h"

namespace ivv::reports {

struct DampingMapRow {
  std::string name, formula;
  std::vector<double> delivered;  // simulated, at RestitutionSection::map_targets
};

struct RestitutionSection {
  std::vector<Figure> figures;
  std::vector<verification::UndampedCorRow> slopes;  // the tabulated rows of the study
  double log_step = 0.0;  // relative velocity step of the central differences [-]
  std::vector<double> map_targets;
  std::vector<DampingMapRow> maps;
};

// Throws verification::StudyError if a study it draws failed.
RestitutionSection restitution_section(const SectionOptions& options);

}  // namespace ivv::reports
