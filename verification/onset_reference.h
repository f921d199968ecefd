// The 50-digit reference for the onset series (solver/driver/onset_series.h): the same equations
// integrated from tau = 0, independently of the series and of every double-precision stepper.
//
// In tau the solution is not smooth at onset (F ~ tau^{3/2}); in q = tau^{1/2}, with
// u = z/tau (u(0) = 1), it is:
//   da/dq = 2 q w,   dw/dq = -2 kappa q^4 u^{3/2},
//   du/dq = 2 (w - u)/q - 2 beta kappa q^2 u^{3/2}        ((w - u)/q -> 0 as q -> 0),
//   dJ/dq = 2 kappa q^4 u^{3/2},  dWa/dq = 2 kappa q^4 u^{3/2} w,  dWv/dq = 2 beta kappa^2 q^7 u^3.
// Classical RK4 on this smooth system in cpp_bin_float_50 with n equal steps: global error
// O((q/n)^4), and the result is Richardson-extrapolated from n and 2n steps (error
// O((q/n)^5) or better), far below the 1e-13 the comparisons need at n = 400.
#pragma once

#include "solver/driver/onset_series.h"

namespace ivv::verification {

// The state at tau for F_bar = kappa z^{3/2} and beta = 2 zeta, from 0 in 50 digits.
OnsetSeriesState onset_reference_state(double kappa, double beta, double tau, int steps = 400);

}  // namespace ivv::verification
