// simulate() for any contact law: the public entry point of a law author's C++ code.
//
//   struct MyLaw { ... };                        // models ivv::ContactLaw (solver/laws/law.h)
//   ivv::ImpactResult r = ivv::simulate(MyLaw{...}, ivv::paper_scene());
//
// The law is a template parameter all the way into the right-hand side (no virtual call per
// evaluation). A law whose members are templates on the scalar also runs in the 50-digit
// reference (IntegratorKind::mp50); one that is not gets a failed result that says so.
// Including this header compiles every integrator for the law: expect a few seconds per law.
#pragma once

#include <type_traits>
#include <vector>

#include "scene/input_error.h"
#include "solver/simulate_impl.h"
#include "solver/steppers/integrator_list.h"

namespace ivv {

// Stops compilation, naming the member, unless Law models ContactLaw on double and, when its
// members are templates on the scalar, on the 50-digit scalar of the reference too.
template <class Law>
constexpr bool assert_contact_law_everywhere() {
  static_assert(assert_contact_law<Law, double>());
  if constexpr (law_templated_on<Law, mp50>) static_assert(assert_contact_law<Law, mp50>());
  return true;
}

// Validates the scene and options (InputError naming the field) and runs one impact of `law`.
// Failures of the integration or of the law's domain come back in the result's status/reason.
// A type that does not model ContactLaw is a compile error naming the member at fault.
template <class Law>
requires(!std::is_convertible_v<const Law&, const SimulationRequest&> &&
         !std::is_convertible_v<const Law&, const ValidatedRequest&>) ImpactResult
    simulate(const Law& law, const Scene& scene,
             IntegratorKind integrator = IntegratorKind::odeint_dopri5,
             const IntegratorOptions& options = {},
             std::vector<TrajectoryPoint>* trajectory = nullptr) {
  static_assert(assert_contact_law_everywhere<Law>());
  validate(scene);
  validate(options);
  if (Law::rate_dependent && scene.damping.kind != Damping::Kind::none)
    throw InputError("damping", std::string("the ") + std::string(Law::name) +
                                    " law depends on the deformation rate and carries its own "
                                    "damping; it runs without the series dashpot");
  const DerivedParameters p = derive(scene);
  return with_integrator(integrator, [&]<class Entry>() {
    return detail::run_law<Entry::template stepper, typename Entry::scalar>(law, scene, options, p,
                                                                            trajectory);
  });
}

}  // namespace ivv
