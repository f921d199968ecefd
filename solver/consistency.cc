#include "solver/consistency.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

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
  if (!std::isfinite(m.ledger_residual)) {
    // not an integration error: a quantity of the run left the double range (a dashpot so
    // weak that zeta = sqrt(m K_y)/(2c) overflows, A = rho = 1e-200 for a bar, --lambda 1e300)
    std::ostringstream os;
    os << integrator << ": the energy ledger is not a finite number (residual " << m.ledger_residual
       << "): a quantity of this run overflowed the double range, which no tolerance can mend; "
          "check the scene's scales (an extremely weak dashpot makes zeta overflow)";
    return os.str();
  }
  if (std::abs(m.ledger_residual) > accumulated_error_bound(m.steps, opt)) {
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

namespace {
// Every number fail_non_finite_outcome checks is finite (t_alpha_max and t_contact may also be
// +inf when captured): 0 x is 0 for a finite x and NaN for an infinite or NaN one, so one sum
// decides it. Run on every impact (the table below, built for the message, was ~550
// instructions an impact of a sweep, callgrind).
bool all_finite(const ImpactResult& r, bool captured) {
  auto times = [captured](double t) { return captured && t == INFINITY ? 0.0 : t; };
  const EnergyLedger& led = r.energy;
  const double sum = 0.0 * r.e + 0.0 * r.e_poisson + 0.0 * r.e_energetic + 0.0 * r.F_max +
                     0.0 * r.t_F_max + 0.0 * r.z_max + 0.0 * r.t_z_max + 0.0 * r.alpha_max +
                     0.0 * times(r.t_alpha_max) + 0.0 * r.z_perm + 0.0 * r.y_final +
                     0.0 * times(r.t_contact) + 0.0 * r.rebound_velocity +
                     0.0 * r.impactor_velocity_after + 0.0 * r.target_velocity_after +
                     0.0 * r.impulse + 0.0 * r.impulse_compression + 0.0 * led.final +
                     0.0 * led.stored + 0.0 * led.plastic + 0.0 * led.viscous + 0.0 * led.residual;
  return sum == 0.0;
}
}  // namespace

bool fail_non_finite_outcome(ImpactResult& r, std::string_view what) {
  if (!r.ok()) return false;
  const bool captured = r.status == ImpactStatus::captured;
  if (all_finite(r, captured)) return false;  // the common case, without the table below
  auto never = [captured](double t) { return captured && t == INFINITY; };
  const EnergyLedger& led = r.energy;
  const std::pair<const char*, bool> fields[] = {
      {"e", std::isfinite(r.e)},
      {"e_poisson", std::isfinite(r.e_poisson)},
      {"e_energetic", std::isfinite(r.e_energetic)},
      {"F_max", std::isfinite(r.F_max)},
      {"t_F_max", std::isfinite(r.t_F_max)},
      {"z_max", std::isfinite(r.z_max)},
      {"t_z_max", std::isfinite(r.t_z_max)},
      {"alpha_max", std::isfinite(r.alpha_max)},
      {"t_alpha_max", std::isfinite(r.t_alpha_max) || never(r.t_alpha_max)},
      {"z_perm", std::isfinite(r.z_perm)},
      {"y_final", std::isfinite(r.y_final)},
      {"t_contact", std::isfinite(r.t_contact) || never(r.t_contact)},
      {"rebound_velocity", std::isfinite(r.rebound_velocity)},
      {"impactor_velocity_after", std::isfinite(r.impactor_velocity_after)},
      {"target_velocity_after", std::isfinite(r.target_velocity_after)},
      {"impulse", std::isfinite(r.impulse)},
      {"impulse_compression", std::isfinite(r.impulse_compression)},
      {"energy.final", std::isfinite(led.final)},
      {"energy.stored", std::isfinite(led.stored)},
      {"energy.plastic", std::isfinite(led.plastic)},
      {"energy.viscous", std::isfinite(led.viscous)},
      {"energy.residual", std::isfinite(led.residual)},
  };
  for (const auto& [name, finite] : fields) {
    if (finite) continue;
    std::ostringstream os;
    os << what << ": the run ended " << to_string(r.status) << " but its " << name
       << " is not a finite number; the result is not reported as valid";
    r.status = ImpactStatus::failed;
    r.failure = FailureKind::inconsistent;
    r.reason = os.str();
    return true;
  }
  return false;
}

}  // namespace ivv
