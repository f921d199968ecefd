// What an integrator's tolerance really delivers (gsl-msbdf reached 4e-7 relative error in e
// at rtol 1e-10 without a word). `ivv integrators -v` prints these statements.
//
// The contract common to all: rtol/atol bound the local error of each step in the normalised
// state of impact_system.h (O(1) quantities); after N steps the COR is within the accumulated
// bound of consistency.h, 20 N (atol + 2 rtol) in units of v0, and every run is checked against
// it (three CORs and the energy ledger) or fails with the reason. That bound is absolute: the
// relative error of e grows as 1/e, so a near-capture COR of 1e-7 may be right to 1e-4 only.
// Measured on the paper scene at v0 = 1 m/s (zeta 0.1 and no dashpot), default settings,
// against the 50-digit reference: see kMeasured below and integrators_test.cc, which re-measures.
#pragma once

#include <string>

#include "solver/simulate.h"

namespace ivv {

// Largest relative error of e measured as above [-]; the test asserts the integrator stays
// within it.
double measured_relative_error(IntegratorKind k);

// One line: the contract and the measured figure, for `ivv integrators -v` and the docs.
std::string accuracy_statement(IntegratorKind k);

}  // namespace ivv
