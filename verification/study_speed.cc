#include "verification/study_speed.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "oracles/undamped_elastoplastic.h"
#include "verification/study.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

FixedStepConvergenceStudy compute_convergence() {
  FixedStepConvergenceStudy st;
  st.base = request(with(paper_scene(), 1.0, 0.1), LawKind::linearized, IntegratorKind::rk4);
  const std::vector<double> rk4_steps = {0.2, 0.1, 0.05, 0.025, 0.0125, 0.00625};
  const std::vector<double> dp45_steps = {0.1, 0.05, 0.025, 0.0125};
  for (IntegratorKind k : {IntegratorKind::rk4, IntegratorKind::dp45})
    for (EventLocation located : {EventLocation::located, EventLocation::at_step_ends}) {
      SimulationRequest base = st.base;
      base.integrator = k;
      st.runs.push_back(
          measure_convergence(base, k, k == IntegratorKind::rk4 ? rk4_steps : dp45_steps, located));
    }
  return st;
}

Scene paper_at(double v0, Damping damping) {
  Scene s = paper_scene();
  s.velocity = v0;
  s.damping = damping;
  return s;
}

// One hard case: its row (what it is, the reference) and the request every integrator runs.
struct HardCaseSpec {
  HardCaseRow row;
  SimulationRequest req;
};

HardCaseSpec stiff_dashpot_case() {
  SimulationRequest r;
  r.scene = paper_at(1.0, Damping::ratio(1000));
  return {{"stiff dashpot",
           "paper scene, v0 = 1 m/s, ζ = 1000: the dashpot time scale is 1/(2ζ) = "
           "5e-4 in τ, the contact lasts far longer",
           std::numeric_limits<double>::quiet_NaN(),
           "none in closed form: the integrators check each other",
           {}},
          r};
}

HardCaseSpec grazing_case() {
  SimulationRequest r;
  r.scene = paper_at(1e-6, Damping::none());
  return {{"grazing",
           "paper scene, v0 = 1e-6 m/s, no dashpot: a nanometre-scale Hertz impact",
           1.0,
           "Hertz: elastic, e = 1",
           {}},
          r};
}

HardCaseSpec fast_case() {
  SimulationRequest r;
  r.scene = paper_at(100.0, Damping::none());
  const double e =
      oracles::solve_undamped_elastoplastic(oracles::elastoplastic_input(r.scene, derive(r.scene)))
          .e;
  return {{"fast",
           "paper scene, v0 = 100 m/s, no dashpot: deep in the plastic range",
           e,
           "undamped elastoplastic closed form (energy)",
           {}},
          r};
}

// The linearized law at 50 m/s, zeta = 0.6: its unloading damping ratio zeta/gamma exceeds 1,
// so the closed form says capture (the scene of stability.capture.*).
HardCaseSpec capture_case() {
  SimulationRequest r;
  r.scene = paper_at(50.0, Damping::ratio(0.6));
  r.law = LawKind::linearized;
  const auto lin =
      closed_forms::solve_linear_model(closed_forms::linear_model_input(r.scene, derive(r.scene)));
  const std::string zeta1 = "ζ1 = ζ/γ = " + fmt(lin.zeta_unload, 4);
  return {{"capture",
           "linearized law, paper scene, v0 = 50 m/s, ζ = 0.6: " + zeta1 +
               (lin.captured ? " ≥ 1, so the unloading is overdamped: the spring relaxes only "
                               "asymptotically and nothing rebounds"
                             : " < 1: a rebound"),
           lin.e,
           lin.captured ? "linearized closed form: capture, e = 0"
                        : "linearized closed form (eqs 22-25)",
           {}},
          r};
}

HardCaseSpec hunt_crossley_case() {
  SimulationRequest r;
  r.scene = paper_at(1.0, Damping::none());
  r.law = LawKind::hunt_crossley;
  r.parameters["mu"] = 5.0;
  return {{"Hunt-Crossley μv0 = 5",
           "Hunt-Crossley (eq. 27) with K = K_h, μ = 5 s/m, v0 = 1 m/s: μv0 > 1, a "
           "damping force larger than the elastic one",
           closed_forms::hunt_crossley_cor(5.0),
           "exact Hunt-Crossley COR (Lambert W)",
           {}},
          r};
}

// Every hard case on every production integrator (timed: information only, never judged).
std::vector<HardCaseRow> compute_hard_cases() {
  std::vector<HardCaseSpec> specs = {stiff_dashpot_case(), grazing_case(), fast_case(),
                                     capture_case(), hunt_crossley_case()};
  std::vector<HardCaseRow> out;
  for (auto& spec : specs) {
    for (IntegratorKind k : production_integrators()) {
      SimulationRequest r = spec.req;
      r.integrator = k;
      HardCaseCell cell;
      cell.integrator = k;
      const auto start = std::chrono::steady_clock::now();
      cell.result = simulate(r);
      cell.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      spec.row.cells.push_back(cell);
    }
    out.push_back(std::move(spec.row));
  }
  return out;
}

}  // namespace

const ConvergenceStudy& FixedStepConvergenceStudy::of(IntegratorKind k,
                                                      EventLocation events) const {
  const bool located = events == EventLocation::located;
  for (const auto& r : runs)
    if (r.integrator == k && r.events_located == located) return r;
  throw std::out_of_range("no fixed-step convergence run of " + std::string(to_string(k)));
}

const FixedStepConvergenceStudy& fixed_step_convergence_study() {
  static const Study<FixedStepConvergenceStudy> study("fixed-step convergence of rk4 and dp45",
                                                      compute_convergence);
  return study.get();
}

const std::vector<HardCaseRow>& hard_case_study() {
  static const Study<std::vector<HardCaseRow>> study("hard cases, every integrator",
                                                     compute_hard_cases);
  return study.get();
}

namespace {

WorkPrecisionStudies compute_work_precision(bool quick) {
  WorkPrecisionStudies out;
  out.machine = describe_machine();
  WorkPrecisionOptions wp;
  if (quick) {
    wp.rtols = {1e-4, 1e-7, 1e-10};
    wp.rk4_steps = {1e-1, 1e-2, 1e-3};
    wp.min_seconds_per_point = 0.002;
    wp.min_repeats = 1;
  }
  struct Spec {
    const char* id;
    const char* label;
    double zeta;
  };
  for (const Spec& spec :
       {Spec{"paper", "paper scene, v0 = 1 m/s, ζ = 0.1 (elastoplastic)", 0.1},
        Spec{"stiff", "stiff dashpot, v0 = 1 m/s, ζ = 10 (elastoplastic)", 10.0}}) {
    SimulationRequest base;
    base.scene = paper_at(1.0, Damping::ratio(spec.zeta));
    // quick: a 1e-20 reference still resolves the >= 1e-16 errors of double precision
    if (quick) base.options.reference_tolerance = 1e-20;
    out.studies.push_back(measure_work_precision(spec.label, base, wp));
    out.ids.push_back(spec.id);
    if (std::string(spec.id) != "paper") continue;
    out.peers = measure_peers(wp.rtols, out.studies.back().reference, wp.min_seconds_per_point,
                              wp.min_repeats);
    std::vector<SpeedPoint> ivv_points;
    for (const auto& series : out.studies.back().series)
      for (const auto& pt : series.points) {
        SpeedPoint b;
        b.integrator = std::string(to_string(series.integrator));
        b.law = "elastoplastic";
        b.scene = scene_label(1.0, 0.1);
        b.rtol = pt.tolerance;
        b.ok = pt.ok;
        b.err_e = pt.error_e;
        b.err_F = pt.error_F_max;
        b.err_t = pt.error_t_contact;
        b.us_per_impact = pt.seconds_per_impact * 1e6;
        b.rhs_evals = pt.rhs_evaluations;
        ivv_points.push_back(b);
      }
    out.ratios = ratio_table(ivv_points, out.peers);
  }
  return out;
}

}  // namespace

const WorkPrecisionStudies& work_precision_study(bool quick) {
  static const Study<WorkPrecisionStudies> full("work-precision",
                                                [] { return compute_work_precision(false); });
  static const Study<WorkPrecisionStudies> fast("work-precision (quick)",
                                                [] { return compute_work_precision(true); });
  return quick ? fast.get() : full.get();
}

}  // namespace ivv::verification
