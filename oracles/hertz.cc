#include "oracles/hertz.h"

#include <boost/math/special_functions/beta.hpp>
#include <cmath>
#include <sstream>

#include "scene/input_error.h"

namespace ivv::oracles {

double hertz_contact_time_factor() {
  return 0.8 * boost::math::beta(0.4, 0.5);
}

HertzImpact solve_hertz(double mass, double K_h, double v0) {
  require_positive("mass", mass);
  require_positive("K_h", K_h);
  require_positive("v0", v0);
  HertzImpact r;
  r.z_max = std::pow(1.25 * mass * v0 * v0 / K_h, 0.4);
  r.F_max = K_h * r.z_max * std::sqrt(r.z_max);
  r.t_contact = hertz_contact_time_factor() * r.z_max / v0;
  r.t_max = 0.5 * r.t_contact;
  r.e = 1.0;
  return r;
}

}  // namespace ivv::oracles
