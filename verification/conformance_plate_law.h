// A C++ contact law checked on a finite plate: law_under_test<Law> (conformance_law.h) with the
// plate run of solver/plate/plate_law_impact.h, so that run_conformance on a scene with a finite
// plate strikes the plate (verification/conformance.h). Kept apart from conformance_law.h: it
// compiles the plate's driver for the law (seconds and a gigabyte per law), which a law checked
// only against rigid targets should not pay.
//
//   auto law = ivv::conformance::law_under_test_on_plate<MyLaw>(
//       "my-law", "F = ...", [](const ivv::Scene& s) { return MyLaw{...}; });
#pragma once

#include <string>
#include <utility>

#include "solver/plate/plate_law_impact.h"
#include "verification/conformance_law.h"

namespace ivv::conformance {

template <class Law, class MakeLaw>
LawUnderTest law_under_test_on_plate(std::string name, std::string description, MakeLaw make_law) {
  static_assert(!Law::rate_dependent,
                "a rate-dependent law is not modelled on a finite plate (its contact force is "
                "solved at zdot = 0)");
  LawUnderTest t = law_under_test<Law>(std::move(name), std::move(description), make_law);
  t.simulate_plate = [make_law](const Scene& s, const PlateImpactOptions& o) {
    return simulate_plate_impact_of(make_law(s), s, o);
  };
  return t;
}

}  // namespace ivv::conformance
