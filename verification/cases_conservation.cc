// Conservation tier: for every run of every integrator, the energy ledger closes, the impulse
// equals m v0 (1 + e), and the Newton, Poisson and energetic CORs agree (frictionless central
// impact). The ledger uses the closed-form loop area W_p and the integrated dashpot work W_v;
// the Poisson and energetic CORs come from the impulse and work quadratures, not from the
// velocity, so each comparison measures integration error.
#include <cmath>

#include "closed_forms/linear_model.h"
#include "verification/cases.h"
#include "verification/support.h"
#include "verification/tolerances.h"

namespace ivv::verification {
namespace {

// The end state's exact parts are products and sums of a few inputs: round-off.
constexpr double kEndStateRoundOff = 1e-14;

std::vector<std::pair<std::string, SimulationRequest>> runs(IntegratorKind k) {
  std::vector<std::pair<std::string, SimulationRequest>> out;
  for (LawKind law : {LawKind::hertz, LawKind::elastoplastic, LawKind::linearized}) {
    for (const GridScene& gs : paper_grid()) {
      if (law == LawKind::linearized && gs.scene.velocity < 0.5) continue;
      out.emplace_back(std::string(to_string(law)) + " " + gs.label, request(gs.scene, law, k));
    }
  }
  for (double u0 : {0.5, 5.0})
    out.emplace_back("hunt-crossley mu v0=" + fmt(u0),
                     request(with(paper_scene(), 1.0, 0.0), LawKind::hunt_crossley, k, u0));
  return out;
}

enum class Check { ledger, impulse, cor_definitions };

Outcome conservation(IntegratorKind k, Check check, double tolerance) {
  double worst = 0.0;
  std::string where = "no run";
  int count = 0;
  for (const auto& [label, req] : runs(k)) {
    const ImpactResult r = simulate(req);
    if (!r.separated())
      return at_most(INFINITY, tolerance, label + " did not separate: " + r.reason);
    double err = 0.0;
    switch (check) {
      case Check::ledger:
        err = std::abs(r.energy.residual) / r.energy.initial;
        break;
      case Check::impulse: {
        const double expected = req.scene.mass * req.scene.velocity * (1 + r.e);
        err = std::abs(r.impulse - expected) / expected;
        break;
      }
      case Check::cor_definitions:
        err = std::max(std::abs(r.e_poisson - r.e), std::abs(r.e_energetic - r.e));
        break;
    }
    ++count;
    if (!(err <= worst)) {
      worst = err;
      where = label;
    }
  }
  static const char* what[] = {"|energy residual| / (m v0^2/2)",
                               "|impulse - m v0 (1 + e)| / (m v0 (1 + e))",
                               "max(|e_Poisson - e|, |e_energetic - e|)"};
  return at_most(worst, tolerance,
                 std::string("largest ") + what[static_cast<int>(check)] + " over " +
                     std::to_string(count) + " runs: " + fmt(worst, 3) + " at " + where);
}

// Captured impacts (no rebound) end at rest relative to the target (capture_end_state.h):
// impulse m* v0, both bodies at the common velocity, dashpot displacement m* v0/c, the spring
// at its permanent set z_f, final kinetic and stored energy 0 with the ledger still closed.
// Scenes: the one that reported snapshot values (paper, v0 = 10 m/s, zeta = 2), a slower one,
// and a free target sphere.
std::vector<std::pair<std::string, Scene>> captured_scenes() {
  Scene free_target = with(paper_scene(), 10.0, 2.0);
  free_target.target_radius = 0.010;
  free_target.target_mass = 1.5;
  return {{"paper v0=10 zeta=2", with(paper_scene(), 10.0, 2.0)},
          {"paper v0=1 zeta=3", with(paper_scene(), 1.0, 3.0)},
          {"free sphere m2=1.5 kg v0=10 zeta=2", free_target}};
}

// The end state's exact parts (products of the inputs; round-off only) and its measured parts
// (z_perm, alpha_max and the dashpot work, from the located z_m and the integrated energy)
// against the reference `ref` (mp50, or the linear model's closed form for the linearized law).
void compare_end_state(WorstError& exact, WorstError& w, const ImpactResult& r,
                       const ImpactResult& ref, const Scene& s, const std::string& where) {
  if (r.status != ImpactStatus::captured) {
    w.fail(where + ": " + std::string(to_string(r.status)) + " (expected captured) " + r.reason);
    return;
  }
  const DerivedParameters p = derive(s);
  const double m = p.effective_mass, v0 = s.velocity, E0 = 0.5 * m * v0 * v0;
  const BodyVelocities common = body_velocities_after(s, 0.0);
  exact.add(r.impulse, m * v0, where + " impulse = m* v0");
  exact.add(r.y_final, m * v0 / p.c, where + " y_final = m* v0/c");
  exact.add(r.alpha_max, r.z_perm + m * v0 / p.c, where + " alpha_max = z_f + m* v0/c");
  exact.add(1.0 + (r.impactor_velocity_after - common.impactor) / v0, 1.0,
            where + " impactor at the common velocity");
  exact.add(1.0 + (r.target_velocity_after - common.target) / v0, 1.0,
            where + " target at the common velocity");
  exact.add(1.0 + (r.energy.final + r.energy.stored) / E0, 1.0,
            where + " final kinetic + stored energy = 0");
  w.add(r.z_perm, ref.z_perm, where + " z_perm");
  w.add(r.alpha_max, ref.alpha_max, where + " alpha_max");
  w.add(1.0 + (r.energy.viscous - ref.energy.viscous) / E0, 1.0, where + " W_v / E0");
  w.add(1.0 + r.energy.residual / E0, 1.0, where + " ledger residual / E0");
}

Outcome captured_end_state(IntegratorKind k) {
  WorstError exact, w;
  for (const auto& [label, scene] : captured_scenes()) {
    const SimulationRequest req = request(scene, LawKind::elastoplastic, k);
    compare_end_state(exact, w, simulate(req), reference(req), scene, label);
    // the linearized law integrated against the linear model's closed form of its limit
    if (scene.velocity < 5.0) continue;  // its domain: z_m >= 2.25 z_y
    const SimulationRequest lin = request(scene, LawKind::linearized, k);
    const DerivedParameters p = derive(scene);
    const closed_forms::LinearModelInput in = closed_forms::linear_model_input(scene, p);
    const closed_forms::LinearImpact L = closed_forms::solve_linear_model(in);
    ImpactResult closed;
    closed.z_perm = L.z_perm;
    closed.alpha_max = L.alpha_max;
    closed.energy.viscous = L.W_v;
    if (!L.captured) {
      w.fail(label + ": the linear model separates (zeta1 = " + fmt(L.zeta_unload) + ")");
      continue;
    }
    exact.add(L.impulse, p.effective_mass * scene.velocity, label + " linear closed form impulse");
    compare_end_state(exact, w, simulate(lin), closed, scene, label + " linearized");
  }
  const Tolerance tol = default_settings_tolerance(k);
  if (exact.value() > kEndStateRoundOff)
    return at_most(exact.value(), kEndStateRoundOff,
                   "an exact part of the end state is off by " + fmt(exact.value(), 3) +
                       " relative at " + exact.where());
  return worst_case(w, tol.value,
                    "z_perm, alpha_max, W_v/E0, ledger residual/E0 against mp50 (linearized law: "
                    "the linear model's closed form); impulse, y_final, bodies' common velocity "
                    "and final energy exact to " +
                        fmt(exact.value(), 3));
}

}  // namespace

void register_conservation_cases(Registry& reg) {
  for (IntegratorKind k :
       {IntegratorKind::dop853, IntegratorKind::rodas4, IntegratorKind::odeint_rosenbrock4,
        IntegratorKind::gsl_msbdf, IntegratorKind::gsl_rk8pd, IntegratorKind::odeint_dopri5,
        IntegratorKind::dp45}) {
    const std::string n(to_string(k));
    reg.add({"conservation.captured-end-state." + n,
             "A captured impact reports its end state: impulse m* v0, common velocity, "
             "final energy 0 (" +
                 n + ")",
             Tier::conservation,
             std::string(default_settings_tolerance(k).reason) +
                 "; the exact parts (m* v0, m* v0/c, the common velocity) to round-off, 1e-14",
             Cost::quick, [k] { return captured_end_state(k); }});
  }
  for (IntegratorKind k : all_integrators()) {
    const Tolerance tol = conservation_tolerance(k);
    const std::string n(to_string(k));
    const Cost cost = k == IntegratorKind::mp50 ? Cost::slow : Cost::quick;
    reg.add({"conservation.energy-ledger." + n,
             "Energy ledger 1/2 m v0^2 = 1/2 m v_f^2 + W_p + W_v closes (" + n + ")",
             Tier::conservation, tol.reason, cost,
             [k, tol] { return conservation(k, Check::ledger, tol.value); }});
    reg.add({"conservation.impulse." + n, "Impulse equals m v0 (1 + e) (" + n + ")",
             Tier::conservation,
             std::string(tol.reason) +
                 "; for Runge-Kutta methods the impulse is a linear invariant and holds to "
                 "round-off, so this mainly checks event bookkeeping",
             cost, [k, tol] { return conservation(k, Check::impulse, tol.value); }});
    reg.add({"conservation.cor-definitions." + n,
             "Newton, Poisson and energetic COR agree (" + n + ")", Tier::conservation, tol.reason,
             cost, [k, tol] { return conservation(k, Check::cor_definitions, tol.value); }});
  }
}

}  // namespace ivv::verification
