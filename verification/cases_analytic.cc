// Analytic tier: every integrator against the closed forms of oracles/ (no integration there).
#include "closed_forms/hunt_crossley.h"
#include "closed_forms/linear_model.h"
#include "oracles/hertz.h"
#include "oracles/undamped_elastoplastic.h"
#include "verification/cases.h"
#include "verification/support.h"
#include "verification/tolerances.h"

namespace ivv::verification {
namespace {

std::string name(IntegratorKind k) {
  return std::string(to_string(k));
}

// Hertz, no dashpot: z_m = (5 m v0^2/(4 K_h))^{2/5}, F_max = K_h z_m^{3/2},
// t_f = (4/5) B(2/5, 1/2) z_m / v0, e = 1.
Outcome hertz_undamped(IntegratorKind k) {
  WorstError w;
  for (double mass : {1e-3, 0.5, 10.0}) {
    for (double v0 : {1e-3, 0.1, 3.0}) {
      Scene s = with(paper_scene(), v0, 0.0);
      s.mass = mass;
      const ImpactResult r = simulate(request(s, LawKind::hertz, k));
      const std::string where = "m=" + fmt(mass) + " kg v0=" + fmt(v0) + " m/s";
      if (!r.separated()) {
        w.fail(where + ": " + r.reason);
        continue;
      }
      const auto x = oracles::solve_hertz(mass, derive(s).K_h, v0);
      w.add_cor(r.e, 1.0, where + " e");
      w.add(r.F_max, x.F_max, where + " F_max");
      w.add(r.z_max, x.z_max, where + " z_max");
      w.add(r.t_contact, x.t_contact, where + " t_contact");
    }
  }
  return worst_case(w, default_settings_tolerance(k).value, "e, F_max, z_max, t_contact");
}

// Elastoplastic, no dashpot: the energy closed form (docs/design.md §2) with quadrature contact
// time.
Outcome elastoplastic_undamped(IntegratorKind k) {
  WorstError w;
  const DerivedParameters p = derive(paper_scene());
  for (double ratio : {0.5, 2.0, 10.0, 100.0}) {
    const double v0 = ratio * p.v_yield;
    const Scene s = with(paper_scene(), v0, 0.0);
    const ImpactResult r = simulate(request(s, LawKind::elastoplastic, k));
    const std::string where = "v0=" + fmt(ratio) + " v_y";
    if (!r.separated()) {
      w.fail(where + ": " + r.reason);
      continue;
    }
    const auto x = oracles::solve_undamped_elastoplastic(oracles::elastoplastic_input(s, p));
    w.add_cor(r.e, x.e, where + " e");
    w.add(r.F_max, x.F_max, where + " F_max");
    w.add(r.z_max, x.z_max, where + " z_max");
    w.add(r.t_contact, x.t_contact, where + " t_contact");
    if (x.yielded) w.add(r.z_perm, x.z_perm, where + " z_perm");
  }
  return worst_case(w, default_settings_tolerance(k).value, "e, F_max, z_max, t_contact, z_perm");
}

// Linearized law in every damping regime that rebounds (eqs 22-25, closed form).
Outcome linearized(IntegratorKind k) {
  WorstError w;
  for (double v0 : {1.0, 5.0}) {
    for (double zeta : {0.0, 0.05, 0.1, 0.3}) {
      const Scene s = with(paper_scene(), v0, zeta);
      const ImpactResult r = simulate(request(s, LawKind::linearized, k));
      const std::string where = "v0=" + fmt(v0) + " zeta=" + fmt(zeta);
      if (!r.separated()) {
        w.fail(where + ": " + r.reason);
        continue;
      }
      const auto x =
          closed_forms::solve_linear_model(closed_forms::linear_model_input(s, derive(s)));
      w.add_cor(r.e, x.e, where + " e");
      w.add(r.F_max, x.F_max, where + " F_max");
      w.add(r.z_max, x.z_max, where + " z_max");
      w.add(r.t_contact, x.t_contact, where + " t_contact");
      w.add(r.alpha_max, x.alpha_max, where + " alpha_max");
    }
  }
  return worst_case(w, default_settings_tolerance(k).value,
                    "e, F_max, z_max, t_contact, alpha_max");
}

// Hunt-Crossley: e from the Lambert-W relation, maximum indentation from the energy integral.
Outcome hunt_crossley(IntegratorKind k) {
  WorstError w;
  const Scene s = with(paper_scene(), 1.0, 0.0);
  const DerivedParameters p = derive(s);
  for (double u0 : {0.05, 0.5, 2.0, 5.0}) {
    const ImpactResult r = simulate(request(s, LawKind::hunt_crossley, k, u0 / s.velocity));
    const std::string where = "mu v0=" + fmt(u0);
    if (!r.separated()) {
      w.fail(where + ": " + r.reason);
      continue;
    }
    const auto x = closed_forms::solve_hunt_crossley({p.K_h, u0 / s.velocity, s.mass, s.velocity});
    w.add_cor(r.e, x.e, where + " e");
    w.add(r.z_max, x.x_max, where + " alpha_max");
  }
  return worst_case(w, default_settings_tolerance(k).value, "e and maximum indentation");
}

}  // namespace

void register_analytic_cases(Registry& reg) {
  for (IntegratorKind k : all_integrators()) {
    const Tolerance tol = default_settings_tolerance(k);
    const Cost cost = k == IntegratorKind::mp50 ? Cost::slow : Cost::quick;
    reg.add({"analytic.hertz-undamped." + name(k),
             "Hertz impact without dashpot vs closed form (" + name(k) + ")", Tier::analytic,
             tol.reason, cost, [k] { return hertz_undamped(k); }});
    reg.add({"analytic.elastoplastic-undamped." + name(k),
             "Undamped elastoplastic impact vs energy closed form (" + name(k) + ")",
             Tier::analytic, tol.reason, cost, [k] { return elastoplastic_undamped(k); }});
    reg.add({"analytic.linearized." + name(k),
             "Linearized law, zeta 0-0.3, vs closed form of eqs 22-25 (" + name(k) + ")",
             Tier::analytic, tol.reason, cost, [k] { return linearized(k); }});
    reg.add({"analytic.hunt-crossley." + name(k),
             "Hunt-Crossley COR and indentation vs Lambert-W closed form (" + name(k) + ")",
             Tier::analytic, tol.reason, cost, [k] { return hunt_crossley(k); }});
  }
}

}  // namespace ivv::verification
