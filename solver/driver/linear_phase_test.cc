// The closed form of linear_phase.h against an independent evaluation of exp(M tau) X0: its
// Taylor series summed in long double (64-bit significand) with tau split into pieces of
// |M| tau <= 1/2, so that no term cancels. Under-, critically and over-damped segments, the
// elastoplastic law's (k = 1 in the units of omega0 = sqrt(K_y/m)) and far from it.
#include "solver/driver/linear_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace ivv {
namespace {

using Vec = std::array<long double, 2>;

// exp(M tau) X0 for M = [[0, -1], [k, -k beta]] by the Taylor series on pieces of tau.
Vec reference(double k, double beta, double w0, double u0, double tau) {
  const long double K = k, B = beta;
  const long double norm = 1 + K + K * B;
  const int pieces = std::max(1, static_cast<int>(std::ceil(2 * norm * tau)));
  const long double h = static_cast<long double>(tau) / pieces;
  Vec x{w0, u0};
  for (int p = 0; p < pieces; ++p) {
    Vec sum = x, term = x;
    for (int n = 1; n < 60; ++n) {
      const Vec m{-term[1], K * term[0] - K * B * term[1]};
      term = {m[0] * h / n, m[1] * h / n};
      sum = {sum[0] + term[0], sum[1] + term[1]};
    }
    x = sum;
  }
  return x;
}

// The closed form's rounding: a few operations on values of the size of the state, with the
// exponential's argument rounded to a relative eps (an error of eps times the largest exponent
// s tau, mu tau or nu tau, at most ~50 below).
constexpr double kRelative = 1e-13;

struct Segment {
  double k, beta;
};
constexpr std::array<Segment, 8> kSegments = {{{1.0, 0.0},    // no dashpot
                                               {1.0, 0.2},    // the paper's zeta = 0.1
                                               {1.0, 1.9},    // just underdamped
                                               {1.0, 2.0},    // critical: k beta^2 = 4
                                               {1.0, 2.1},    // just overdamped
                                               {1.0, 20.0},   // strongly overdamped
                                               {40.0, 0.05},  // stiff, weak dashpot
                                               {0.02, 3.0}}};

TEST(LinearPhase, TheClosedFormIsTheExponential) {
  for (const Segment& seg : kSegments)
    for (double tau : {1e-6, 0.1, 0.7, 2.0}) {
      const LinearPhasePoint p = linear_phase_at(seg.k, seg.beta, 0.9, 0.3, tau);
      const Vec r = reference(seg.k, seg.beta, 0.9, 0.3, tau);
      const double scale = std::abs(0.9) + std::abs(0.3) / std::sqrt(seg.k);
      EXPECT_NEAR(p.w, static_cast<double>(r[0]), kRelative * scale)
          << "k " << seg.k << " beta " << seg.beta << " tau " << tau;
      EXPECT_NEAR(p.u, static_cast<double>(r[1]), kRelative * scale * std::sqrt(seg.k))
          << "k " << seg.k << " beta " << seg.beta << " tau " << tau;
    }
}

// Maximum compression: w - beta u vanishes there (to the rounding of the state) and changes
// sign across it, on the reference's solution, 1e-6 of tau either side.
TEST(LinearPhase, MaximumCompressionIsTheFirstZeroOfTheCompressionRate) {
  for (const Segment& seg : kSegments)
    for (const auto& [w0, u0] : {std::pair{1.0, 0.0}, {0.95, 0.4}, {0.3, 2.0}}) {
      if (!(w0 - seg.beta * u0 > 0)) continue;  // not compressing at the start
      const std::optional<LinearPhasePoint> m =
          linear_phase_max_compression(seg.k, seg.beta, w0, u0);
      ASSERT_TRUE(m) << "k " << seg.k << " beta " << seg.beta << " w0 " << w0;
      const double scale = w0 + seg.beta * std::abs(m->u);
      EXPECT_NEAR(m->w - seg.beta * m->u, 0.0, kRelative * scale)
          << "k " << seg.k << " beta " << seg.beta << " w0 " << w0;
      auto rate = [&](double tau) {
        const Vec r = reference(seg.k, seg.beta, w0, u0, tau);
        return static_cast<double>(r[0] - seg.beta * r[1]);
      };
      EXPECT_GT(rate(m->tau * (1 - 1e-6)), 0.0);
      EXPECT_LT(rate(m->tau * (1 + 1e-6)), 0.0);
      // the first zero: the rate is positive at every tenth of the way there
      for (int i = 1; i < 10; ++i) EXPECT_GT(rate(m->tau * i / 10), 0.0);
    }
}

TEST(LinearPhase, NoMaximumWhereTheSpringIsNotBeingCompressed) {
  EXPECT_FALSE(linear_phase_max_compression(1.0, 0.2, 0.1, 0.5));  // w - beta u = 0
  EXPECT_FALSE(linear_phase_max_compression(1.0, 0.2, -0.1, 0.2));
  EXPECT_FALSE(linear_phase_max_compression(0.0, 0.2, 1.0, 0.2));
}

}  // namespace
}  // namespace ivv
