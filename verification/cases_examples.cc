// The contact-law worked examples (verification/examples.h) as verification cases: each
// example's conformance verdict, and what each published claim delivers.
#include <algorithm>
#include <cmath>

#include "closed_forms/hunt_crossley.h"
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
