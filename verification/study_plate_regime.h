// Which model a plate impact needs, as a study (verification/study.h): computed once per
// process, judged by the plate.regime.* cases (cases_plate_regime.cc) and drawn by the report's
// subsection "Where the infinite plate stops" (reports/plate_regime_section.cc).
//
// Every point runs the full plate (solver/plate/plate_impact.h, dop853 at rtol 1e-10, cut-off
// 40: e to ~1e-6 by the plate cases) and the three cheaper models (solver/plate/plate_regime.h)
// at the same rtol, and keeps each model's measured error against the full plate.
//   small_ball  the shipped steel-ball-on-finite-steel-plate (Hertz), the paper's dashpot case;
//   coupon      the shipped drop-weight-coupon (elastoplastic), the paper's own domain;
//   map         the 200 x 200 mm steel plate of the first scene, struck at 1 m/s by R = 5 mm
//               steel-faced spheres (Hertz) of mass 4.168 g ... 4.168 kg (x10 steps) on plates
//               of thickness 1, 2, 4 and 8 mm: mass ratio and relative stiffness over three and
//               four decades, the axes of Christoforou & Yigit's characterisation diagram.
#pragma once

#include <string>
#include <vector>

#include "solver/plate/plate_regime.h"

namespace ivv::verification {

struct RegimePoint {
  double mass = 0.0;       // impactor [kg]
  double thickness = 0.0;  // plate h [m]
  PlateRegime regime;      // the facts, every model's outcome and error, the regime at 1e-3
};

// Two studies, so that a case of the shipped scenes (~0.3 s) does not compute the map (~10 s).
struct PlateSceneRegimes {
  PlateRegime small_ball;
  PlateRegime coupon;
};
struct PlateRegimeMap {
  std::vector<double> masses;       // [kg]
  std::vector<double> thicknesses;  // [m]
  std::vector<RegimePoint> points;  // thickness-major: points[i * masses.size() + j]
};

const PlateSceneRegimes& plate_scene_regimes();
const PlateRegimeMap& plate_regime_map();

}  // namespace ivv::verification
