// Puts Thornton's law (thornton.h) through ivv's conformance checks and prints the verdict:
// what `ivv check-law` prints for an expression law, for a law written in C++. Exit 0 when
// every check passed, 1 otherwise. Copy it with CMakeLists.txt to check a law of your own.
#include <cmath>
#include <iostream>

#include "examples/laws/thornton.h"
#include "oracles/published.h"
#include "verification/conformance_law.h"

int main() {
  // The law on one scene: its constants from the scene (here p_y such that Thornton's yield
  // deformation is the paper's, z_y = 0.68 S_y^2 pi^2 R/E*^2).
  const auto make_law = [](const ivv::Scene& s) {
    const ivv::DerivedParameters p = ivv::derive(s);
    return ivv::examples::ThorntonLaw{p.E_star, p.effective_radius,
                                      std::sqrt(4 * 0.68) * s.yield_strength.value()};
  };
  const auto law = ivv::conformance::law_under_test<ivv::examples::ThorntonLaw>(
      "thornton", "Thornton (1997) elastic-perfectly-plastic", make_law);

  // What the law claims: e -> 1 at low speed, and Thornton's closed-form COR.
  const ivv::Scene scene = ivv::paper_scene();
  const double V_y = make_law(scene).yield_velocity(ivv::derive(scene).effective_mass);
  ivv::conformance::Claims claims;
  claims.elastic_at_low_speed = true;
  claims.expected_cor = [V_y](double v0) { return ivv::oracles::thornton_cor(V_y / v0); };
  claims.expected_cor_text = "Thornton's e(V_y/v0)";

  const ivv::conformance::ConformanceResult result =
      ivv::conformance::run_conformance(law, claims, ivv::conformance::default_grid(scene));
  std::cout << result.full();
  return result.passed() ? 0 : 1;
}
