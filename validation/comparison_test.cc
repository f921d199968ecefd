// Model ranking: AIC/BIC arithmetic, order, failed fits last.
#include "validation/comparison.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ivv::validation {
namespace {

CalibrationResult fit(double chi2, int k, int n, bool ok = true) {
  CalibrationResult r;
  r.ok = ok;
  r.failure = ok ? "" : "did not converge";
  r.chi2 = chi2;
  r.points = n;
  r.determined = k;
  r.dof = n - k;
  r.p_value = 0.5;  // stated uncertainties: chi^2 is -2 ln L up to a shared constant
  for (int j = 0; j < k; ++j) r.parameters.emplace_back();
  return r;
}

TEST(Comparison, RanksByAicWithBicBeside) {
  const ModelRanking c =
      compare({"a", "b", "c"}, {fit(30.0, 1, 25), fit(20.0, 3, 25), fit(0, 0, 25, false)});
  ASSERT_EQ(c.models.size(), 3u);
  EXPECT_EQ(c.models[0].name, "b");  // AIC 26 against 32
  EXPECT_DOUBLE_EQ(c.models[0].aic, 26.0);
  EXPECT_DOUBLE_EQ(c.models[0].bic, 20.0 + 3 * std::log(25.0));
  EXPECT_DOUBLE_EQ(c.models[1].delta_aic, 6.0);
  EXPECT_EQ(c.models[2].rank, 0);  // the failed fit: listed last, not ranked
  EXPECT_EQ(c.best()->name, "b");
  EXPECT_NE(c.table().find("fit failed"), std::string::npos);
}

// k counts the directions the data determine: a parameter without effect costs nothing, and
// two parameters of which only the product is determined (both named unidentifiable) count
// once, not zero times (which ranked such a law without any penalty).
TEST(Comparison, KIsTheNumberOfDeterminedDirections) {
  CalibrationResult r = fit(10.0, 2, 20);
  r.parameters[1].identifiable = false;
  r.determined = 1;
  EXPECT_EQ(compare({"x"}, {r}).models[0].k, 1);
  EXPECT_DOUBLE_EQ(compare({"x"}, {r}).models[0].aic, 12.0);
  r.parameters[0].identifiable = false;  // only their combination is determined
  EXPECT_EQ(compare({"x"}, {r}).models[0].k, 1);
}

TEST(Comparison, DifferentDataAreRefused) {
  EXPECT_THROW(compare({"a", "b"}, {fit(1, 1, 10), fit(1, 1, 11)}), std::invalid_argument);
}

}  // namespace
}  // namespace ivv::validation
