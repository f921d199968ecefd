#include "reports/restitution.h"

#include <cmath>
#include <stdexcept>

#include "oracles/hunt_crossley.h"
#include "oracles/linear_model.h"
#include "oracles/published.h"
#include "oracles/undamped_elastoplastic.h"
#include "reports/html.h"
#include "solver/simulate.h"
#include "solver/sweep.h"

namespace ivv::reports {
namespace {

using verification::Plot;
using verification::Series;

Scene undamped_paper(double v0) {
  Scene s = paper_scene();
  s.damping = Damping::none();
  s.velocity = v0;
  return s;
}

double closed_form_cor(double v0) {
  const Scene s = undamped_paper(v0);
  return oracles::solve_undamped_elastoplastic(oracles::elastoplastic_input(s, derive(s))).e;
}

double simulated_cor(double v0, double rtol) {
  SimulationRequest req;
  req.scene = undamped_paper(v0);
  req.options.rtol = rtol;
  req.options.atol = rtol;
  const ImpactResult r = simulate(req);
  if (!r.separated())
    throw std::runtime_error("restitution: undamped impact at v0 = " + number(v0) +
                             " m/s did not separate: " + r.reason);
  return r.e;
}

}  // namespace

double undamped_cor_asymptote(double velocity_ratio) {
  return std::pow(15.0 / 8.0, 1.0 / 8.0) * std::pow(velocity_ratio, -0.25);
}

RestitutionSection restitution_section(const SectionOptions& options) {
  RestitutionSection out;
  const DerivedParameters paper = derive(undamped_paper(1.0));
  const double v_y = paper.v_yield;

  // COR against v0/v_y, log-log, with the asymptote.
  options.say("restitution: undamped COR against v0/v_y (closed form, sweep, slopes)");
  {
    Plot p;
    p.id = "restitution-cor-loglog";
    p.title = "Undamped elastoplastic COR against v0/v_y, with the v0^(-1/4) asymptote";
    p.x_label = "v0/v_y [-]";
    p.y_label = "coefficient of restitution e [-]";
    p.log_x = p.log_y = true;
    Series closed = curve("closed form (energy, SPEC §2)");
    for (double r : log_grid(1.0, 1e4, 200)) add(closed, r, closed_form_cor(r * v_y));
    SweepRequest sweep;
    sweep.base.scene = undamped_paper(1.0);
    sweep.velocities = log_grid(1.2 * v_y, 1e4 * v_y, options.quick ? 8 : 25);
    sweep.zetas = {0.0};
    sweep.threads = options.threads;
    Series simulated = curve("simulated (odeint-dopri5, rtol 1e-10)", Series::Style::points);
    for (const auto& pt : run_sweep(sweep))
      if (pt.result.separated()) add(simulated, pt.v0 / v_y, pt.result.e);
    Series asymptote = curve("asymptote (15/8)^(1/8) (v0/v_y)^(-1/4)", Series::Style::dashed);
    for (double r : {3.0, 1e4}) add(asymptote, r, undamped_cor_asymptote(r));
    p.series = {closed, simulated, asymptote};
    out.figures.push_back(
        {p,
         "Table 1 scene without dashpot (v<sub>y</sub> = " + number(v_y, 4) +
             " m/s). The curve is the closed form by energy; points are simulations; the "
             "dashed line is the high-velocity limit e → (15/8)<sup>1/8</sup> "
             "(v<sub>0</sub>/v<sub>y</sub>)<sup>−1/4</sup>, derived in "
             "<code>reports/restitution.h</code> (the nonlinear counterpart of the paper's "
             "eq. 21). The local slope approaches −1/4 only slowly: see the table.",
         true});

    out.log_step = 1e-3;
    for (double r : {1.5, 3.0, 10.0, 15.0, 30.0, 100.0, 1e3, 1e4}) {
      const double v = r * v_y, h = out.log_step;
      SlopeRow row;
      row.velocity_ratio = r;
      row.e = closed_form_cor(v);
      row.slope_closed_form =
          (std::log(closed_form_cor(v * (1 + h))) - std::log(closed_form_cor(v * (1 - h)))) /
          (std::log1p(h) - std::log1p(-h));
      row.slope_simulated = (std::log(simulated_cor(v * (1 + h), 1e-12)) -
                             std::log(simulated_cor(v * (1 - h), 1e-12))) /
                            (std::log1p(h) - std::log1p(-h));
      row.e_over_asymptote = row.e / undamped_cor_asymptote(r);
      out.slopes.push_back(row);
    }
  }

  // COR against zeta at fixed v0.
  options.say("restitution: COR against zeta (sweep and linearized closed form)");
  {
    const std::vector<double> velocities = {0.1, 1.0, 5.0};
    SweepRequest sweep;
    sweep.base.scene = paper_scene();
    sweep.velocities = velocities;
    sweep.zetas = log_grid(0.01, 10.0, options.quick ? 8 : 30);
    sweep.threads = options.threads;
    const auto points = run_sweep(sweep);
    Plot p;
    p.id = "restitution-cor-zeta";
    p.title = "COR against the damping ratio ζ at fixed v0";
    p.x_label = "damping ratio ζ [-]";
    p.y_label = "coefficient of restitution e [-]";
    p.log_x = true;
    int captured = 0;
    for (double v0 : velocities) {
      Series c = curve("nonlinear, v0 = " + number(v0) + " m/s", Series::Style::linespoints);
      for (const auto& pt : points) {
        if (pt.v0 != v0 || !pt.result.ok()) continue;
        if (pt.result.status == ImpactStatus::captured) ++captured;
        add(c, pt.zeta, pt.result.e);
      }
      p.series.push_back(c);
    }
    for (double v0 : velocities) {
      Series c =
          curve("linearized closed form, v0 = " + number(v0) + " m/s", Series::Style::dashed);
      for (double zeta : log_grid(0.01, 10.0, 120)) {
        Scene s = paper_scene();
        s.velocity = v0;
        s.damping = Damping::ratio(zeta);
        try {
          add(c, zeta, oracles::solve_linear_model(oracles::linear_model_input(s, derive(s))).e);
        } catch (const oracles::LinearizedLawUndefined&) {
          // outside the linearized law's domain: no point (said in the caption)
        }
      }
      if (!c.x.empty()) p.series.push_back(c);
    }
    out.figures.push_back(
        {p,
         "Table 1 scene, elastoplastic law (numerical, odeint-dopri5) and the linearized "
         "closed form (eqs 22-25) at the same ζ. e falls with ζ; strong damping leaves no "
         "rebound (capture, e = 0: " +
             std::to_string(captured) +
             " of the simulated points). The linearized law is undefined at 0.1 m/s and for "
             "the heavily damped impacts whose loading stops below 2.25 z<sub>y</sub>: no "
             "dashed points there."});
  }

  // Thornton beside the model.
  options.say("restitution: Thornton (1997) beside the model");
  {
    Plot p;
    p.id = "restitution-thornton";
    p.title = "Thornton (1997) elastic-perfectly-plastic spheres beside the elastoplastic model";
    p.x_label = "v0/v_y (impact over yield velocity) [-]";
    p.y_label = "coefficient of restitution e [-]";
    p.log_x = p.log_y = true;
    Series thornton = curve("Thornton (1997), r = V_y/V_i");
    Series model = curve("elastoplastic model, closed form (undamped)");
    Series thornton_asym = curve("Thornton asymptote 1.185 r^(1/4)", Series::Style::dashed);
    Series model_asym = curve("model asymptote 1.0819 (v0/v_y)^(-1/4)", Series::Style::dashed);
    for (double r : log_grid(0.5, 1e4, 200)) {
      add(thornton, r, oracles::thornton_cor(1.0 / r));
      add(model, r, r <= 1 ? 1.0 : closed_form_cor(r * v_y));
    }
    for (double r : {10.0, 1e4}) {
      add(thornton_asym, r, oracles::thornton_asymptote(1.0 / r));
      add(model_asym, r, undamped_cor_asymptote(r));
    }
    p.series = {thornton, model, thornton_asym, model_asym};
    out.figures.push_back(
        {p,
         "Both against impact velocity over the velocity at which yield begins. Thornton's "
         "formula (J. Appl. Mech. 64:383, oracles/published.h) models elastic-perfectly-"
         "plastic spheres; the paper's law keeps hardening (slope K<sub>y</sub>) after "
         "yield, so the two share the −1/4 slope but not the coefficient "
         "(1.185 against 1.0819). A published trend beside the model, not a fit."});
  }

  // Hunt-Crossley damping maps.
  options.say("restitution: Hunt-Crossley damping maps");
  {
    Plot p;
    p.id = "restitution-hc-maps";
    p.title = "Hunt-Crossley damping maps mu(e): the COR each delivers against its target";
    p.x_label = "target coefficient of restitution e [-]";
    p.y_label = "delivered coefficient of restitution [-]";
    const auto targets = linear_grid(0.02, 0.98, options.quick ? 25 : 97);
    for (const auto& map : oracles::damping_maps()) {
      Series c = curve(std::string(map.name) + ": " + std::string(map.formula));
      for (double e : targets) add(c, e, oracles::delivered_cor(map, e));
      p.series.push_back(c);
    }
    Series diagonal = curve("delivered = target", Series::Style::dashed);
    add(diagonal, 0.0, 0.0);
    add(diagonal, 1.0, 1.0);
    p.series.push_back(diagonal);
    out.figures.push_back(
        {p,
         "Each map picks μ from a target e; the exact Hunt-Crossley restitution "
         "e = [1 + W<sub>0</sub>(−(1+u<sub>0</sub>) "
         "e<sup>−(1+u<sub>0</sub>)</sup>)]/u<sub>0</sub>, "
         "u<sub>0</sub> = μv<sub>0</sub> (SPEC §2, oracles/hunt_crossley.h), says what it "
         "really delivers, independently of K, m and v<sub>0</sub>. On the diagonal a map "
         "is exact.",
         true});
    out.map_targets = {0.1, 0.3, 0.5, 0.7, 0.9};
    for (const auto& map : oracles::damping_maps()) {
      DampingMapRow row{std::string(map.name), std::string(map.formula), {}};
      for (double e : out.map_targets) row.delivered.push_back(oracles::delivered_cor(map, e));
      out.maps.push_back(row);
    }
  }
  return out;
}

}  // namespace ivv::reports
