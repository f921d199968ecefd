// A finite-plate impact as a front end asks for it (`ivv simulate` on a scene whose plate has
// length_x and length_y): the full plate (plate_impact.h), its truncation error, and the model
// the impact needs (plate_regime.h).
//
// From RequestOptions: the scene with --v0, the law (--law, or an expression law's --force and
// --unload; --param), --rtol/--atol for every
// model's integration (absent: kPlateSimulateRtol and kPlateSimulateAtol, 1e-8 and 1e-10), --model
// (auto, full, half-space, infinite-plate, quasi-static) and
// --model-tol. Flags that describe a dashpot (--zeta, --c, --lambda, --no-dashpot), an
// integrator other than auto, --dt and --max-steps are refused by name (InputError): a finite
// plate has no dashpot and runs its own integration. A law the plate does not model (rate-
// dependent, or with tension) is refused by name too (solver/plate/plate_law.h).
//
// Every run integrates the full plate (the reference of the choice) and the three cheaper
// models, and answers with
//   --model auto   the cheapest model within --model-tol of the full plate (the regime);
//   --model NAME   that model, with its measured distance from the full plate;
// estimated error of the answer = its measured distance from the full plate + the full plate's
// own truncation error (below).
//
// The cut-off is chosen for a truncation error of kPlateTruncationTol (1e-6) in e by the rule of
// plate_impact.h (two cut-offs c' < c, est = 1.25 |e(c) - e(c')|/((c/c')^p - 1), p the order of
// the scene's dropped modes: 3 for the static compliance, 4 for the oscillator), which also gives
// the truncation's estimated cost in e.
#pragma once

#include <limits>
#include <optional>

#include "solver/plate/plate_impact.h"
#include "solver/plate/plate_regime.h"
#include "solver/request_options.h"

namespace ivv {

struct PlateRun {
  static constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  Scene scene;
  LawKind law = LawKind::elastoplastic;
  LawParameters parameters;
  ExpressionLawSpec expression;  // law == expression: the typed law
  PlateImpactOptions options;
  PlateImpactResult result;           // the full plate
  double e_half_cutoff = nan;         // e at the coarser cut-off of the rule's last pair
  double truncation_error = nan;      // the rule's estimate (plate_impact.h)
  std::optional<PlateModel> forced;   // --model other than auto
  std::optional<PlateRegime> regime;  // when the full plate ran (result.ok)

  // The model whose numbers answer the request: the forced one, or the regime's choice (the
  // full plate when the full run failed).
  PlateModel answered() const;
  const PlateModelOutcome* answer() const;  // nullptr when the regime was not measured
  // |answer - full| + truncation_error (NaN when unknown).
  double estimated_error() const;
  // The law as a request: scene, law, parameters and expression (for the law's JSON and runs).
  SimulationRequest law_request() const;
};

PlateRun run_plate_simulation(const RequestOptions& options);
// The refusals above alone (InputError naming the flag), for a front end that applies the
// overrides to a scene before it runs (the Python module's ivv.scene).
void refuse_dashpot_and_integrator_flags(const RequestOptions& options);
// The stepper --integrator names on a finite plate: auto or exponential (the default), dop853,
// odeint-dopri5 (PlateImpactOptions::Stepper); InputError("--integrator") for any other name.
PlateImpactOptions::Stepper plate_stepper(const std::string& integrator);
// A command that runs its own plate steppers (a sweep, check-law) refuses --integrator other
// than auto: InputError("--integrator") saying `what` runs the exponential stepper.
void refuse_stepper_choice(const RequestOptions& options, const char* what);
// The same for a scene the front end already holds (the Python module): options.scene is not
// read.
PlateRun run_plate_simulation(Scene scene, const RequestOptions& options);

}  // namespace ivv
