// DEM benchmark: Chung & Ooi (2011), Granular Matter 13:643-656, "Benchmark tests for
// verifying discrete element modelling codes at particle impact level", normal-impact
// Tests 1 and 2 (provenance: reference_data/chung_ooi_2011.md). The scenes are the shipped
// files reference_data/scenes/chung-ooi-*.toml, loaded by name as a user would run them.
//
// Both tests are elastic (no yield strength, no damping), so the reference is the Hertz
// closed form of docs/design.md §2 with the effective radius and mass (oracles/hertz.h):
//   z_m = (5 m* v0^2/(4 K_h))^{2/5},  F_max = K_h z_m^{3/2},  t_f = 2.9432752 z_m/v0,  e = 1,
// K_h = (4/3) sqrt(R*) E*. Test 1 (two identical free spheres) also checks the body velocities
// after impact: with e = 1, v1 = (m1 - m2) v0/(m1 + m2) and v2 = 2 m1 v0/(m1 + m2) in the
// frame where the target was at rest (identical spheres exchange velocities).
//
// Tier analytic: the reference values are a closed form, not numbers digitised from the paper.
#include <array>
#include <string>

#include "oracles/hertz.h"
#include "verification/cases.h"
#include "verification/study.h"
#include "verification/support.h"
#include "verification/tolerances.h"

namespace ivv::verification {
namespace {

constexpr std::array<DemBenchmarkScene, 4> kChungOoi = {{
    {"chung-ooi-1-glass", "Test 1", "two glass spheres, R = 10 mm, 20 m/s relative"},
    {"chung-ooi-1-limestone", "Test 1", "two limestone spheres, R = 10 mm, 20 m/s relative"},
    {"chung-ooi-2-aluminium", "Test 2", "Al alloy sphere, R = 0.1 m, on a rigid plane, 0.2 m/s"},
    {"chung-ooi-2-magnesium", "Test 2", "Mg alloy sphere, R = 0.1 m, on a rigid plane, 0.2 m/s"},
}};

const DemReference& reference_of(const DemBenchmarkScene& t) {
  for (const auto& ref : chung_ooi_references())
    if (ref.benchmark.scene == t.scene) return ref;
  throw std::logic_error("no Chung & Ooi reference for " + std::string(t.scene));
}

Outcome chung_ooi(const DemBenchmarkScene& t, IntegratorKind k) {
  const DemReference& ref = reference_of(t);
  const Scene& s = ref.scene;
  const ImpactResult r = simulate(request(s, LawKind::hertz, k));
  WorstError w;
  if (!r.separated()) {
    w.fail(std::string(t.scene) + ": " + r.reason);
  } else {
    const oracles::HertzImpact& x = ref.closed_form;
    w.add(r.z_max, x.z_max, "maximum overlap");
    w.add(r.F_max, x.F_max, "peak force");
    w.add(r.t_contact, x.t_contact, "contact time");
    w.add_cor(r.e, x.e, "e");
    if (s.free_target()) {
      const double m1 = s.mass, m2 = *s.target_mass, v0 = s.velocity;
      // both in units of v0 like e (v1 vanishes for identical spheres: no relative error)
      w.add_cor(r.impactor_velocity_after / v0, (m1 - m2) / (m1 + m2), "impactor velocity / v0");
      w.add_cor(r.target_velocity_after / v0, 2 * m1 / (m1 + m2), "target velocity / v0");
    }
  }
  return worst_case(w, default_settings_tolerance(k).value,
                    std::string(t.scene) + ": maximum overlap, peak force, contact time, e" +
                        (s.free_target() ? ", body velocities" : ""));
}

// Test 3, normal component: Hertz with the Tsuji-type damping of DEM codes (docs/design.md §3) set
// for a target e_t, as an expression law, once clamped (F >= 0) and once with tension until z = 0.
// With damping ~ z^{1/4} sqrt(m* E* sqrt(R*)) the normalised equation has neither v0 nor the
// material in it, so the delivered e depends on e_t alone: both materials must give the same e
// (and e_t = 1, no damping, must give e = 1).
constexpr std::array<std::string_view, 2> kTest3 = {"chung-ooi-3-alumina", "chung-ooi-3-cast-iron"};
constexpr std::array<double, 5> kTest3Targets = {0.2, 0.4, 0.6, 0.8, 1.0};
constexpr const char* kTsujiForce =
    "K_h*z^1.5 - 2*sqrt(5/6)*log(et)/sqrt(log(et)^2 + _pi^2)*sqrt(2*E_star*sqrt(R*z)*m)*zdot";

Outcome chung_ooi_test3(bool tension) {
  WorstError w;
  std::string delivered;
  for (double e_t : kTest3Targets) {
    double first = 0;
    for (std::size_t i = 0; i < kTest3.size(); ++i) {
      SimulationRequest req;
      req.scene = load_scene(std::string(kTest3[i]));
      req.law = LawKind::expression;
      req.expression = {kTsujiForce, "", tension};
      req.parameters = {{"et", e_t}};
      const ImpactResult r = simulate(req);
      const std::string where = std::string(kTest3[i]) + " e_t = " + fmt(e_t);
      if (!r.separated()) {
        w.fail(where + ": " + r.reason);
        continue;
      }
      if (i == 0) {
        first = r.e;
        delivered += (delivered.empty() ? "" : ", ") + fmt(e_t) + " -> " + fmt(r.e, 6);
      } else {
        w.add_cor(r.e, first, where + " against " + std::string(kTest3[0]));
      }
      if (e_t == 1.0) w.add_cor(r.e, 1.0, where + " (no damping)");
    }
  }
  Outcome o = worst_case(w, default_settings_tolerance(IntegratorKind::odeint_dopri5).value,
                         "e of both materials, and e = 1 without damping");
  o.detail += "; delivered e for targets " + delivered;
  return o;
}

DemReference compute_reference(const DemBenchmarkScene& t) {
  DemReference ref{t, load_scene(std::string(t.scene)), {}, {}};
  ref.derived = derive(ref.scene);
  ref.closed_form =
      oracles::solve_hertz(ref.derived.effective_mass, ref.derived.K_h, ref.scene.velocity);
  return ref;
}

}  // namespace

const std::vector<DemReference>& chung_ooi_references() {
  static const Study<std::vector<DemReference>> study("Chung & Ooi references", [] {
    std::vector<DemReference> out;
    for (const auto& t : kChungOoi) out.push_back(compute_reference(t));
    return out;
  });
  return study.get();
}

std::span<const DemBenchmarkScene> chung_ooi_scenes() {
  return kChungOoi;
}

void register_dem_cases(Registry& reg) {
  for (const DemBenchmarkScene& t : kChungOoi) {
    for (IntegratorKind k : all_integrators()) {
      const std::string integrator(to_string(k));
      reg.add({"dem." + std::string(t.scene) + "." + integrator,
               "Chung & Ooi (2011) " + std::string(t.test) + ", " + std::string(t.what) +
                   ": Hertz overlap, force, contact time, e = 1 (" + integrator + ")",
               Tier::analytic, default_settings_tolerance(k).reason, Cost::quick,
               [t, k] { return chung_ooi(t, k); }});
    }
  }
  for (bool tension : {false, true}) {
    const std::string mode = tension ? "tension" : "clamped";
    reg.add({"dem.chung-ooi-3.tsuji-" + mode,
             "Chung & Ooi (2011) Test 3 (normal), Tsuji-type damping " + mode +
                 ": the delivered e depends on the target alone, e = 1 undamped",
             Tier::published_trend,
             default_settings_tolerance(IntegratorKind::odeint_dopri5).reason +
                 std::string(" (odeint-dopri5, both materials)"),
             Cost::quick, [tension] { return chung_ooi_test3(tension); }});
  }
}

}  // namespace ivv::verification
