#include "verification/study_paper.h"

#include <stdexcept>

#include "solver/sweep/sweep.h"
#include "verification/study.h"
#include "verification/study_restitution.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

constexpr std::size_t kMaxCurvePoints = 1500;  // per series: plenty for a smooth SVG curve

// At most `max_points` of a curve, evenly strided, keeping the first and last point.
std::vector<TrajectoryPoint> thin(const std::vector<TrajectoryPoint>& v, std::size_t max_points) {
  if (v.size() <= max_points || max_points < 2) return v;
  std::vector<TrajectoryPoint> out;
  out.reserve(max_points);
  const double stride = static_cast<double>(v.size() - 1) / static_cast<double>(max_points - 1);
  for (std::size_t i = 0; i < max_points; ++i)
    out.push_back(v[static_cast<std::size_t>(static_cast<double>(i) * stride + 0.5)]);
  return out;
}

PaperRun run(const SimulationRequest& req, std::string label, const std::string& what) {
  PaperRun out;
  out.label = std::move(label);
  out.scene = req.scene;
  out.result = simulate(req, &out.trajectory);
  if (!out.result.ok()) throw std::runtime_error(what + " failed: " + out.result.reason);
  out.trajectory = thin(out.trajectory, kMaxCurvePoints);
  return out;
}

PaperRun run(const Scene& s, std::string label, const std::string& what) {
  return run(trend_request(s), std::move(label), what);
}

LinearizedCurve linearized(const Scene& s) {
  LinearizedCurve out;
  const closed_forms::LinearModelInput in = closed_forms::linear_model_input(s, derive(s));
  try {
    out.solution = closed_forms::solve_linear_model(in);
  } catch (const closed_forms::LinearizedLawUndefined& e) {
    out.z_reached = e.z_max();
    out.z_needed = e.z_min();
    return out;
  }
  out.defined = true;
  const double t_end = out.solution.captured ? 10.0 * out.solution.t_max : out.solution.t_contact;
  constexpr int kSamples = 600;
  for (int i = 0; i <= kSamples; ++i) {
    const double t = t_end * i / kSamples;
    const closed_forms::LinearState st = closed_forms::linear_model_state(in, out.solution, t);
    out.t.push_back(t);
    out.alpha.push_back(st.alpha);
    out.force.push_back(st.F);
  }
  return out;
}

PaperResponse response(double v0) {
  PaperResponse r;
  r.v0 = v0;
  const Scene s = paper_with_dashpot(v0);
  const std::string at = " at v0 = " + fmt(v0) + " m/s";
  r.model = run(s, "nonlinear elastoplastic", "the elastoplastic model" + at);
  r.fit = fit_hunt_crossley(trend_request(s));
  SimulationRequest hc = trend_request(s, LawKind::hunt_crossley);
  hc.scene.damping = Damping::none();
  hc.parameters["K"] = r.fit.K;
  hc.parameters["mu"] = r.fit.mu;
  r.hunt_crossley = run(hc, "Hunt-Crossley fitted", "the fitted Hunt-Crossley run" + at);
  r.linearized = linearized(s);
  return r;
}

PaperStudy compute() {
  PaperStudy st;
  for (double v0 : {0.1, 1.0, 5.0}) st.responses.push_back(response(v0));

  st.yield_strengths = {50.5e6, 101e6, 151.5e6, 202e6, 404e6};
  for (double sy : st.yield_strengths) {
    Scene s = paper_with_dashpot(1.0);
    s.yield_strength = sy;
    const std::string label = "S_y = " + fmt(sy / 1e6, 4) + " MPa";
    st.by_yield_strength.push_back(run(s, label, "Fig 8, " + label));
  }
  st.masses = {0.125, 0.25, 0.5, 1.0, 2.0};
  for (double m : st.masses) {
    Scene s = paper_with_dashpot(1.0);
    s.mass = m;
    const std::string label = "m = " + fmt(m, 4) + " kg";
    st.by_mass.push_back(run(s, label, "Fig 9, " + label));
  }
  st.velocities = {0.1, 0.5, 1.0, 2.0, 5.0};
  for (double v0 : st.velocities) {
    const std::string label = "v0 = " + fmt(v0) + " m/s";
    st.by_velocity.push_back(run(with(paper_scene(), v0, 0.1), label, "Fig 10, " + label));
  }
  st.zetas = {0.0, 0.05, 0.1, 0.2, 0.3, 0.5};
  for (double zeta : st.zetas) {
    const std::string label = zeta == 0 ? std::string("ζ = 0 (no dashpot)") : "ζ = " + fmt(zeta);
    st.by_zeta.push_back(run(with(paper_scene(), 1.0, zeta), label, "Fig 12, zeta = " + fmt(zeta)));
  }

  st.fig14_velocities = log_grid(0.01, 10.0, 40);
  st.fig14_zetas = {0.0, 0.05, 0.1, 0.2, 0.3, 0.5};
  for (double zeta : st.fig14_zetas) {
    std::vector<ImpactResult> row;
    for (double v0 : st.fig14_velocities)
      row.push_back(simulate(trend_request(with(paper_scene(), v0, zeta))));
    st.fig14.push_back(std::move(row));
  }
  return st;
}

}  // namespace

Scene paper_with_dashpot(double v0) {
  Scene s = paper_scene();
  s.velocity = v0;
  s.damping = Damping::coefficient(kPaperDashpot);
  return s;
}

std::vector<const PaperRun*> PaperStudy::damped_runs() const {
  std::vector<const PaperRun*> out;
  for (const auto& r : responses) out.push_back(&r.model);
  for (const auto* family : {&by_yield_strength, &by_mass, &by_velocity, &by_zeta})
    for (const auto& r : *family)
      if (r.scene.damping.kind != Damping::Kind::none) out.push_back(&r);
  return out;
}

const PaperStudy& paper_study() {
  static const Study<PaperStudy> study("paper figures (Figs 2-14)", compute);
  return study.get();
}

}  // namespace ivv::verification
