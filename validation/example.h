// The shipped calibration example (reference_data/calibration_example*.csv, SYNTHETIC; see
// reference_data/calibration_example.md): the calibration, the prediction band, the V&V 20
// comparison with the held-back file and the ranking of three laws, computed once per process
// (memoised, thread-safe) for the verification case validation.example.* and the report.
//
// What `ivv calibrate` runs on it (the README's example, the same numbers):
//   ivv calibrate --scene paper-damped --data reference_data/calibration_example.csv
//                 --fit c,yield_strength --start c=8000 --start yield_strength=3e8
// The generating values are c = 11440 N s/m and S_y = 202 MPa (kExampleTruth*); the fit starts
// away from them (kExampleStart*) so that the recovery means something.
#pragma once

#include <string>

#include "validation/calibration.h"
#include "validation/comparison.h"
#include "validation/prediction.h"

namespace ivv::validation {

inline constexpr double kExampleTruthC = 11440.0;    // [N s/m]
inline constexpr double kExampleTruthYield = 202e6;  // [Pa]
inline constexpr double kExampleStartC = 8000.0;     // [N s/m]
inline constexpr double kExampleStartYield = 3e8;    // [Pa]
inline constexpr int kExampleBandSpeeds = 40;        // band over 0.3..5 m/s
inline constexpr int kExampleSamples = 2000;         // Monte Carlo draws of the example

struct ShippedExample {
  CalibrationProblem problem;
  CalibrationResult fit;
  Prediction band;
  MeasuredData holdout;
  ValidationComparison validation;
  ModelRanking ranking;  // elastoplastic (c, S_y), hertz + dashpot (c), hunt-crossley (mu)
  std::vector<std::vector<double>> ranking_curves;  // each ranked model's e over band speeds
};

// Throws InputError when the shipped files or the scene cannot be found (data_directories()).
const ShippedExample& shipped_example();

}  // namespace ivv::validation
