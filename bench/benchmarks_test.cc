// validate_benchmark_arguments (benchmarks.h): --benchmark_* values Google Benchmark would
// misuse (nan, -5 repetitions, /dev/full) are bad input, named.
#include "bench/benchmarks.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "scene/input_error.h"

namespace ivv::bench {
namespace {

// The InputError's field for one argument, or "" when accepted.
std::string rejected(const std::string& arg) {
  std::string program = "ivv", copy = arg;
  std::vector<char*> argv = {program.data(), copy.data()};
  try {
    validate_benchmark_arguments(static_cast<int>(argv.size()), argv.data());
  } catch (const InputError& e) {
    return e.field();
  }
  return "";
}

TEST(BenchArguments, MisusedValuesAreBadInputNamingTheFlag) {
  EXPECT_EQ(rejected("--benchmark_min_time=nan"), "--benchmark_min_time");
  EXPECT_EQ(rejected("--benchmark_min_time=-1s"), "--benchmark_min_time");
  EXPECT_EQ(rejected("--benchmark_repetitions=-5"), "--benchmark_repetitions");
  EXPECT_EQ(rejected("--benchmark_repetitions=two"), "--benchmark_repetitions");
  EXPECT_EQ(rejected("--benchmark_out=/dev/full"), "--benchmark_out");
  EXPECT_EQ(rejected("--benchmark_out=/nonexistent/x.json"), "--benchmark_out");
}

TEST(BenchArguments, ValidFlagsPass) {
  EXPECT_EQ(rejected("--benchmark_min_time=0.5s"), "");
  EXPECT_EQ(rejected("--benchmark_min_time=100x"), "");
  EXPECT_EQ(rejected("--benchmark_repetitions=5"), "");
  EXPECT_EQ(rejected("--benchmark_filter=paper"), "");
}

}  // namespace
}  // namespace ivv::bench
