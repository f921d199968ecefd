// Conservation tier: for every run of every integrator, the energy ledger closes, the impulse
// equals m v0 (1 + e), and the Newton, Poisson and energetic CORs agree (frictionless central
// impact). The ledger uses the closed-form loop area W_p and the integrated dashpot work W_v;
// the Poisson and energetic CORs come from the impulse and work quadratures, not from the
// velocity, so each comparison measures integration error.
#include <cmath>

#include "verification/cases.h"
#include "verification/support.h"
#include "verification/tolerances.h"

namespace ivv::verification {
namespace {

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

}  // namespace

void register_conservation_cases(Registry& reg) {
  for (IntegratorKind k : all_integrators()) {
    const Tolerance tol = conservation_tolerance(k);
    const std::string n(to_string(k));
    const bool slow = k == IntegratorKind::mp50;
    reg.add({"conservation.energy-ledger." + n,
             "Energy ledger 1/2 m v0^2 = 1/2 m v_f^2 + W_p + W_v closes (" + n + ")",
             Tier::conservation, tol.reason, slow,
             [k, tol] { return conservation(k, Check::ledger, tol.value); }});
    reg.add({"conservation.impulse." + n, "Impulse equals m v0 (1 + e) (" + n + ")",
             Tier::conservation,
             std::string(tol.reason) +
                 "; for Runge-Kutta methods the impulse is a linear invariant and holds to "
                 "round-off, so this mainly checks event bookkeeping",
             slow, [k, tol] { return conservation(k, Check::impulse, tol.value); }});
    reg.add({"conservation.cor-definitions." + n,
             "Newton, Poisson and energetic COR agree (" + n + ")", Tier::conservation, tol.reason,
             slow, [k, tol] { return conservation(k, Check::cor_definitions, tol.value); }});
  }
}

}  // namespace ivv::verification
