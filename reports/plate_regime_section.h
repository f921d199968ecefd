// The report's subsection "Where the infinite plate stops" (solver/plate/plate_regime.h), drawn
// from the plate-regime study (verification/study_plate_regime.h), the data the plate.regime.*
// cases judge. Nothing here simulates: it formats.
//
//   * the characterisation map: mass ratio against relative stiffness, each point marked with
//     its measured regime at 1e-3 and at 1e-2, Olsson's mass criterion drawn as two lines;
//   * each cheaper model's error against the full plate along the 2 mm row of the map;
//   * the drop-weight coupon and the small ball: every model's e, F_max, t_contact side by side.
#pragma once

#include <string>
#include <vector>

#include "reports/figure.h"

namespace ivv::reports {

struct PlateRegimeSection {
  std::vector<Figure> figures;  // [0], [1]: the map at 1e-3 and 1e-2; [2]: the 2 mm row
  std::string intro_html;
  std::string models_table_html;  // the coupon and the small ball, model by model
};

// Throws verification::StudyError if the study failed.
PlateRegimeSection plate_regime_section(const SectionOptions& options);

}  // namespace ivv::reports
