// Instantiates simulate() for the GSL odeiv2 steppers.
#include <gsl/gsl_errno.h>

#include <mutex>

#include "solver/simulate_impl.h"
#include "solver/stepper_traits.h"
#include "solver/steppers/gsl_odeiv2.h"

namespace ivv {
namespace gsl_detail {

void disable_abort_on_error() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

}  // namespace gsl_detail

namespace detail {
namespace {
template <class S>
using GslRk8pd = GslStepper<S, GslMethod::rk8pd>;
template <class S>
using GslMsbdf = GslStepper<S, GslMethod::msbdf>;
}  // namespace

ImpactResult simulate_gsl_rk8pd(const ValidatedRequest& v,
                                std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<GslRk8pd>(v, trajectory);
}

ImpactResult simulate_gsl_msbdf(const ValidatedRequest& v,
                                std::vector<TrajectoryPoint>* trajectory) {
  return simulate_with<GslMsbdf>(v, trajectory);
}

IntegratorTraits traits_gsl_rk8pd() {
  return stepper_traits<GslRk8pd>(IntegratorKind::gsl_rk8pd);
}

IntegratorTraits traits_gsl_msbdf() {
  return stepper_traits<GslMsbdf>(IntegratorKind::gsl_msbdf);
}

}  // namespace detail
}  // namespace ivv
