// One impact, chosen at run time: scene x contact law x integrator.
//
// The runtime choice dispatches once per impact into code templated on the law, the presence
// of a dashpot and the stepper (impact_driver.h), so the right-hand side is never dispatched
// per evaluation.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "solver/integrator_options.h"
#include "solver/integrators.h"
#include "solver/result.h"
#include "solver/scene.h"

namespace ivv {

enum class LawKind { hertz, elastoplastic, linearized, hunt_crossley };
// IntegratorKind, the table of integrator traits and parse_integrator: solver/integrators.h.

std::span<const LawKind> all_laws();
std::string_view to_string(LawKind k);
// Parse a name; throws InputError(field, "unknown ...; valid names: ...") otherwise.
LawKind parse_law(const std::string& name, const std::string& field = "--law");

// Hunt-Crossley parameters (used only by LawKind::hunt_crossley).
struct HuntCrossleyParameters {
  std::optional<double> K;  // [N/m^1.5]; default: the scene's Hertz stiffness K_h
  double mu = 0.0;          // [s/m]
};

struct SimulationRequest {
  Scene scene;
  LawKind law = LawKind::elastoplastic;
  IntegratorKind integrator = IntegratorKind::odeint_dopri5;
  IntegratorOptions options;
  HuntCrossleyParameters hunt_crossley;
};

// One sample of the trajectory (SI and the normalised variables of paper eq. 26).
struct TrajectoryPoint {
  double t, alpha, alpha_dot, y, z, force;  // [s, m, m/s, m, m, N]
  double tau, alpha_bar, force_bar;         // [-]
};

// Validates the request (InputError naming the field) and runs it. Failures of the
// integration or of the law's domain come back in ImpactResult::status/failure/reason.
// `trajectory`, when given, receives samples along the solution (several per step).
ImpactResult simulate(const SimulationRequest& request,
                      std::vector<TrajectoryPoint>* trajectory = nullptr);

// Throws InputError for invalid options or an incompatible combination.
void validate(const SimulationRequest& request);

}  // namespace ivv
