// bench/arithmetic_limit.h: callgrind's total read from its output, a failed count that says
// why, a cost of one right-hand-side evaluation measured on the impact's states, and an impact's
// time split into its fixed part and its part per evaluation.
#include "bench/arithmetic_limit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ivv::bench {
namespace {

TEST(CallgrindTotal, IsReadFromTheCollectedLine) {
  const std::string output =
      "==12890== Callgrind, a call-graph generating cache profiler\n"
      "==12890== Events    : Ir\n"
      "==12890== Collected : 3487672\n"
      "==12890== I   refs:      3,487,672\n";
  EXPECT_EQ(parse_callgrind_total(output), 3487672.0);
}

TEST(CallgrindTotal, IsAbsentWithoutTheCollectedLine) {
  EXPECT_FALSE(parse_callgrind_total("valgrind: command not found\n"));
  EXPECT_FALSE(parse_callgrind_total("==1== Collected : \n"));
}

TEST(InstructionCount, AFailedChildIsNotMeasuredAndSaysWhy) {
  const InstructionCount count = count_instructions({.ivv = "/nonexistent/ivv",
                                                     .args = "--scene paper --v0 1 --out -",
                                                     .points = 1,
                                                     .single = {},
                                                     .simulate_only = true});
  EXPECT_TRUE(std::isnan(count.per_impact));
  EXPECT_NE(count.how.find("not measured"), std::string::npos) << count.how;
}

TEST(RhsCost, IsMeasuredOnTheImpactsStates) {
  // NaN when the paper impact gave no trajectory states to evaluate on; no bound on the time
  // (timings are the benchmark's, never pass/fail)
  const double ns = rhs_nanoseconds(0.001, 3);
  EXPECT_TRUE(std::isfinite(ns) && ns > 0.0) << ns;
}

TEST(ImpactCost, RecoversTheFixedPartAndTheCostPerEvaluationOfALine) {
  // 2.8 us + 1.6 ns an evaluation, exactly: the fit returns them to rounding
  std::vector<ImpactRun> runs;
  for (double rhs : {80.0, 99.0, 123.0, 219.0, 400.0}) runs.push_back({rhs, 2.8 + 1.6e-3 * rhs});
  const std::optional<ImpactCostModel> fit = fit_impact_cost(runs);
  ASSERT_TRUE(fit);
  constexpr double kRounding = 1e-12;  // a few operations on O(1) numbers
  EXPECT_NEAR(fit->fixed_us, 2.8, kRounding);
  EXPECT_NEAR(fit->per_rhs_ns, 1.6, 1e3 * kRounding);
  EXPECT_EQ(fit->runs, 5);
}

TEST(ImpactCost, NeedsThreeRunsAndTwoEvaluationCounts) {
  const std::vector<ImpactRun> two = {{100.0, 4.0}, {200.0, 6.0}};
  EXPECT_FALSE(fit_impact_cost(two));
  const std::vector<ImpactRun> one_count = {{100.0, 4.0}, {100.0, 4.2}, {100.0, 3.9}};
  EXPECT_FALSE(fit_impact_cost(one_count));
}

}  // namespace
}  // namespace ivv::bench
