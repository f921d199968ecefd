// HTML for a calibration: `ivv calibrate --report DIR` writes it as a whole
// page (DIR/index.html, DIR/calibration.json), and the main report shows the shipped example
// through the same section.
//
// The section: the data with error bars (+-1 u), the fitted curve with its 95 % band (Monte
// Carlo over the fitted covariance, validation/prediction.h), the normalised residuals, the
// parameter table (estimate, SE, linearised and profile 95 % intervals, identifiability), the
// correlation matrix, the chi^2 test, and - when given - the V&V 20 comparison with held-back
// points and the ranking of several laws with all their fitted curves over the data.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "reports/html.h"
#include "reports/law_report.h"
#include "validation/calibration.h"
#include "validation/comparison.h"
#include "validation/prediction.h"

namespace ivv::reports {

struct CalibrationView {
  const validation::CalibrationProblem* problem = nullptr;
  const validation::CalibrationResult* fit = nullptr;
  const validation::Prediction* band = nullptr;  // over the band speeds (may be null)
  const validation::ValidationComparison* validation = nullptr;  // may be null
  const validation::ModelRanking* ranking = nullptr;             // may be null
  // ranking_curves[i]: e of ranking->models[i] at band->points' speeds (may be empty)
  const std::vector<std::vector<double>>* ranking_curves = nullptr;
};

// The section's HTML; `place` puts each plot (default: drawn now, inline); `source` labels its
// tables and figures.
std::string calibration_section_html(const CalibrationView& view, const std::string& anchor,
                                     const PlacePlot& place, const Source& source);

// Writes DIR/index.html and DIR/calibration.json atomically; InputError("--report") for a bad
// DIR. Returns the index.html path.
std::filesystem::path write_calibration_report(const CalibrationView& view,
                                               const std::filesystem::path& dir,
                                               const std::string& command_line);

}  // namespace ivv::reports
