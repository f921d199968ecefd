// Runs the law on a scene (default: the paper's; or a scene file or shipped scene name) over
// impact velocities from 0.1 to 10 m/s and prints the COR it delivers against its target.
// Exit 1 when an impact fails or misses the target by more than 1e-6 (100x the integration
// error of e at the default rtol 1e-10, as ivv's conformance checks allow).
#include <cmath>
#include <cstdio>
#include <string>

#include "restitution_law.h"
#include "scene/scene.h"
#include "solver/simulate_law.h"

int main(int argc, char** argv) {
  ivv::Scene scene = argc > 1 ? ivv::load_scene(argv[1]) : ivv::paper_scene();
  const downstream::RestitutionHertz law{ivv::derive(scene).K_h, 0.7};
  int misses = 0;
  for (double v0 : {0.1, 1.0, 10.0}) {
    scene.velocity = v0;
    const ivv::ImpactResult r = ivv::simulate(law, scene);
    const bool ok = r.ok() && std::abs(r.e - law.e) <= 1e-6;
    std::printf("v0 = %5.1f m/s   e = %.9f   target %.1f   %s\n", v0, r.e, law.e,
                ok ? "ok" : r.reason.c_str());
    misses += ok ? 0 : 1;
  }
  return misses == 0 ? 0 : 1;
}
