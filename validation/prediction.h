// Prediction with uncertainty and the ASME V&V 20 validation comparison.
//
// Prediction band. ln theta ~ N(ln theta_hat, Sigma_ln) over the identifiable fitted
// parameters (Sigma_ln,ij = Sigma_ij / (theta_i theta_j), Sigma the calibration's covariance,
// linearised in ln theta as the calibration is; unidentifiable ones are held at their start
// values and the prediction says so), drawn by theta = theta_hat exp(L z) (L the factor of
// Sigma_ln, z from validation/normal.h with the stated seed): every draw is positive. Each draw
// runs every requested v0 (--model auto, at rtol = 1e-10: stated error <= 3e-8 in e, far below any
// band the data allow), the draws spread over the project's parallel loop (solver/parallel.h). Per
// v0:
//   e_nominal   the model at theta_hat
//   e_lo, e_hi  the 2.5 % and 97.5 % quantiles of the draws (linear interpolation between
//               order statistics): the 95 % band of the model prediction from the parameter
//               uncertainty alone (add the data's scatter for where new measurements fall)
//   u_input     the standard deviation of the draws
//   u_num       --model auto's stated integration error at theta_hat
//
// V&V 20 comparison (ASME V&V 20-2009, §2): at each validation point, with S the simulation
// (e_nominal), D the measurement,
//     E = S - D,     u_val = sqrt(u_num^2 + u_input^2 + u_D^2),
// u_D the point's stated u_e (or the calibration's estimated sigma of e when the file has no
// u_e; neither: bad input). The model error delta_model lies in E +- k u_val; a point with
// |E| > 2 u_val (k = 2, ~95 % for a normal u_val) is flagged: there the model's error exceeds
// what the uncertainties explain.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "validation/calibration_file.h"
#include "validation/measured_data.h"

namespace ivv::validation {

inline constexpr double kPredictionRtol = 1e-10;
inline constexpr double kValidationCoverage = 2.0;  // k of |E| > k u_val

struct PredictionOptions {
  int samples = 10000;  // Monte Carlo draws (>= 100: the 2.5 % quantile needs >= 2 below it)
  std::uint64_t seed = 1;
  int threads = 0;
  void validate() const;  // InputError("--samples", ...)
};

struct BandPoint {
  double v0 = 0.0;
  double e_nominal = 0.0;
  double e_lo = 0.0, e_hi = 0.0;  // 95 % band
  double u_input = 0.0;
  double u_num = 0.0;
};

struct Prediction {
  std::vector<BandPoint> points;
  int samples = 0;
  std::uint64_t seed = 0;
  int redrawn = 0;                    // draws outside the bounds, drawn again
  std::vector<std::string> held;      // unidentifiable parameters held at their start values
  std::vector<std::string> failures;  // draws whose impacts failed (then the run fails)
  bool ok() const { return failures.empty(); }
};

Prediction predict(const CalibratedModel& model, const std::vector<double>& velocities,
                   const PredictionOptions& options);

struct ValidationPoint {
  double v0 = 0.0;
  double S = 0.0, D = 0.0, E = 0.0;
  double u_num = 0.0, u_input = 0.0, u_D = 0.0, u_val = 0.0;
  bool exceeds = false;  // |E| > kValidationCoverage u_val
  int line = 0;
};

struct ValidationComparison {
  Prediction prediction;
  std::vector<ValidationPoint> points;
  int exceeding = 0;
  std::string summary() const;
};

// The V&V 20 comparison at the data's velocities (e only). InputError("--data", ...) when a
// point has no u_e and the calibration estimated no sigma of e.
ValidationComparison compare_with_data(const CalibratedModel& model, const MeasuredData& data,
                                       const PredictionOptions& options);

// The band of `ivv predict --json` and, with vv, its ASME V&V 20 comparison: the one JSON form
// of a prediction, for the command line and the Python module alike.
nlohmann::json prediction_json(const Prediction& band, const ValidationComparison* vv);

}  // namespace ivv::validation
