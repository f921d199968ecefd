// ivv's conformance checks as this project's GoogleTest suite: one test per check
// (RestitutionHertzConformance/Check.Run/static_onset, ...).
#include "restitution_law.h"
#include "verification/conformance_gtest.h"

namespace {

ivv::conformance::testing::Subject restitution_hertz() {
  ivv::conformance::Claims claims;
  claims.expected_cor = [](double) { return 0.7; };  // at every v0, without a dashpot
  claims.expected_cor_text = "0.7";
  return {ivv::conformance::law_under_test<downstream::RestitutionHertz>(
              "restitution-hertz", "F = K z^1.5; unloading K/e^3 (z - (1-e^2) z_m)^1.5, e = 0.7",
              [](const ivv::Scene& s) {
                return downstream::RestitutionHertz{ivv::derive(s).K_h, 0.7};
              }),
          claims, ivv::conformance::default_grid(ivv::paper_scene())};
}

}  // namespace

IVV_CONFORMANCE_SUITE(RestitutionHertzConformance, restitution_hertz);
