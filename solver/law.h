// The contact-law interface shared by every integrator.
//
// A contact law gives the spring force F(z) [N] of spring deformation z [m] on the current
// *branch* of its history: a loading segment (between kinks such as z = z_y) or the unloading
// curve fixed at maximum compression z_m. Inside one branch the force is a smooth function,
// continued analytically beyond the branch's ends (e.g. below zero force), so that a stepper
// never straddles a kink: the driver locates each branch end as an event and restarts there.
//
// Laws are written in SI units and templated on the scalar type so that the same code runs
// in double and in the 50-digit reference. Conventions: z > 0 is compression; the rate
// argument v [m/s] is the spring deformation rate (only rate-dependent laws use it).
#pragma once

#include <concepts>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace ivv {

enum class Phase { loading, unloading };

// Where a law is on its force-deformation curve. `segment` counts the loading pieces passed
// (elastoplastic: 0 = Hertz, 1 = elastic-plastic); the unloading fields are set by
// `begin_unloading` from the maximum deformation z_m.
template <class T>
struct Branch {
  Phase phase = Phase::loading;
  int segment = 0;
  T z_max = 0;   // z_m [m]
  T z_perm = 0;  // z_f [m]: zero-force deformation of the unloading branch
  T coef = 0;    // law-specific constant of the unloading branch
};

// Thrown when a law is evaluated where it is not defined (the linearized law below
// z_m = 2.25 z_y). The message says so in the user's terms.
class LawDomainError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Requirements, checked on double:
//   name, rate_dependent                      identification; rate laws use v in force()
//   force(b, z, v)           [N]              smooth continuation on branch b
//   stiffness(b, z, v)       [N/m]            dF/dz on branch b (implicit integrators, events)
//   rate_stiffness(b, z, v)  [N s/m]          dF/dv on branch b (0 for rate-independent laws)
//   segment_end(b)           [m]              z where the current loading segment ends, if any
//   next_segment(b)                           enter the next loading segment
//   begin_unloading(b, z_m)                   switch to unloading (may throw LawDomainError)
//   stored_energy(b, z)      [J]              energy recoverable from z down to zero force on
//                                             the unloading branch (bounds any rebound)
//   hysteresis_work(b)       [J]              closed-form loop area for a completed unloading
//                                             branch, or nullopt if the law has none
template <class L>
concept ContactLaw = requires(const L& law, Branch<double>& b, const Branch<double>& cb, double z,
                              double v) {
  { L::name } -> std::convertible_to<std::string_view>;
  { L::rate_dependent } -> std::convertible_to<bool>;
  { law.force(cb, z, v) } -> std::convertible_to<double>;
  { law.stiffness(cb, z, v) } -> std::convertible_to<double>;
  { law.rate_stiffness(cb, z, v) } -> std::convertible_to<double>;
  { law.segment_end(cb) } -> std::same_as<std::optional<double>>;
  law.next_segment(b);
  law.begin_unloading(b, z);
  { law.stored_energy(cb, z) } -> std::convertible_to<double>;
  { law.hysteresis_work(cb) } -> std::same_as<std::optional<double>>;
};

// z |z|^{1/2}: the Hertz power z^{3/2} continued to z < 0 as an odd, C^1 function, so that a
// step that overshoots separation (z < 0) stays finite and the sign change can be located.
template <class T>
T signed_pow_1_5(const T& z) {
  using std::abs;
  using std::sqrt;
  return z * sqrt(abs(z));
}

}  // namespace ivv
