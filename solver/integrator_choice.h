// `--integrator auto`: the integrator a scene needs, chosen from its time scales (issue 8,
// part 3, integrator side only; the law is the one requested).
//
// Criterion. In the normalised variables (tau = omega0 t) the loading lasts O(1) and the
// spring-dashpot relaxation has the eigenvalue lambda = -2 zeta k, with k = dF_bar/dz_bar the
// normalised contact stiffness (solver/impact_system.h). Its largest value over the impact is
// reached at the maximum compression z_m: k_max = max(1, sqrt(z_m / z_y)) for the Hertz and
// elastoplastic curves (1.5 K_h sqrt(z_m) / K_y), with z_m bounded by its undamped value (the
// closed form by energy, SPEC §2: damping only shortens it). The stiffness ratio
//   S = 2 zeta k_max = |lambda_max| x (loading time scale 1)
// counts how many relaxation times fit into the loading. An explicit method is held to
// |h lambda| <= O(3-6) by stability wherever S exceeds what its accuracy would need, and its
// cost grows as S; an implicit one's does not. The implicit choice is rodas4 (the hand-written
// RODAS4 of solver/steppers/rodas.h: the method of odeint-rosenbrock4, same steps and errors,
// 4x faster: 44 against 177 us per impact at zeta = 100, rtol 1e-8). Measured on the paper
// scene (elastoplastic, v0 = 0.3, 1, 5 m/s, median us per impact, the commit that made rodas4
// the choice), dop853 against rodas4 cost the same at
//   rtol 1e-10: S ~ 100-150 (S = 97: 177 against 408 us; S = 106: 272 against 252 us)
//   rtol 1e-8:  S ~ 30-60   (S = 49: 55 against 79 us; S = 56: 102 against 78 us)
//   rtol 1e-6:  S < 30      (S = 28: 67 against 33 us)
// and rodas4 is faster above, by 40-75 times at zeta = 100. The choice does not see rtol; the
// threshold is the crossover at the default rtol 1e-10, which leaves rodas4's 2-7 times
// advantage unused for 30 < S < 100 at looser tolerances:
//   S > kStiffnessThreshold = 100  -> rodas4 (implicit, L-stable, dense output)
//   otherwise                      -> dop853 (eighth order, dense output)
// No dashpot (c = inf, and Hunt-Crossley which carries its own damping): S = 0.
//
// Estimated error (of e in units of v0, and relative of F_max and z_max; of t_f relative and
// divided by e, because separation is the crossing of z_f at the speed e v0, so a state error
// delta moves t_f by delta/e: near capture t_f is ill-conditioned, 2e-8 at rtol 1e-10 for
// e = 2.5e-4 at v0 = 5 m/s, zeta = 0.5, found by the autochoice.model case). dop853: 200 rtol.
// On the elastoplastic paper grid above yield it stays within 10 rtol (bench: 0.002-0.3 rtol for
// rtol 1e-4 ... 1e-12), but where the contact ends at z = 0 (the Hertz law, Hunt-Crossley, and
// elastic impacts of the elastoplastic law) the force z^{3/2} has an unbounded second
// derivative at separation, the embedded error estimate of the last steps is not asymptotic,
// and the autochoice.model case measured 145 rtol (Hertz law, v0 = 5 m/s, zeta = 0.1, rtol =
// atol = 1e-10, 27 steps) and 31 rtol (elastoplastic, elastic at 0.05 m/s). rodas4 against
// dop853 at 1e-13 (max over F_max, z_max relative and e in v0): on the autochoice case's stiff
// scene (v0 = 1 m/s, zeta = 100, rtol 1e-6, 1e-8, 1e-10) 5.4, 0.19 and 38 rtol; on the wider
// grid v0 = 0.3, 1, 5 m/s x zeta = 30, 100, 1000 x rtol = 1e-6 ... 1e-12, 172 rtol at worst
// (zeta = 1000, rtol 1e-11 and 1e-12: the dense output is of order 3, so the state it gives at
// maximum compression errs by O(h^4) against the step's O(h^5), a ratio to rtol that grows as
// rtol^{-1/5}). Hence 300 rtol: a margin of 1.7 over the worst measured, 8 over the cases'
// grid. (odeint-rosenbrock4 gives the same numbers; its former 100 rtol did not cover zeta =
// 1000 at rtol <= 1e-10.) Checked by the verification cases autochoice.* (cases_convergence.cc).
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv {

inline constexpr double kStiffnessThreshold = 100.0;
// estimated_error = this x rtol
inline constexpr double kAutoErrorFactorExplicit = 200.0;
inline constexpr double kAutoErrorFactorImplicit = 300.0;

struct IntegratorChoice {
  IntegratorKind integrator = IntegratorKind::dop853;
  double stiffness_ratio = 0.0;  // S above
  double estimated_error = 0.0;  // error of e [v0], F_max, z_max; of t_f times e (above)
  std::vector<std::string> reasons;
};

// The choice for `request` (its law, scene and rtol; its integrator field is ignored), with
// the reasons in words.
IntegratorChoice choose_integrator(const SimulationRequest& request);
// The same choice without the words (no allocation): the per-run path of --integrator auto.
IntegratorKind auto_integrator(const Scene& scene, const DerivedParameters& p);
// The stiffness ratio S above (0 without a dashpot).
double stiffness_ratio(const Scene& scene, const DerivedParameters& p);

}  // namespace ivv
