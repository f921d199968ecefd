// infinite_plate_warnings: the two outcomes that leave the infinite plate's idealisation
// (infinite_plate_check.h), on a drop-weight test given without its plate's size, and none on
// a small ball on a thick plate or a scene without a plate.
#include "solver/infinite_plate_check.h"

#include <gtest/gtest.h>

#include "solver/simulate.h"

namespace ivv {
namespace {

// A drop-weight test (ASTM D7136-like: 5.5 kg striker, R = 8 mm, 2 m/s) on a 4 mm carbon/epoxy
// laminate given only as [structure] plate: the paper's laminate (E22, S_u) with D* of the
// scene paper-on-laminate-plate scaled by h^3 from 23.8 mm to 4 mm.
Scene drop_weight_on_infinite_plate() {
  Scene s = load_scene("paper-on-laminate-plate");
  s.mass = 5.5;
  s.radius = 0.008;
  s.velocity = 2.0;
  Structure& plate = s.damping.structure;
  const double scale = 0.004 / plate.thickness;
  plate.bending_stiffness = *plate.bending_stiffness * scale * scale * scale;
  plate.thickness = 0.004;
  return s;
}

TEST(InfinitePlateWarnings, DropWeightOnAThinPlateLeavesTheIdealisation) {
  SimulationRequest req;
  req.scene = drop_weight_on_infinite_plate();
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.ok()) << r.reason;
  // y_final = m v0/c when captured: 5.5 * 2 / (8 sqrt(1580 * 0.004 * D*)) ~ 34 mm = 8.5 h
  EXPECT_GT(r.y_final, 5 * 0.004);
  const std::vector<std::string> w = infinite_plate_warnings(req.scene, r);
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w[0].find("times its thickness h = 4 mm"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("structure.length_x"), std::string::npos) << w[0];
  const bool captured = r.status == ImpactStatus::captured;
  EXPECT_EQ(w.size(), captured ? 2u : 1u);
  if (captured) {
    EXPECT_NE(w[1].find("captured by an infinite plate"), std::string::npos) << w[1];
  }
}

TEST(InfinitePlateWarnings, NoneForASmallBallOnAThickPlate) {
  SimulationRequest req;
  req.scene = load_scene("steel-ball-on-steel-plate");
  req.law = LawKind::hertz;  // the scene has no yield strength (Zener's problem)
  const ImpactResult r = simulate(req);
  ASSERT_TRUE(r.ok()) << r.reason;
  EXPECT_LT(r.y_final, req.scene.damping.structure.thickness);
  EXPECT_TRUE(infinite_plate_warnings(req.scene, r).empty());
}

// The deflection rule is y_final > h, exactly; a scene without a plate dashpot, or a failed
// run, has no warnings whatever its numbers.
TEST(InfinitePlateWarnings, DeflectionThresholdIsTheThickness) {
  const Scene s = drop_weight_on_infinite_plate();
  ImpactResult r;
  r.status = ImpactStatus::separated;
  r.y_final = 0.999 * 0.004;
  EXPECT_TRUE(infinite_plate_warnings(s, r).empty());
  r.y_final = 1.001 * 0.004;
  EXPECT_EQ(infinite_plate_warnings(s, r).size(), 1u);
  r.status = ImpactStatus::failed;
  EXPECT_TRUE(infinite_plate_warnings(s, r).empty());
  r.status = ImpactStatus::captured;
  EXPECT_TRUE(infinite_plate_warnings(paper_scene(), r).empty());
}

}  // namespace
}  // namespace ivv
