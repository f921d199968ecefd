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
// cost grows as S; an implicit one's does not. Measured on the paper scene at rtol 1e-8
// (`ivv bench`, and the table in the commit that added this): dop853 and odeint-rosenbrock4 cost
// the same near S ~ 100-150 (v0 = 0.3-5 m/s); below, dop853 is 5-20 times faster; above,
// rosenbrock4 is, by up to 17 times at zeta = 100. Hence:
//   S > kStiffnessThreshold = 100  -> odeint-rosenbrock4 (implicit, L-stable, dense output)
//   otherwise                      -> dop853 (eighth order, dense output)
// No dashpot (c = inf, and Hunt-Crossley which carries its own damping): S = 0.
//
// Estimated error (relative, of e, F_max, z_max and t_f): dop853 stays within 10 rtol on the
// paper grid (bench: 0.002-0.3 rtol for rtol 1e-4 ... 1e-12): 10 rtol. odeint-rosenbrock4 on
// the stiff scene reaches 38 rtol at rtol 1e-10 (F_max, zeta = 100; the autochoice case found
// it when the estimate was 10 rtol): 100 rtol. Checked by the verification cases
// autochoice.* (cases_convergence.cc).
#pragma once

#include <string>
#include <vector>

#include "solver/simulate.h"

namespace ivv {

inline constexpr double kStiffnessThreshold = 100.0;
// estimated_error = this x rtol
inline constexpr double kAutoErrorFactorExplicit = 10.0;
inline constexpr double kAutoErrorFactorImplicit = 100.0;

struct IntegratorChoice {
  IntegratorKind integrator = IntegratorKind::dop853;
  double stiffness_ratio = 0.0;  // S above
  double estimated_error = 0.0;  // relative error of e, F_max, t_f
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
