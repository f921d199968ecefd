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
//   dmt             an adhesive DMT-type law K_h z^{3/2} - F_ad with its declared jump at onset
//                   (expression law, tension allowed), on the shipped scene glass-bead; the same
//                   law with the jump undeclared is rejected
//   jkr             a JKR-type hysteresis: Hertz loading, unloading K_h z^{3/2} - F_ad (1 - z/z_m),
//                   captured in its adhesive well below a speed, e rising with v0 above it
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

// The adhesive examples: the 100 um glass bead of reference_data/scenes/glass-bead.toml with a
// pull-off force F_ad (an illustrative value, the README's; not a measurement).
inline constexpr double kBeadPullOff = 3.1e-5;  // F_ad [N]
Scene glass_bead_scene();                       // the shipped scene, loaded by name
// DMT-type law F = K_h z^{3/2} - F_ad, tension until z = 0, its jump to -F_ad at onset declared
// (`--onset-force=-Fad`) or not; conservative: e = 1 at every v0.
enum class OnsetDeclaration { declared, undeclared };
const ExampleRun& dmt_example(OnsetDeclaration onset);
// JKR-type law: loading K_h z^{3/2}, unloading K_h z^{3/2} - F_ad (1 - z/z_m), tension until
// z = 0, no dashpot, claimed: e = jkr_cor(v0), captured below jkr_capture_speed(), e rising in v0.
const ExampleRun& jkr_example();
// Its COR by energy (exact for this law without a dashpot): loading stores the Hertz energy
// E0 = (2/5) K_h z_m^{5/2} = 1/2 m v0^2, so z_m = (5 m v0^2/(4 K_h))^{2/5}; unloading from z_m to
// z = 0 returns E0 - F_ad z_m/2 (the linear adhesive term's area). Below z_f (F = 0) the force
// pulls, so the speed is least at z = 0: the bead leaves iff E0 > F_ad z_m/2, with
//   e^2 = 1 - F_ad z_m/(2 E0) = 1 - 5 F_ad/(4 F_max),   F_max = K_h z_m^{3/2} [N],
// and is captured (e = 0) below v_c, where 4 F_max(v_c) = 5 F_ad. Scene SI units; e in [0, 1].
double jkr_cor(const Scene& bead, double v0);
double jkr_capture_speed(const Scene& bead);  // v_c [m/s]
// The grid velocities of the JKR example [m/s]: the README's five and two bracketing v_c.
const std::vector<double>& jkr_velocities();

// The check of a report with this id, or nullptr.
const conformance::Check* find_check(const conformance::Report& r, const std::string& id);

}  // namespace ivv::verification
