#include "reports/paper_figures.h"

#include <cmath>

#include "reports/html.h"
#include "verification/study_paper.h"

namespace ivv::reports {
namespace {

using verification::kPaperDashpot;
using verification::PaperRun;
using verification::Plot;
using verification::Series;

std::string zeta_text(const Scene& s) {
  const DerivedParameters p = derive(s);
  if (!p.has_dashpot()) return "no dashpot";
  return "c = " + number(p.c, 5) + " N s/m (ζ = " + number(p.zeta, 3) + ")";
}

std::string ms(double seconds) {
  return number(seconds * 1e3, 4) + " ms";
}

std::string outcome_values(const ImpactResult& r) {
  return "e = " + number(r.e, 4) + ", F<sub>max</sub> = " + number(r.F_max, 4) +
         " N, t<sub>f</sub> = " + ms(r.t_contact);
}

Plot force_history_plot(std::string id, std::string title) {
  Plot p;
  p.id = std::move(id);
  p.title = std::move(title);
  p.x_label = "time t [ms]";
  p.y_label = "impact force F [N]";
  return p;
}

constexpr const char* kTable1 =
    "Table 1 scene (m = 0.5 kg, R = 10 mm, steel E<sub>1</sub> = 207 GPa, ν<sub>1</sub> = 0.3; "
    "T300/934 E<sub>22</sub> = 7.9 GPa, ν<sub>2</sub> = 0.3, S<sub>y</sub> = 2·101 = 202 MPa)";

constexpr const char* kIntegrator = "numerical, odeint-dopri5 at rtol 1e-12";

// The curves of one velocity of Figs 2-7: each model's force against time and against the
// sphere's displacement.
struct ResponseCurves {
  Series nl_force, nl_hyst, lin_force, lin_hyst, hc_force, hc_hyst;
};

ResponseCurves response_curves(const verification::PaperResponse& r) {
  ResponseCurves c{curve("nonlinear elastoplastic (numerical)"),
                   curve("nonlinear elastoplastic (numerical)"),
                   curve("linearized (closed form)", Series::Style::dashed),
                   curve("linearized (closed form)", Series::Style::dashed),
                   curve("Hunt-Crossley fitted (numerical)"),
                   curve("Hunt-Crossley fitted (numerical)")};
  for (const auto& pt : r.model.trajectory) {
    add(c.nl_force, pt.t * 1e3, pt.force);
    add(c.nl_hyst, pt.alpha * 1e3, pt.force);
  }
  const verification::LinearizedCurve& lin = r.linearized;
  for (std::size_t i = 0; i < lin.t.size(); ++i) {
    add(c.lin_force, lin.t[i] * 1e3, lin.force[i]);
    add(c.lin_hyst, lin.alpha[i] * 1e3, lin.force[i]);
  }
  for (const auto& pt : r.hunt_crossley.trajectory) {
    add(c.hc_force, pt.t * 1e3, pt.force);
    add(c.hc_hyst, pt.alpha * 1e3, pt.force);
  }
  return c;
}

// Why no linearized curve is drawn (empty when the law is defined at this velocity).
std::string linearized_undefined_text(const verification::LinearizedCurve& lin) {
  if (lin.defined) return {};
  return "The linearized law is undefined here: its loading reaches z<sub>m</sub> = " +
         number(lin.z_reached * 1e6, 4) +
         " µm &lt; (K<sub>y</sub>/K<sub>h</sub>)<sup>2</sup>"
         " = 2.25 z<sub>y</sub> = " +
         number(lin.z_needed * 1e6, 4) +
         " µm, where eq. 17 would raise a negative number to the power 2/3; no "
         "linearized curve is drawn.";
}

// The caption of a force history: the scene, the fitted Hunt-Crossley law and each model's
// outcome.
std::string force_history_caption(const verification::PaperResponse& r) {
  const double v0 = r.v0;
  const HuntCrossleyFit& fit = r.fit;
  const verification::LinearizedCurve& lin = r.linearized;
  const std::string hc_text =
      "Hunt-Crossley (eq. 27, no dashpot) fitted to the model's "
      "F<sub>max</sub> and e by <code>fit_hunt_crossley</code>: <b>K = " +
      number_html(fit.K, 5) + " N/m<sup>1.5</sup>, μ = " + number(fit.mu, 5) +
      " s/m</b> (μv<sub>0</sub> = " + number(fit.mu * v0, 4) + ").";
  std::string results = " Model: " + outcome_values(r.model.result);
  if (lin.defined)
    results += "; linearized: e = " + number(lin.solution.e, 4) +
               ", F<sub>max</sub> = " + number(lin.solution.F_max, 4) + " N, t<sub>f</sub> = " +
               (lin.solution.captured ? std::string("∞ (capture)") : ms(lin.solution.t_contact));
  results += "; Hunt-Crossley: " + outcome_values(r.hunt_crossley.result) + ".";
  return " v<sub>0</sub> = " + number(v0, 3) + " m/s, " + zeta_text(r.model.scene) + "; " +
         kTable1 + "; " + kIntegrator + ". " + hc_text + results +
         (lin.defined ? "" : " " + linearized_undefined_text(lin));
}

// The caption of a force-displacement loop (Fig. fb) of the impacts of Fig. fa.
std::string force_displacement_caption(const verification::PaperResponse& r,
                                       const std::string& fa) {
  return " The impacts of Fig. " + fa + " (v<sub>0</sub> = " + number(r.v0, 3) +
         " m/s, ζ = 0.1; Hunt-Crossley K = " + number_html(r.fit.K, 4) +
         " N/m<sup>1.5</sup>, μ = " + number(r.fit.mu, 4) +
         " s/m). Each loop ends at separation; the model's final displacement "
         "is the dashpot set y<sub>f</sub> = " +
         number(r.model.result.y_final * 1e3, 3) +
         " mm plus the spring's permanent set z<sub>f</sub> = " +
         number(r.model.result.z_perm * 1e3, 3) + " mm." +
         (r.linearized.defined
              ? ""
              : " No linearized curve: undefined at this velocity (see Fig. " + fa + ").");
}

// Figs 2-7: one velocity, two figures (Fig. `fig`: force history; Fig. fig + 1: force against
// displacement).
void response_figures(const verification::PaperResponse& r, int fig, std::vector<Figure>& out) {
  const ResponseCurves c = response_curves(r);
  const std::string v = number(r.v0, 3), fa = std::to_string(fig), fb = std::to_string(fig + 1);
  const Source related = Source::illustration(
      {"trend.paper.elastic-at-0.1-plastic-at-1-and-5", "trend.paper.linear-close-to-nonlinear",
       "trend.paper.hunt-crossley-fit", "trend.paper.hunt-crossley-longer-contact",
       "trend.paper.displacement-after-force"});
  Plot force = force_history_plot("paper-fig" + fa + "-force-history",
                                  "Fig. " + fa + ": impact force history, v0 = " + v + " m/s");
  // an undefined linearized law leaves its (empty) series in place: colours stay the same
  // across Figs 2-7
  force.series = {c.nl_force, c.lin_force, c.hc_force};
  out.push_back({.plot = force, .caption = force_history_caption(r), .source = related});

  Plot hyst;
  hyst.id = "paper-fig" + fb + "-force-displacement";
  hyst.title = "Fig. " + fb + ": impact force against sphere displacement, v0 = " + v + " m/s";
  hyst.x_label = "sphere displacement α [mm]";
  hyst.y_label = "impact force F [N]";
  hyst.series = {c.nl_hyst, c.lin_hyst, c.hc_hyst};
  out.push_back({.plot = hyst, .caption = force_displacement_caption(r, fa), .source = related});
}

// Figs 8 and 9: one parameter varied, force history, c held.
Figure family(const std::string& id, const std::string& title, const std::string& held,
              const std::vector<PaperRun>& runs, const std::string& trend, const Source& source) {
  Plot p = force_history_plot(id, title);
  std::string caption =
      " Nonlinear elastoplastic model (" + std::string(kIntegrator) + "), " + held + ". ";
  for (const PaperRun& r : runs) {
    Series c = curve(r.label);
    for (const auto& pt : r.trajectory) add(c, pt.t * 1e3, pt.force);
    p.series.push_back(c);
    caption += r.label + " (ζ = " + number(derive(r.scene).zeta, 3) +
               "): " + outcome_values(r.result) + ". ";
  }
  return {p, caption + trend, false, source};
}

// Figs 10-13: normalised responses (paper eq. 26): the tau and alpha figures, and the
// spring-deformation companion.
void normalised(int fig_a, const std::string& what, const std::string& fixed,
                const std::vector<PaperRun>& runs, const std::string& trend, const Source& source,
                std::vector<Figure>& out, std::vector<Figure>& companions) {
  const std::string fa = std::to_string(fig_a), fb = std::to_string(fig_a + 1);
  Plot tau_plot, alpha_plot, z_plot;
  tau_plot.id = "paper-fig" + fa + "-normalised-force-history";
  tau_plot.title =
      "Fig. " + fa + ": effect of " + what + " on the normalised force history, " + fixed;
  tau_plot.x_label = "normalised time τ = ω0 t [-]";
  tau_plot.y_label = "normalised force F/(m v0 ω0) [-]";
  alpha_plot.id = "paper-fig" + fb + "-normalised-force-displacement";
  alpha_plot.title = "Fig. " + fb + ": effect of " + what +
                     " on the normalised force-displacement relation, " + fixed;
  alpha_plot.x_label = "normalised displacement ᾱ = α ω0/v0 [-]";
  alpha_plot.y_label = tau_plot.y_label;
  z_plot.id = alpha_plot.id + "-spring";
  z_plot.title =
      "Fig. " + fb + " (companion): normalised force against spring deformation, " + fixed;
  z_plot.x_label = "normalised spring deformation z ω0/v0 [-]";
  z_plot.y_label = tau_plot.y_label;
  std::string outcomes;
  for (const PaperRun& r : runs) {
    const Scene& s = r.scene;
    const DerivedParameters p = derive(s);
    const double length = s.velocity / p.omega0;
    Series a = curve(r.label), b = curve(r.label), c = curve(r.label);
    for (const auto& pt : r.trajectory) {
      add(a, pt.tau, pt.force_bar);
      add(b, pt.alpha_bar, pt.force_bar);
      add(c, pt.z / length, pt.force_bar);
    }
    tau_plot.series.push_back(a);
    alpha_plot.series.push_back(b);
    z_plot.series.push_back(c);
    outcomes += r.label + ": e = " + number(r.result.e, 3) + ", F̄<sub>max</sub> = " +
                number(r.result.F_max / (s.mass * s.velocity * p.omega0), 3) +
                ", τ<sub>f</sub> = " + number(r.result.t_contact * p.omega0, 3) + ". ";
  }
  out.push_back({tau_plot,
                 " Nonlinear elastoplastic model (" + std::string(kIntegrator) +
                     "), Table 1 scene, " + fixed +
                     "; τ = ω<sub>0</sub>t, F̄ = F/(m v<sub>0</sub> ω<sub>0</sub>) (eq. 26). " +
                     outcomes + trend,
                 false, source});
  out.push_back({alpha_plot,
                 " The impacts of Fig. " + fa +
                     ", force against the impactor displacement ᾱ = α ω<sub>0</sub>/"
                     "v<sub>0</sub> (eq. 26). " +
                     trend,
                 false, source});
  companions.push_back({z_plot,
                        " The impacts of Fig. " + fa +
                            ", force against the spring deformation z = α − y "
                            "(normalised like α): unloading follows the contact law "
                            "itself (eq. 10), without the dashpot's share.",
                        false, source});
}

}  // namespace

std::string paper_parameters_html() {
  const DerivedParameters p = derive(verification::paper_with_dashpot(1.0));
  return std::string(kTable1) + " gives E* = " + number(p.E_star / 1e9, 4) +
         " GPa, K<sub>h</sub> = " + number_html(p.K_h, 4) +
         " N/m<sup>1.5</sup>, z<sub>y</sub> = " + number(p.z_y * 1e6, 4) +
         " µm, K<sub>y</sub> = " + number_html(p.K_y, 4) +
         " N/m, ω<sub>0</sub> = " + number_html(p.omega0, 4) +
         " rad/s, v<sub>y</sub> = " + number(p.v_yield, 4) +
         " m/s; with c = " + number(kPaperDashpot, 5) + " N s/m, ζ = " + number(p.zeta, 4) + ".";
}

std::vector<Figure> paper_figures(const SectionOptions& options) {
  options.say("paper: Figs 2-14 from the paper study (computed once, shared with the cases)");
  const verification::PaperStudy& st = verification::paper_study();
  std::vector<Figure> out;
  int fig = 2;
  for (const auto& r : st.responses) {
    response_figures(r, fig, out);
    fig += 2;
  }

  out.push_back(family(
      "paper-fig8-yield-strength", "Fig. 8: effect of the yield strength S_y on the force history",
      "Table 1 scene except S<sub>y</sub>, v<sub>0</sub> = 1 m/s, c = 11440 N s/m held "
      "(ζ follows K<sub>y</sub>)",
      st.by_yield_strength,
      "Lower S<sub>y</sub>: lower F<sub>max</sub>, longer contact (paper §3) from 50.5 to "
      "202 MPa. Above the Table 1 value the contact-time trend reverses: at 404 MPa the "
      "impact at 1 m/s is nearly elastic (v<sub>y</sub> = 0.74 m/s) and the contact lasts "
      "longer than at 202 MPa, so the case trend.paper.fig8-yield-strength checks the "
      "claim on 50.5-202 MPa only.",
      Source::illustration(
          {"trend.paper.fig8-yield-strength", "trend.paper.displacement-after-force"})));
  out.push_back(family(
      "paper-fig9-mass", "Fig. 9: effect of the impactor mass m on the force history",
      "Table 1 scene except m, v<sub>0</sub> = 1 m/s, c = 11440 N s/m held (ζ grows as √m)",
      st.by_mass, "Lower mass: lower F<sub>max</sub>, shorter contact (paper §3).",
      Source::illustration({"trend.paper.fig9-mass", "trend.paper.displacement-after-force"})));

  std::vector<Figure> companions;
  normalised(10, "impact velocity", "ζ = 0.1", st.by_velocity,
             "Higher v<sub>0</sub>: more plastic deformation, shorter normalised contact, "
             "steeper unloading (paper §3).",
             Source::illustration(
                 {"trend.paper.fig10-11-velocity", "trend.paper.displacement-after-force"}),
             out, companions);
  normalised(12, "damping ratio", "v0 = 1 m/s", st.by_zeta,
             "Higher ζ: lower F<sub>max</sub>, longer contact, smaller permanent spring set "
             "(paper §3).",
             Source::illustration(
                 {"trend.paper.fig12-13-damping", "trend.paper.displacement-after-force"}),
             out, companions);
  for (auto& c : companions) out.push_back(std::move(c));

  // Fig 14: COR against v0 for several zeta.
  Plot p;
  p.id = "paper-fig14-cor";
  p.title = "Fig. 14: coefficient of restitution against impact velocity for several ζ";
  p.x_label = "impact velocity v0 [m/s]";
  p.y_label = "coefficient of restitution e [-]";
  p.log_x = true;
  int failed = 0;
  for (std::size_t j = 0; j < st.fig14_zetas.size(); ++j) {
    const double zeta = st.fig14_zetas[j];
    Series c = curve(zeta == 0 ? std::string("ζ = 0 (no dashpot)") : "ζ = " + number(zeta),
                     Series::Style::linespoints);
    for (std::size_t i = 0; i < st.fig14_velocities.size(); ++i) {
      const ImpactResult& r = st.fig14[j][i];
      if (!r.ok()) {
        ++failed;
        continue;
      }
      add(c, st.fig14_velocities[i], r.e);
    }
    p.series.push_back(c);
  }
  const DerivedParameters d = derive(paper_scene());
  std::string caption =
      " Nonlinear elastoplastic model (" + std::string(kIntegrator) + "), Table 1 scene, " +
      std::to_string(st.fig14_velocities.size()) +
      " velocities log-spaced in [0.01, 10] m/s. Below v<sub>y</sub> = " + number(d.v_yield, 4) +
      " m/s the undamped impact is elastic (e = 1); e falls with ζ until "
      "capture (paper §3; the case named above checks it at every v<sub>0</sub> "
      "drawn) and with v<sub>0</sub> above yield (case "
      "<code>trend.cor-falls-with-v0</code>, on its own grid).";
  if (failed > 0) caption += " " + std::to_string(failed) + " points failed and are not drawn.";
  const Source fig14 = Source::from_cases({"trend.paper.fig14-cor-falls-with-zeta"});
  out.push_back({.plot = p, .caption = caption, .full_width = true, .source = fig14});
  return out;
}

}  // namespace ivv::reports
