#include "scene/structure.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "scene/scene_json.h"

namespace ivv {
namespace {

// Each formula is a handful of floating-point operations: 1e-14 relative covers their
// rounding (a few ulps) with room, and fails on any wrong factor.
constexpr double kRounding = 1e-14;

// A 2 mm steel plate (E = 207 GPa, nu = 0.3, rho = 7850 kg/m^3), by hand:
// D = 207e9 * 8e-9 / (12 * 0.91) = 151.648... N m; c = 8 sqrt(7850 * 0.002 * D).
TEST(Structure, SteelPlateByHand) {
  const double D = 207e9 * 8e-9 / (12.0 * 0.91);
  EXPECT_NEAR(plate_bending_stiffness(207e9, 0.3, 0.002) / D, 1.0, kRounding);
  const double c = 8.0 * std::sqrt(7850.0 * 0.002 * D);
  EXPECT_NEAR(plate_dashpot(7850.0, 0.002, D) / c, 1.0, kRounding);
  EXPECT_NEAR(c, 390.354, 0.001);  // by hand, to the digits written above
}

// A 1 cm^2 steel bar: c = rho A c_L with c_L = sqrt(E/rho) = 5135.2 m/s.
TEST(Structure, BarIsDensityAreaWaveSpeed) {
  const double cL = std::sqrt(207e9 / 7850.0);
  EXPECT_NEAR(bar_dashpot(1e-4, 207e9, 7850.0) / (7850.0 * 1e-4 * cL), 1.0, kRounding);
}

TEST(Structure, SeriesDashpotsAddCompliances) {
  EXPECT_NEAR(series_dashpot(300.0, 600.0), 200.0, 200.0 * kRounding);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(series_dashpot(inf, 5.0), 5.0);
  EXPECT_EQ(series_dashpot(5.0, inf), 5.0);
  EXPECT_TRUE(std::isinf(series_dashpot(inf, inf)));
}

TEST(Structure, DashpotOfEachKind) {
  Structure s;
  s.density = 7850.0;
  s.thickness = 0.002;
  s.area = 1e-4;
  s.kind = Structure::Kind::plate_and_bar;
  const StructureDashpot d = structure_dashpot(s, 207e9, 0.3);
  EXPECT_NEAR(d.c_plate / plate_dashpot(7850.0, 0.002, plate_bending_stiffness(207e9, 0.3, 0.002)),
              1.0, kRounding);
  EXPECT_NEAR(d.c_bar / bar_dashpot(1e-4, 207e9, 7850.0), 1.0, kRounding);
  EXPECT_NEAR(1.0 / d.c, 1.0 / d.c_plate + 1.0 / d.c_bar, kRounding / d.c);
  EXPECT_FALSE(d.bending_stiffness_given);
  s.kind = Structure::Kind::bar;
  s.thickness = 0.0;
  EXPECT_TRUE(std::isinf(structure_dashpot(s, 207e9, 0.3).c_plate));
  // a given D* is used as it is, and the structure's own modulus overrides the target's
  s.kind = Structure::Kind::plate;
  s.thickness = 0.002;
  s.area = 0.0;
  s.bending_stiffness = 100.0;
  EXPECT_NEAR(structure_dashpot(s, 7.9e9, 0.3).c, plate_dashpot(7850.0, 0.002, 100.0),
              kRounding * 400);
  s.bending_stiffness.reset();
  s.youngs_modulus = 207e9;
  EXPECT_NEAR(structure_dashpot(s, 7.9e9, 0.3).c / d.c_plate, 1.0, kRounding);
}

// lambda and the c that gives it are inverse; the paper's c = 11440 N s/m at v0 = 1 m/s is
// lambda = 0.5^{3/5} K_h^{2/5} / 11440 = 0.23981 (K_h = 1.11496e9 N/m^1.5, Table 1).
TEST(Structure, ZenerLambdaRoundTripAndPaperValue) {
  const DerivedParameters p = derive(paper_scene());
  const double lambda = zener_lambda(0.5, p.K_h, 1.0, 11440.0);
  EXPECT_NEAR(lambda, 0.23981, 1e-5);
  EXPECT_NEAR(dashpot_for_zener_lambda(0.5, p.K_h, 1.0, lambda) / 11440.0, 1.0, kRounding);
  EXPECT_EQ(zener_lambda(0.5, p.K_h, 1.0, std::numeric_limits<double>::infinity()), 0.0);
  // z*: K_h z*^{5/2} = m v0^2
  const double z = zener_length(0.5, p.K_h, 3.0);
  EXPECT_NEAR(p.K_h * std::pow(z, 2.5) / (0.5 * 9.0), 1.0, kRounding);
}

TEST(Structure, ThicknessForDashpotInvertsThePlateFormula) {
  const double d3 = 207e9 / (12.0 * 0.91);
  const double h = plate_thickness_for_dashpot(11440.0, 7850.0, d3);
  EXPECT_NEAR(plate_dashpot(7850.0, h, d3 * h * h * h) / 11440.0, 1.0, kRounding);
}

// Isotropic plies: lamination theory must give back D = E h^3/(12(1 - nu^2)), D12 = nu D,
// D66 = (1 - nu) D/2, so A = 1 and Olsson's D* = D.
TEST(Laminate, IsotropicPliesGiveThePlateStiffness) {
  const double E = 70e9, nu = 0.3, h = 0.004;
  const Ply iso{E, E, E / (2.0 * (1.0 + nu)), nu};
  const LaminateBending b = laminate_bending_stiffness(iso, {0, 90, 0, 90, 90, 0, 90, 0}, h);
  const double D = plate_bending_stiffness(E, nu, h);
  EXPECT_NEAR(b.D11 / D, 1.0, kRounding);
  EXPECT_NEAR(b.D22 / D, 1.0, kRounding);
  EXPECT_NEAR(b.D12 / (nu * D), 1.0, kRounding);
  EXPECT_NEAR(b.D66 / ((1.0 - nu) * D / 2.0), 1.0, kRounding);
  EXPECT_NEAR(b.D_star / D, 1.0, kRounding);
}

// A unidirectional stack is one homogeneous orthotropic plate: D11 = Q11 h^3/12.
TEST(Laminate, UnidirectionalStack) {
  const Ply ply{120e9, 7.9e9, 5.5e9, 0.3};
  const double h = 0.002, den = 1.0 - 0.3 * 0.3 * 7.9 / 120.0;
  const LaminateBending b = laminate_bending_stiffness(ply, {0, 0, 0, 0}, h);
  EXPECT_NEAR(b.D11 / (120e9 / den * h * h * h / 12.0), 1.0, kRounding);
  EXPECT_NEAR(b.D22 / (7.9e9 / den * h * h * h / 12.0), 1.0, kRounding);
  EXPECT_THROW(laminate_bending_stiffness(ply, {0, 45}, h), std::invalid_argument);
  EXPECT_THROW(laminate_bending_stiffness(ply, {}, h), std::invalid_argument);
}

// The [0/90/0/90/0]s stack: outer 0 plies dominate D11. By hand with z_k = -h/2 + k h/10:
// the 0 plies (k = 0, 2, 4, 5, 7, 9) carry sum (z1^3 - z0^3)/3 = 0.0699 h^3 of h^3/12 = 0.0833.
TEST(Laminate, CrossPlyWeightsByDistanceFromTheMidplane) {
  const Ply ply{120e9, 7.9e9, 5.5e9, 0.3};
  const LaminateBending b =
      laminate_bending_stiffness(ply, {0, 90, 0, 90, 0, 0, 90, 0, 90, 0}, 1.0);
  double w0 = 0.0;
  for (int k : {0, 2, 4, 5, 7, 9}) {
    const double z0 = -0.5 + 0.1 * k, z1 = z0 + 0.1;
    w0 += (z1 * z1 * z1 - z0 * z0 * z0) / 3.0;
  }
  const double den = 1.0 - 0.3 * 0.3 * 7.9 / 120.0;
  EXPECT_NEAR(b.D11, 120e9 / den * w0 + 7.9e9 / den * (1.0 / 12.0 - w0), 1e-14 * b.D11);
  EXPECT_NEAR(b.D66, 5.5e9 / 12.0, 1e-14 * b.D66);
}

std::string field_of(const Structure& s, double E = 207e9, double nu = 0.3) {
  try {
    validate_structure(s, E, nu);
  } catch (const InputError& e) {
    return e.field();
  }
  return "";
}

TEST(Structure, BadInputNamesTheField) {
  Structure s;
  s.density = 7850.0;
  s.thickness = 0.002;
  EXPECT_EQ(field_of(s), "");
  s.thickness = -0.002;
  EXPECT_EQ(field_of(s), "structure.thickness");
  s.thickness = 0.002;
  s.density = 0.0;
  EXPECT_EQ(field_of(s), "structure.density");
  s.density = 7850.0;
  s.poisson_ratio = 0.5;
  EXPECT_EQ(field_of(s), "structure.poisson_ratio");
  s.poisson_ratio.reset();
  EXPECT_EQ(field_of(s, 207e9, 0.5), "target.poisson_ratio");
  EXPECT_EQ(field_of(s, std::numeric_limits<double>::infinity()), "structure.bending_stiffness");
  s.kind = Structure::Kind::bar;
  EXPECT_EQ(field_of(s), "structure.thickness");  // a bar has no thickness
  s.thickness = 0.0;
  s.area = -1.0;
  EXPECT_EQ(field_of(s), "structure.area");
  s.area = 1e-4;
  EXPECT_EQ(field_of(s), "");
  s.bending_stiffness = 10.0;
  EXPECT_EQ(field_of(s), "structure.bending_stiffness");
  s.bending_stiffness.reset();
  EXPECT_EQ(field_of(s, std::numeric_limits<double>::infinity()), "structure.youngs_modulus");
}

// A finite plate in a scene file: the 5 mm steel ball on a 200 x 150 x 2 mm steel plate.
std::string plate_scene(const std::string& extra) {
  return R"(
[impactor]
mass = 0.004168
radius = 0.0025
youngs_modulus = 207e9
poisson_ratio = 0.3
[target]
youngs_modulus = 207e9
poisson_ratio = 0.3
[structure]
kind = "plate"
thickness = 0.002
density = 7960
)" + extra +
         R"(
[impact]
velocity = 1.0
)";
}

constexpr const char* kFiniteKeys =
    "length_x = 0.2\nlength_y = 0.15\nedges = \"simply-supported\"\n";

TEST(FinitePlate, LengthsMakeThePlateFiniteWithItsDefaults) {
  const Scene s = parse_scene_toml(plate_scene(kFiniteKeys), "p.toml");
  const Structure& st = s.damping.structure;
  ASSERT_TRUE(st.finite_plate());
  const FinitePlate p = finite_plate(st, 207e9, 0.3);
  EXPECT_EQ(p.length_x, 0.2);
  EXPECT_EQ(p.length_y, 0.15);
  EXPECT_EQ(p.impact_x, 0.1);  // the centre by default
  EXPECT_EQ(p.impact_y, 0.075);
  const double D = plate_bending_stiffness(207e9, 0.3, 0.002);
  EXPECT_NEAR(p.bending.D11 / D, 1.0, kRounding);
  EXPECT_NEAR(p.bending.D22 / D, 1.0, kRounding);
  EXPECT_NEAR(p.bending.D12 / (0.3 * D), 1.0, kRounding);
  EXPECT_NEAR(p.bending.D66 / (0.35 * D), 1.0, kRounding);
  EXPECT_FALSE(p.orthotropic_given);
  EXPECT_NEAR(p.mass(), 7960 * 0.002 * 0.2 * 0.15, 1e-15);
  // without lengths the plate is infinite exactly as before
  const Scene inf = parse_scene_toml(plate_scene(""), "i.toml");
  EXPECT_FALSE(inf.damping.structure.finite_plate());
  EXPECT_THROW(finite_plate(inf.damping.structure, 207e9, 0.3), std::logic_error);
}

// Given D's are used as they are, and the infinite plate's D* is Olsson's of them: for an
// isotropic set (D12 = nu D, D66 = (1 - nu) D/2) A = 1 and D* = D.
TEST(FinitePlate, OrthotropicStiffnessesAndOlssonsDStar) {
  const Scene s = parse_scene_toml(
      plate_scene(std::string(kFiniteKeys) +
                  "impact_x = 0.05\nimpact_y = 0.04\nD11 = 483.9\nD22 = 282.2\nD12 = 12.7\n"
                  "D66 = 29.3\n"),
      "o.toml");
  const FinitePlate p = finite_plate(s.damping.structure, 207e9, 0.3);
  EXPECT_EQ(p.impact_x, 0.05);
  EXPECT_EQ(p.impact_y, 0.04);
  EXPECT_EQ(p.bending.D11, 483.9);
  EXPECT_EQ(p.bending.D66, 29.3);
  EXPECT_TRUE(p.orthotropic_given);
  const double A = (12.7 + 2 * 29.3) / std::sqrt(483.9 * 282.2);
  EXPECT_NEAR(structure_dashpot(s.damping.structure, 207e9, 0.3).bending_stiffness,
              std::sqrt(483.9 * 282.2 * (A + 1) / 2), 1e-12);
  EXPECT_NEAR(olsson_bending_stiffness({100, 100, 30, 35}), 100.0, 100 * kRounding);
}

// dropped_modes says what a finite plate's impact does with the modes above its cut-off: absent
// (the static compliance, as before the key), or one of its three names, kept through the
// scene's JSON form.
TEST(FinitePlate, DroppedModesKeyNamesWhatTheImpactDoesAboveTheCutoff) {
  EXPECT_FALSE(
      parse_scene_toml(plate_scene(kFiniteKeys), "p.toml").damping.structure.dropped_modes);
  for (DroppedModes d :
       {DroppedModes::static_compliance, DroppedModes::oscillator, DroppedModes::truncated}) {
    const std::string name(dropped_modes_name(d));
    const Scene s = parse_scene_toml(
        plate_scene(std::string(kFiniteKeys) + "dropped_modes = \"" + name + "\"\n"), "d.toml");
    EXPECT_EQ(s.damping.structure.dropped_modes, d) << name;
    EXPECT_EQ(dropped_modes_from_name(name), d);
    const Scene back = scene_from_json(nlohmann::json::parse(scene_json(s).dump()), "scene.");
    EXPECT_EQ(back.damping.structure.dropped_modes, d) << name;
  }
  EXPECT_FALSE(dropped_modes_from_name("static"));
  try {
    parse_scene_toml(plate_scene(std::string(kFiniteKeys) + "dropped_modes = \"modal\"\n"),
                     "bad.toml");
    FAIL() << "accepted";
  } catch (const InputError& e) {  // the message lists what is accepted
    for (const char* name : {"static-compliance", "oscillator", "truncated"})
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
  }
}

struct BadPlate {
  const char* label;
  std::string extra;
  const char* field;
};

class FinitePlateBad : public ::testing::TestWithParam<BadPlate> {};

// Each bad finite plate is one InputError naming its field (exit 2 at the command line).
TEST_P(FinitePlateBad, NamesTheField) {
  try {
    parse_scene_toml(plate_scene(GetParam().extra), "bad.toml");
    FAIL() << "accepted: " << GetParam().extra;
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), GetParam().field) << e.what();
  }
}

const std::string kEdges = "edges = \"simply-supported\"\n";

INSTANTIATE_TEST_SUITE_P(
    Structure, FinitePlateBad,
    ::testing::Values(
        BadPlate{"one_length", "length_x = 0.2\n" + kEdges, "structure.length_y"},
        BadPlate{"other_length", "length_y = 0.2\n" + kEdges, "structure.length_x"},
        BadPlate{"zero_length", "length_x = 0\nlength_y = 0.2\n" + kEdges, "structure.length_x"},
        BadPlate{"inf_length", "length_x = 0.2\nlength_y = inf\n" + kEdges, "structure.length_y"},
        BadPlate{"no_edges", "length_x = 0.2\nlength_y = 0.2\n", "structure.edges"},
        BadPlate{"clamped", "length_x = 0.2\nlength_y = 0.2\nedges = \"clamped\"\n",
                 "structure.edges"},
        BadPlate{"free_edges", "length_x = 0.2\nlength_y = 0.2\nedges = \"free\"\n",
                 "structure.edges"},
        BadPlate{"edges_without_lengths", kEdges, "structure.edges"},
        BadPlate{"dropped_modes_unknown",
                 std::string(kFiniteKeys) + "dropped_modes = \"residual\"\n",
                 "structure.dropped_modes"},
        BadPlate{"dropped_modes_not_text", std::string(kFiniteKeys) + "dropped_modes = 1\n",
                 "structure.dropped_modes"},
        BadPlate{"dropped_modes_without_lengths", "dropped_modes = \"oscillator\"\n",
                 "structure.dropped_modes"},
        BadPlate{"impact_without_lengths", "impact_x = 0.1\n", "structure.impact_x"},
        BadPlate{"impact_outside", std::string(kFiniteKeys) + "impact_x = 0.25\n",
                 "structure.impact_x"},
        BadPlate{"impact_on_edge", std::string(kFiniteKeys) + "impact_y = 0\n",
                 "structure.impact_y"},
        BadPlate{"three_ds", std::string(kFiniteKeys) + "D11 = 1\nD22 = 1\nD12 = 0.1\n",
                 "structure.D66"},
        BadPlate{"d_not_definite",
                 std::string(kFiniteKeys) + "D11 = 1\nD22 = 1\nD12 = 1.5\nD66 = 0.3\n",
                 "structure.D12"},
        BadPlate{"d66_negative",
                 std::string(kFiniteKeys) + "D11 = 1\nD22 = 1\nD12 = 0.1\nD66 = -0.3\n",
                 "structure.D66"},
        BadPlate{"ds_and_dstar",
                 std::string(kFiniteKeys) +
                     "D11 = 1\nD22 = 1\nD12 = 0.1\nD66 = 0.3\nbending_stiffness = 1\n",
                 "structure.bending_stiffness"}),
    [](const auto& info) { return std::string(info.param.label); });

// Lengths with a bar are refused by name (a bar has no plate to be finite).
TEST(FinitePlate, LengthsWithABarAreRefused) {
  std::string text = plate_scene(kFiniteKeys);
  text.replace(text.find("kind = \"plate\"\nthickness = 0.002"), 31, "kind = \"bar\"\narea = 1e-4");
  try {
    parse_scene_toml(text, "bar.toml");
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "structure.length_x") << e.what();
  }
}

}  // namespace
}  // namespace ivv
