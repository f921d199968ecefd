#include "solver/driver/capture.h"

namespace ivv {

std::optional<double> grazing_capture(bool has_dashpot, double w, long steps,
                                      const IntegratorOptions& opt) {
  const double bound = accumulated_error_bound(steps, opt);
  if (has_dashpot && w <= bound) return bound;
  return std::nullopt;
}

}  // namespace ivv
