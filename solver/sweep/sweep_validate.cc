// validate(SweepRequest) (solver/sweep/sweep_grid.h): every entry point's one check of a grid.
#include "solver/sweep/sweep_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "scene/input_error.h"
#include "scene/scene_values.h"
#include "solver/format.h"
#include "solver/parallel.h"
#include "solver/plate/plate_law.h"

namespace ivv {

namespace {

std::string shortest(double x) {
  std::string s;
  append_shortest(s, x);
  return s;
}

// `e` (about a scene field) as an error of the flag the grid's value was typed with: the grid's
// values were typed as --v0, --zeta or --set KEY, not as the scene's impact.velocity and
// damping.zeta (`--v0 1e308` named impact.velocity, a field the user never typed).
InputError as_flag(const InputError& e, const std::string& flag) {
  const std::string what = e.what();
  return InputError(flag, what.substr(std::min(what.size(), e.field().size() + 2)));
}

// The flag that typed the scene field `field` in this sweep: --v0, --zeta, --set KEY, or the
// field itself (a value of the scene file).
std::string flag_of(const SweepRequest& req, const std::string& field) {
  if (field == "impact.velocity") return "--v0";
  if (field == "damping.zeta") return "--zeta";
  for (const SceneAxis& a : req.axes)
    if (a.key == field) return "--set " + a.key;
  return field;
}

// A point on a finite plate: the plate's checks (solver/plate/plate_impact.h), its tolerances,
// and no integrator it would ignore (its modes run on dop853).
void validate_finite_plate_point(const SimulationRequest& r) {
  if (!r.auto_integrator)
    throw InputError("--integrator",
                     "not used with a finite plate (the plate's modes are integrated by dop853 "
                     "with event location); leave it auto");
  validate(r.options);
  validate_plate_law(r);
}

// Validates point `r` of the sweep, naming a field of the scene that the sweep sets by the flag
// that set it.
// One point, on a finite plate or with the dashpot.
void validate_request(const SimulationRequest& r) {
  if (has_finite_plate(r.scene))
    validate_finite_plate_point(r);
  else
    validate(r);
}

void validate_point(const SweepRequest& req, const SimulationRequest& r) {
  try {
    validate_request(r);
  } catch (const InputError& e) {
    const std::string flag = flag_of(req, e.field());
    if (flag != e.field()) throw as_flag(e, flag);
    throw;
  }
}

// Each axis a key of scene/scene_values.h, given once, with finite values, that the base scene
// has a place for.
void validate_axis_keys(const SweepRequest& req) {
  if (req.axes.size() > kMaxSceneAxes)
    throw InputError("--set", "at most " + std::to_string(kMaxSceneAxes) +
                                  " scene values can be swept at once, got " +
                                  std::to_string(req.axes.size()));
  std::set<std::string> seen;
  for (const SceneAxis& axis : req.axes) {
    const std::string flag = "--set " + axis.key;
    if (!seen.insert(axis.key).second) throw InputError(flag, "given twice");
    if (axis.values.empty()) throw InputError(flag, "the grid is empty");
    Scene probe = req.base.scene;
    try {
      set_scene_value(probe, axis.key, axis.values.front());
    } catch (const InputError& e) {
      throw as_flag(e, flag);
    }
    for (double v : axis.values)
      if (!std::isfinite(v))
        throw InputError(flag, "values must be finite numbers, got " + shortest(v));
  }
}

// A request at the first value of every axis but scene axis `skip` (SIZE_MAX: none).
SimulationRequest first_point(const SweepRequest& req, std::size_t skip = SIZE_MAX) {
  SimulationRequest r = req.base;
  r.scene.velocity = req.velocities.front();
  if (!req.scene_dashpot)
    r.scene.damping = req.zetas.front() > 0 ? Damping::ratio(req.zetas.front()) : Damping::none();
  for (std::size_t k = 0; k < req.axes.size(); ++k)
    if (k != skip) set_scene_value(r.scene, req.axes[k].key, req.axes[k].values.front());
  return r;
}

// Every value of every scene axis with the others at their first value.
void validate_axis_values(const SweepRequest& req) {
  for (std::size_t k = 0; k < req.axes.size(); ++k) {
    const SceneAxis& axis = req.axes[k];
    SimulationRequest r = first_point(req, k);
    for (double v : axis.values) {
      set_scene_value(r.scene, axis.key, v);
      validate_point(req, r);
    }
  }
}

struct Range {
  double lo, hi;
};
Range range_of(const std::vector<double>& v) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return Range{*lo, *hi};
}

// Every corner of the grid's box: each axis (v0, zeta, scene values) at its smallest or largest
// value (sweep_grid.h: the checks of several inputs at once are monotone in each).
void validate_corners(const SweepRequest& req) {
  const Range v0 = range_of(req.velocities);
  const Range zeta = req.scene_dashpot ? Range{0, 0} : range_of(req.zetas);
  std::vector<Range> axes;
  for (const SceneAxis& a : req.axes) axes.push_back(range_of(a.values));
  const std::size_t dimensions = 2 + axes.size();
  for (std::size_t corner = 0; corner < (std::size_t{1} << dimensions); ++corner) {
    auto pick = [&](const Range& r, std::size_t bit) { return corner >> bit & 1 ? r.hi : r.lo; };
    SimulationRequest r = req.base;
    r.scene.velocity = pick(v0, 0);
    if (!req.scene_dashpot) {
      const double z = pick(zeta, 1);
      r.scene.damping = z > 0 ? Damping::ratio(z) : Damping::none();
    }
    for (std::size_t k = 0; k < axes.size(); ++k)
      set_scene_value(r.scene, req.axes[k].key, pick(axes[k], 2 + k));
    try {
      validate_request(r);
    } catch (const InputError& e) {
      std::string where = "--v0 " + shortest(r.scene.velocity);
      if (!req.scene_dashpot) where += " --zeta " + shortest(pick(zeta, 1));
      for (std::size_t k = 0; k < axes.size(); ++k)
        where += ", " + req.axes[k].key + " = " + shortest(pick(axes[k], 2 + k));
      throw InputError(flag_of(req, e.field()),
                       "the grid's corner (" + where + ") is not a valid impact: " + e.what());
    }
  }
}

// A sweep that keeps the scene's own dashpot: no zeta grid, a dashpot to keep, each v0 valid.
void validate_scene_dashpot(const SweepRequest& req) {
  if (!req.zetas.empty())
    throw InputError("--zeta", "give either a zeta grid or keep the scene's own dashpot, not both");
  if (req.base.scene.damping.kind == Damping::Kind::none)
    throw InputError("--zeta", "missing: the scene has no dashpot of its own to keep");
  SimulationRequest r = first_point(req);
  for (double v : req.velocities) {
    if (!(std::isfinite(v) && v > 0))
      throw InputError("--v0", "velocities must be finite and > 0 m/s, got " + shortest(v));
    r.scene.velocity = v;
    validate_point(req, r);
  }
}

// The v0 x zeta grid: each value in range, each v0 with the first zeta and each zeta with the
// first v0 a valid request (a rate-dependent law with a dashpot is refused there, naming --zeta).
void validate_velocities_and_zetas(const SweepRequest& req) {
  if (req.zetas.empty()) throw InputError("--zeta", "the damping grid is empty");
  if (has_finite_plate(req.base.scene))
    throw InputError("--zeta",
                     "not used with a finite plate (its modes carry the energy away; without "
                     "length_x/length_y the plate is infinite and has the dashpot): leave --zeta "
                     "out to sweep the plate");
  for (double v : req.velocities)
    if (!(std::isfinite(v) && v > 0))
      throw InputError("--v0", "velocities must be finite and > 0 m/s, got " + shortest(v));
  for (double z : req.zetas)
    if (!(std::isfinite(z) && z >= 0))
      throw InputError(
          "--zeta", "damping ratios must be finite and >= 0 (0: no dashpot), got " + shortest(z));
  SimulationRequest r = first_point(req);
  for (double z : req.zetas)
    if (z > 0 && !r.scene.yield_strength)
      throw InputError("--zeta",
                       "a damping ratio is defined with K_y and needs target.yield_strength; "
                       "this scene has none: use --zeta 0 (no dashpot)");
  for (double v : req.velocities) {
    r.scene.velocity = v;
    validate_point(req, r);
  }
  r = first_point(req);
  for (double z : req.zetas) {
    r.scene.damping = z > 0 ? Damping::ratio(z) : Damping::none();
    validate_point(req, r);
  }
}

// The number of points, refused past kMaxSweepPoints before anything is allocated.
void validate_size(const SweepRequest& req) {
  double points = static_cast<double>(req.velocities.size());
  std::string sizes = std::to_string(req.velocities.size());
  if (!req.scene_dashpot) {
    points *= static_cast<double>(req.zetas.size());
    sizes += " x " + std::to_string(req.zetas.size());
  }
  for (const SceneAxis& a : req.axes) {
    points *= static_cast<double>(a.values.size());
    sizes += " x " + std::to_string(a.values.size());
  }
  if (points > kMaxSweepPoints)
    throw InputError("--v0", "the grid (--v0 x --zeta x each --set) has " + sizes + " = " +
                                 fmt(points, 3) +
                                 " points; at most 1e8 are accepted (split the study)");
}

}  // namespace

void validate(const SweepRequest& req) {
  validate_threads(req.threads);
  if (req.velocities.empty()) throw InputError("--v0", "the velocity grid is empty");
  validate_axis_keys(req);
  validate_size(req);
  if (req.scene_dashpot)
    validate_scene_dashpot(req);
  else
    validate_velocities_and_zetas(req);
  validate_axis_values(req);
  validate_corners(req);
}

}  // namespace ivv
