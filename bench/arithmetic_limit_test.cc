// bench/arithmetic_limit.h: callgrind's total read from its output, a failed count that says
// why, and a cost of one right-hand-side evaluation measured on the impact's states.
#include "bench/arithmetic_limit.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace ivv::bench
