// The one JSON form of a scene: every kind of scene reads back as the same impact, and the
// file's own fields are named when one is missing.
#include "scene/scene_json.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

Scene with(Damping damping) {
  Scene s = paper_scene();
  s.damping = damping;
  return s;
}

Scene plate_and_bar() {
  Structure st;
  st.kind = Structure::Kind::plate_and_bar;
  st.density = 7850;
  st.thickness = 0.02;
  st.area = 1e-3;
  st.bending_stiffness = 5e4;  // c_plate ~ 22400, c_bar ~ 12800, in series ~ 8200 N s/m
  st.youngs_modulus = 2.1e11;
  return with(Damping::from_structure(st));
}

// Written, parsed as text, read: the JSON is the same (every input and derived value), and so
// is the impact (e to the last bit: the scene is the same scene, not a near one).
void expect_round_trip(const Scene& s) {
  SCOPED_TRACE(s.name + " " + damping_kind_name(s.damping.kind));
  const nlohmann::json j = scene_json(s);
  const Scene back = scene_from_json(nlohmann::json::parse(j.dump()), "scene.");
  EXPECT_EQ(scene_json(back), j);
  SimulationRequest a, b;
  a.scene = s;
  b.scene = back;
  a.law = b.law = s.yield_strength ? LawKind::elastoplastic : LawKind::hertz;
  a.auto_integrator = b.auto_integrator = true;
  EXPECT_EQ(simulate(a).e, simulate(b).e);
}

TEST(SceneJson, EveryDashpotKindRoundTrips) {
  expect_round_trip(with(Damping::none()));
  expect_round_trip(with(Damping::ratio(0.1)));
  expect_round_trip(with(Damping::coefficient(11440)));
  expect_round_trip(with(Damping::zener(0.4)));
  expect_round_trip(plate_and_bar());
  Scene rigid_free = paper_scene();
  rigid_free.target_youngs_modulus = std::numeric_limits<double>::infinity();
  rigid_free.target_radius = 0.02;
  rigid_free.target_mass = 2.0;
  expect_round_trip(rigid_free);
}

TEST(SceneJson, EveryShippedSceneRoundTrips) {
  for (const char* name :
       {"paper-damped", "paper-on-laminate-plate", "steel-ball-on-steel-plate",
        "steel-on-aluminium", "chung-ooi-1-glass", "chung-ooi-2-aluminium", "chung-ooi-3-alumina"})
    expect_round_trip(load_scene(name));
}

// The keys of the `simulate --json` contract (docs/design.md §5) stay where they were.
TEST(SceneJson, KeepsTheSimulateContract) {
  const nlohmann::json j = scene_json(with(Damping::ratio(0.1)));
  for (const char* key : {"E_star", "K_h", "z_y", "K_y", "zeta", "c", "v_yield", "v0",
                          "zener_lambda", "dashpot_source", "structure"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["dashpot_source"], "damping.zeta");
}

TEST(SceneJson, AMissingFieldIsNamed) {
  nlohmann::json j = scene_json(with(Damping::zener(0.4)));
  j["damping"].erase("value");
  try {
    scene_from_json(j, "cal.json: scene.");
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "cal.json: scene.damping.value");
  }
  j = scene_json(plate_and_bar());
  j["structure"]["kind"] = "membrane";
  EXPECT_THROW(scene_from_json(j, ""), InputError);
}

// Calibration files written before this form gave the velocity as "velocity".
TEST(SceneJson, ReadsTheOlderVelocityKey) {
  nlohmann::json j = scene_json(paper_scene());
  j.erase("v0");
  j["velocity"] = 2.5;
  EXPECT_EQ(scene_from_json(j, "").velocity, 2.5);
}

}  // namespace
}  // namespace ivv
