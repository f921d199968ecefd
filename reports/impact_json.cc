#include "reports/impact_json.h"

#include <cmath>
#include <optional>
#include <sstream>

#include "solver/infinite_plate_check.h"
#include "solver/plate/plate_modes.h"

namespace ivv {

nlohmann::json result_json(const ImpactResult& r) {
  nlohmann::json events = nlohmann::json::array();
  for (const auto& ev : r.events) {
    events.push_back({{"kind", to_string(ev.kind)},
                      {"t", ev.t},
                      {"z", ev.z},
                      {"alpha", ev.alpha},
                      {"force", ev.force}});
  }
  // A failed run has no outcome: its numbers are null, never a plausible 0.
  // What happened before the failure stays: the steps, the evaluations, the events located.
  const bool failed = !r.ok();
  auto value = [failed](double v) { return failed ? nlohmann::json(nullptr) : nlohmann::json(v); };
  nlohmann::json j = {
      {"status", to_string(r.status)},
      {"separated", r.separated()},
      {"e", value(r.e)},
      {"e_poisson", value(r.e_poisson)},
      {"e_energetic", value(r.e_energetic)},
      {"F_max", value(r.F_max)},
      {"t_F_max", value(r.t_F_max)},
      {"z_max", value(r.z_max)},
      {"t_z_max", value(r.t_z_max)},
      {"alpha_max", value(r.alpha_max)},
      {"t_alpha_max", value(r.t_alpha_max)},
      {"z_perm", value(r.z_perm)},
      {"y_final", value(r.y_final)},
      {"t_contact", value(r.t_contact)},
      {"rebound_velocity", value(r.rebound_velocity)},
      // frame: the target at rest before impact; positive towards the target
      {"bodies",
       {{"impactor_velocity_after", value(r.impactor_velocity_after)},
        {"target_velocity_after", value(r.target_velocity_after)}}},
      {"impulse", value(r.impulse)},
      {"impulse_compression", value(r.impulse_compression)},
      {"energy",
       {{"initial", r.energy.initial},
        {"final", value(r.energy.final)},
        {"stored", value(r.energy.stored)},
        {"plastic", value(r.energy.plastic)},
        {"viscous", value(r.energy.viscous)},
        {"residual", value(r.energy.residual)},
        {"plastic_integrated", r.energy.plastic_integrated}}},
      {"steps", r.steps},
      {"rhs_evaluations", r.rhs_evaluations},
      {"events", events},
  };
  if (!r.reason.empty()) j["reason"] = r.reason;
  if (r.failure != FailureKind::none) j["failure"] = to_string(r.failure);
  if (r.status == ImpactStatus::captured) {
    // the end state (solver/driver/capture_end_state.h): the contact never ends, so t_contact (and
    // t_alpha_max when the impactor never turned back) is infinite, null here; when capture
    // was established is t_capture, an "at capture" time
    j["e_bound"] = r.e_bound;
    j["t_capture"] = r.t_capture;
    j["contact_ends"] = false;
    if (!std::isfinite(r.t_contact)) j["t_contact"] = nullptr;
    if (!std::isfinite(r.t_alpha_max)) j["t_alpha_max"] = nullptr;
  }
  return j;
}

nlohmann::json law_json(const SimulationRequest& req) {
  const LawInfo& info = law_info(req.law);
  nlohmann::json j = {{"law_summary", info.summary}};
  // every parameter in use: given, or its default (from the scene where the spec says so)
  nlohmann::json params = req.parameters;
  if (req.law != LawKind::expression) {
    const DerivedParameters p = derive(req.scene);
    for (const ParameterSpec& spec : info.parameters)
      params[std::string(spec.name)] = parameter_value(req.parameters, spec, p);
  }
  j["parameters"] = params.is_null() ? nlohmann::json::object() : params;
  if (req.law == LawKind::expression) {
    j["force"] = req.expression.force;
    if (!req.expression.unload.empty()) j["unload"] = req.expression.unload;
    j["allow_tension"] = req.expression.allow_tension;
  }
  return j;
}

nlohmann::json simulation_json(const SimulationRequest& req, const ImpactResult& r) {
  const DerivedParameters p = derive(req.scene);
  nlohmann::json request = {{"law", to_string(req.law)},
                            {"integrator", to_string(req.integrator)},
                            {"rtol", req.options.rtol},
                            {"atol", req.options.atol}};
  if (traits(req.integrator).fixed_step) request["dt"] = req.options.fixed_dt();
  const nlohmann::json law = law_json(req);  // named: items() of a temporary would dangle
  for (const auto& [key, value] : law.items()) request[key] = value;
  if (req.law == LawKind::hunt_crossley) {  // the names of the contract (docs/design.md §5)
    request["hc_k"] = request["parameters"]["K"];
    request["hc_mu"] = request["parameters"]["mu"];
  }
  nlohmann::json j = {
      {"scene", scene_json(req.scene, p)}, {"request", request}, {"result", result_json(r)}};
  // where the scene's idealisation stops (solver/infinite_plate_check.h): absent when none
  if (auto w = infinite_plate_warnings(req.scene, r); !w.empty()) j["warnings"] = w;
  return j;
}

nlohmann::json model_choice_json(const ModelChoice& c, ModelKind model) {
  return {{"model", to_string(model)},
          {"route", to_string(c.decision.route)},
          {"law", c.law},
          {"integrator", c.integrator},
          {"reasons", c.reasons},
          {"estimated_error", c.estimated_error}};
}

nlohmann::json simulation_json(const SimulationRun& run) {
  nlohmann::json j = simulation_json(run.request, run.result);
  if (run.choice) j["model_choice"] = model_choice_json(*run.choice, run.request.model);
  return j;
}

namespace {

nlohmann::json plate_result_json(const PlateImpactResult& r) {
  auto value = [&r](double v) { return r.ok ? finite_or_null(v) : nlohmann::json(nullptr); };
  nlohmann::json contacts = nlohmann::json::array();
  for (const PlateContact& c : r.contacts)
    contacts.push_back({{"t_start", c.t_start},
                        {"t_end", c.t_end},
                        {"impulse", c.impulse},
                        {"peak_force", c.peak_force},
                        {"velocity_end", c.velocity_end}});
  return {
      {"ok", r.ok},
      {"reason", r.reason},
      {"e", value(r.e)},
      {"e_first", value(r.e_first)},
      {"F_max", value(r.F_max)},
      {"t_contact", value(r.t_contact)},
      {"t_contact_is", "the first contact's duration"},
      {"z_max", value(r.z_max)},
      {"impulse", value(r.impulse)},
      {"contact_count", r.contacts.size()},
      {"contacts", contacts},
      {"mode_count", r.mode_count},
      {"omega_cut", finite_or_null(r.omega_cut)},
      {"static_compliance", finite_or_null(r.static_compliance)},
      {"residual_compliance", finite_or_null(r.residual_compliance)},
      {"excursion_bound", value(r.excursion_bound)},
      {"t_end", value(r.t_end)},
      {"compression_maxima", r.compression_maxima},
      {"reloads", r.reloads},
      {"energy",
       {{"initial", r.energy.initial},
        {"kinetic", value(r.energy.kinetic)},
        {"plate", value(r.energy.plate)},
        {"plastic", value(r.energy.plastic)},
        {"ledger_max_error", r.energy.max_error},
        {"ledger_checks", r.energy.checks}}},
      {"steps", r.steps},
      {"free_flight_steps", r.free_flight_steps},
      {"rhs_evaluations", r.rhs_evaluations},
  };
}

nlohmann::json plate_model_json(const PlateModelOutcome& m) {
  return {{"model", std::string(to_string(m.model))},
          {"ok", m.ok},
          {"reason", m.reason},
          {"e", finite_or_null(m.e)},
          {"F_max", finite_or_null(m.F_max)},
          {"t_contact", finite_or_null(m.t_contact)},
          {"error", finite_or_null(m.error)},
          {"error_e", finite_or_null(m.error_e)},
          {"error_F_max", finite_or_null(m.error_F)},
          {"rhs_evaluations", m.rhs_evaluations}};
}

// The model the request was answered with, and the regime (solver/plate/plate_regime.h).
nlohmann::json plate_model_choice_json(const PlateRun& run) {
  const PlateRegime& g = *run.regime;
  const PlateModelOutcome& a = *run.answer();
  nlohmann::json models = nlohmann::json::array();
  for (const PlateModelOutcome& m : g.models) models.push_back(plate_model_json(m));
  return {{"requested", run.forced ? std::string(to_string(*run.forced)) : "auto"},
          {"model", std::string(to_string(a.model))},
          {"regime", g.regime},
          {"tolerance", g.tolerance},
          {"e", finite_or_null(a.e)},
          {"F_max", finite_or_null(a.F_max)},
          {"t_contact", finite_or_null(a.t_contact)},
          {"estimated_error", finite_or_null(run.estimated_error())},
          {"error_is",
           "the answer's measured distance from the full plate (max of |de| in units of v0 and "
           "|dF_max|/F_max) plus the full plate's truncation error"},
          {"reasons", g.reasons},
          {"models", models}};
}

}  // namespace

nlohmann::json plate_regime_json(const PlateRegime& g) {
  return {{"mass_ratio", finite_or_null(g.mass_ratio)},
          {"wave_return_time", finite_or_null(g.wave_return_time)},
          {"contact_time", finite_or_null(g.contact_time)},
          {"relative_stiffness", finite_or_null(g.relative_stiffness)},
          {"zeta_plate", finite_or_null(g.zeta_plate)},
          {"c_plate", finite_or_null(g.c_plate)},
          {"zener_lambda", finite_or_null(g.zener_lambda)},
          {"regime", g.regime},
          {"olsson_mass_criterion", g.olsson}};
}

nlohmann::json plate_simulation_json(const PlateRun& run) {
  const Scene& s = run.scene;
  const FinitePlate plate =
      finite_plate(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio);
  return {
      {"scene", scene_json(s, derive(s))},
      {"model", "finite-plate"},
      {"law", std::string(to_string(run.law))},
      // the law's parameters in use, and an expression law's force and unloading expressions
      {"law_details", law_json(run.law_request())},
      {"plate",
       {{"length_x", plate.length_x},
        {"length_y", plate.length_y},
        {"impact_x", plate.impact_x},
        {"impact_y", plate.impact_y},
        {"D11", plate.bending.D11},
        {"D22", plate.bending.D22},
        {"D12", plate.bending.D12},
        {"D66", plate.bending.D66},
        {"mass", plate.mass()},
        {"mass_ratio", s.mass / plate.mass()},
        // 2 d_edge/c_g at omega = pi/t_contact (solver/plate/plate_modes.h), against t_contact
        {"wave_return_time", run.result.ok
                                 ? nlohmann::json(flexural_return_time(plate, run.result.t_contact))
                                 : nlohmann::json(nullptr)}}},
      {"options",
       {{"stepper", plate_stepper_name(run.options.stepper)},
        {"rtol", run.options.rtol},
        {"atol", run.options.atol},
        {"truncation_tol", run.options.truncation_tol}}},
      {"truncation",
       {{"mode_count", run.result.mode_count},
        {"cutoff", finite_or_null(run.result.cutoff)},
        {"omega_cut", finite_or_null(run.result.omega_cut)},
        {"coarser_cutoff", finite_or_null(run.result.cutoff_coarser)},
        {"e_at_coarser_cutoff", finite_or_null(run.e_half_cutoff)},
        {"estimated_error_e", finite_or_null(run.truncation_error)},
        {"tolerance", run.options.truncation_tol},
        {"runs", run.result.cutoff_runs},
        // the modes above the cut-off ([structure] dropped_modes): "static-compliance",
        // "oscillator" or "truncated"
        {"dropped_modes", std::string(dropped_modes_name(run.result.dropped))},
        // the order p of the rule below, that of the dropped modes' treatment
        {"order", truncation_order(run.result.dropped)},
        {"rule",
         "modes with omega <= cutoff * max(1/T, sqrt(k_H 4/(rho h a b))) kept, the rest as "
         "dropped_modes says (by default the static compliance C_res in series; the oscillator "
         "also matches their second moment); error of e estimated from two cut-offs c' < c as "
         "1.25 |e(c) - e(c')|/((c/c')^p - 1), p = order, the observed order of e in the cut-off "
         "with that treatment (3 static compliance, 4 oscillator, 1 truncated), 1.25 Roache's "
         "safety factor; the cut-off raised from 40 until that estimate is within the "
         "tolerance"}}},
      {"result", plate_result_json(run.result)},
      {"regime", run.regime ? plate_regime_json(*run.regime) : nlohmann::json(nullptr)},
      {"model_choice", run.regime ? plate_model_choice_json(run) : nlohmann::json(nullptr)},
  };
}

}  // namespace ivv
