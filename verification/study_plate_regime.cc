#include "verification/study_plate_regime.h"

#include <stdexcept>

#include "solver/plate/plate_run.h"
#include "verification/study.h"

namespace ivv::verification {
namespace {

PlateRegime scene_regime(const std::string& scene, const std::string& law) {
  RequestOptions o;
  o.scene = scene;
  o.law = law;
  o.rtol = 1e-10;
  const PlateRun run = run_plate_simulation(o);
  if (!run.result.ok || !run.regime)
    throw std::runtime_error(scene + ": the full plate failed: " + run.result.reason);
  return *run.regime;
}

RegimePoint map_point(double mass, double thickness) {
  Scene s = load_scene("steel-ball-on-finite-steel-plate");
  s.mass = mass;
  s.damping.structure.thickness = thickness;
  const PlateImpactOptions opt;  // rtol 1e-10, cut-off 40
  const PlateImpactResult full = simulate_plate_impact(s, LawKind::hertz, {}, opt);
  if (!full.ok)
    throw std::runtime_error("m = " + std::to_string(mass) +
                             " kg, h = " + std::to_string(thickness) + " m: " + full.reason);
  return {mass, thickness, plate_regime({s, LawKind::hertz, {}, opt}, full)};
}

PlateSceneRegimes compute_scene_regimes() {
  return {scene_regime("steel-ball-on-finite-steel-plate", "hertz"),
          scene_regime("drop-weight-coupon", "elastoplastic")};
}

PlateRegimeMap compute_regime_map() {
  PlateRegimeMap map;
  map.masses = {0.004168, 0.04168, 0.4168, 4.168};
  map.thicknesses = {0.001, 0.002, 0.004, 0.008};
  for (double h : map.thicknesses)
    for (double m : map.masses) map.points.push_back(map_point(m, h));
  return map;
}

}  // namespace

const PlateSceneRegimes& plate_scene_regimes() {
  static const Study<PlateSceneRegimes> study("the regimes of the shipped plate scenes",
                                              compute_scene_regimes);
  return study.get();
}

const PlateRegimeMap& plate_regime_map() {
  static const Study<PlateRegimeMap> study("the plate-impact characterisation map",
                                           compute_regime_map);
  return study.get();
}

}  // namespace ivv::verification
