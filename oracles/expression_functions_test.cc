// The published formulas as expression functions: each equals the oracle it calls, a value
// outside the domain is NaN, and a --expect-cor claim can use them by name.
#include "oracles/expression_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "oracles/published.h"

namespace ivv::oracles {
namespace {

const ExpressionFunction& function(std::string_view name) {
  for (const ExpressionFunction& f : expression_functions())
    if (f.name == name) return f;
  throw std::runtime_error("no function " + std::string(name));
}

TEST(ExpressionFunctions, EachIsTheOracleItNames) {
  EXPECT_EQ(function("hc_cor").one(0.3), closed_forms::hunt_crossley_cor(0.3));
  EXPECT_EQ(function("kk_cor").two(0.02, 1.5), kuwabara_kono_pade(kuwabara_kono_v_star(0.02, 1.5)));
  EXPECT_EQ(function("thornton_cor").two(0.1, 2.0), thornton_cor(0.05));
  EXPECT_EQ(function("linear_cor").one(0.1), closed_forms::linear_spring_dashpot_cor(0.1));
  EXPECT_EQ(function("tsuji_beta").one(0.5), tsuji_beta(0.5));
  for (const ExpressionFunction& f : expression_functions())
    EXPECT_TRUE((f.one == nullptr) != (f.two == nullptr)) << f.name;
}

TEST(ExpressionFunctions, TsujiBetaIsTheDemFormula) {
  // beta = ln e / sqrt(ln^2 e + pi^2): e = 1 gives 0; e = exp(-pi) gives -1/sqrt(2)
  EXPECT_EQ(tsuji_beta(1.0), 0.0);
  EXPECT_NEAR(tsuji_beta(std::exp(-std::numbers::pi)), -1.0 / std::sqrt(2.0), 1e-15);
  EXPECT_THROW(tsuji_beta(0.0), std::exception);
  EXPECT_THROW(tsuji_beta(1.5), std::exception);
}

TEST(ExpressionFunctions, OutsideItsDomainAFunctionIsNan) {
  EXPECT_TRUE(std::isnan(function("hc_cor").one(-1.0)));
  EXPECT_TRUE(std::isnan(function("tsuji_beta").one(2.0)));
  EXPECT_TRUE(std::isnan(function("thornton_cor").two(-1.0, 1.0)));
}

TEST(ExpressionFunctions, AClaimCallsThemByName) {
  const Scene paper = paper_scene();
  const auto claim =
      compile_cor_claim("kk_cor(beta, v0)", {{"beta", 0.02}}, paper, expression_functions());
  EXPECT_EQ(claim(1.5), kuwabara_kono_pade(kuwabara_kono_v_star(0.02, 1.5)));
  const auto hc = compile_cor_claim("hc_cor(u)", {{"u", 0.4}}, paper, expression_functions());
  EXPECT_EQ(hc(3.0), closed_forms::hunt_crossley_cor(0.4));
  // without the table the name is unknown, and the error names the column
  EXPECT_THROW(compile_cor_claim("hc_cor(u)", {{"u", 0.4}}, paper), ExpressionError);
}

}  // namespace
}  // namespace ivv::oracles
