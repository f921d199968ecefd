// The contact-law worked examples (examples/, docs/design.md §3: the law author's workflow), run
// through the conformance checks. The verification cases (cases_examples.cc) and the report's
// worked-examples section read the same memoised results, so the two cannot disagree.
//
//   thornton        Thornton (1997) elastic-perfectly-plastic law (C++, examples/laws/thornton.h)
//                   against Thornton's closed-form COR
//   kuwabara-kono   viscoelastic Hertz (C++, examples/laws/kuwabara_kono.h) against the Pade COR
//   kelvin-voigt    F = k z + c dz/dt (expression law): rejected, F(0) != 0 at impact
//   hunt-crossley   F = K_h z^{3/2} (1 + mu dz/dt) with each published mu(e) map as the claim
//   tsuji           Hertz with the Tsuji-type damping of DEM codes, clamped and with tension
#pragma once

#include <string>
#include <vector>

#include "verification/conformance.h"

namespace ivv::verification {

// Target CORs for which the Hunt-Crossley maps and the Tsuji damping are put to the test.
const std::vector<double>& example_target_cors();

// One conformance run of a worked example (memoised, thread-safe; computed on first use).
struct ExampleRun {
  std::string id;       // e.g. "thornton", "hunt-crossley/lankarani-nikravesh/e=0.5"
  std::string title;    // for people
  std::string command;  // the equivalent `ivv check-law` command line, when there is one
  conformance::Report report;
  double target = 0.0;  // the claimed COR, for the map and Tsuji examples (0 otherwise)
};

const ExampleRun& thornton_example();
const ExampleRun& kuwabara_kono_example();
const ExampleRun& kelvin_voigt_example();
// Hunt-Crossley with the named map of closed_forms::damping_maps() at target COR e_t.
const ExampleRun& hunt_crossley_map_example(const std::string& map, double e_t);
// Tsuji-type damping at target e_t, clamped (F >= 0) or with tension until z = 0.
const ExampleRun& tsuji_example(double e_t, bool tension);

// The check of a report with this id, or nullptr.
const conformance::Check* find_check(const conformance::Report& r, const std::string& id);

}  // namespace ivv::verification
