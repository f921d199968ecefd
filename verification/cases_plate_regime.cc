// Which model a plate impact needs (solver/plate/plate_regime.h), judged on the study of
// verification/study_plate_regime.h: the choice on the two shipped plate scenes whose physics
// is known, and the characterisation map (mass ratio against relative stiffness), every
// cheaper model measured against the full plate, Olsson's mass criterion drawn beside it.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "verification/cases.h"
#include "verification/study_plate_regime.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

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
  const PlateRegime& g = plate_scene_regimes().small_ball;
  return named(
      at_most(g.outcome(PlateModel::infinite_plate).error, kPlateModelTolerance, models_detail(g)),
      g, g.regime == "infinite-plate");
}

Outcome coupon_is_not_infinite_plate() {
  const PlateRegime& g = plate_scene_regimes().coupon;
  return named(
      at_least(g.outcome(PlateModel::infinite_plate).error, kPlateModelTolerance, models_detail(g)),
      g, g.regime != "infinite-plate" && g.regime != "half-space");
}

// The two-spring model leaves out the plate's inertia, an effect of order
// (omega_contact/omega_11)^2 ~ 1/mass ratio (plate.quasi-static.approach measures order 1 in
// 1/m): ~1e-2 at the coupon's mass ratio 93.
constexpr double kQuasiStaticOnCoupon = 1e-2;

Outcome coupon_quasi_static() {
  const PlateRegime& g = plate_scene_regimes().coupon;
  return at_most(g.outcome(PlateModel::quasi_static).error, kQuasiStaticOnCoupon, models_detail(g));
}

double error_of(const RegimePoint& p, PlateModel m) {
  return p.regime.outcome(m).error;
}

// Olsson's small-mass limit: below it the impact is wave-controlled, and the two-spring model's
// error follows the radiation (Zener's lambda grows with the mass: on the 4 and 8 mm plates it
// rose from 0.71 to 0.81 and from 0.426 to 0.428 between the two lightest balls), not the
// plate's inertia; the quasi-static trend is asserted from there on.
constexpr double kOlssonSmallMass = 0.23;

// The map's trends, each strict from point to point: along a row (one thickness, growing mass)
// the infinite plate's error grows, and from Olsson's small-mass limit on the quasi-static
// one's falls; along a column (one mass, growing thickness) the half-space's error falls (a
// thicker plate is nearer rigid).
Outcome map_trends() {
  const PlateRegimeMap& st = plate_regime_map();
  const std::size_t nm = st.masses.size(), nh = st.thicknesses.size();
  int violations = 0;
  std::string where;
  auto check = [&](bool ok, const RegimePoint& p, const char* what) {
    if (ok) return;
    ++violations;
    where += std::string(what) + " at m = " + fmt(p.mass, 4) +
             " kg, h = " + fmt(p.thickness * 1e3, 3) + " mm; ";
  };
  for (std::size_t i = 0; i < nh; ++i)
    for (std::size_t j = 1; j < nm; ++j) {
      const RegimePoint &a = st.points[i * nm + j - 1], &b = st.points[i * nm + j];
      check(error_of(b, PlateModel::infinite_plate) > error_of(a, PlateModel::infinite_plate), b,
            "infinite-plate error not growing with mass");
      if (a.regime.mass_ratio >= kOlssonSmallMass)
        check(error_of(b, PlateModel::quasi_static) < error_of(a, PlateModel::quasi_static), b,
              "quasi-static error not falling with mass");
    }
  for (std::size_t j = 0; j < nm; ++j)
    for (std::size_t i = 1; i < nh; ++i) {
      const RegimePoint &a = st.points[(i - 1) * nm + j], &b = st.points[i * nm + j];
      check(error_of(b, PlateModel::half_space) < error_of(a, PlateModel::half_space), b,
            "half-space error not falling with thickness");
    }
  std::map<std::string, int> count;
  for (const RegimePoint& p : st.points) ++count[p.regime.regime];
  std::string tally;
  for (const auto& [name, n] : count) tally += name + " " + std::to_string(n) + ", ";
  return at_most(violations, 0.0,
                 std::to_string(st.points.size()) + " points; regimes at 1e-3: " + tally +
                     "violations of the trends: " + std::to_string(violations) +
                     (where.empty() ? "" : " (" + where + ")"));
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
  reg.add({.id = "plate.regime.map.trends",
           .title = "the characterisation map: each cheaper model's error moves the right way",
           .tier = Tier::convergence,
           .reason = "trends, no tolerance: over 4 masses x 4 thicknesses the infinite plate's "
                     "error grows with the mass, the quasi-static one's falls with it above "
                     "Olsson's small-mass limit 0.23, the half-space's falls with the "
                     "thickness, at every step",
           .run = map_trends});
}

}  // namespace ivv::verification
