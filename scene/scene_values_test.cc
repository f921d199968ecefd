// The scene values by key: every key reaches its own member (set, then read back), carries a
// unit, and a key the scene has no place for is refused naming the key.
#include "scene/scene_values.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "scene/input_error.h"

namespace ivv {
namespace {

// A finite orthotropic plate: a scene in which every key of the table has a place.
Scene finite_orthotropic_plate() {
  Scene s = paper_scene();
  Structure st;
  st.kind = Structure::Kind::plate;
  st.density = 1580.0;
  st.thickness = 0.004;
  st.length_x = 0.125;
  st.length_y = 0.075;
  st.edges = PlateEdges::simply_supported;
  st.bending = OrthotropicBending{483.9, 282.2, 12.7, 29.3};
  s.damping = Damping::from_structure(st);
  return s;
}

std::string field_of_set(Scene s, const std::string& key, double value) {
  try {
    set_scene_value(s, key, value);
  } catch (const InputError& e) {
    return e.field() + ": " + e.what();
  }
  return "";
}

TEST(SceneValues, EveryKeySetsItsOwnValueAndOnlyThat) {
  std::set<std::string> keys;
  for (const SceneValueInfo& info : scene_values()) {
    EXPECT_TRUE(keys.insert(std::string(info.key)).second) << info.key << " listed twice";
    EXPECT_FALSE(info.unit.empty()) << info.key;
    EXPECT_FALSE(info.description.empty()) << info.key;
    Scene s = finite_orthotropic_plate();
    s.target_radius = 0.05;  // a free target sphere: its radius and mass have a place
    s.target_mass = 2.0;
    if (info.key == "structure.area") s.damping.structure.kind = Structure::Kind::plate_and_bar;
    const Scene before = s;
    // 0.1234 is no default and no value of the scene above: reading it back proves the member
    set_scene_value(s, info.key, 0.1234);
    const double expected = 0.1234;
    EXPECT_EQ(scene_value(s, info.key), expected) << info.key;
    // every other key reads what it read before (shear_strength and yield_strength are one
    // member, S_y = 2 S_u)
    for (const SceneValueInfo& other : scene_values()) {
      const bool same_member =
          other.key == info.key ||
          (info.key.starts_with("target.") && other.key.starts_with("target.") &&
           info.key.ends_with("_strength") && other.key.ends_with("_strength"));
      if (!same_member) {
        EXPECT_EQ(scene_value(s, other.key), scene_value(before, other.key))
            << "setting " << info.key << " changed " << other.key;
      }
    }
  }
  EXPECT_EQ(keys.size(), scene_values().size());
}

TEST(SceneValues, ShearStrengthIsHalfTheYieldStrength) {
  Scene s = paper_scene();  // S_y = 202 MPa from S_u = 101 MPa
  EXPECT_EQ(scene_value(s, "target.shear_strength"), 101e6);
  set_scene_value(s, "target.shear_strength", 50e6);
  EXPECT_EQ(s.yield_strength, 100e6);
}

TEST(SceneValues, UnknownKeyListsTheAcceptedOnes) {
  const std::string error = field_of_set(paper_scene(), "impactor.mas", 1.0);
  EXPECT_EQ(error.rfind("impactor.mas: ", 0), 0u) << error;
  EXPECT_NE(error.find("impactor.mass, impactor.radius"), std::string::npos) << error;
  // the velocity and the dashpot are the flags' (--v0, --zeta), and the message says so
  EXPECT_NE(field_of_set(paper_scene(), "impact.velocity", 1.0).find("--v0"), std::string::npos);
  EXPECT_EQ(find_scene_value("damping.zeta"), nullptr);
  EXPECT_THROW(scene_value(paper_scene(), "nonsense"), InputError);
}

TEST(SceneValues, AKeyTheSceneHasNoPlaceForIsRefusedNamingIt) {
  // the paper's scene has no [structure]
  EXPECT_NE(field_of_set(paper_scene(), "structure.thickness", 0.002).find("no [structure]"),
            std::string::npos);
  EXPECT_EQ(scene_value(paper_scene(), "structure.thickness"), std::nullopt);
  Scene plate = finite_orthotropic_plate();
  // a bar's value on a plate, and a finite plate's on an infinite one
  EXPECT_EQ(field_of_set(plate, "structure.area", 1e-4).rfind("structure.area: ", 0), 0u);
  plate.damping.structure.length_x.reset();
  plate.damping.structure.length_y.reset();
  plate.damping.structure.edges.reset();
  EXPECT_NE(field_of_set(plate, "structure.length_x", 0.2).find("infinite"), std::string::npos);
  // D11..D66 only on a plate that gives all four
  plate.damping.structure.bending.reset();
  EXPECT_NE(field_of_set(plate, "structure.D11", 400.0).find("isotropic"), std::string::npos);
  // a value out of range is not this table's business: validate() names it, as for a file
  Scene s = paper_scene();
  set_scene_value(s, "impactor.mass", -1.0);
  try {
    validate(s);
    ADD_FAILURE() << "a negative mass passed validate()";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "impactor.mass");
  }
}

TEST(SceneValues, AnOptionalValueCanBeLeftOutARequiredOneCannot) {
  Scene s = paper_scene();
  clear_scene_value(s, "target.yield_strength");
  EXPECT_EQ(s.yield_strength, std::nullopt);
  EXPECT_THROW(clear_scene_value(s, "impactor.mass"), InputError);
  Scene plate = finite_orthotropic_plate();
  plate.damping.structure.youngs_modulus = 70e9;
  clear_scene_value(plate, "structure.youngs_modulus");
  EXPECT_EQ(plate.damping.structure.youngs_modulus, std::nullopt);
  EXPECT_THROW(clear_scene_value(s, "structure.youngs_modulus"), InputError);  // no [structure]
}

}  // namespace
}  // namespace ivv
