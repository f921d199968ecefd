// run_conformance: the grid completed, the impacts run, then the static checks (which scan
// beyond the largest z_m the impacts reached) and the dynamic checks, in the order of
// conformance.h.
#include "verification/conformance.h"

#include <algorithm>
#include <cmath>

#include "scene/input_error.h"
#include "verification/conformance_internal.h"

namespace ivv::conformance {

namespace detail {

Scales hertz_scales(const Scene& s, double v) {
  const DerivedParameters p = derive(s);
  Scales k;
  k.v = v;
  k.z = std::pow(5.0 * p.effective_mass * v * v / (4.0 * p.K_h), 0.4);
  k.F = p.K_h * k.z * std::sqrt(k.z);
  k.k = k.F / k.z;
  return k;
}

void load_to(LawProbe& probe, double z) {
  probe.reset();
  while (auto end = probe.segment_end()) {
    if (*end >= z) break;
    probe.next_segment();
  }
}

}  // namespace detail

namespace {

// Force-deformation loops of the trajectory at the scene's v0, one per damping of the grid.
std::vector<ForceLoop> force_loops(const LawUnderTest& law, const Grid& grid,
                                   const std::vector<detail::Run>& runs) {
  std::vector<ForceLoop> loops;
  if (!law.trajectory) return loops;
  std::vector<Damping> seen;
  const double v0 = grid.scene.velocity;
  for (const detail::Run& r : runs) {
    if (std::any_of(seen.begin(), seen.end(), [&](const Damping& d) {
          return d.kind == r.damping.kind && d.value == r.damping.value;
        }))
      continue;
    seen.push_back(r.damping);
    ForceLoop loop{v0, detail::damping_label(r.damping), {}, {}};
    for (const TrajectoryPoint& p :
         law.trajectory(detail::at(grid.scene, v0, r.damping), grid.options))
      loop.z.push_back(p.z), loop.F.push_back(p.force);
    if (!loop.z.empty()) loops.push_back(std::move(loop));
  }
  return loops;
}

}  // namespace

Grid default_grid(const Scene& scene) {
  Grid g;
  g.scene = scene;
  if (!scene.yield_strength || has_finite_plate(scene)) g.zetas = {0.0};  // zeta undefined
  if (has_finite_plate(scene)) return g;  // the plate's modes are its damping: no dashpot
  switch (scene.damping.kind) {
    case Damping::Kind::none:
      break;
    case Damping::Kind::ratio:
      if (std::find(g.zetas.begin(), g.zetas.end(), scene.damping.value) == g.zetas.end())
        g.zetas.push_back(scene.damping.value);
      break;
    case Damping::Kind::coefficient:
      g.dashpots.push_back(scene.damping.value);
      break;
    case Damping::Kind::zener_lambda:  // the c of that lambda at the scene's v0
    case Damping::Kind::structure:     // the structure's c, the same at every v0
      g.dashpots.push_back(derive(scene).c);
      break;
  }
  return g;
}

namespace {
// A claimed COR is a number in [0, 1] at every velocity of the grid; anything else (0/0,
// sqrt(-1), 1.5) is bad input, not a claim a check could pass (0/0 once passed "at no
// separated run").
void require_cor_claim_in_range(const Claims& claims, const std::vector<double>& velocities) {
  if (!claims.expected_cor) return;
  for (double v0 : velocities) {
    const double e = claims.expected_cor(v0);
    if (std::isfinite(e) && e >= 0.0 && e <= 1.0) continue;
    throw InputError("--expect-cor", "'" + claims.expected_cor_text + "' evaluates to " +
                                         detail::fmt(e) + " at v0 = " + detail::fmt(v0) +
                                         " m/s; a COR is a finite number in [0, 1]");
  }
}
// On a finite plate: the plate's runs, then the static checks (on the law, the scene without the
// plate) and the plate's dynamic checks (conformance_plate.cc).
ConformanceResult plate_conformance(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                                    ConformanceResult& result) {
  const detail::PlateGrid runs = detail::run_plate_grid(law, grid);
  const double v_hi = grid.velocities.back();
  double z_scan = 2.0 * detail::hertz_scales(grid.scene, v_hi).z;
  for (const detail::PlatePoint& p : runs.points)
    if (p.reference.ok && std::isfinite(p.reference.z_max))
      z_scan = std::max(z_scan, 1.25 * p.reference.z_max);
  const Scene rigid = detail::at(grid.scene, v_hi, Damping::none());
  detail::static_checks(law, rigid, v_hi, z_scan, result);
  detail::reloading_checks(law, rigid, v_hi, result);
  detail::plate_dynamic_checks(law, claims, grid, runs, result);
  return result;
}

}  // namespace

ConformanceResult run_conformance(const LawUnderTest& law, const Claims& claims,
                                  const Grid& given) {
  Grid grid = given;
  if (grid.velocities.empty()) {
    const double v = grid.scene.velocity;
    for (int i = 0; i < 7; ++i) grid.velocities.push_back(v * std::pow(10.0, -2.0 + 0.5 * i));
  }
  std::sort(grid.velocities.begin(), grid.velocities.end());
  if (grid.zetas.empty() && grid.dashpots.empty()) grid.zetas = {0.0};
  std::sort(grid.zetas.begin(), grid.zetas.end());
  std::sort(grid.dashpots.begin(), grid.dashpots.end(), std::greater<>());
  require_cor_claim_in_range(claims, grid.velocities);  // bad input before any run
  if (claims.cor_nondecreasing_in_v0 && claims.cor_nonincreasing_in_v0)
    throw InputError("--cor-increasing-in-v0",
                     "e cannot be claimed both rising and falling with v0: the rising claim "
                     "replaces the default falling one");
  if (claims.captured_below &&
      !(*claims.captured_below > 0 && std::isfinite(*claims.captured_below)))
    throw InputError("--captured-below", "a speed > 0 m/s, finite");
  ConformanceResult result;
  result.law = law.name;
  result.description = law.description;
  if (has_finite_plate(grid.scene)) {
    if (!grid.dashpots.empty() || grid.zetas != std::vector<double>{0.0})
      throw InputError(grid.dashpots.empty() ? "--zeta" : "--c",
                       "not used with a finite plate (its modes carry the energy away; without "
                       "length_x/length_y the plate is infinite and has the dashpot)");
    return plate_conformance(law, claims, grid, result);
  }
  const std::vector<detail::Run> runs = detail::run_grid(law, grid);
  // the scan goes beyond the largest z_m of the grid (and at least to 2 z_ref)
  const double v_hi = grid.velocities.back();
  double z_scan = 2.0 * detail::hertz_scales(grid.scene, v_hi).z;
  for (const detail::Run& r : runs)
    if (r.reference.ok() && std::isfinite(r.reference.z_max))
      z_scan = std::max(z_scan, 1.25 * r.reference.z_max);
  detail::static_checks(law, detail::at(grid.scene, v_hi, Damping::none()), v_hi, z_scan, result);
  detail::reloading_checks(law, detail::at(grid.scene, v_hi, Damping::none()), v_hi, result);
  detail::dynamic_checks(law, claims, grid, runs, result);
  result.skipped.push_back(
      {"dynamic.impulse",
       "checked on a finite plate (int F dt from the sampled force); here the impulse enters "
       "Poisson's COR, which dynamic.cor_definitions holds to Newton's"});
  result.loops = force_loops(law, grid, runs);
  return result;
}

}  // namespace ivv::conformance
