#include <gsl/gsl_errno.h>

#include <mutex>

#include "solver/steppers/gsl_odeiv2.h"

namespace ivv::gsl_detail {

void disable_abort_on_error() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

}  // namespace ivv::gsl_detail
