// Synthetic measured data: what a model with stated parameters gives at stated velocities,
// plus seeded Gaussian noise of a stated standard deviation. For the verification cases
// (recovery, coverage, identifiability, wrong model) and the shipped example; every data set
// made here carries a provenance line beginning "SYNTHETIC" with what generated it.
//
// The model runs with --model auto at rtol = kSyntheticRtol (stated error <= 300 rtol = 3e-10
// in e, validation/model_runs.h), so "noise-free" data carry at most that error.
// Noise: e_i = S(v0_i) + u_e * N(0, 1), N from validation/normal.h (seeded, the same with
// every standard library); e is clamped at 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "solver/simulate.h"
#include "validation/measured_data.h"

namespace ivv::validation {

inline constexpr double kSyntheticRtol = 1e-12;

struct SyntheticSpec {
  std::vector<double> velocities;  // v0 [m/s]
  double u_e = 0.01;               // standard deviation of the noise on e, and the stated u_e
  bool noise = true;               // false: the model's values, u_e still stated
  bool state_uncertainty = true;   // false: no u_e column (the fit estimates the noise)
  std::uint64_t seed = 1;
  std::string description;  // what the data stand for (a provenance line)
};

// Throws InputError when the request is invalid; std::runtime_error naming v0 when an impact
// fails.
MeasuredData synthetic_data(const SimulationRequest& request, const SyntheticSpec& spec);

// n log-spaced velocities from lo to hi [m/s].
std::vector<double> log_velocities(double lo, double hi, int n);

}  // namespace ivv::validation
