#include "reports/restitution.h"

#include <cmath>

#include "reports/html.h"

namespace ivv::reports {
namespace {

using verification::Plot;
using verification::Series;

// COR against v0/v_y, log-log, with the asymptote; the slopes table's rows.
void add_cor_loglog(const verification::UndampedCorStudy& undamped, RestitutionSection& out) {
  const double v_y = undamped.v_yield;
  Plot p;
  p.id = "restitution-cor-loglog";
  p.title = "Undamped elastoplastic COR against v0/v_y, with the v0^(-1/4) asymptote";
  p.x_label = "v0/v_y [-]";
  p.y_label = "coefficient of restitution e [-]";
  p.log_x = p.log_y = true;
  Series closed = curve("closed form (energy, docs/design.md §2)");
  for (std::size_t i = 0; i < undamped.curve_ratio.size(); ++i)
    if (undamped.curve_ratio[i] >= 1.0)
      add(closed, undamped.curve_ratio[i], undamped.curve_e_closed_form[i]);
  Series simulated = curve("simulated (odeint-dopri5, rtol 1e-12)", Series::Style::points);
  for (const auto& row : undamped.rows)
    if (row.ratio > 1.0) add(simulated, row.ratio, row.e_simulated);
  Series asymptote = curve("asymptote (15/8)^(1/8) (v0/v_y)^(-1/4)", Series::Style::dashed);
  for (const auto& row : undamped.rows)
    if (row.ratio >= 3.0) add(asymptote, row.ratio, row.asymptote);
  p.series = {closed, simulated, asymptote};
  out.figures.push_back(
      {p,
       "Table 1 scene without dashpot (v<sub>y</sub> = " + number(v_y, 4) +
           " m/s). The curve is the closed form by energy; points are simulations; the "
           "dashed line is the high-velocity limit e → (15/8)<sup>1/8</sup> "
           "(v<sub>0</sub>/v<sub>y</sub>)<sup>−1/4</sup>, derived in "
           "<code>verification/study_restitution.h</code> (the nonlinear counterpart of the "
           "paper's eq. 21). The local slope approaches −1/4 only slowly: see the table.",
       true,
       Source::from_cases(
           {"trend.cor-undamped-simulated-is-closed-form", "trend.cor-undamped-asymptote"})});
  out.log_step = undamped.log_step;
  for (const auto& row : undamped.rows)
    if (row.tabulated) out.slopes.push_back(row);
}

// COR against zeta at fixed v0, the nonlinear model beside the linearized closed form.
void add_cor_against_zeta(RestitutionSection& out) {
  const verification::CorZetaStudy& st = verification::cor_zeta_study();
  Plot p;
  p.id = "restitution-cor-zeta";
  p.title = "COR against the damping ratio ζ at fixed v0";
  p.x_label = "damping ratio ζ [-]";
  p.y_label = "coefficient of restitution e [-]";
  p.log_x = true;
  int captured = 0, failed = 0;
  for (std::size_t i = 0; i < st.velocities.size(); ++i) {
    Series c =
        curve("nonlinear, v0 = " + number(st.velocities[i]) + " m/s", Series::Style::linespoints);
    for (std::size_t j = 0; j < st.zetas.size(); ++j) {
      const ImpactResult& r = st.runs[i][j];
      if (!r.ok()) {
        ++failed;
        continue;
      }
      if (r.status == ImpactStatus::captured) ++captured;
      add(c, st.zetas[j], r.e);
    }
    p.series.push_back(c);
  }
  for (std::size_t i = 0; i < st.velocities.size(); ++i) {
    Series c = curve("linearized closed form, v0 = " + number(st.velocities[i]) + " m/s",
                     Series::Style::dashed);
    for (std::size_t j = 0; j < st.linear_zetas.size(); ++j)
      if (!std::isnan(st.linear_e[i][j])) add(c, st.linear_zetas[j], st.linear_e[i][j]);
    if (!c.x.empty()) p.series.push_back(c);
  }
  std::string caption =
      "Table 1 scene, elastoplastic law (numerical, odeint-dopri5 at its default rtol 1e-10) "
      "and the linearized closed form (eqs 22-25, checked by the "
      "<code>analytic.linearized.*</code> cases) at the same ζ. e falls with ζ until strong "
      "damping leaves no rebound (capture, e = 0: " +
      std::to_string(captured) +
      " of the simulated points); past the first capture the series dashpot still lets "
      "rebounds of order 10<sup>-6</sup> v<sub>0</sub> through at some ζ, invisible here and "
      "not claimed. The linearized law is undefined at 0.1 m/s and for the heavily damped "
      "impacts whose loading stops below 2.25 z<sub>y</sub>: no dashed points there.";
  if (failed > 0) caption += " " + std::to_string(failed) + " runs failed and are not drawn.";
  out.figures.push_back({.plot = p,
                         .caption = caption,
                         .source = Source::from_cases(
                             {"trend.cor-falls-with-zeta-to-capture", "analytic.linearized.*"})});
}

// Thornton beside the model.
void add_thornton(const verification::UndampedCorStudy& undamped, RestitutionSection& out) {
  Plot p;
  p.id = "restitution-thornton";
  p.title = "Thornton (1997) elastic-perfectly-plastic spheres beside the elastoplastic model";
  p.x_label = "v0/v_y (impact over yield velocity) [-]";
  p.y_label = "coefficient of restitution e [-]";
  p.log_x = p.log_y = true;
  Series thornton = curve("Thornton (1997), r = V_y/V_i");
  Series model = curve("elastoplastic model, closed form (undamped)");
  for (std::size_t i = 0; i < undamped.curve_ratio.size(); ++i) {
    add(thornton, undamped.curve_ratio[i], undamped.curve_e_thornton[i]);
    add(model, undamped.curve_ratio[i], undamped.curve_e_closed_form[i]);
  }
  Series thornton_asym = curve("Thornton asymptote 1.185 r^(1/4)", Series::Style::dashed);
  Series model_asym = curve("model asymptote 1.0819 (v0/v_y)^(-1/4)", Series::Style::dashed);
  for (const auto& row : undamped.rows)
    if (row.ratio >= 10.0) {
      add(thornton_asym, row.ratio, row.thornton_asymptote);
      add(model_asym, row.ratio, row.asymptote);
    }
  p.series = {thornton, model, thornton_asym, model_asym};
  out.figures.push_back(
      {p,
       "Both against impact velocity over the velocity at which yield begins. Thornton's "
       "formula (J. Appl. Mech. 64:383, oracles/published.h) models elastic-perfectly-"
       "plastic spheres; the paper's law keeps hardening (slope K<sub>y</sub>) after "
       "yield, so the two share the −1/4 slope but not the coefficient "
       "(1.185 against 1.0819). A published trend beside the model, not a fit.",
       false,
       Source::from_cases({"trend.thornton-same-exponent", "trend.thornton-reference-table",
                           "trend.cor-undamped-simulated-is-closed-form"})});
}

// Hunt-Crossley damping maps: the COR each delivers against its target, and the table's rows.
void add_damping_maps(RestitutionSection& out) {
  const auto& maps = verification::damping_map_study();
  Plot p;
  p.id = "restitution-hc-maps";
  p.title = "Hunt-Crossley damping maps mu(e): the COR each delivers against its target";
  p.x_label = "target coefficient of restitution e [-]";
  p.y_label = "delivered coefficient of restitution [-]";
  for (const auto& map : maps) {
    Series c = curve(map.name + ": " + map.formula);
    for (std::size_t i = 0; i < map.curve_target.size(); ++i)
      add(c, map.curve_target[i], map.curve_e_exact[i]);
    p.series.push_back(c);
  }
  Series simulated = curve("simulated (odeint-dopri5, rtol 1e-12)", Series::Style::points);
  for (const auto& map : maps)
    for (const auto& pt : map.points)
      if (pt.simulated.separated()) add(simulated, pt.e_target, pt.simulated.e);
  p.series.push_back(simulated);
  Series diagonal = curve("delivered = target", Series::Style::dashed);
  add(diagonal, 0.0, 0.0);
  add(diagonal, 1.0, 1.0);
  p.series.push_back(diagonal);
  out.figures.push_back(
      {p,
       "Each map picks μ from a target e; the exact Hunt-Crossley restitution "
       "e = [1 + W<sub>0</sub>(−(1+u<sub>0</sub>) "
       "e<sup>−(1+u<sub>0</sub>)</sup>)]/u<sub>0</sub>, "
       "u<sub>0</sub> = μv<sub>0</sub> (docs/design.md §2, closed_forms/hunt_crossley.h), says "
       "what it "
       "really delivers, independently of K, m and v<sub>0</sub> (curves); the points are "
       "simulations at the targets of <code>reference_data/hunt_crossley_mu_maps.csv</code>. "
       "On the diagonal a map is exact.",
       true, Source::from_cases({"trend.hunt-crossley-map.*"})});
  out.map_targets = {0.1, 0.3, 0.5, 0.7, 0.9};
  for (const auto& map : maps) {
    DampingMapRow row{map.name, map.formula, {}};
    for (double e : out.map_targets) {
      double delivered = std::nan("");
      for (const auto& pt : map.points)
        if (std::abs(pt.e_target - e) < 1e-12 && pt.simulated.separated())
          delivered = pt.simulated.e;
      row.delivered.push_back(delivered);
    }
    out.maps.push_back(row);
  }
}

}  // namespace

// The section's four figures, each from its study (computed once, shared with the cases).
RestitutionSection restitution_section(const SectionOptions& options) {
  RestitutionSection out;
  options.say("restitution: from the restitution studies (computed once, shared with the cases)");
  const verification::UndampedCorStudy& undamped = verification::undamped_cor_study();
  add_cor_loglog(undamped, out);
  add_cor_against_zeta(out);
  add_thornton(undamped, out);
  add_damping_maps(out);
  return out;
}

}  // namespace ivv::reports
