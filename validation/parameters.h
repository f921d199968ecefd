// The parameters a calibration may fit, by the name the user types after --fit.
//
// Scene parameters (SI units, scene/scene.h):
//   mass [kg] (impactor m1), radius [m] (impactor R1), impactor_youngs_modulus [Pa],
//   target_youngs_modulus [Pa], yield_strength [Pa] (S_y),
//   c [N s/m] (the dashpot as a coefficient), zeta [-] (the dashpot as a damping ratio,
//   zeta = sqrt(m K_y)/(2c)). Fitting c holds c fixed while S_y moves; fitting zeta holds zeta
//   (so c moves with K_y). Both at once is refused: they are one dashpot.
// Law parameters: the built-in law's --param names (law_info(law).parameters, e.g.
//   Hunt-Crossley K [N/m^1.5] and mu [s/m]); for an expression law, every --param it was
//   given (its value is the start of the fit).
//
// Bounds: each parameter lies in a closed range; the default is (0, +inf) for every one of
// these (all are positive quantities), narrowed to the law's own accepted range for a law
// parameter. A start value outside its bounds is bad input.
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv::validation {

struct ParameterInfo {
  std::string name;
  std::string unit;
  double lower = 0.0;  // accepted range; positive by default (lower_open)
  double upper = 0.0;
  bool lower_open = true;
};

// The names fittable in this request, in a stable order (scene first, then the law's).
std::vector<std::string> fittable_parameters(const SimulationRequest& request);

// What `name` means in this request; InputError("--fit", "unknown parameter ...; fittable:
// ...") when the request has no such parameter (e.g. yield_strength for a Hertz law whose
// scene gives none is still fittable: it becomes the scene's S_y).
ParameterInfo parameter_info(const SimulationRequest& request, const std::string& name);

// The parameter's value in the request (a law default taken from the scene included).
// Throws InputError naming --fit when it has none (e.g. c without a dashpot: give the scene a
// [damping] to start from).
double parameter_value(const SimulationRequest& request, const std::string& name);

// Sets the parameter (no validation: the run validates the request).
void set_parameter(SimulationRequest& request, const std::string& name, double value);

// Throws InputError("--fit", ...) for an unknown name, a name given twice, or c with zeta.
void check_fit_names(const SimulationRequest& request, const std::vector<std::string>& names);

}  // namespace ivv::validation
