#include "reports/structure_section.h"

#include "verification/study_structure.h"

namespace ivv::reports {
namespace {

using verification::Series;

Figure zener_figure(const verification::StructureStudy& st) {
  Figure f;
  f.plot.id = "structure-zener";
  f.plot.title = "Zener's sphere on a plate: e against lambda (Hertz law)";
  f.plot.x_label = "lambda = m^{3/5} K_h^{2/5} v_0^{1/5} / c [-]";
  f.plot.y_label = "coefficient of restitution e [-]";
  f.plot.log_x = true;
  f.plot.log_y = true;
  Series curve = reports::curve("simulated (odeint-dopri5, rtol 1e-12)");
  for (const auto& p : st.curve) add(curve, p.lambda, p.e);
  Series asym =
      reports::curve("1 - a lambda, a = " + number(st.slope_quadrature, 6) + " (quadrature)",
                     Series::Style::dashed);
  for (const auto& p : st.curve)
    if (1.0 - st.slope_quadrature * p.lambda > 0.05)
      add(asym, p.lambda, 1.0 - st.slope_quadrature * p.lambda);
  Series sim =
      reports::curve("similarity scenes (4 unlike scenes, lambda = 0.5)", Series::Style::points);
  for (const auto& s : st.similarity) add(sim, s.point.lambda, s.point.e);
  Series series = reports::curve("Taylor-series solution, 50 digits", Series::Style::points);
  for (const auto& z : st.series_solution) add(series, z.lambda, z.e);
  f.plot.series = {curve, asym, sim, series};
  f.caption =
      "Zener's problem: the Hertz law in series with the dashpot of an infinite plate; e depends "
      "on "
      "lambda alone. Curve: 41 simulated impacts; dashed: the first-order loss 1 &minus; a&lambda; "
      "from the undamped Hertz impact; points: four scenes with different m, R, E*, h, &rho; and "
      "v<sub>0</sub> at the same lambda, and at three lambda an independent solution of Zener's "
      "equation (a Taylor-series method in 50 digits, oracles/zener.h). Beyond lambda "
      "&asymp; 5 the plate nearly captures the sphere (e &lt; 1e-4).";
  f.full_width = true;
  f.source = Source::from_cases({"structure.zener.*"});
  return f;
}

Figure thickness_figure(const verification::StructureStudy& st) {
  Figure f;
  f.plot.id = "structure-thickness";
  f.plot.title = "Paper impactor on an infinite T300/934 plate: e against thickness";
  f.plot.x_label = "plate thickness h [mm]";
  f.plot.y_label = "coefficient of restitution e [-]";
  f.plot.log_x = true;
  Series e1 = reports::curve("v0 = 1 m/s", Series::Style::linespoints);
  Series e5 = reports::curve("v0 = 5 m/s", Series::Style::linespoints);
  for (const auto& r : st.thickness_rows) {
    add(e1, r.thickness * 1e3, r.e_1);
    add(e5, r.thickness * 1e3, r.e_5);
  }
  Series mark = reports::curve("h where the plate gives zeta = 0.1", Series::Style::dashed);
  add(mark, st.thickness_for_paper_zeta * 1e3, 0.0);
  add(mark, st.thickness_for_paper_zeta * 1e3, 1.0);
  f.plot.series = {e1, e5, mark};
  f.caption =
      "The paper's Table 1 impactor and target (elastoplastic law), the dashpot that of a "
      "[0/90/0/90/0]s T300/934 plate, c = 8 &radic;(&rho; h D*) (properties beside the plot); "
      "--integrator auto at rtol 1e-10. Thin plates take most of the energy. Near capture e is "
      "not monotone in h (the table): on the thinnest plates the force c v<sub>0</sub> stays "
      "below the yield force, the spring stays elastic and creeps back (e between 1e-9 and "
      "1e-5 at 1 m/s); on somewhat thicker ones it yields, and the permanent set with an "
      "overdamped unloading captures the sphere (e = 0). All of it on an infinite plate: a "
      "finite one may give the energy back (the note above).";
  f.source = Source::from_cases({"structure.laminate.*"});
  return f;
}

std::string similarity_table(const verification::StructureStudy& st) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : st.similarity) {
    const Scene& sc = s.scene;
    rows.push_back({escape(s.label), number(sc.mass, 4), number(sc.radius * 1e3, 3),
                    number(s.E_star / 1e9, 4), number(s.thickness * 1e3, 4),
                    number(sc.damping.structure.density, 4), number(sc.velocity, 3),
                    number(s.point.e, 9), number(s.point.contact_time, 9),
                    number(s.point.peak_force, 9)});
  }
  return table({"scene (synthetic)", "m [kg]", "R [mm]", "E* [GPa]", "h [mm]", "&rho; [kg/m³]",
                "v<sub>0</sub> [m/s]", "e", "t<sub>f</sub> v<sub>0</sub>/z*",
                "F<sub>max</sub>/(K<sub>h</sub> z*<sup>3/2</sup>)"},
               rows, Source::from_cases({"structure.zener.similarity"}));
}

std::string plate_properties(const verification::StructureStudy& st) {
  std::string s =
      "<p><b>The plate beside the plot.</b> [0/90/0/90/0]s T300/934 carbon-epoxy, ply data and "
      "density from the paper's Table 1: E<sub>11</sub> = " +
      number(st.ply.E1 / 1e9, 4) + " GPa, E<sub>22</sub> = " + number(st.ply.E2 / 1e9, 4) +
      " GPa, G<sub>12</sub> = " + number(st.ply.G12 / 1e9, 4) +
      " GPa, &nu;<sub>12</sub> = " + number(st.ply.nu12, 3) + ", &rho; = " + number(st.density, 5) +
      " kg/m³. D* = &radic;(D<sub>11</sub> D<sub>22</sub> (A + 1)/2), A = (D<sub>12</sub> + 2 "
      "D<sub>66</sub>)/&radic;(D<sub>11</sub> D<sub>22</sub>) (Olsson, Composites A 31 (2000) "
      "879), with D<sub>ij</sub> by lamination theory: D* = " +
      number(st.d_star_per_h3, 6) +
      " h³ N m. The plate alone gives the paper's &zeta; = 0.1 at h = " +
      number(st.thickness_for_paper_zeta * 1e3, 5) +
      " mm (&zeta; of that scene: " + number(st.zeta_at_that_thickness, 10) + ").</p>\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : st.thickness_rows)
    rows.push_back({number(r.thickness * 1e3, 4), number(r.D_star, 5), number(r.c, 5),
                    number(r.zeta, 4), number(r.e_1, 6), number(r.e_5, 6)});
  return s + table({"h [mm]", "D* [N m]", "c [N s/m]", "&zeta;", "e (1 m/s, infinite plate)",
                    "e (5 m/s, infinite plate)"},
                   rows, Source::from_cases({"structure.laminate.*"}));
}

}  // namespace

StructureSection structure_section(const SectionOptions& so) {
  so.say("structure study (Zener's curve, similarity, the paper's impactor on a plate)");
  const verification::StructureStudy& st = verification::structure_study();
  StructureSection out;
  out.figures = {zener_figure(st), thickness_figure(st)};
  out.intro_html =
      "<div class=\"note\" id=\"infinite-plate\"><p><b>Zener's curve, the similarity scenes "
      "and the thickness study below are the infinite-plate idealisation.</b> The plate's "
      "dashpot c = 8 &radic;(&rho; h D*) is the "
      "energy that bending waves carry away from an <i>infinite</i> plate, never to return: it "
      "holds while no wave comes back from the plate's edges during the contact. So the e = 0 "
      "of the thin plates below (capture) is the infinite plate's answer. A finite plate of "
      "the same thickness keeps that energy in its modes and may give it back: the ball may "
      "rebound, after one contact or several. A scene whose <code>[structure]</code> gives "
      "<code>length_x</code> and <code>length_y</code> (with <code>edges</code>) is such a "
      "finite plate: ivv then integrates its modes and uses no dashpot. The cases "
      "<code>plate.infinite-limit.*</code> check that a plate large enough for no wave to "
      "return reproduces the infinite plate's e, <code>plate.cross.convolution.*</code> check "
      "small plates that rebound with repeated contacts, and <a href=\"#plate-regime\">Where "
      "the infinite plate stops</a> (the end of this section) maps where a finite plate departs "
      "from the idealisation.</p></div>\n"
      "<p>The dashpot derived from the struck structure (paper, after eq. 4): a plate's "
      "c = 8 &radic;(&rho; h D), a bar's c = A &radic;(E &rho;), the two in series. For the Hertz "
      "law it is Zener's (1941) problem with one group, &lambda; = m<sup>3/5</sup> "
      "K<sub>h</sub><sup>2/5</sup> v<sub>0</sub><sup>1/5</sup>/c. Small-&lambda; slope of 1 "
      "&minus; e: "
      "simulated " +
      number(st.slope_richardson, 7) + ", quadrature " + number(st.slope_quadrature, 7) + ".</p>\n";
  out.similarity_table_html = similarity_table(st);
  out.plate_properties_html = plate_properties(st);
  return out;
}

}  // namespace ivv::reports
