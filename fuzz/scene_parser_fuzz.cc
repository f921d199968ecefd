// Fuzz target: the scene TOML parser (scene/scene.h parse_scene_toml).
// Contract under test (docs/design.md §7): any text is either a valid scene, whose derived parameters
// and scales are finite and positive, or an InputError naming a field; nothing else escapes.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "fuzz/fuzz_targets.h"
#include "scene/input_error.h"
#include "scene/scene.h"

namespace {

void expect(bool ok, const char* what) {
  if (ok) return;
  std::fprintf(stderr, "scene_parser_fuzz: broken postcondition: %s\n", what);
  std::abort();
}

bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const ivv::Scene s = ivv::parse_scene_toml(text, "fuzz.toml");
    const ivv::DerivedParameters p = ivv::derive(s);
    expect(positive(p.E_star) && positive(p.K_h), "E*, K_h finite and > 0");
    if (p.has_yield()) {
      expect(positive(p.z_y) && positive(p.K_y), "z_y, K_y finite and > 0");
      expect(positive(p.omega0) && positive(p.v_yield), "omega0, v_y finite and > 0");
      if (p.has_dashpot()) expect(positive(p.zeta) && positive(p.c), "zeta, c finite and > 0");
    }
    for (ivv::ScaleBasis basis : {ivv::ScaleBasis::hertz, ivv::ScaleBasis::yield}) {
      if (basis == ivv::ScaleBasis::yield && !p.has_yield()) continue;
      const ivv::Scales k = ivv::scales(s, p, basis);
      expect(positive(k.time) && positive(k.length) && positive(k.force) && positive(k.energy),
             "scales finite and > 0");
    }
  } catch (const ivv::InputError& e) {
    expect(!e.field().empty(), "an InputError names its field");
  }
  return 0;
}
