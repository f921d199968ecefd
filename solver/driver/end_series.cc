#include "solver/driver/end_series.h"

#include <cmath>
#include <limits>
#include <optional>

#include "solver/driver/onset_series.h"

namespace ivv {

std::optional<EndSeriesMatch> match_end_series(double kappa, double beta, double z, double w,
                                               double tolerance) {
  if (!(z > 0 && w < 0 && kappa > 0 && beta >= 0)) return std::nullopt;
  double W = -w, s = z / W;
  // the bound at the first estimate: most states of an unloading branch are far outside
  if (!(onset_series_error_bound(kappa * std::sqrt(W), beta, s) <= tolerance)) return std::nullopt;
  constexpr double ulps = 8 * std::numeric_limits<double>::epsilon();
  for (int iteration = 0; iteration < kEndSeriesIterations; ++iteration) {
    const double k = kappa * std::sqrt(W);
    const OnsetSeriesState S = onset_series_state(k, -beta, s);
    const double W_next = -w / S.w;
    const double slope = S.w + beta * k * S.z * std::sqrt(S.z);
    const double s_next = s + (z / W_next - S.z) / slope;
    const bool converged = std::abs(s_next - s) <= ulps * s && std::abs(W_next - W) <= ulps * W;
    W = W_next;
    s = s_next;
    if (!(s > 0 && W > 0)) return std::nullopt;
    if (converged) {
      const double k_end = kappa * std::sqrt(W);
      if (!(onset_series_error_bound(k_end, beta, s) <= tolerance)) return std::nullopt;
      return EndSeriesMatch{s, W, k_end, onset_series_state(k_end, -beta, s)};
    }
  }
  return std::nullopt;
}

std::optional<EndSeriesTarget> end_series_target(double kappa, double beta, double z, double w,
                                                 double tolerance) {
  if (!(z > 0 && w < 0 && kappa > 0 && beta >= 0)) return std::nullopt;
  const double W = -w;
  return EndSeriesTarget{z / W, onset_series_reach(kappa * std::sqrt(W), beta, tolerance)};
}

}  // namespace ivv
