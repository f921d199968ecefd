// The choice of model for a plate impact (plate_regime.h): each cheaper model measured against
// the full plate, on the two shipped plate scenes whose regimes are known from their physics.
#include "solver/plate/plate_regime.h"
#include "solver/plate/plate_run.h"

#include <gtest/gtest.h>

#include "scene/input_error.h"
#include "scene/scene.h"

namespace ivv {
namespace {

PlateRun full_run(const std::string& scene_name, const std::string& law) {
  RequestOptions o;
  o.scene = scene_name;
  o.law = law;
  o.rtol = 1e-10;
  return run_plate_simulation(o);
}

// A 5 mm ball on a 200 mm steel plate: no flexural wave returns during the ~30 us contact, so
// the paper's dashpot is the model (the plate cases measure 1e-5 in e against it).
TEST(PlateRegime, SmallBallOnALargePlateIsTheInfinitePlate) {
  const PlateRun run = full_run("steel-ball-on-finite-steel-plate", "hertz");
  ASSERT_TRUE(run.result.ok) << run.result.reason;
  ASSERT_TRUE(run.regime.has_value());
  const PlateRegime& g = *run.regime;
  EXPECT_EQ(g.regime, "infinite-plate");
  EXPECT_EQ(g.chosen(), PlateModel::infinite_plate);
  const PlateModelOutcome& inf = g.outcome(PlateModel::infinite_plate);
  EXPECT_LE(inf.error, kPlateModelTolerance);
  // the half-space ignores the plate's radiation: e = 1 against ~0.19
  EXPECT_GT(g.outcome(PlateModel::half_space).error, 0.5);
  EXPECT_LT(g.mass_ratio, 0.23);  // Olsson's small-mass class agrees here
  EXPECT_GT(g.wave_return_time, g.contact_time);
}

// The drop-weight coupon: a 5.5 kg striker on a 125 x 75 mm laminate (95 times its mass). The
// infinite plate captures the striker (e = 0, 673 N); the plate bends and throws it back.
TEST(PlateRegime, DropWeightCouponIsNeverTheInfinitePlate) {
  const PlateRun run = full_run("drop-weight-coupon", "elastoplastic");
  ASSERT_TRUE(run.result.ok) << run.result.reason;
  ASSERT_TRUE(run.regime.has_value());
  const PlateRegime& g = *run.regime;
  EXPECT_NE(g.regime, "infinite-plate");
  EXPECT_NE(g.regime, "half-space");
  EXPECT_GT(g.outcome(PlateModel::infinite_plate).error, 0.5);
  EXPECT_GT(g.mass_ratio, 2.0);
  // the quasi-static model: the contact in series with the plate's static stiffness
  const PlateModelOutcome& qs = g.outcome(PlateModel::quasi_static);
  ASSERT_TRUE(qs.ok) << qs.reason;
  EXPECT_LT(qs.error, 0.1);
}

TEST(PlateRegime, TheCheaperScenes) {
  const Scene s = load_scene("drop-weight-coupon");
  const Scene inf = infinite_plate_scene(s);
  EXPECT_FALSE(inf.damping.structure.finite_plate());
  EXPECT_EQ(inf.damping.kind, Damping::Kind::structure);
  EXPECT_EQ(half_space_scene(s).damping.kind, Damping::Kind::none);
}

TEST(PlateRegime, ModelNames) {
  EXPECT_FALSE(parse_plate_model("auto").has_value());
  EXPECT_EQ(parse_plate_model("quasi-static"), PlateModel::quasi_static);
  EXPECT_EQ(parse_plate_model("full"), PlateModel::full);
  EXPECT_THROW(parse_plate_model("two-spring"), InputError);
}

}  // namespace
}  // namespace ivv
