// Which model a plate impact needs (solver/plate/plate_regime.h): the choice on the two shipped
// plate scenes whose physics is known, and the characterisation of a family of impacts from a
// light ball to a heavy striker on one plate, every cheaper model measured against the full
// plate, with Olsson's mass criterion drawn beside the measured regimes.
#include <cmath>
#include <string>
#include <vector>

#include "solver/plate/plate_regime.h"
#include "solver/plate/plate_run.h"
#include "verification/cases.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

PlateRun run_scene(const std::string& scene, const std::string& law, double rtol = 1e-10) {
  RequestOptions o;
  o.scene = scene;
  o.law = law;
  o.rtol = rtol;
  PlateRun run = run_plate_simulation(o);
  if (!run.result.ok || !run.regime)
    throw std::runtime_error(scene + ": the full plate failed: " + run.result.reason);
  return run;
}

std::string models_detail(const PlateRegime& g) {
  std::string d = "regime " + g.regime + "; ";
  for (const PlateModelOutcome& m : g.models)
    d += std::string(to_string(m.model)) + " e = " + fmt(m.e, 6) + ", F_max = " + fmt(m.F_max, 6) +
         " N" + (m.model == PlateModel::full ? "" : " (error " + fmt(m.error, 3) + ")") + "; ";
  return d;
}

// Fails, whatever the number, when the regime is not the expected one.
Outcome named(Outcome o, const PlateRegime& g, bool regime_ok) {
  if (!regime_ok) {
    o.passed = false;
    o.detail = "unexpected regime " + g.regime + ": " + o.detail;
  }
  return o;
}

Outcome small_ball_is_infinite_plate() {
  const PlateRegime g = *run_scene("steel-ball-on-finite-steel-plate", "hertz").regime;
  return named(
      at_most(g.outcome(PlateModel::infinite_plate).error, kPlateModelTolerance, models_detail(g)),
      g, g.regime == "infinite-plate");
}

Outcome coupon_is_not_infinite_plate() {
  const PlateRegime g = *run_scene("drop-weight-coupon", "elastoplastic").regime;
  return named(
      at_least(g.outcome(PlateModel::infinite_plate).error, kPlateModelTolerance, models_detail(g)),
      g, g.regime != "infinite-plate" && g.regime != "half-space");
}

// kQuasiStaticOnCoupon: the two-spring model leaves out the plate's inertia, an effect of order
// (omega_contact/omega_11)^2 ~ 1/mass ratio (plate.quasi-static.approach measures order 1 in
// 1/m): ~1e-2 at the coupon's mass ratio 93.
constexpr double kQuasiStaticOnCoupon = 1e-2;

Outcome coupon_quasi_static() {
  const PlateRegime g = *run_scene("drop-weight-coupon", "elastoplastic").regime;
  return at_most(g.outcome(PlateModel::quasi_static).error, kQuasiStaticOnCoupon, models_detail(g));
}

// The family: the 200 x 200 x 2 mm steel plate of the shipped scene struck at 1 m/s by steel
// spheres of R = 5 mm whose mass (a density, not a size) goes from the 4.2 g ball to 42 kg.
struct FamilyPoint {
  double mass_ratio;
  double error_half_space, error_infinite, error_quasi_static;
  std::string regime;
};

std::vector<FamilyPoint> mass_family() {
  const std::vector<double> masses = {0.004168, 0.04168, 0.4168, 4.168, 41.68};
  std::vector<FamilyPoint> out;
  for (double m : masses) {
    Scene s = load_scene("steel-ball-on-finite-steel-plate");
    s.mass = m;
    const PlateImpactOptions opt;  // rtol 1e-10, cut-off 40
    const PlateImpactResult full = simulate_plate_impact(s, LawKind::hertz, {}, opt);
    if (!full.ok) throw std::runtime_error("m = " + fmt(m, 4) + " kg: " + full.reason);
    const PlateRegime g = plate_regime({s, LawKind::hertz, {}, opt}, full);
    out.push_back({g.mass_ratio, g.outcome(PlateModel::half_space).error,
                   g.outcome(PlateModel::infinite_plate).error,
                   g.outcome(PlateModel::quasi_static).error, g.regime});
  }
  return out;
}

Plot family_plot(const std::vector<FamilyPoint>& f) {
  Plot p{.id = "plate-regime-mass",
         .title = "each cheaper model against the full plate, by mass ratio",
         .x_label = "impactor / plate mass",
         .y_label = "error in e (v_0) or F_max (relative)",
         .log_x = true,
         .log_y = true,
         .series = {}};
  Series hs{"half-space", {}, {}, Series::Style::linespoints};
  Series inf{"infinite plate (dashpot)", {}, {}, Series::Style::linespoints};
  Series qs{"quasi-static (two springs)", {}, {}, Series::Style::linespoints};
  for (const FamilyPoint& q : f) {
    hs.x.push_back(q.mass_ratio), hs.y.push_back(q.error_half_space);
    inf.x.push_back(q.mass_ratio), inf.y.push_back(q.error_infinite);
    qs.x.push_back(q.mass_ratio), qs.y.push_back(q.error_quasi_static);
  }
  const double lo = 1e-7, hi = 10.0;
  p.series = {
      hs,
      inf,
      qs,
      {"tolerance 1e-3",
       {f.front().mass_ratio, f.back().mass_ratio},
       {1e-3, 1e-3},
       Series::Style::dashed},
      {"Olsson: 0.23 (wave-controlled below)", {0.23, 0.23}, {lo, hi}, Series::Style::dashed},
      {"Olsson: 2 (quasi-static above)", {2.0, 2.0}, {lo, hi}, Series::Style::dashed}};
  return p;
}

// Along the family the infinite plate's error grows and the quasi-static one's falls (each
// strictly, point to point): the light ball is named infinite-plate, and the heavy striker's
// nearest cheaper model is the quasi-static one. (It is not within 1e-3 there: on this thin
// steel plate the two-spring model's error falls like (mass ratio)^-1/2, measured 0.16, 0.062,
// 0.020 at ratios 65, 655, 6550, so the heavy end stays plate-dynamics at the default
// tolerance; the drop-weight coupon is quasi-static within 1e-2.)
Outcome family_trend() {
  const std::vector<FamilyPoint> f = mass_family();
  int violations = 0;
  std::string detail;
  for (std::size_t i = 0; i < f.size(); ++i) {
    detail += "ratio " + fmt(f[i].mass_ratio, 3) + ": " + f[i].regime + " (infinite " +
              fmt(f[i].error_infinite, 2) + ", quasi-static " + fmt(f[i].error_quasi_static, 2) +
              "); ";
    if (i > 0 && !(f[i].error_infinite > f[i - 1].error_infinite)) ++violations;
    if (i > 0 && !(f[i].error_quasi_static < f[i - 1].error_quasi_static)) ++violations;
  }
  if (f.front().regime != "infinite-plate") ++violations;
  const FamilyPoint& heavy = f.back();  // its nearest cheaper model is the quasi-static one
  if (!(heavy.error_quasi_static < std::min(heavy.error_infinite, heavy.error_half_space)))
    ++violations;
  Outcome o = at_most(violations, 0.0, detail + "violations of the trend: " + fmt(violations, 2));
  o.plots.push_back(family_plot(f));
  return o;
}

}  // namespace

void register_plate_regime_cases(Registry& reg) {
  const std::string choice_tolerance =
      "the choice's default tolerance (solver/plate/plate_regime.h kPlateModelTolerance = 1e-3 "
      "in e and relative F_max); ";
  reg.add({.id = "plate.regime.small-ball.infinite-plate",
           .title = "a 5 mm ball on a 200 mm steel plate is named infinite-plate",
           .tier = Tier::cross_implementation,
           .reason = choice_tolerance +
                     "the infinite plate's dashpot within it of the modal plate, which has none",
           .run = small_ball_is_infinite_plate});
  reg.add({.id = "plate.regime.coupon.not-infinite-plate",
           .title = "the drop-weight coupon is never named infinite-plate",
           .tier = Tier::cross_implementation,
           .reason = choice_tolerance +
                     "the infinite plate must be outside it: its dashpot captures the 5.5 kg "
                     "striker that the bending coupon throws back",
           .run = coupon_is_not_infinite_plate});
  reg.add({.id = "plate.regime.coupon.quasi-static",
           .title = "the drop-weight coupon: the two-spring model within 1e-2 of the full plate",
           .tier = Tier::cross_implementation,
           .reason = "the two-spring model leaves out the plate's inertia, of order 1/mass ratio "
                     "(plate.quasi-static.approach measures order 1 in 1/m): 1e-2 at 93",
           .run = coupon_quasi_static});
  reg.add({.id = "plate.regime.mass-family",
           .title = "from a light ball to a heavy striker: infinite plate to quasi-static",
           .tier = Tier::convergence,
           .reason = "a trend, no tolerance: along mass ratios 0.0065 ... 65 the infinite plate's "
                     "error grows and the quasi-static one's falls at every step; the light end "
                     "is named infinite-plate, the heavy end is nearest the quasi-static model",
           .run = family_trend});
}

}  // namespace ivv::verification
