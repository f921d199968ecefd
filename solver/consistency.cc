#include "solver/consistency.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace ivv {

double accumulated_error_bound(long steps, const IntegratorOptions& opt) {
  const double per_step = kComponents * (opt.atol + 2.0 * opt.rtol);
  return kEstimatorSafety * static_cast<double>(std::max(1L, steps)) * per_step;
}

std::string consistency_failure(const ConsistencyMeasures& m, const IntegratorOptions& opt,
                                std::string_view integrator) {
  // nothing is allocated unless a check fails (this runs once per impact on the hot path)
  constexpr const char* advice =
      "; the integration error exceeds its tolerance: tighten --rtol/--atol (or --dt for rk4) "
      "or use another integrator";
  if (!std::isfinite(m.ledger_residual) ||
      std::abs(m.ledger_residual) > accumulated_error_bound(m.steps, opt)) {
    std::ostringstream os;
    os.precision(3);
    os << integrator << ": the energy ledger does not close: residual " << m.ledger_residual
       << " of m v0^2 after " << m.steps << " steps, beyond the bound "
       << accumulated_error_bound(m.steps, opt) << advice;
    return os.str();
  }
  if (!m.has_restitution) return {};
  // e^2 and e_E^2 are energies in units of 1/2 m v0^2: twice the invariant's bound
  const double e2 = m.e * m.e;
  const double energetic_bound = 2.0 * (accumulated_error_bound(m.restitution_steps, opt) +
                                        e2 * accumulated_error_bound(m.steps, opt));
  if (!(std::abs(m.e_energetic_sq - e2) <= energetic_bound)) {
    std::ostringstream os;
    os.precision(3);
    os << integrator << ": Newton and energetic COR disagree: e^2 = " << e2
       << ", e_energetic^2 = " << m.e_energetic_sq << " (difference "
       << std::abs(m.e_energetic_sq - e2) << " of m v0^2/2 over " << m.restitution_steps
       << " restitution steps, bound " << energetic_bound << ")" << advice;
    return os.str();
  }
  const double poisson_bound = accumulated_error_bound(m.steps, opt);
  if (!(std::abs(m.e_poisson - m.e) <= poisson_bound)) {
    std::ostringstream os;
    os.precision(3);
    os << integrator << ": Newton and Poisson COR disagree: e = " << m.e
       << ", e_poisson = " << m.e_poisson << " (bound " << poisson_bound << ")" << advice;
    return os.str();
  }
  return {};
}

}  // namespace ivv
