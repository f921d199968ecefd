// Tolerances of the battery, each with its reason. A case names one of these; none is picked
// to make a case pass.
#pragma once

#include "solver/simulate.h"

namespace ivv::verification {

struct Tolerance {
  double value;
  const char* reason;
};

// An integrator at its default settings, against an exact value (closed form or the 50-digit
// reference), for e, F_max, z_max and t_contact.
inline Tolerance default_settings_tolerance(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::rk4:
      return {
          1e-7,
          "rk4 at its default step h = 1e-3 (normalised): global error C h^4 ~ 1e-12 C on smooth "
          "phases, but the Hertz onset F ~ z^{3/2} is not smooth at z = 0 and costs one step of "
          "local error ~h^{5/2} ~ 3e-8; 1e-7 covers that term with a factor 3"};
    case IntegratorKind::mp50:
      return {1e-12,
              "mp50 integrates at 1e-26; the comparison is limited by the closed forms in double "
              "(round-off and GSL quadrature of the contact time, estimated error <= 1e-13)"};
    default:
      return {1e-7,
              "adaptive integrator at its default rtol = 1e-10 per step: local errors add over the "
              "N steps of a contact without amplification (the normalised contact problem is not "
              "unstable), so the global error is at most N rtol; the cases that use this "
              "tolerance are contacts of N <= 1000 steps (paper scene, zeta <= 1), and a run "
              "whose error exceeds its own bound (consistency.h: 20 N rtol, e.g. rosenbrock4's "
              "3385 steps at zeta = 10) is a failure with its reason, not a number"};
  }
}

// Cross-checks of derived quantities (ledger residual, impulse, COR definitions) per run.
inline Tolerance conservation_tolerance(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::rk4:
      return {1e-7,
              "the quadratures ride on the same rk4 steps: their error is that of the "
              "solution, bounded as for e (1e-7, onset term h^{5/2})"};
    case IntegratorKind::mp50:
      return {1e-13, "50-digit integration; closed-form loop area and rounding to double"};
    default:
      return {1e-7,
              "quadratures integrated with the state at rtol = 1e-10: global error at most "
              "N rtol, as for e (N <= 1000 in the cases using it; runs beyond their own bound "
              "fail, consistency.h)"};
  }
}

}  // namespace ivv::verification
