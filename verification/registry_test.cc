// The registry itself: ids are unique and well formed, every tier is represented, builders
// judge comparisons correctly.
#include "verification/registry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace ivv::verification {
namespace {

TEST(Registry, EveryTierHasCasesAndIdsAreUnique) {
  std::set<Tier> tiers;
  std::set<std::string> ids;
  for (const Case& c : all_cases().cases()) {
    tiers.insert(c.tier);
    EXPECT_TRUE(ids.insert(c.id).second) << c.id;
    EXPECT_FALSE(c.reason.empty()) << c.id;
    EXPECT_EQ(c.id.find(' '), std::string::npos) << c.id;
  }
  EXPECT_EQ(tiers.size(), all_tiers().size());
  EXPECT_GE(all_cases().cases().size(), 60u);
}

TEST(Registry, RejectsDuplicatesAndMissingReasons) {
  Registry reg;
  reg.add({"a", "A", Tier::analytic, "because", Cost::quick, [] { return Outcome{}; }});
  EXPECT_THROW(
      reg.add({"a", "A", Tier::analytic, "because", Cost::quick, [] { return Outcome{}; }}),
      std::logic_error);
  EXPECT_THROW(reg.add({"b", "B", Tier::analytic, "", Cost::quick, [] { return Outcome{}; }}),
               std::logic_error);
}

TEST(Outcome, ComparisonsJudgeCorrectly) {
  EXPECT_TRUE(relative(1.0 + 1e-9, 1.0, 1e-8, "").passed);
  EXPECT_FALSE(relative(1.0 + 1e-7, 1.0, 1e-8, "").passed);
  EXPECT_TRUE(absolute(0.1, 0.0, 0.2, "").passed);
  EXPECT_FALSE(at_most(2.0, 1.0, "").passed);
  EXPECT_TRUE(at_least(2.0, 1.0, "").passed);
  EXPECT_FALSE(at_most(std::nan(""), 1.0, "").passed);  // NaN never passes
  EXPECT_NEAR(relative(1.0 + 1e-9, 1.0, 1e-8, "").margin(), 10.0, 1e-6);
}

TEST(Glob, MatchesShellStyle) {
  EXPECT_TRUE(glob_match("analytic.*", "analytic.hertz.rk4"));
  EXPECT_TRUE(glob_match("*rk4", "analytic.hertz.rk4"));
  EXPECT_TRUE(glob_match("a?c", "abc"));
  EXPECT_FALSE(glob_match("analytic.*", "cross.hertz"));
  EXPECT_TRUE(glob_match("*", "anything"));
}

TEST(RunCase, ExceptionBecomesFailureNamingIt) {
  const Case c{"x", "throws",    Tier::analytic,
               "r", Cost::quick, []() -> Outcome { throw std::runtime_error("boom"); }};
  const CaseRecord rec = run_case(c);
  EXPECT_FALSE(rec.outcome.passed);
  EXPECT_NE(rec.outcome.detail.find("boom"), std::string::npos);
}

}  // namespace
}  // namespace ivv::verification
