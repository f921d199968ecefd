// The outcome of one impact, in SI units.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "solver/steppers/step_result.h"

namespace ivv {

enum class ImpactStatus {
  separated,  // the contact force returned to zero: a rebound (possibly with e ~ 0)
  captured,   // no rebound: the remaining energy bounds e below the capture threshold
  failed      // see ImpactResult::reason
};

// Why a run failed: a code for tests and programs (to_string spells it: the JSON's "failure"),
// beside ImpactResult::reason for people.
//   law_domain         the law is undefined for this scene or at contact onset, known before any
//                      step (a front end treats it as bad input)
//   law_non_finite     the law returned NaN or infinity at a state reached inside contact
//   step_underflow ... library_error
//                      one step failed: the codes of StepFailure (solver/steppers/step_result.h)
//   event_location     a root finder out of iterations, or a NaN inside its bracket
//   event_refinement   the Hermite re-steps that refine an event did not converge, or one failed
//   step_limit         no separation within IntegratorOptions::max_steps
//   time_limit         no separation before IntegratorOptions::tau_max
//   still_approaching  the force vanished with the impactor still approaching: the integration
//                      error exceeds the remaining force
//   inconsistent       the run ended but its CORs or energy ledger disagree beyond the stated
//                      error, or an outcome is not a finite number (solver/consistency.h)
//   integrator         any other failure of an integration (no integrator of that number)
enum class FailureKind {
  none,
  law_domain,
  law_non_finite,
  step_underflow,
  attempts_exhausted,
  non_finite_state,
  singular_matrix,
  unstable_step,
  library_error,
  event_location,
  event_refinement,
  step_limit,
  time_limit,
  still_approaching,
  inconsistent,
  integrator,
};

std::string_view to_string(FailureKind k);
// Every kind but none, law_domain and law_non_finite: the integration, not the law, failed.
bool is_integrator_failure(FailureKind k);
// The run's failure for a step that failed with `f`.
FailureKind failure_of_step(StepFailure f);

enum class EventKind {
  onset,
  yield,
  max_compression,
  max_displacement,
  peak_force,
  separation,
  capture
};

std::string_view to_string(ImpactStatus s);
std::string_view to_string(EventKind k);

struct ImpactEvent {
  EventKind kind;
  double t;      // [s]
  double z;      // spring deformation [m]
  double alpha;  // impactor displacement [m]
  double force;  // [N]
};

// Energy ledger (docs/design.md §1): initial = final + stored + plastic + viscous + residual.
struct EnergyLedger {
  double initial = 0.0;  // 1/2 m v0^2 [J]
  double final = 0.0;    // 1/2 m alpha_dot_f^2 [J]
  double stored = 0.0;   // spring energy still stored at the end (capture only) [J]
  double plastic = 0.0;  // hysteresis loop area of the spring, closed form (integrated for
                         // laws without one, e.g. Hunt-Crossley) [J]
  double viscous = 0.0;  // int F^2/c dt, integrated [J]
  double residual = 0.0;
  bool plastic_integrated = false;  // true when `plastic` came from quadrature
};

struct ImpactResult {
  ImpactStatus status = ImpactStatus::failed;
  FailureKind failure = FailureKind::none;
  std::string reason;  // why it failed (empty otherwise)

  double e = 0.0;                 // Newton COR, -alpha_dot(t_f)/v0
  double e_bound = 0.0;           // captured: the true COR lies in [0, e_bound]
  double e_poisson = 0.0;         // restitution impulse / compression impulse
  double e_energetic = 0.0;       // sqrt(restitution work / compression work)
  double F_max = 0.0;             // [N]
  double t_F_max = 0.0;           // [s]
  double z_max = 0.0;             // maximum spring deformation z_m [m]
  double t_z_max = 0.0;           // [s]
  double alpha_max = 0.0;         // maximum impactor displacement alpha_c [m] (captured
                                  // without turning back: the limit z_f + m* v0/c)
  double t_alpha_max = 0.0;       // [s]; +inf when that limit is approached, not reached
  double z_perm = 0.0;            // permanent spring set z_f [m]
  double y_final = 0.0;           // dashpot displacement at the end [m] (captured: m* v0/c)
  double t_contact = 0.0;         // [s]; +inf when captured (the contact never ends)
  double t_capture = 0.0;         // captured: when capture was established [s] (an "at
                                  // capture" time, integrator-dependent); 0 otherwise
  double rebound_velocity = 0.0;  // alpha_dot at the end [m/s] (< 0: moving away); the
                                  // relative velocity when the target is a free sphere
  // Each body's velocity after the impact [m/s], in the frame where the target was at rest
  // before, positive towards the target: m1 v1 + m2 v2 = m1 v0 (Scene::body_velocities_after).
  // A fixed target (half-space) stays at 0 and the impactor leaves at rebound_velocity.
  double impactor_velocity_after = 0.0;
  double target_velocity_after = 0.0;
  // The pull-off work of the unloading branch, -int_0^{z_f} F ds [J]: the depth of an attractive
  // well below zero force (a law that allows tension and states its separation work, law.h),
  // computed once where unloading begins; 0 without a well. An impactor whose remaining energy
  // cannot climb out of it is captured (solver/driver/capture.h, criterion 4).
  double pull_off_work = 0.0;
  double impulse = 0.0;              // int F dt [N s]
  double impulse_compression = 0.0;  // int_0^{t_c} F dt [N s]
  EnergyLedger energy;
  long steps = 0;
  long rhs_evaluations = 0;
  // What produced the numbers (static strings, no allocation per impact): `route` is
  // "integrated" or the closed-form route --model auto took (solver/choice/model_choice.h, the
  // names of model_choice.route), `integrator` the one that ran, "none" for a closed form.
  std::string_view route = "integrated";
  std::string_view integrator = "none";
  std::vector<ImpactEvent> events;

  bool separated() const { return status == ImpactStatus::separated; }
  bool ok() const { return status != ImpactStatus::failed; }
};

}  // namespace ivv
