// Seeded standard normal deviates: std::mt19937_64 (its sequence is fixed by the standard) and
// the Box-Muller transform on 53-bit uniforms in (0, 1], written here because the algorithm of
// std::normal_distribution is left to the standard library: the same seed gives the same
// synthetic data and the same prediction band with every compiler.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace ivv::validation {

class StandardNormal {
 public:
  explicit StandardNormal(std::uint64_t seed) : rng_(seed) {}
  double operator()() {
    const double u1 = uniform(), u2 = uniform();
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * std::numbers::pi * u2);
  }

 private:
  double uniform() { return (static_cast<double>(rng_() >> 11) + 1.0) * 0x1.0p-53; }
  std::mt19937_64 rng_;
};

}  // namespace ivv::validation
