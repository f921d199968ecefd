#include "verification/study_restitution.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "oracles/published.h"
#include "oracles/reference_tables.h"
#include "oracles/undamped_elastoplastic.h"
#include "solver/sweep/sweep.h"
#include "verification/study.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The ratios of the report's slope table.
constexpr double kSlopeTableRatios[] = {1.5, 3.0, 10.0, 15.0, 30.0, 100.0, 1e3, 1e4};
constexpr double kSlopeLogStep = 1e-3;

bool same_ratio(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::abs(b);
}

Scene undamped_at(double v0) {
  return with(paper_scene(), v0, 0.0);
}

double closed_form_cor(double v0) {
  const Scene s = undamped_at(v0);
  return oracles::solve_undamped_elastoplastic(oracles::elastoplastic_input(s, derive(s))).e;
}

UndampedCorStudy compute_undamped_cor() {
  UndampedCorStudy st;
  st.v_yield = derive(paper_scene()).v_yield;
  st.log_step = kSlopeLogStep;
  std::vector<double> ratios = {0.5, 0.7};
  for (double r : log_grid(1.0, 1e4, 49)) ratios.push_back(r);
  for (double r : kSlopeTableRatios)
    if (std::none_of(ratios.begin(), ratios.end(), [&](double x) { return same_ratio(x, r); }))
      ratios.push_back(r);
  std::sort(ratios.begin(), ratios.end());
  const double h = st.log_step;
  const double dlog = std::log1p(h) - std::log1p(-h);
  for (double r : ratios) {
    UndampedCorRow row;
    row.ratio = r;
    const double v = r * st.v_yield;
    const std::string at = "undamped impact at " + fmt(r, 6) + " v_y";
    row.e_closed_form = r <= 1.0 ? 1.0 : closed_form_cor(v);
    row.e_simulated = trend_run(undamped_at(v), LawKind::elastoplastic, at).e;
    row.slope_closed_form = row.slope_simulated = kNaN;
    if (r * (1 - h) > 1.0) {
      row.slope_closed_form =
          (std::log(closed_form_cor(v * (1 + h))) - std::log(closed_form_cor(v * (1 - h)))) / dlog;
      const double e_hi = trend_run(undamped_at(v * (1 + h)), LawKind::elastoplastic, at).e;
      const double e_lo = trend_run(undamped_at(v * (1 - h)), LawKind::elastoplastic, at).e;
      row.slope_simulated = (std::log(e_hi) - std::log(e_lo)) / dlog;
    }
    row.e_thornton = oracles::thornton_cor(1.0 / r);
    row.asymptote = undamped_cor_asymptote(r);
    row.thornton_asymptote = oracles::thornton_asymptote(1.0 / r);
    row.tabulated = std::any_of(std::begin(kSlopeTableRatios), std::end(kSlopeTableRatios),
                                [&](double x) { return same_ratio(r, x); });
    st.rows.push_back(row);
  }
  for (double r : log_grid(0.5, 1e4, 200)) {
    st.curve_ratio.push_back(r);
    st.curve_e_closed_form.push_back(r <= 1.0 ? 1.0 : closed_form_cor(r * st.v_yield));
    st.curve_e_thornton.push_back(oracles::thornton_cor(1.0 / r));
  }
  return st;
}

CorMapStudy compute_cor_map() {
  CorMapStudy m;
  const Scene base = paper_scene();
  const double vy = derive(base).v_yield;
  m.ratio = log_grid(1.5, 100.0, 30);
  m.zeta = {0.0, 0.02, 0.04, 0.06, 0.08, 0.1, 0.13, 0.16, 0.2, 0.25};
  m.e.assign(m.zeta.size(), std::vector<double>(m.ratio.size()));
  for (std::size_t j = 0; j < m.zeta.size(); ++j)
    for (std::size_t i = 0; i < m.ratio.size(); ++i)
      m.e[j][i] =
          trend_run(with(base, m.ratio[i] * vy, m.zeta[j]), LawKind::elastoplastic,
                    "grid point v0 = " + fmt(m.ratio[i] * vy) + ", zeta = " + fmt(m.zeta[j]))
              .e;
  return m;
}

CorZetaStudy compute_cor_zeta() {
  CorZetaStudy st;
  st.velocities = {0.1, 1.0, 5.0};
  st.zetas = log_grid(0.01, 10.0, 30);
  st.linear_zetas = log_grid(0.01, 10.0, 120);
  for (double v0 : st.velocities) {
    std::vector<ImpactResult> runs;
    for (double zeta : st.zetas)
      runs.push_back(simulate(request(with(paper_scene(), v0, zeta), LawKind::elastoplastic,
                                      IntegratorKind::odeint_dopri5)));
    st.runs.push_back(std::move(runs));
    std::vector<double> lin;
    for (double zeta : st.linear_zetas) {
      const Scene s = with(paper_scene(), v0, zeta);
      const closed_forms::LinearModelInput in = closed_forms::linear_model_input(s, derive(s));
      // NaN outside the linearized law's domain (a gap in the curve)
      lin.push_back(
          closed_forms::linearized_law_defined(in) ? closed_forms::solve_linear_model(in).e : kNaN);
    }
    st.linear_e.push_back(std::move(lin));
  }
  return st;
}

std::vector<DampingMapCurve> compute_damping_maps() {
  const auto rows = oracles::read_hunt_crossley_map_table(oracles::reference_data_dir() /
                                                          "hunt_crossley_mu_maps.csv");
  const Scene s = with(paper_scene(), 1.0, 0.0);
  std::vector<DampingMapCurve> out;
  for (const auto& map : closed_forms::damping_maps()) {
    DampingMapCurve c;
    c.name = std::string(map.name);
    c.formula = std::string(map.formula);
    for (const auto& row : rows) {
      if (row.model != map.name) continue;
      DampingMapPoint p;
      p.e_target = row.e_target;
      p.mu = map.mu(row.e_target, s.velocity);
      p.e_exact = closed_forms::delivered_cor(map, row.e_target);
      p.e_table = row.e_delivered;
      SimulationRequest req =
          request(s, LawKind::hunt_crossley, IntegratorKind::odeint_dopri5, p.mu);
      req.options.rtol = kTrendRtol;
      req.options.atol = kTrendAtol;
      p.simulated = simulate(req);
      c.points.push_back(p);
    }
    std::sort(c.points.begin(), c.points.end(),
              [](const auto& a, const auto& b) { return a.e_target < b.e_target; });
    for (double e : linear_grid(0.02, 0.98, 97)) {
      c.curve_target.push_back(e);
      c.curve_e_exact.push_back(closed_forms::delivered_cor(map, e));
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

SimulationRequest trend_request(const Scene& s, LawKind law) {
  SimulationRequest r = request(s, law, IntegratorKind::odeint_dopri5);
  r.options.rtol = kTrendRtol;
  r.options.atol = kTrendAtol;
  return r;
}

ImpactResult trend_run(const Scene& s, LawKind law, const std::string& what) {
  const ImpactResult out = simulate(trend_request(s, law));
  if (!out.separated()) throw std::runtime_error(what + " did not separate: " + out.reason);
  return out;
}

double undamped_cor_asymptote(double velocity_ratio) {
  return std::pow(15.0 / 8.0, 1.0 / 8.0) * std::pow(velocity_ratio, -0.25);
}

const UndampedCorRow& UndampedCorStudy::at(double ratio) const {
  for (const auto& row : rows)
    if (same_ratio(row.ratio, ratio)) return row;
  throw std::out_of_range("the undamped COR study has no row at " + fmt(ratio) + " v_y");
}

const UndampedCorStudy& undamped_cor_study() {
  static const Study<UndampedCorStudy> study("undamped COR against v0/v_y", compute_undamped_cor);
  return study.get();
}

const CorMapStudy& cor_map_study() {
  static const Study<CorMapStudy> study("COR map e(v0, zeta)", compute_cor_map);
  return study.get();
}

const CorZetaStudy& cor_zeta_study() {
  static const Study<CorZetaStudy> study("COR against zeta", compute_cor_zeta);
  return study.get();
}

const std::vector<DampingMapCurve>& damping_map_study() {
  static const Study<std::vector<DampingMapCurve>> study("Hunt-Crossley damping maps",
                                                         compute_damping_maps);
  return study.get();
}

}  // namespace ivv::verification
