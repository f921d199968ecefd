// `--model auto`: model only what a scene needs. From the scene, the law and the requested
// tolerance rtol, one of these routes runs (first that applies):
//
//  1. closed-form elastoplastic (energy): elastoplastic law, no dashpot. docs/design.md §2
//     "Undamped elastoplastic, closed form by energy" gives z_m, F_max, z_f, e and the hysteresis
//     work exactly; the contact time in closed form on the loading legs (elastic leg: incomplete
//     beta function, t = (z_H/v0)(2/5) B(u_y; 2/5, 1/2) with u_y = (z_y/z_H)^{5/2}, z_H the
//     Hertz z_m at v0; plastic leg: harmonic, 2 sqrt(m/K_y) asin(sqrt(K_y d/(2 F_m)))) and by
//     Gauss-Legendre quadrature on the unloading leg after z = z_m - s^2 (which removes the
//     1/sqrt endpoint singularity; error estimated by 20 against 30 nodes, adaptive
//     Gauss-Kronrod when that estimate exceeds rtol/10). Below yield: Hertz (route 2).
//     Written here apart from oracles/undamped_elastoplastic.h (GSL QAGS, ~3-14 us per impact:
//     slower than integrating), which checks it in the autochoice cases.
//  2. closed-form hertz (energy): hertz law, no dashpot. z_m = (5 m v0^2/(4 K_h))^{2/5},
//     F_max = K_h z_m^{3/2}, t_f = (4/5) B(2/5, 1/2) z_m/v0, e = 1 (docs/design.md §2).
//  3. hunt-crossley: e exactly by Lambert W (closed_forms/hunt_crossley.h: independent of K, m and
//     the exponent); F_max (not at z_m: the rate term), t_f and the impulses have no closed
//     form, so the integrator runs for them and its e is replaced by the exact one (the
//     difference is reported).
//  4. linearized closed form (paper eqs 22-25, closed_forms/linear_model.h) for the elastoplastic
//  law
//     with a dashpot, where its estimated error against the nonlinear law is within rtol.
//     Estimate: both laws have exact undamped solutions, so their relative difference
//     D0 = max over e, z_m, F_max, t_f is known exactly at the request's v0 without a dashpot;
//     with one, the difference grows with zeta (measured on the paper grid: x3.3 in t_f at
//     zeta = 0.3, x6.4 in e at zeta = 0.6), covered by
//        estimated_error = 2 (1 + 10 zeta) D0,
//     used only where the linearized law is defined (z_m >= 2.25 z_y) and the linear model's
//     unloading is far from capture (zeta1 = zeta/gamma <= 0.5: as e -> 0 near the capture
//     boundary the relative error of e is unbounded). D0 >= 2e-3 up to v0 = 100 m/s on the
//     paper scene, so in practice this route is taken only at rtol near its upper limit 1e-2.
//     Verified on a grid by the autochoice cases (verification/cases_autochoice.cc).
//  5. otherwise the full ODE model with the requested integrator (choose_integrator()'s with
//     --integrator auto). Capture is then decided by the driver's criterion (the rebound
//     sqrt(w^2 + 2U) still attainable from the remaining energy below capture_cor,
//     solver/driver/impact_driver.h), which ends an overdamped creep once no rebound is possible.
//  A trajectory asked for, an expression law or the linearized law always run route 5 (a
//  closed form gives no trajectory; the linearized law is integrated as asked).
//
// Estimated error (of e in units of v0, relative of F_max and z_max, and of t_f relative
// divided by e: see solver/choice/integrator_choice.h): closed forms kEstimateClosedForm
// (round-off of a few operations, pow and cbrt) or the quadrature's estimate when larger;
// route 3: the integrator's (e then exact); route 4: as above; route 5: choose_integrator()'s
// factor (200 rtol explicit, 300 rtol implicit: solver/choice/integrator_choice.h).
//
// The ImpactResult of a closed form is complete where the form gives a field and says where it
// does not: Newton, Poisson and energetic COR are equal by momentum and by the work of the
// contact force on the impactor (both exact here); events carry onset, maximum compression,
// maximum displacement and separation (route 1 omits the yield event: its time is not
// computed); steps and RHS evaluations are 0. The consistency check of consistency.h runs on it
// as on an integrated result (as one step).
#pragma once

#include <string>
#include <vector>

#include "solver/choice/integrator_choice.h"
#include "solver/simulate.h"

namespace ivv {

enum class ModelRoute {
  closed_form_elastoplastic,
  closed_form_hertz,
  hunt_crossley_lambert_w,
  linearized_closed_form,
  integrated
};

// "closed-form-elastoplastic", "closed-form-hertz", "hunt-crossley-lambert-w",
// "linearized-closed-form", "integrated": the route in `simulate --json` model_choice.route.
std::string_view to_string(ModelRoute r);

// Relative error of a closed form evaluated in double: a few operations with pow/cbrt/sqrt.
inline constexpr double kEstimateClosedForm = 1e-14;
// The linearized route (4): estimated_error = kLinearSafety (1 + kLinearZetaGrowth zeta) D0.
inline constexpr double kLinearSafety = 2.0;
inline constexpr double kLinearZetaGrowth = 10.0;
// A floor under the linearized route's undamped difference in e, before any closed form is
// evaluated: both undamped models depend on v0/v_y alone (paper eq. 26; eq. 20 through
// q = 1.5 (15/8)^{1/4} (v_y/v0)^{1/2}), and |gamma - e|/e >= kLinearDifferenceFloor (v0/v_y)^{-1/2}
// for every v0 above yield: |gamma - e|/e (v0/v_y)^{1/2} falls smoothly towards its asymptote
// 0.0487 from above (model_choice_test.cc holds the floor over 1 < v0/v_y <= 1e12).
// So the route cannot be within rtol unless v0/v_y >= (kLinearSafety floor / rtol)^2, which at
// rtol = 1e-8 is ~8e13: the per-point decision of a sweep then costs a square root.
inline constexpr double kLinearDifferenceFloor = 0.045;
// ... only where zeta1 = zeta/gamma <= this.
inline constexpr double kLinearMaxUnloadingDamping = 0.5;

// The decision, without words (no allocation: the per-impact path of a sweep).
struct ModelDecision {
  ModelRoute route = ModelRoute::integrated;
  IntegratorKind integrator = IntegratorKind::dop853;  // routes 3 and 5
  double estimated_error = 0.0;
  double linear_difference = -1.0;  // D0 of route 4 when it was estimated, else < 0
};

// The decision and its reasons in words (`simulate --json` "model_choice").
struct ModelChoice {
  ModelDecision decision;
  std::string law;         // what ran, e.g. "closed-form elastoplastic (energy)"
  std::string integrator;  // the integrator that ran, "none" for a closed form
  std::vector<std::string> reasons;
  double estimated_error = 0.0;

  // One line: "<law> (integrator <name>, estimated error <e>)", as the summary prints it.
  std::string brief() const;
  // brief() and every reason, one per line: the words every front end prints.
  std::string full() const;
};

struct ModelRun {
  ImpactResult result;
  ModelChoice choice;
};

// What the caller needs besides the result: a trajectory is only made by integrating, so a
// request for one rules out the closed forms.
enum class RunOutput { result, result_and_trajectory };

ModelDecision decide_model(const ValidatedRequest& request, RunOutput output);
// Runs the decision (route 1-5) for the request.
ImpactResult run_model(const ValidatedRequest& request, const ModelDecision& decision,
                       std::vector<TrajectoryPoint>* trajectory);
// What run_model adds to the route's result: the route's name, and a failure for a non-finite
// outcome of a route that made its numbers itself.
void finish_route(ImpactResult& result, const ModelDecision& decision);
// The decision in words; `result` adds what the run found (route 3: the integrated e).
ModelChoice explain(const ValidatedRequest& request, const ModelDecision& decision,
                    const ImpactResult& result);

// --model full with --integrator auto: the full model, integrated by `chosen`'s integrator,
// with its reasons (route `integrated`).
ModelChoice integrated_choice(const SimulationRequest& request, const IntegratorChoice& chosen);

// --model auto for a validated request: the decision, the run and the reasons.
ModelRun simulate_model(const ValidatedRequest& request,
                        std::vector<TrajectoryPoint>* trajectory = nullptr);

}  // namespace ivv
