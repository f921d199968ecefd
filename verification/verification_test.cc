// The gtest front end of the registry: every case is one test, so ctest runs each as its own
// entry. Slow cases carry a SLOW_ prefix that CMake uses to label them "slow".
#include <gtest/gtest.h>

#include <string>

#include "verification/registry.h"

namespace ivv::verification {
namespace {

class VerificationCase : public ::testing::TestWithParam<const Case*> {};

TEST_P(VerificationCase, Passes) {
  const Case& c = *GetParam();
  const CaseRecord rec = run_case(c);
  const Outcome& o = rec.outcome;
  RecordProperty("measured", std::to_string(o.measured));
  EXPECT_TRUE(o.passed) << c.id << " (" << to_string(c.tier) << "): " << c.title << "\n"
                        << "  measured  " << o.measured << "\n"
                        << "  reference " << o.reference << "\n"
                        << "  tolerance " << o.tolerance << " (" << to_string(o.comparison) << ")\n"
                        << "  why       " << c.reason << "\n"
                        << "  detail    " << o.detail;
}

std::vector<const Case*> every_case() {
  return all_cases().matching("");
}

std::string test_name(const ::testing::TestParamInfo<const Case*>& info) {
  std::string n = (info.param->slow() ? "SLOW_" : "") + info.param->id;
  for (char& ch : n)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return n;
}

INSTANTIATE_TEST_SUITE_P(Registry, VerificationCase, ::testing::ValuesIn(every_case()), test_name);

}  // namespace
}  // namespace ivv::verification
