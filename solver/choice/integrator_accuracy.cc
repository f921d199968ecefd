#include "solver/choice/integrator_accuracy.h"

#include <sstream>

namespace ivv {

double measured_relative_error(IntegratorKind k) {
  // each stepper's own statement (its header says what was measured), via the traits table
  return traits(k).measured_relative_error;
}

std::string accuracy_statement(IntegratorKind k) {
  std::ostringstream os;
  if (traits(k).reference) {
    os << "reference: rtol = atol = 1e-26 in 50 digits; results rounded to double";
    return os.str();
  }
  os << (traits(k).fixed_step ? "fixed step --dt (default 1e-3), held to rtol/atol"
                              : "local error per step <= atol + rtol |x| (normalised)")
     << "; e within 20 N (atol + 2 rtol) of v0 after N steps, checked every run (relative "
        "error grows as 1/e); paper scene at defaults: relative error of e < "
     << measured_relative_error(k);
  return os.str();
}

}  // namespace ivv
