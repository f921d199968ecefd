#include "reports/paper_figures.h"

#include <cmath>
#include <stdexcept>

#include "oracles/linear_model.h"
#include "reports/html.h"
#include "solver/fit_hunt_crossley.h"
#include "solver/simulate.h"
#include "solver/sweep.h"

namespace ivv::reports {
namespace {

using verification::Plot;
using verification::Series;

constexpr std::size_t kMaxCurvePoints = 1500;  // per series: plenty for a smooth SVG curve

struct Run {
  ImpactResult result;
  std::vector<TrajectoryPoint> trajectory;
};

Run run(const SimulationRequest& req, const std::string& what) {
  Run out;
  out.result = simulate(req, &out.trajectory);
  if (!out.result.ok())
    throw std::runtime_error("paper figures: " + what + " failed: " + out.result.reason);
  out.trajectory = thin(out.trajectory, kMaxCurvePoints);
  return out;
}

SimulationRequest request(const Scene& s, LawKind law = LawKind::elastoplastic) {
  SimulationRequest req;
  req.scene = s;
  req.law = law;
  return req;
}

Scene paper_with(double v0, Damping damping) {
  Scene s = paper_scene();
  s.velocity = v0;
  s.damping = damping;
  return s;
}

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

// The closed-form linearized solution sampled over its contact, or why there is none.
struct LinearCurves {
  bool defined = false;
  std::string why_not;  // HTML
  oracles::LinearImpact solution;
  Series force_history = curve("linearized (closed form)", Series::Style::dashed);
  Series hysteresis = curve("linearized (closed form)", Series::Style::dashed);
};

LinearCurves linear_curves(const Scene& s) {
  LinearCurves out;
  const oracles::LinearModelInput in = oracles::linear_model_input(s, derive(s));
  try {
    out.solution = oracles::solve_linear_model(in);
  } catch (const oracles::LinearizedLawUndefined& e) {
    out.why_not = "The linearized law is undefined here: its loading reaches z<sub>m</sub> = " +
                  number(e.z_max() * 1e6, 4) +
                  " µm &lt; (K<sub>y</sub>/K<sub>h</sub>)<sup>2</sup>"
                  " = 2.25 z<sub>y</sub> = " +
                  number(e.z_min() * 1e6, 4) +
                  " µm, where eq. 17 would raise a negative number to the power 2/3; no "
                  "linearized curve is drawn.";
    return out;
  }
  out.defined = true;
  const double t_end = out.solution.captured ? 10.0 * out.solution.t_max : out.solution.t_contact;
  constexpr int kSamples = 600;
  for (int i = 0; i <= kSamples; ++i) {
    const double t = t_end * i / kSamples;
    const oracles::LinearState st = oracles::linear_model_state(in, out.solution, t);
    add(out.force_history, t * 1e3, st.F);
    add(out.hysteresis, st.alpha * 1e3, st.F);
  }
  return out;
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

// Figs 2-7: one velocity, two figures.
void response_figures(double v0, int fig, std::vector<Figure>& out) {
  const Scene s = paper_with(v0, Damping::coefficient(kPaperDashpot));
  const SimulationRequest req = request(s);
  const Run nl = run(req, "nonlinear elastoplastic at v0 = " + number(v0));
  const HuntCrossleyFit fit = fit_hunt_crossley(req);
  SimulationRequest hc_req = request(s, LawKind::hunt_crossley);
  hc_req.scene.damping = Damping::none();
  hc_req.parameters["K"] = fit.K;
  hc_req.parameters["mu"] = fit.mu;
  const Run hc = run(hc_req, "fitted Hunt-Crossley at v0 = " + number(v0));
  const LinearCurves lin = linear_curves(s);

  Series nl_force = curve("nonlinear elastoplastic (numerical)");
  Series nl_hyst = curve("nonlinear elastoplastic (numerical)");
  for (const auto& pt : nl.trajectory) {
    add(nl_force, pt.t * 1e3, pt.force);
    add(nl_hyst, pt.alpha * 1e3, pt.force);
  }
  Series hc_force = curve("Hunt-Crossley fitted (numerical)");
  Series hc_hyst = curve("Hunt-Crossley fitted (numerical)");
  for (const auto& pt : hc.trajectory) {
    add(hc_force, pt.t * 1e3, pt.force);
    add(hc_hyst, pt.alpha * 1e3, pt.force);
  }

  const std::string v = number(v0, 3), fa = std::to_string(fig), fb = std::to_string(fig + 1);
  const std::string hc_text =
      "Hunt-Crossley (eq. 27, no dashpot) fitted to the model's "
      "F<sub>max</sub> and e by <code>fit_hunt_crossley</code>: <b>K = " +
      number_html(fit.K, 5) + " N/m<sup>1.5</sup>, μ = " + number(fit.mu, 5) +
      " s/m</b> (μv<sub>0</sub> = " + number(fit.mu * v0, 4) + ").";
  std::string results = " Model: " + outcome_values(nl.result);
  if (lin.defined)
    results += "; linearized: e = " + number(lin.solution.e, 4) +
               ", F<sub>max</sub> = " + number(lin.solution.F_max, 4) + " N, t<sub>f</sub> = " +
               (lin.solution.captured ? std::string("∞ (capture)") : ms(lin.solution.t_contact));
  results += "; Hunt-Crossley: " + outcome_values(hc.result) + ".";

  Plot force = force_history_plot("paper-fig" + fa + "-force-history",
                                  "Fig. " + fa + ": impact force history, v0 = " + v + " m/s");
  // an undefined linearized law leaves its (empty) series in place: colours stay the same
  // across Figs 2-7
  force.series.push_back(nl_force);
  force.series.push_back(lin.force_history);
  force.series.push_back(hc_force);
  out.push_back({force, " v<sub>0</sub> = " + v + " m/s, " + zeta_text(s) + "; " + kTable1 + ". " +
                            hc_text + results + (lin.defined ? "" : " " + lin.why_not)});

  Plot hyst;
  hyst.id = "paper-fig" + fb + "-force-displacement";
  hyst.title = "Fig. " + fb + ": impact force against sphere displacement, v0 = " + v + " m/s";
  hyst.x_label = "sphere displacement α [mm]";
  hyst.y_label = "impact force F [N]";
  hyst.series.push_back(nl_hyst);
  hyst.series.push_back(lin.hysteresis);
  hyst.series.push_back(hc_hyst);
  out.push_back({hyst, " The impacts of Fig. " + fa + " (v<sub>0</sub> = " + v +
                           " m/s, ζ = 0.1; Hunt-Crossley K = " + number_html(fit.K, 4) +
                           " N/m<sup>1.5</sup>, μ = " + number(fit.mu, 4) +
                           " s/m). Each loop ends at separation; the model's final displacement "
                           "is the dashpot set y<sub>f</sub> = " +
                           number(nl.result.y_final * 1e3, 3) +
                           " mm plus the spring's permanent set z<sub>f</sub> = " +
                           number(nl.result.z_perm * 1e3, 3) + " mm." +
                           (lin.defined ? ""
                                        : " No linearized curve: undefined at this "
                                          "velocity (see Fig. " +
                                              fa + ").")});
}

}  // namespace

std::string paper_parameters_html() {
  Scene s = paper_with(1.0, Damping::coefficient(kPaperDashpot));
  const DerivedParameters p = derive(s);
  return std::string(kTable1) + " gives E* = " + number(p.E_star / 1e9, 4) +
         " GPa, K<sub>h</sub> = " + number_html(p.K_h, 4) +
         " N/m<sup>1.5</sup>, z<sub>y</sub> = " + number(p.z_y * 1e6, 4) +
         " µm, K<sub>y</sub> = " + number_html(p.K_y, 4) +
         " N/m, ω<sub>0</sub> = " + number_html(p.omega0, 4) +
         " rad/s, v<sub>y</sub> = " + number(p.v_yield, 4) +
         " m/s; with c = " + number(kPaperDashpot, 5) + " N s/m, ζ = " + number(p.zeta, 4) + ".";
}

std::vector<Figure> paper_figures(const SectionOptions& options) {
  std::vector<Figure> out;
  int fig = 2;
  for (double v0 : {0.1, 1.0, 5.0}) {
    options.say("paper: Figs " + std::to_string(fig) + "-" + std::to_string(fig + 1) +
                " (v0 = " + number(v0) + " m/s: nonlinear, linearized, fitted Hunt-Crossley)");
    response_figures(v0, fig, out);
    fig += 2;
  }

  // Figs 8 and 9: one parameter varied, force history, c held.
  struct Variant {
    std::string label;
    Scene scene;
  };
  auto family = [&](const std::string& id, const std::string& title, const std::string& held,
                    const std::vector<Variant>& variants, const std::string& trend) {
    Plot p = force_history_plot(id, title);
    std::string caption = " Nonlinear elastoplastic model (numerical), " + held + ". ";
    for (const auto& [label, s] : variants) {
      const Run r = run(request(s), title + ", " + label);
      Series c = curve(label);
      for (const auto& pt : r.trajectory) add(c, pt.t * 1e3, pt.force);
      p.series.push_back(c);
      caption +=
          label + " (ζ = " + number(derive(s).zeta, 3) + "): " + outcome_values(r.result) + ". ";
    }
    out.push_back({p, caption + trend});
  };
  options.say("paper: Fig 8 (yield strength)");
  {
    std::vector<Variant> variants;
    for (double sy : {50e6, 101e6, 202e6, 404e6}) {
      Scene s = paper_with(1.0, Damping::coefficient(kPaperDashpot));
      s.yield_strength = sy;
      variants.push_back({"S_y = " + number(sy / 1e6, 4) + " MPa", s});
    }
    family("paper-fig8-yield-strength",
           "Fig. 8: effect of the yield strength S_y on the force history",
           "Table 1 scene except S<sub>y</sub>, v<sub>0</sub> = 1 m/s, c = 11440 N s/m held "
           "(ζ follows K<sub>y</sub>)",
           variants,
           "Lower S<sub>y</sub>: lower F<sub>max</sub>, longer contact (paper §3) from 50 to "
           "202 MPa. Above the Table 1 value the contact-time trend reverses: at 404 MPa the "
           "impact at 1 m/s is nearly elastic (v<sub>y</sub> = 0.74 m/s) and the contact lasts "
           "longer than at 202 MPa, so the case trend.paper.fig8-yield-strength checks the "
           "claim on 50.5-202 MPa only.");
  }
  options.say("paper: Fig 9 (impactor mass)");
  {
    std::vector<Variant> variants;
    for (double m : {0.125, 0.25, 0.5, 1.0, 2.0}) {
      Scene s = paper_with(1.0, Damping::coefficient(kPaperDashpot));
      s.mass = m;
      variants.push_back({"m = " + number(m, 4) + " kg", s});
    }
    family("paper-fig9-mass", "Fig. 9: effect of the impactor mass m on the force history",
           "Table 1 scene except m, v<sub>0</sub> = 1 m/s, c = 11440 N s/m held (ζ grows as √m)",
           variants, "Lower mass: lower F<sub>max</sub>, shorter contact (paper §3).");
  }

  // Figs 10-13: normalised responses (paper eq. 26).
  std::vector<Figure> companions;
  auto normalised = [&](int fig_a, const std::string& what, const std::string& fixed,
                        const std::vector<Variant>& variants, const std::string& trend) {
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
    for (const auto& [label, s] : variants) {
      const Run r = run(request(s), "Fig " + fa + " " + label);
      const DerivedParameters p = derive(s);
      const double length = s.velocity / p.omega0;
      Series a = curve(label), b = curve(label), c = curve(label);
      for (const auto& pt : r.trajectory) {
        add(a, pt.tau, pt.force_bar);
        add(b, pt.alpha_bar, pt.force_bar);
        add(c, pt.z / length, pt.force_bar);
      }
      tau_plot.series.push_back(a);
      alpha_plot.series.push_back(b);
      z_plot.series.push_back(c);
      outcomes += label + ": e = " + number(r.result.e, 3) + ", F̄<sub>max</sub> = " +
                  number(r.result.F_max / (s.mass * s.velocity * p.omega0), 3) +
                  ", τ<sub>f</sub> = " + number(r.result.t_contact * p.omega0, 3) + ". ";
    }
    out.push_back({tau_plot, " Nonlinear elastoplastic model (numerical), Table 1 scene, " + fixed +
                                 "; τ = ω<sub>0</sub>t, F̄ = F/(m v<sub>0</sub> ω<sub>0</sub>) "
                                 "(eq. 26). " +
                                 outcomes + trend});
    out.push_back({alpha_plot, " The impacts of Fig. " + fa +
                                   ", force against the impactor displacement ᾱ = α ω<sub>0</sub>/"
                                   "v<sub>0</sub> (eq. 26). " +
                                   trend});
    companions.push_back({z_plot, " The impacts of Fig. " + fa +
                                      ", force against the spring deformation z = α − y "
                                      "(normalised like α): unloading follows the contact law "
                                      "itself (eq. 10), without the dashpot's share."});
  };

  options.say("paper: Figs 10-11 (normalised, several v0, zeta = 0.1)");
  {
    std::vector<Variant> variants;
    for (double v0 : {0.1, 0.5, 1.0, 2.0, 5.0})
      variants.push_back({"v0 = " + number(v0) + " m/s", paper_with(v0, Damping::ratio(0.1))});
    normalised(10, "impact velocity", "ζ = 0.1", variants,
               "Higher v<sub>0</sub>: more plastic deformation, shorter normalised contact, "
               "steeper unloading (paper §3).");
  }
  options.say("paper: Figs 12-13 (normalised, several zeta, v0 = 1 m/s)");
  {
    std::vector<Variant> variants;
    for (double zeta : {0.0, 0.1, 0.2, 0.3, 0.5})
      variants.push_back({zeta == 0 ? std::string("ζ = 0 (no dashpot)") : "ζ = " + number(zeta),
                          paper_with(1.0, zeta == 0 ? Damping::none() : Damping::ratio(zeta))});
    normalised(12, "damping ratio", "v0 = 1 m/s", variants,
               "Higher ζ: lower F<sub>max</sub>, longer contact, smaller permanent spring set "
               "(paper §3).");
  }
  for (auto& c : companions) out.push_back(std::move(c));

  // Fig 14: COR against v0 for several zeta.
  options.say("paper: Fig 14 (COR against v0 for several zeta, sweep)");
  {
    SweepRequest sweep;
    sweep.base = request(paper_scene());
    sweep.velocities = log_grid(0.01, 10.0, options.quick ? 10 : 40);
    const std::vector<double> zetas = {0.0, 0.05, 0.1, 0.2, 0.3, 0.5};
    sweep.zetas = zetas;
    sweep.threads = options.threads;
    const auto points = run_sweep(sweep);
    Plot p;
    p.id = "paper-fig14-cor";
    p.title = "Fig. 14: coefficient of restitution against impact velocity for several ζ";
    p.x_label = "impact velocity v0 [m/s]";
    p.y_label = "coefficient of restitution e [-]";
    p.log_x = true;
    int failed = 0;
    for (double zeta : zetas) {
      Series c = curve(zeta == 0 ? std::string("ζ = 0 (no dashpot)") : "ζ = " + number(zeta),
                       Series::Style::linespoints);
      for (const auto& pt : points) {
        if (pt.zeta != zeta) continue;
        if (!pt.result.ok()) {
          ++failed;
          continue;
        }
        add(c, pt.v0, pt.result.e);
      }
      p.series.push_back(c);
    }
    const DerivedParameters d = derive(paper_scene());
    std::string caption =
        " Nonlinear elastoplastic model (numerical, odeint-dopri5), Table 1 "
        "scene, " +
        std::to_string(sweep.velocities.size()) +
        " velocities log-spaced in [0.01, 10] m/s. Below v<sub>y</sub> = " + number(d.v_yield, 4) +
        " m/s the undamped impact is elastic (e = 1); e falls with v<sub>0</sub> "
        "and with ζ (paper §3).";
    if (failed > 0)
      caption += " " + std::to_string(failed) + " sweep points failed and are not drawn.";
    out.push_back({p, caption, true});
  }
  return out;
}

}  // namespace ivv::reports
