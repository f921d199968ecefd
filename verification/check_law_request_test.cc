// The one translation of check-law's flags (and ivv.check_law's keywords) into a grid, claims and
// the JSON both front ends print: bad input names the flag, the law is echoed as given.
#include "verification/check_law_request.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "scene/scene.h"

namespace ivv::conformance {
namespace {

SimulationRequest expression_request(std::string force) {
  RequestOptions o;
  o.expression.force = std::move(force);
  return to_check_law_request(paper_scene(), o);
}

std::string field_of(auto&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.field();
  }
  return "(no error)";
}

TEST(CheckLawRequest, AValueOutOfRangeNamesItsFlag) {
  const SimulationRequest req = expression_request("K_h*z^1.5");
  EXPECT_EQ(field_of([&] { check_law_grid(req, {.velocities = std::vector{1.0, 0.0}}); }), "--v0");
  EXPECT_EQ(field_of([&] { check_law_grid(req, {.zetas = std::vector{-0.1}}); }), "--zeta");
  EXPECT_EQ(field_of([&] { check_law_grid(req, {.dashpots = std::vector{1e300 * 1e300}}); }),
            "--c");
  EXPECT_EQ(field_of([&] { check_law_claims(req, {.captured_below = 0.0}, {}); }),
            "--captured-below");
  EXPECT_EQ(field_of([&] { check_law_claims(req, {.cor_tolerance = 1.0}, {}); }),
            "--cor-tolerance");
  RequestOptions builtin;  // the registry's elastoplastic law declares its own onset force
  EXPECT_EQ(field_of([&] { declare_onset_force(builtin, std::string("0")); }), "--onset-force");
  RequestOptions blank;
  blank.expression.force = "K_h*z^1.5";
  EXPECT_EQ(field_of([&] { declare_onset_force(blank, std::string(" \t")); }), "--onset-force");
}

TEST(CheckLawRequest, TheGridKeepsTheDefaultsThatAreNotGiven) {
  const SimulationRequest req = expression_request("K_h*z^1.5");
  const Grid g = check_law_grid(req, {.velocities = std::vector{0.5, 2.0}});
  EXPECT_EQ(g.velocities, (std::vector<double>{0.5, 2.0}));
  EXPECT_EQ(g.zetas, default_grid(req.scene).zetas);
  EXPECT_TRUE(g.dashpots.empty());
}

TEST(CheckLawRequest, IncreasingInV0ReplacesTheFallingClaim) {
  const SimulationRequest req = expression_request("K_h*z^1.5");
  const Claims c = check_law_claims(req, {.monotone = true, .cor_increasing_in_v0 = true}, {});
  EXPECT_FALSE(c.cor_nonincreasing_in_v0);
  EXPECT_TRUE(c.cor_nondecreasing_in_v0);
  EXPECT_TRUE(c.cor_nonincreasing_in_damping);
  const Claims none = check_law_claims(req, {.monotone = false}, {});
  EXPECT_FALSE(none.cor_nonincreasing_in_v0 || none.cor_nonincreasing_in_damping);
}

TEST(CheckLawRequest, TheJsonCarriesTheLawAsGiven) {
  RequestOptions o;
  o.expression.force = "K_h*z^1.5 - Fad";
  o.parameters = {{"Fad", 1e-5}};
  declare_onset_force(o, std::string("-Fad"));
  const SimulationRequest req = to_check_law_request(paper_scene(), o);
  const Claims claims = check_law_claims(req, {.expect_cor = "1"}, {});
  ConformanceResult result;
  const nlohmann::json j = check_law_json(result, req, claims);
  EXPECT_EQ(j["law"]["force"], "K_h*z^1.5 - Fad");
  EXPECT_EQ(j["law"]["onset_force"], "-Fad");
  EXPECT_EQ(j["law"]["expect_cor"], "1");
  EXPECT_EQ(j["law"]["parameters"]["Fad"], 1e-5);
  EXPECT_EQ(j["law"]["scene"], req.scene.name);
  EXPECT_NEAR(claims.expected_cor(1.0), 1.0, 0.0);
}

}  // namespace
}  // namespace ivv::conformance
