#include "reports/plate_regime_section.h"

#include <map>

#include "reports/html.h"
#include "verification/study_plate_regime.h"

namespace ivv::reports {
namespace {

using verification::Plot;
using verification::RegimePoint;
using verification::Series;

const std::vector<std::string> kMapCases = {"plate.regime.map.trends", "plate.regime.coupon.*"};

Figure regime_map(const verification::PlateRegimeMap& st, const PlateRegime& c, double tolerance) {
  Plot p;
  p.id = "plate-regime-map-" + number(tolerance, 1);
  p.title = "measured regime at tolerance " + number(tolerance, 1);
  p.x_label = "impactor / plate mass";
  p.y_label = "relative stiffness (contact / plate)";
  p.log_x = p.log_y = true;
  std::map<std::string, Series> by_regime;
  double y_lo = 1e300, y_hi = 0.0;
  for (const RegimePoint& q : st.points) {
    const std::string r = q.regime.regime_at(tolerance);
    Series& s = by_regime.try_emplace(r, curve(r, Series::Style::points)).first->second;
    add(s, q.regime.mass_ratio, q.regime.relative_stiffness);
    y_lo = std::min(y_lo, q.regime.relative_stiffness);
    y_hi = std::max(y_hi, q.regime.relative_stiffness);
  }
  for (auto& [name, s] : by_regime) p.series.push_back(std::move(s));
  p.series.push_back({"coupon: " + c.regime_at(tolerance),
                      {c.mass_ratio},
                      {c.relative_stiffness},
                      Series::Style::points});
  y_lo = std::min(y_lo, c.relative_stiffness);
  p.series.push_back({"Olsson 0.23", {0.23, 0.23}, {y_lo, y_hi}, Series::Style::dashed});
  p.series.push_back({"Olsson 2", {2.0, 2.0}, {y_lo, y_hi}, Series::Style::dashed});
  p.margins = true;
  return {p,
          "The 200 mm steel plate, 1 to 8 mm thick, struck at 1 m/s by spheres of 4.2 g to "
          "4.2 kg (Hertz), and the drop-weight coupon (laminate, elastoplastic): each point is the "
          "cheapest model within " +
              number(tolerance, 1) +
              " of the full plate in e and F_max (plate-dynamics: none is). Dashed: Olsson's "
              "mass criterion (wave-controlled below 0.23, quasi-static above 2), drawn for "
              "comparison; the choice does not use it.",
          false, Source::from_cases(kMapCases)};
}

Figure row_errors(const verification::PlateRegimeMap& st) {
  Plot p;
  p.id = "plate-regime-row";
  p.title = "each cheaper model against the full plate, 2 mm plate";
  p.x_label = "impactor / plate mass";
  p.y_label = "error (e in v_0, F_{max} relative)";
  p.log_x = p.log_y = true;
  Series hs = curve("half-space", Series::Style::linespoints);
  Series inf = curve("infinite plate (dashpot)", Series::Style::linespoints);
  Series qs = curve("quasi-static (two springs)", Series::Style::linespoints);
  double x_lo = 1e300, x_hi = 0.0;
  for (const RegimePoint& q : st.points) {
    if (q.thickness != 0.002) continue;
    const PlateRegime& g = q.regime;
    add(hs, g.mass_ratio, g.outcome(PlateModel::half_space).error);
    add(inf, g.mass_ratio, g.outcome(PlateModel::infinite_plate).error);
    add(qs, g.mass_ratio, g.outcome(PlateModel::quasi_static).error);
    x_lo = std::min(x_lo, g.mass_ratio);
    x_hi = std::max(x_hi, g.mass_ratio);
  }
  p.series = {hs,
              inf,
              qs,
              {"tolerance 1e-3", {x_lo, x_hi}, {1e-3, 1e-3}, Series::Style::dashed},
              {"tolerance 1e-2", {x_lo, x_hi}, {1e-2, 1e-2}, Series::Style::dashed}};
  return {p,
          "Along the 2 mm row of the map: the infinite plate is exact for the light ball and "
          "loses as the mass grows (the waves return during the longer contact); the "
          "two-spring model gains, slowly, on this thin stiff-contact plate.",
          false, Source::from_cases(kMapCases)};
}

std::string models_table(const verification::PlateSceneRegimes& st) {
  std::vector<std::vector<std::string>> rows;
  auto add_scene = [&](const std::string& name, const PlateRegime& g) {
    for (const PlateModelOutcome& m : g.models)
      rows.push_back({escape(name), escape(std::string(to_string(m.model))), number(m.e, 6),
                      number(m.F_max, 5), number(m.t_contact, 4),
                      m.model == PlateModel::full ? "reference" : number(m.error, 2),
                      m.model == PlateModel::full ? "<b>" + escape(g.regime) + "</b>" : ""});
  };
  add_scene("drop-weight coupon (5.5 kg, 2 m/s, 125 x 75 x 4 mm laminate)", st.coupon);
  add_scene("5 mm steel ball on a 200 x 200 x 2 mm steel plate, 1 m/s", st.small_ball);
  return table({"scene", "model", "e", "F_max [N]", "t_contact [s]", "error vs full", "regime"},
               rows, Source::from_cases({"plate.regime.coupon.*", "plate.regime.small-ball.*"}));
}

}  // namespace

PlateRegimeSection plate_regime_section(const SectionOptions&) {
  const verification::PlateSceneRegimes& scenes = verification::plate_scene_regimes();
  const verification::PlateRegimeMap& map = verification::plate_regime_map();
  PlateRegimeSection s;
  s.intro_html =
      "<p>Every result above is the infinite plate: the paper's dashpot stands for waves that "
      "never come back. A plate of finite size (<code>length_x</code>, <code>length_y</code> in "
      "<code>[structure]</code>) is integrated with its modes, and ivv runs the three cheaper "
      "models beside it &mdash; the half-space, the infinite plate and the quasi-static "
      "two-spring model &mdash; and names the regime after the cheapest one within the "
      "tolerance (<code>solver/plate/plate_regime.h</code>). The drop-weight coupon, the "
      "paper's own domain, is not an infinite plate: its dashpot captures the striker "
      "that the bending coupon throws back. The force histories of three plate impacts "
      "(repeated contacts, reloading past z<sub>m</sub>, the coupon's vibration), by the modal "
      "ODE and by the convolution oracle, are drawn with the cases "
      "<code>plate.cross.convolution.*.contacts</code> in the table of every case.</p>\n";
  s.figures = {regime_map(map, scenes.coupon, 1e-3), regime_map(map, scenes.coupon, 1e-2),
               row_errors(map)};
  s.models_table_html = models_table(scenes);
  return s;
}

}  // namespace ivv::reports
