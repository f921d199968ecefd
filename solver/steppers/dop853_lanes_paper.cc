// Paper-scene lanes for dop853 in lanes (dop853_lanes_run.h), baseline code: kept out of
// dop853_lanes.cc, whose headers are read for AVX2 + FMA.
#include <algorithm>
#include <cmath>
#include <string>

#include "scene/input_error.h"
#include "scene/scene.h"
#include "solver/steppers/dop853_lanes_run.h"

namespace ivv {

LaneStart paper_lane(double v0, double zeta, const LanePlace& at) {
  if (!(zeta > 0) || !std::isfinite(zeta))  // v0 is validated with the scene
    throw InputError(
        "damping.zeta",
        "must be finite and > 0 (the lanes' system has a dashpot), got " + std::to_string(zeta));
  Scene scene = paper_scene();
  scene.velocity = v0;
  scene.damping = Damping::ratio(zeta);
  validate(scene);
  const DerivedParameters p = derive(scene);
  const Scales k = scales(scene, p, ElastoplasticLaw::scale_basis);
  LaneStart lane;
  PaperLaneSystem& sys = lane.system;
  sys.law = ElastoplasticLaw::make({}, p);
  sys.length = k.length;
  sys.velocity = k.velocity;
  sys.force_scale = k.force;
  sys.inverse_force_scale = 1.0 / k.force;
  sys.two_zeta = p.effective_mass / (k.time * p.c);  // as run_typed (simulate_impl.h)
  using Branch = LanePlace::Branch;
  if (at.branch == Branch::plastic_loading || at.branch == Branch::plastic_unloading)
    sys.law.next_segment(sys.branch);
  if (at.branch == Branch::elastic_unloading || at.branch == Branch::plastic_unloading)
    sys.law.begin_unloading(sys.branch, at.z_max_over_z_y * sys.law.z_y);
  const double z = at.z_over_z_y * sys.law.z_y / sys.length;  // normalised
  auto& x = lane.x;
  x[PaperLaneSystem::Z] = z;
  x[PaperLaneSystem::W] = at.w;
  x[PaperLaneSystem::J] = 1.0 - at.w;
  x[PaperLaneSystem::WA] = 0.5 * (1.0 - at.w * at.w);
  x[PaperLaneSystem::A] = z + sys.two_zeta * x[PaperLaneSystem::J];
  const double held = z > 0 ? sys.recoverable_energy(x) - 0.5 * at.w * at.w : 0.0;
  x[PaperLaneSystem::WV] = std::max(0.0, x[PaperLaneSystem::WA] - held);
  lane.h = at.h;
  return lane;
}

}  // namespace ivv
