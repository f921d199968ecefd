// Study<T> (verification/study.h): computed once however many threads ask, and a failure is a
// named StudyError for every reader (and a failed case, not a crash, through run_case).
#include "verification/study.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "oracles/undamped_elastoplastic.h"
#include "verification/registry.h"
#include "verification/study_restitution.h"

namespace ivv::verification {
namespace {

TEST(Study, ComputesOnceForConcurrentReaders) {
  std::atomic<int> computations = 0;
  const Study<std::vector<int>> study("counting", [&] {
    ++computations;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));  // readers arrive meanwhile
    return std::vector<int>{1, 2, 3};
  });
  std::vector<std::thread> readers;
  std::vector<const std::vector<int>*> seen(8);
  for (std::size_t i = 0; i < seen.size(); ++i)
    readers.emplace_back([&, i] { seen[i] = &study.get(); });
  for (auto& t : readers) t.join();
  EXPECT_EQ(computations.load(), 1);
  for (const auto* p : seen) {
    EXPECT_EQ(p, seen.front()) << "every reader shares the one result";
    EXPECT_EQ(p->size(), 3u);
  }
}

TEST(Study, FailureIsNamedForEveryReaderAndNotRecomputed) {
  int computations = 0;
  const Study<int> study("always failing", [&]() -> int {
    ++computations;
    throw std::runtime_error("run at v0 = 3 m/s did not separate");
  });
  for (int i = 0; i < 2; ++i) {
    try {
      study.get();
      ADD_FAILURE() << "expected StudyError";
    } catch (const StudyError& e) {
      EXPECT_EQ(e.study(), "always failing");
      EXPECT_NE(std::string(e.what()).find("study 'always failing' failed"), std::string::npos);
      EXPECT_NE(std::string(e.what()).find("did not separate"), std::string::npos);
    }
  }
  EXPECT_EQ(computations, 1);
}

TEST(Study, AFailedStudyIsAFailedCaseWithItsReason) {
  static const Study<double> failing(
      "broken study", []() -> double { throw std::runtime_error("the reference failed"); });
  const Case c{
      "unit.reads-broken-study", "reads a failed study", Tier::analytic, "none", Cost::quick, [] {
        return relative(failing.get(), 1.0, 1e-9, "value");
      }};
  const CaseRecord r = run_case(c);
  EXPECT_FALSE(r.outcome.passed);
  EXPECT_NE(r.outcome.detail.find("study 'broken study' failed: the reference failed"),
            std::string::npos)
      << r.outcome.detail;
}

// The one slope computation: rows at the report's table ratios, slopes defined above yield
// only, and the 15 v_y slope the case trend.cor-slope-near-yield judges.
TEST(UndampedCorStudy, HasTheTableRowsAndSlopesAboveYield) {
  const UndampedCorStudy& st = undamped_cor_study();
  int tabulated = 0;
  for (const auto& row : st.rows) {
    tabulated += row.tabulated;
    if (row.ratio * (1 - st.log_step) <= 1.0)
      EXPECT_TRUE(std::isnan(row.slope_simulated)) << row.ratio;
    else
      EXPECT_LT(row.slope_simulated, 0.0) << row.ratio;
  }
  EXPECT_EQ(tabulated, 8);
  EXPECT_NEAR(st.at(15.0).slope_simulated, -0.257, 1e-3);
  EXPECT_THROW(st.at(16.0), std::out_of_range);
  EXPECT_EQ(&undamped_cor_study(), &st) << "computed once per process";
}

TEST(UndampedCorStudy, ClosedFormApproachesTheDerivedAsymptote) {
  // e -> (15/8)^{1/8} (v0/v_y)^{-1/4}; the first correction is O((v0/v_y)^{-1/2}) relative,
  // 1e-3 at 1e6 v_y (the report's table shows 1.001 at 1e4 v_y).
  Scene s = paper_scene();
  const double v_y = derive(s).v_yield;
  for (double ratio : {1e6, 1e8}) {
    s.velocity = ratio * v_y;
    const double e =
        oracles::solve_undamped_elastoplastic(oracles::elastoplastic_input(s, derive(s))).e;
    EXPECT_NEAR(e / undamped_cor_asymptote(ratio), 1.0, 1e-3) << "v0/v_y = " << ratio;
  }
  EXPECT_NEAR(undamped_cor_asymptote(1.0), std::pow(15.0 / 8.0, 0.125), 1e-15);
}

}  // namespace
}  // namespace ivv::verification
