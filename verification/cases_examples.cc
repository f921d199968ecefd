// The contact-law worked examples (verification/examples.h) as verification cases: each
// example's conformance verdict, and what each published claim delivers.
#include <algorithm>
#include <cmath>

#include "closed_forms/hunt_crossley.h"
#include "solver/simulate.h"
#include "verification/cases.h"
#include "verification/examples.h"
#include "verification/support.h"

namespace ivv::verification {
namespace {

// The checks a law failed, "id: detail; ...", and how many.
std::pair<int, std::string> failures(const conformance::Report& r, const std::string& except = "") {
  int n = 0;
  std::string text;
  for (const auto& c : r.checks)
    if (!c.passed && c.id != except) {
      ++n;
      text += (text.empty() ? "" : "; ") + c.id + ": " + c.detail;
    }
  return {n, text};
}

Outcome all_checks_pass(const ExampleRun& run) {
  const auto [n, text] = failures(run.report);
  return at_most(n, 0, run.report.brief() + (n ? ": " + text : ""));
}

Outcome claimed_cor(const ExampleRun& run) {
  const conformance::Check* c = find_check(run.report, "dynamic.expected_cor");
  if (!c) return at_most(NAN, 0, "the expected-COR check did not run");
  Outcome o = at_most(c->measured, c->tolerance, c->detail);
  o.plots = run.report.plots();
  return o;
}

// Reference tolerance for e of the double-precision reference (dp45 at rtol 1e-13): global
// error <= N rtol = 1e-10 over N <= 1000 steps; 1e-9 leaves a factor 10.
constexpr double kDoubleReference = 1e-9;

// The Kelvin-Voigt example must fail static.onset: its force jumps to c v0 at impact.
Outcome kelvin_voigt_rejected() {
  const ExampleRun& run = kelvin_voigt_example();
  const conformance::Check* onset = find_check(run.report, "static.onset");
  if (!onset) return at_least(NAN, 1e-12, "static.onset did not run");
  Outcome o = at_least(run.report.passed() ? 0.0 : onset->measured, 1e-12,
                       run.report.brief() + "; " + onset->detail);
  return o;
}

// The DMT-type law with its jump at onset left undeclared must fail static.onset: F(0) = -F_ad.
Outcome undeclared_adhesive_jump_rejected() {
  const ExampleRun& run = dmt_example(OnsetDeclaration::undeclared);
  const conformance::Check* onset = find_check(run.report, "static.onset");
  if (!onset) return at_least(NAN, 1e-12, "static.onset did not run");
  return at_least(onset->passed ? 0.0 : onset->measured, 1e-12,
                  run.report.brief() + "; " + onset->detail);
}

// The JKR-type law's captured runs (no dashpot, v0 < v_c) through every integrator of the
// example's grid: each is captured with the bound e <= 0, at the first unloading step. The
// measure: the RHS evaluations of the captured run over those of the same integrator through a
// whole contact of the law's loading curve alone (the expression K_h z^{3/2}, which rebounds at
// the same v0). Deciding at the first unloading step costs about the loading half of that (~0.5);
// running on in the well (before: to max_steps = 2e6 steps) is thousands of times more.
// One glass-bead run of the JKR-type law (or, hertz_only, of its loading curve alone).
ImpactResult bead_run(double v0, IntegratorKind k, bool hertz_only) {
  SimulationRequest req;
  req.scene = glass_bead_scene();
  req.scene.velocity = v0;
  req.law = LawKind::expression;
  if (hertz_only) {
    req.expression.force = "K_h*z^1.5";
  } else {
    req.expression = {
        .force = "K_h*z^1.5", .unload = "K_h*z^1.5 - Fad*(1 - z/zmax)", .allow_tension = true};
    req.parameters = {{"Fad", kBeadPullOff}};
  }
  req.integrator = k;
  return simulate(req);
}

Outcome jkr_captured_in_well() {
  const Scene bead = glass_bead_scene();
  const double v_c = jkr_capture_speed(bead);
  double worst = 0;
  std::string counts, failed;
  for (double v0 : jkr_velocities()) {
    if (v0 >= v_c) continue;
    for (IntegratorKind k : conformance::default_grid(bead).integrators) {
      const ImpactResult captured = bead_run(v0, k, false);
      const ImpactResult hertz = bead_run(v0, k, true);
      const std::string at = std::string(to_string(k)) + " at v0 = " + fmt(v0);
      if (captured.status != ImpactStatus::captured || captured.e_bound != 0.0) {
        failed += "; " + at + ": not captured in the well: " + captured.reason;
        continue;
      }
      if (!hertz.separated()) {
        failed += "; " + at + ": the loading curve alone did not rebound: " + hertz.reason;
        continue;
      }
      const double ratio = double(captured.rhs_evaluations) / double(hertz.rhs_evaluations);
      worst = std::max(worst, ratio);
      counts += (counts.empty() ? "" : ", ") + at + ": " + std::to_string(captured.steps) +
                " steps, " + std::to_string(captured.rhs_evaluations) + " RHS (" +
                std::to_string(hertz.rhs_evaluations) + " for a Hertz contact)";
    }
  }
  if (!failed.empty()) return at_most(NAN, 1.0, failed.substr(2));
  return at_most(worst, 1.0,
                 "captured with e <= 0 at the first unloading step, largest RHS ratio " +
                     fmt(worst, 3) + " (v_c = " + fmt(v_c, 4) + " m/s); " + counts);
}

// Hunt-Crossley with one damping map: ivv's delivered e against the exact Lambert-W value at
// every target COR, and the conformance checks' soundness.
Outcome hunt_crossley_map_delivers(const std::string& name) {
  WorstError w;
  std::string misses;
  int unsound = 0;
  const auto m = *closed_forms::find_damping_map(name);
  for (double e_t : example_target_cors()) {
    const ExampleRun& run = hunt_crossley_map_example(name, e_t);
    unsound += failures(run.report, "dynamic.expected_cor").first;
    const double exact = closed_forms::delivered_cor(m, e_t);
    for (const auto& c : run.report.cor) {
      if (!c.e) {
        w.fail("v0 = " + fmt(c.v0) + ": " + c.status);
        continue;
      }
      w.add_cor(*c.e, exact, "target " + fmt(e_t) + " v0 = " + fmt(c.v0));
    }
    misses +=
        (misses.empty() ? "" : ", ") + std::string("target ") + fmt(e_t) + " -> " + fmt(exact, 5);
  }
  if (unsound) w.fail(std::to_string(unsound) + " soundness check(s) failed");
  Outcome o = worst_case(w, kDoubleReference, "e against the exact COR");
  o.detail += "; the map delivers " + misses;
  return o;
}

// Hertz with Tsuji-type damping, force clamped or tension allowed: e does not depend on v0.
Outcome tsuji_cor_independent_of_v0(bool tension) {
  double spread = 0;
  std::string delivered, failed;
  for (double e_t : example_target_cors()) {
    const ExampleRun& run = tsuji_example(e_t, tension);
    double lo = 2, hi = -1;
    for (const auto& c : run.report.cor) {
      if (!c.e) {
        failed += " v0 = " + fmt(c.v0) + ": " + c.status;
        continue;
      }
      lo = std::min(lo, *c.e);
      hi = std::max(hi, *c.e);
    }
    spread = std::max(spread, hi - lo);
    delivered +=
        (delivered.empty() ? "" : ", ") + std::string("target ") + fmt(e_t) + " -> " + fmt(hi, 6);
  }
  if (!failed.empty()) return at_most(NAN, kDoubleReference, "failed:" + failed);
  return at_most(
      spread, kDoubleReference,
      "largest spread of e over v0 0.01-10 m/s " + fmt(spread) + "; delivered: " + delivered);
}

// The adhesive laws on the shipped glass bead (examples.h: dmt, jkr).
void register_adhesive_example_cases(Registry& reg) {
  reg.add({"examples.dmt.conformance",
           "A DMT-type adhesive law K_h z^{3/2} - F_ad with its declared jump at onset passes "
           "every conformance check on the glass bead",
           Tier::published_trend,
           "each check carries its own tolerance and reason; the case counts the failures (the "
           "grazing runs' integrator-accuracy notes are not failures)",
           Cost::quick, [] { return all_checks_pass(dmt_example(OnsetDeclaration::declared)); }});
  reg.add({"examples.dmt.cor", "The DMT-type law is conservative: e = 1 at every v0, grazing too",
           Tier::conservation,
           "the reference's error of e, ~1e-10 relative to the largest speed, which the well makes "
           "~80 v0 at v0 = 1e-4 m/s: 8e-9; 1e-8",
           Cost::quick, [] { return claimed_cor(dmt_example(OnsetDeclaration::declared)); }});
  reg.add({"examples.dmt.undeclared-jump-rejected",
           "The same DMT-type law without its onset declaration fails static.onset: F(0) = -F_ad",
           Tier::published_trend,
           "the onset force |F(0)| = F_ad is measured in units of F_ref; anything above the 1e-12 "
           "rounding allowance of static.onset is a jump the check must catch",
           Cost::quick, undeclared_adhesive_jump_rejected});
  reg.add({"examples.jkr.conformance",
           "A JKR-type adhesive hysteresis passes every conformance check, its adhesive claims too "
           "(captured below v_c, e rising with v0)",
           Tier::published_trend,
           "each check carries its own tolerance and reason; the case counts the failures",
           Cost::quick, [] { return all_checks_pass(jkr_example()); }});
  reg.add({"examples.jkr.cor",
           "The JKR-type law delivers its energy-balance COR, e^2 = 1 - 5 F_ad/(4 F_max), and "
           "e = 0 (captured) below v_c",
           Tier::analytic,
           "the energy balance is exact for this law: the miss is the reference's error of e "
           "(~1e-10); 1e-9 leaves a factor 10",
           Cost::quick, [] { return claimed_cor(jkr_example()); }});
  reg.add({"examples.jkr.captured-in-well",
           "Below v_c the JKR-type law is captured in its well at the first unloading step, by "
           "every integrator, without a dashpot",
           Tier::stability,
           "RHS evaluations of the captured run over those of a whole Hertz contact at the same "
           "v0 and integrator: deciding at the first unloading step costs about the loading "
           "half (~0.5); above 1 the run went on in the well",
           Cost::quick, jkr_captured_in_well});
}

}  // namespace

void register_example_cases(Registry& reg) {
  reg.add({"examples.thornton.conformance",
           "Thornton's law (C++ example) passes every conformance check", Tier::published_trend,
           "each check carries its own tolerance and reason (verification/conformance.h); the "
           "case counts the checks that failed",
           Cost::quick, [] { return all_checks_pass(thornton_example()); }});
  reg.add({"examples.thornton.cor", "Thornton's law delivers Thornton's (1997) closed-form COR",
           Tier::published_trend,
           "Thornton integrated his law exactly: the miss is the 50-digit reference's error of e "
           "(~1e-12); 1e-9, the default bound of an exact claim, leaves a factor 1000",
           Cost::quick, [] { return claimed_cor(thornton_example()); }});
  reg.add({"examples.kuwabara-kono.conformance",
           "Kuwabara-Kono viscoelastic Hertz (C++ example) passes every conformance check",
           Tier::published_trend,
           "each check carries its own tolerance and reason; the case counts the failures",
           Cost::quick, [] { return all_checks_pass(kuwabara_kono_example()); }});
  reg.add({"examples.kuwabara-kono.cor",
           "Kuwabara-Kono viscoelastic Hertz delivers the Muller-Poschel Pade COR",
           Tier::published_trend,
           "the Pade form is pinned only by the published two-term series; its next term "
           "0.27 v*^5 <= 9e-5 on the grid (v* <= 0.2) bounds its accuracy: 1e-4",
           Cost::quick, [] { return claimed_cor(kuwabara_kono_example()); }});
  reg.add({"examples.kelvin-voigt.rejected",
           "A Kelvin-Voigt law k z + c dz/dt is rejected: its force jumps to c v0 at impact",
           Tier::published_trend,
           "the onset force F(0, v0) = c v0 is measured in units of F_ref; anything above the "
           "1e-12 rounding allowance of static.onset is a discontinuity the check must catch",
           Cost::quick, kelvin_voigt_rejected});
  register_adhesive_example_cases(reg);
  for (const auto& map : closed_forms::damping_maps()) {
    const std::string name(map.name);
    reg.add({"examples.hunt-crossley." + name,
             "Hunt-Crossley with the " + name +
                 " map: ivv's delivered e equals the exact "
                 "Lambert-W value, and the law is sound",
             Tier::published_trend,
             "the reference is dp45 at rtol 1e-13 (expression laws run in double): global "
             "error <= 1e-10 in e, so 1e-9 leaves a factor 10",
             Cost::quick, [name] { return hunt_crossley_map_delivers(name); }});
  }
  for (bool tension : {false, true}) {
    const std::string mode = tension ? "tension" : "clamped";
    reg.add({"examples.tsuji." + mode,
             "Hertz with Tsuji-type damping (" + mode + "): the COR is independent of v0",
             Tier::published_trend,
             "with damping ~ z^{1/4} sqrt(m E* sqrt(R)) the normalised equation has no v0 in it, "
             "so e(v0) is constant; the double reference's error (<= 1e-10) gives 1e-9",
             Cost::quick, [tension] { return tsuji_cor_independent_of_v0(tension); }});
  }
}

}  // namespace ivv::verification
