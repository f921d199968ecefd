#include "solver/plate/plate_regime.h"

#include <cmath>
#include <stdexcept>

#include "scene/input_error.h"
#include "solver/format.h"
#include "solver/plate/plate_law.h"
#include "solver/plate/plate_modes.h"
#include "solver/request_options.h"
#include "solver/simulate.h"

namespace ivv {
namespace {

constexpr PlateModel kModels[] = {PlateModel::half_space, PlateModel::infinite_plate,
                                  PlateModel::quasi_static, PlateModel::full};

FinitePlate plate_of(const Scene& s) {
  return finite_plate(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio);
}

// A model of the ODE family (half-space, infinite plate), as `simulate --model auto` runs it.
PlateModelOutcome run_ode_model(PlateModel model, Scene scene, const PlateImpactSpec& run) {
  SimulationRequest req;
  req.scene = std::move(scene);
  req.law = run.law;
  req.parameters = run.parameters;
  if (run.expression) req.expression = *run.expression;
  req.auto_integrator = true;
  req.model = ModelKind::automatic;
  req.options.rtol = run.options.rtol;
  req.options.atol = run.options.atol;
  const SimulationRun r = run_simulation(std::move(req));
  PlateModelOutcome out;
  out.model = model;
  out.ok = r.result.ok();
  out.reason = r.result.reason;
  out.e = r.result.e;
  out.F_max = r.result.F_max;
  out.t_contact = r.result.t_contact;
  out.z_max = r.result.z_max;
  out.rhs_evaluations = r.result.rhs_evaluations;
  return out;
}

// A run of the plate driver (the quasi-static model, or the full plate) as a model's outcome.
PlateModelOutcome outcome_of(PlateModel model, const PlateImpactResult& r) {
  PlateModelOutcome out;
  out.model = model;
  out.ok = r.ok;
  out.reason = r.reason;
  out.e = r.e;
  out.F_max = r.F_max;
  out.t_contact = r.t_contact;
  out.z_max = r.z_max;
  out.rhs_evaluations = r.rhs_evaluations;
  return out;
}

// No mode kept: the plate static, C_res = C_static.
PlateModelOutcome run_quasi_static(const PlateImpactSpec& run) {
  PlateImpactOptions opt = run.options;
  opt.cutoff = 0.0;
  SimulationRequest law;
  law.scene = run.scene;
  law.law = run.law;
  law.parameters = run.parameters;
  if (run.expression) law.expression = *run.expression;
  return outcome_of(PlateModel::quasi_static, simulate_plate_law(law, opt));
}

void measure_against(PlateModelOutcome& m, const PlateImpactResult& full) {
  if (!m.ok) return;  // error stays NaN: never within tolerance
  m.error_e = std::abs(m.e - full.e);
  m.error_F = std::abs(m.F_max / full.F_max - 1.0);
  m.error = std::max(m.error_e, m.error_F);
}

void explain(PlateRegime& g) {
  for (const PlateModelOutcome& m : g.models) {
    if (m.model == PlateModel::full) continue;
    std::string line = std::string(to_string(m.model)) + ": ";
    if (!m.ok)
      line += "failed (" + m.reason + ")";
    else
      line += "e " + fmt(m.e, 2) + ", F_max " + fmt(m.F_max, 2) +
              " N; error against the full plate " + fmt(m.error, 2) +
              (m.error <= g.tolerance ? " <= " : " > ") + "tolerance " + fmt(g.tolerance, 2);
    g.reasons.push_back(line);
  }
  g.reasons.push_back("regime " + g.regime + ": the cheapest model within tolerance" +
                      (g.regime == "plate-dynamics" ? " is the full plate" : ""));
  g.reasons.push_back("for comparison, Olsson's mass criterion (mass ratio " +
                      fmt(g.mass_ratio, 2) + "): " + g.olsson);
}

}  // namespace

std::string_view to_string(PlateModel m) {
  switch (m) {
    case PlateModel::half_space:
      return "half-space";
    case PlateModel::infinite_plate:
      return "infinite-plate";
    case PlateModel::quasi_static:
      return "quasi-static";
    case PlateModel::full:
      return "full";
  }
  return "?";
}

std::optional<PlateModel> parse_plate_model(const std::string& name) {
  if (name == "auto") return std::nullopt;
  for (PlateModel m : kModels)
    if (name == to_string(m)) return m;
  throw InputError("--model", "'" + name +
                                  "' for a finite plate; accepted: auto, full, half-space, "
                                  "infinite-plate, quasi-static");
}

Scene half_space_scene(const Scene& finite) {
  Scene s = finite;
  s.damping = Damping::none();
  return s;
}

Scene infinite_plate_scene(const Scene& finite) {
  Scene s = finite;
  Structure& st = s.damping.structure;
  if (st.bending) st.bending_stiffness = olsson_bending_stiffness(*st.bending);
  st.bending.reset();
  st.length_x.reset();
  st.length_y.reset();
  st.edges.reset();
  st.impact_x.reset();
  st.impact_y.reset();
  st.dropped_modes.reset();  // the infinite plate has no modes to drop
  return s;
}

const PlateModelOutcome& PlateRegime::outcome(PlateModel m) const {
  for (const PlateModelOutcome& o : models)
    if (o.model == m) return o;
  throw std::logic_error("PlateRegime::outcome: model not run");
}

PlateModel PlateRegime::cheapest_within(double t) const {
  for (const PlateModelOutcome& o : models)
    if (o.model != PlateModel::full && o.ok && o.error <= t) return o.model;
  return PlateModel::full;
}

PlateModel PlateRegime::chosen() const {
  return cheapest_within(tolerance);
}

std::string PlateRegime::regime_at(double other_tolerance) const {
  const PlateModel m = cheapest_within(other_tolerance);
  return m == PlateModel::full ? "plate-dynamics" : std::string(to_string(m));
}

std::string olsson_mass_class(double mass_ratio) {
  if (mass_ratio < 0.23) return "small-mass (wave-controlled) impact, mass ratio < 0.23";
  if (mass_ratio > 2.0) return "large-mass (quasi-static) impact, mass ratio > 2";
  return "intermediate, 0.23 <= mass ratio <= 2";
}

PlateRegime plate_regime(const PlateImpactSpec& run, const PlateImpactResult& full,
                         double tolerance) {
  if (!full.ok) throw std::logic_error("plate_regime: the full plate run failed");
  PlateRegime g;
  g.tolerance = tolerance;
  const FinitePlate plate = plate_of(run.scene);
  const DerivedParameters p = derive(run.scene);
  g.mass_ratio = run.scene.mass / plate.mass();
  g.contact_time = full.t_contact;
  g.wave_return_time = flexural_return_time(plate, full.t_contact);
  g.c_plate =
      plate_dashpot(plate.density, plate.thickness, olsson_bending_stiffness(plate.bending));
  g.zeta_plate = std::sqrt(p.effective_mass * p.K_y) / (2.0 * g.c_plate);
  g.zener_lambda = std::pow(p.effective_mass, 0.6) * std::pow(p.K_h, 0.4) *
                   std::pow(run.scene.velocity, 0.2) / g.c_plate;

  g.models.push_back(run_ode_model(PlateModel::half_space, half_space_scene(run.scene), run));
  g.models.push_back(
      run_ode_model(PlateModel::infinite_plate, infinite_plate_scene(run.scene), run));
  g.models.push_back(run_quasi_static(run));
  g.models.push_back(outcome_of(PlateModel::full, full));
  for (PlateModelOutcome& m : g.models)
    if (m.model != PlateModel::full) measure_against(m, full);

  if (const PlateModelOutcome& hs = g.outcome(PlateModel::half_space); hs.ok)
    g.relative_stiffness = hs.F_max / hs.z_max * full.static_compliance;
  g.regime = g.regime_at(tolerance);
  g.olsson = olsson_mass_class(g.mass_ratio);
  explain(g);
  return g;
}

}  // namespace ivv
