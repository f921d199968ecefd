#include "solver/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "solver/input_error.h"

namespace ivv {
namespace {

// Hand arithmetic for Table 1: 1/E* = 0.91/207e9 + 0.91/7.9e9.
TEST(DerivedParameters, PaperSceneMatchesHandArithmetic) {
  const Scene s = paper_scene();
  const DerivedParameters p = derive(s);
  const double E_star = 1.0 / (0.91 / 207e9 + 0.91 / 7.9e9);
  EXPECT_NEAR(p.E_star / E_star, 1.0, 1e-15);
  EXPECT_NEAR(p.K_h / (4.0 / 3.0 * 0.1 * E_star), 1.0, 1e-15);
  const double z_y =
      0.68 * 202e6 * 202e6 * std::numbers::pi * std::numbers::pi * 0.01 / (E_star * E_star);
  EXPECT_NEAR(p.z_y / z_y, 1.0, 1e-14);
  EXPECT_NEAR(p.K_y / (1.5 * p.K_h * std::sqrt(z_y)), 1.0, 1e-14);
  EXPECT_FALSE(p.has_dashpot());
  EXPECT_EQ(p.zeta, 0.0);
}

// The paper states that c = 11440 N s/m gives zeta = 0.1 (to the 3 digits it quotes).
TEST(DerivedParameters, PaperDashpotGivesZetaPointOne) {
  Scene s = paper_scene();
  s.damping = Damping::coefficient(11440.0);
  const DerivedParameters p = derive(s);
  EXPECT_NEAR(p.zeta, 0.1, 0.0005);
  // and zeta <-> c round trip exactly
  s.damping = Damping::ratio(p.zeta);
  EXPECT_NEAR(derive(s).c / 11440.0, 1.0, 1e-14);
}

// v_y is defined by Hertz energy at z_y equal to the kinetic energy: (2/5) K_h z_y^{5/2} = m v^2/2.
TEST(DerivedParameters, YieldVelocityBalancesHertzEnergyAtYield) {
  const Scene s = paper_scene();
  const DerivedParameters p = derive(s);
  const double hertz_energy = 0.4 * p.K_h * std::pow(p.z_y, 2.5);
  EXPECT_NEAR(0.5 * s.mass * p.v_yield * p.v_yield / hertz_energy, 1.0, 1e-14);
  // paper: 0.1 m/s is elastic, 1 m/s plastic
  EXPECT_GT(p.v_yield, 0.1);
  EXPECT_LT(p.v_yield, 1.0);
}

TEST(Scales, NormalisedForceOfLinearSpringIsDisplacement) {
  // With K_y z = F and z = z_bar * L, F_bar = K_y L / (m v0 omega0) = 1 * z_bar.
  const Scene s = paper_scene();
  const DerivedParameters p = derive(s);
  const Scales k = scales(s, p);
  EXPECT_NEAR(p.K_y * k.length / k.force, 1.0, 1e-14);
}

constexpr const char* kGoodScene = R"(
name = "steel-on-laminate"
[impactor]
mass = 0.5
radius = 0.010
youngs_modulus = 207e9
poisson_ratio = 0.3
[target]
youngs_modulus = 7.9e9
poisson_ratio = 0.3
shear_strength = 101e6
[damping]
zeta = 0.1
[impact]
velocity = 1
)";

TEST(SceneParser, ReadsGoodFile) {
  const Scene s = parse_scene_toml(kGoodScene, "good.toml");
  EXPECT_EQ(s.name, "steel-on-laminate");
  EXPECT_EQ(s.yield_strength, 202e6);  // S_y = 2 S_u
  EXPECT_EQ(s.damping.kind, Damping::Kind::ratio);
  EXPECT_EQ(s.velocity, 1.0);  // integer in TOML accepted as a number
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

// Each bad file must name the field at fault.
struct BadScene {
  const char* label;
  std::string text;
  std::string field;
};

class SceneParserBad : public ::testing::TestWithParam<BadScene> {};

TEST_P(SceneParserBad, NamesTheField) {
  const BadScene& bad = GetParam();
  try {
    parse_scene_toml(bad.text, "bad.toml");
    FAIL() << "accepted a bad scene: " << bad.label;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), bad.field) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SceneParserBad,
    ::testing::Values(
        BadScene{"negative_mass", replace(kGoodScene, "mass = 0.5", "mass = -0.5"),
                 "impactor.mass"},
        BadScene{"nan_radius", replace(kGoodScene, "radius = 0.010", "radius = nan"),
                 "impactor.radius"},
        BadScene{
            "poisson_half",
            replace(kGoodScene, "poisson_ratio = 0.3\n[target]", "poisson_ratio = 0.5\n[target]"),
            "impactor.poisson_ratio"},
        BadScene{"missing_velocity", replace(kGoodScene, "velocity = 1", ""), "impact.velocity"},
        BadScene{"unknown_key", replace(kGoodScene, "mass = 0.5", "mas = 0.5"), "impactor.mas"},
        BadScene{"both_strengths",
                 replace(kGoodScene, "shear_strength = 101e6",
                         "shear_strength = 101e6\nyield_strength = 2e8"),
                 "target.shear_strength"},
        BadScene{"string_mass", replace(kGoodScene, "mass = 0.5", "mass = \"heavy\""),
                 "impactor.mass"},
        BadScene{"zero_zeta", replace(kGoodScene, "zeta = 0.1", "zeta = 0"), "damping.zeta"},
        BadScene{"syntax", replace(kGoodScene, "[impact]", "[impact"), "bad.toml"},
        // issue 10: finite inputs whose derived parameters or scales are not representable
        // ended in a TOMS 748 message or inf/nan on stdout; the field at fault is named
        BadScene{"mass_1e308", replace(kGoodScene, "mass = 0.5", "mass = 1e308"), "impactor.mass"},
        BadScene{"modulus_1e_320",
                 replace(kGoodScene, "youngs_modulus = 207e9", "youngs_modulus = 1e-320"),
                 "impactor.youngs_modulus"},
        BadScene{"radius_1e308", replace(kGoodScene, "radius = 0.010", "radius = 1e308"),
                 "impactor.radius"},
        BadScene{"radius_1e_320", replace(kGoodScene, "radius = 0.010", "radius = 1e-320"),
                 "impactor.radius"},
        BadScene{"velocity_1e200", replace(kGoodScene, "velocity = 1", "velocity = 1e200"),
                 "impact.velocity"}),
    [](const auto& info) { return std::string(info.param.label); });

TEST(SceneParser, MissingFileIsInputError) {
  EXPECT_THROW(load_scene("/nonexistent/scene.toml"), InputError);
}

// Issue 10: a directory said "missing section"; /dev/zero was read without bound.
TEST(SceneParser, DirectoryAndEndlessFilesAreRefusedByName) {
  try {
    load_scene("/tmp");
    FAIL() << "a directory was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
  try {
    load_scene("/dev/zero");
    FAIL() << "/dev/zero was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("larger than"), std::string::npos) << e.what();
  }
}

TEST(SceneParser, PaperIsBuiltIn) {
  EXPECT_EQ(load_scene("paper").name, "paper");
}

}  // namespace
}  // namespace ivv
