// The conformance checks as a GoogleTest suite, for a downstream project's own law:
//
//   #include "verification/conformance_gtest.h"   // in the tree and installed alike
//   ivv::conformance::testing::Subject my_law_subject() {
//     return {ivv::conformance::law_under_test<MyLaw>("my-law", "F = ...",
//                                                      [](const ivv::Scene& s) { ... }),
//             ivv::conformance::Claims{}, ivv::conformance::default_grid(ivv::paper_scene())};
//   }
//   IVV_CONFORMANCE_SUITE(MyLawConformance, my_law_subject)
//
// Each check is its own test (`MyLawConformance/Check.Run/static_onset`, ...): it passes when
// the check passes, and is reported SKIPPED with its reason when the check does not apply to
// the law or was not claimed (GTEST_SKIP). The checks run once per suite and process
// (memoised), however many tests there are: register the test program as ONE ctest test
// (add_test(NAME my_law_conformance COMMAND my_law_test), as examples/downstream/ does), not
// with gtest_discover_tests, which starts one process, and so one battery, per check.
#pragma once

#include <gtest/gtest.h>

#include <map>
#include <mutex>
#include <string>

#include "verification/conformance.h"
#include "verification/conformance_law.h"

namespace ivv::conformance::testing {

struct Subject {
  LawUnderTest law;
  Claims claims;
  Grid grid;
};

// Every check id run_conformance can produce.
inline const std::vector<std::string>& all_check_ids() {
  static const std::vector<std::string> ids = {
      "static.onset",           "static.attractive",       "static.loading_monotone",
      "static.breakpoints",     "static.continuity",       "static.unloading_switch",
      "static.unloading_below", "static.stored_energy",    "static.stiffness",
      "static.reloading",       "static.reloading_beyond", "dynamic.energy",
      "dynamic.cor_range",      "dynamic.cor_definitions", "dynamic.impulse",
      "dynamic.integrators",    "dynamic.monotone_v0",     "dynamic.monotone_damping",
      "dynamic.low_speed",      "dynamic.expected_cor",    "dynamic.increasing_v0",
      "dynamic.captured_below"};
  return ids;
}

inline const ConformanceResult& memoised_report(const std::string& suite, Subject (*make)()) {
  static std::mutex mutex;
  static std::map<std::string, ConformanceResult> reports;
  std::lock_guard lock(mutex);
  auto it = reports.find(suite);
  if (it == reports.end()) {
    const Subject s = make();
    it = reports.emplace(suite, run_conformance(s.law, s.claims, s.grid)).first;
  }
  return it->second;
}

// The assertion of one check: passed, or skipped with a reason (the test itself reports a
// skipped check as SKIPPED: see IVV_CONFORMANCE_SUITE).
inline ::testing::AssertionResult check_holds(const ConformanceResult& report,
                                              const std::string& id) {
  for (const Check& c : report.checks)
    if (c.id == id) {
      if (c.passed) return ::testing::AssertionSuccess() << c.detail;
      return ::testing::AssertionFailure()
             << id << " failed: " << c.detail << " (measured " << c.measured << ", tolerance "
             << c.tolerance << ": " << c.why << ")";
    }
  for (const auto& [skipped, why] : report.skipped)
    if (skipped == id && !why.empty()) return ::testing::AssertionSuccess() << "skipped: " << why;
  return ::testing::AssertionFailure() << id << " was neither run nor declared not applicable";
}

inline std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name)
    if (c == '.') c = '_';
  return name;
}

}  // namespace ivv::conformance::testing

// Defines the parameterised suite `SuiteName` over every check for the law of `make_subject`
// (a function returning ivv::conformance::testing::Subject).
#define IVV_CONFORMANCE_SUITE(SuiteName, make_subject)                                           \
  class SuiteName : public ::testing::TestWithParam<std::string> {};                             \
  TEST_P(SuiteName, Run) {                                                                       \
    const auto& report = ::ivv::conformance::testing::memoised_report(#SuiteName, make_subject); \
    if (const auto* skipped = report.find_skipped(GetParam());                                   \
        skipped && !report.find(GetParam()))                                                     \
      GTEST_SKIP() << skipped->why;                                                              \
    EXPECT_TRUE(::ivv::conformance::testing::check_holds(report, GetParam()));                   \
  }                                                                                              \
  INSTANTIATE_TEST_SUITE_P(Check, SuiteName,                                                     \
                           ::testing::ValuesIn(::ivv::conformance::testing::all_check_ids()),    \
                           ::ivv::conformance::testing::test_name)
