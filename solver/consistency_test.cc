// The guard behind every route (consistency.h): a result whose status says it succeeded but
// which carries a number that is not finite becomes a failure naming the field.
#include "solver/consistency.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace ivv {
namespace {

// A Hunt-Crossley run at mu = 1e-200 printed "separated, e = -nan" (HuntCrossley tests): a
// success status beside a NaN, from any route, is now a named failure.
TEST(NonFiniteOutcome, SuccessStatusBesideANaNBecomesANamedFailure) {
  ImpactResult r;
  r.status = ImpactStatus::separated;
  r.e = std::nan("");
  EXPECT_TRUE(fail_non_finite_outcome(r, "test"));
  EXPECT_EQ(r.status, ImpactStatus::failed);
  EXPECT_NE(r.reason.find("its e is not a finite number"), std::string::npos) << r.reason;
  ImpactResult captured;
  captured.status = ImpactStatus::captured;
  captured.t_contact = captured.t_alpha_max = INFINITY;  // the contact never ends: allowed
  EXPECT_FALSE(fail_non_finite_outcome(captured, "test"));
  ImpactResult separated;
  separated.status = ImpactStatus::separated;
  separated.t_contact = INFINITY;  // a separated impact has a finite contact time
  EXPECT_TRUE(fail_non_finite_outcome(separated, "test"));
}

// A ledger that is NaN or infinite is an overflow, not an integration error: the reason says
// so and does not advise a tighter tolerance (a bar with A = rho = 1e-200 printed "residual
// -nan ... tighten --rtol/--atol"); a finite residual beyond the bound keeps that advice.
TEST(ConsistencyFailure, ANonFiniteLedgerIsAnOverflowNotATolerance) {
  IntegratorOptions opt;
  ConsistencyMeasures m;
  m.steps = 100;
  m.ledger_residual = std::nan("");
  const std::string overflow = consistency_failure(m, opt, "dop853");
  EXPECT_NE(overflow.find("overflowed the double range"), std::string::npos) << overflow;
  EXPECT_EQ(overflow.find("tighten"), std::string::npos) << overflow;
  m.ledger_residual = 1.0;
  const std::string error = consistency_failure(m, opt, "dop853");
  EXPECT_NE(error.find("tighten --rtol/--atol"), std::string::npos) << error;
}

}  // namespace
}  // namespace ivv
