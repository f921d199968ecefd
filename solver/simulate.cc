#include "solver/simulate.h"

#include <array>
#include <cmath>
#include <sstream>

#include "solver/input_error.h"
#include "solver/simulate_impl.h"

namespace ivv {
namespace {

constexpr std::array kLaws = {LawKind::hertz, LawKind::elastoplastic, LawKind::linearized,
                              LawKind::hunt_crossley};
template <class Kind, std::size_t N>
std::string name_list(const std::array<Kind, N>& kinds) {
  std::string out;
  for (Kind k : kinds) out += (out.empty() ? "" : ", ") + std::string(to_string(k));
  return out;
}

}  // namespace

std::span<const LawKind> all_laws() {
  return kLaws;
}
std::string_view to_string(LawKind k) {
  switch (k) {
    case LawKind::hertz:
      return "hertz";
    case LawKind::elastoplastic:
      return "elastoplastic";
    case LawKind::linearized:
      return "linearized";
    case LawKind::hunt_crossley:
      return "hunt-crossley";
  }
  return "?";
}

std::string_view to_string(ImpactStatus s) {
  switch (s) {
    case ImpactStatus::separated:
      return "separated";
    case ImpactStatus::captured:
      return "captured";
    case ImpactStatus::failed:
      return "failed";
  }
  return "?";
}

std::string_view to_string(EventKind k) {
  switch (k) {
    case EventKind::onset:
      return "onset";
    case EventKind::yield:
      return "yield";
    case EventKind::max_compression:
      return "max_compression";
    case EventKind::max_displacement:
      return "max_displacement";
    case EventKind::peak_force:
      return "peak_force";
    case EventKind::separation:
      return "separation";
    case EventKind::capture:
      return "capture";
  }
  return "?";
}

LawKind parse_law(const std::string& name, const std::string& field) {
  for (LawKind k : kLaws)
    if (name == to_string(k)) return k;
  throw InputError(field, "unknown contact law '" + name + "'; valid names: " + name_list(kLaws));
}

std::string IntegratorOptions::invalid_reason() const {
  const bool valid = rtol >= 1e-15 && rtol <= 1e-2 && atol > 0 && atol <= 1e-2 && dt >= 0 &&
                     dt <= 0.5 && std::isfinite(dt) && max_steps > 0;
  if (valid) return {};  // no stream on the hot path (validated once per impact)
  std::ostringstream os;
  if (!(rtol >= 1e-15 && rtol <= 1e-2))
    os << "--rtol must lie in [1e-15, 1e-2] (got " << rtol << ")";
  else if (!(atol > 0 && atol <= 1e-2))
    os << "--atol must lie in (0, 1e-2] (got " << atol << ")";
  else if (!(dt >= 0 && dt <= 0.5 && std::isfinite(dt)))
    os << "--dt (normalised step) must lie in (0, 0.5] (got " << dt << ")";
  else if (!(max_steps > 0))
    os << "max_steps must be > 0 (got " << max_steps << ")";
  return os.str();
}

void validate(const SimulationRequest& req) {
  validate(req.scene);
  const std::string why = req.options.invalid_reason();
  if (!why.empty()) throw InputError(why.substr(0, why.find(' ')), why.substr(why.find(' ') + 1));
  if (req.law == LawKind::hunt_crossley) {
    if (req.hunt_crossley.K && !(std::isfinite(*req.hunt_crossley.K) && *req.hunt_crossley.K > 0))
      throw InputError("--hc-k", "must be a finite number > 0 N/m^1.5");
    if (!(std::isfinite(req.hunt_crossley.mu) && req.hunt_crossley.mu >= 0))
      throw InputError("--hc-mu", "must be a finite number >= 0 s/m");
  }
}

ImpactResult simulate(const SimulationRequest& req, std::vector<TrajectoryPoint>* trajectory) {
  validate(req);
  const DerivedParameters p = derive(req.scene);
  switch (req.integrator) {
    case IntegratorKind::odeint_dopri5:
      return detail::simulate_odeint_dopri5(req, p, trajectory);
    case IntegratorKind::odeint_rosenbrock4:
      return detail::simulate_odeint_rosenbrock4(req, p, trajectory);
    case IntegratorKind::rk4:
      return detail::simulate_rk4(req, p, trajectory);
    case IntegratorKind::dp45:
      return detail::simulate_dp45(req, p, trajectory);
    case IntegratorKind::dop853:
      return detail::simulate_dop853(req, p, trajectory);
    case IntegratorKind::gsl_rk8pd:
      return detail::simulate_gsl_rk8pd(req, p, trajectory);
    case IntegratorKind::gsl_msbdf:
      return detail::simulate_gsl_msbdf(req, p, trajectory);
    case IntegratorKind::mp50:
      return detail::simulate_mp50(req, p, trajectory);
  }
  return {};
}

}  // namespace ivv
