// The contact-law interface shared by every integrator, and the traits the driver reads.
//
// A contact law gives the spring force F(z) [N] of spring deformation z [m] on the current
// *branch* of its history: a loading segment (between kinks such as z = z_y) or the unloading
// curve fixed at maximum compression z_m. Inside one branch the force is a smooth function,
// continued analytically beyond the branch's ends (e.g. below zero force), so that a stepper
// never straddles a kink: the driver locates each branch end as an event and restarts there.
//
// Conventions: SI units; z > 0 is compression; the rate argument v [m/s] is the spring
// deformation rate dz/dt (only rate-dependent laws use it). A law templated on its scalar runs
// in double, in the 50-digit reference and on automatic-differentiation types alike.
#pragma once

#include <concepts>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace ivv {

enum class Phase { loading, unloading };

// The history every law has: where it is on its force-deformation curve. `segment` counts the
// loading pieces passed (elastoplastic: 0 = Hertz, 1 = elastic-plastic); `z_max` and `z_perm`
// are set by `begin_unloading`. A law that needs more history declares
//   template <class T> struct History : Branch<T> { T my_named_field; };
// (see laws/elastoplastic.h); every field has one meaning and one unit for that law.
template <class T>
struct Branch {
  Phase phase = Phase::loading;
  int segment = 0;
  T z_max = 0;   // z_m [m]: the maximum spring deformation (set when unloading begins)
  T z_perm = 0;  // z_f [m]: zero-force deformation of the unloading branch (permanent set)
};

// The history type of law L on scalar T: L::History<T> when the law declares one, else Branch<T>.
template <class L, class T>
struct law_history {
  using type = Branch<T>;
};
template <class L, class T>
requires requires {
  typename L::template History<T>;
}
struct law_history<L, T> {
  using type = typename L::template History<T>;
};
template <class L, class T>
using history_t = typename law_history<L, T>::type;

// Thrown when a law is evaluated where it is not defined (the linearized law below
// z_m = 2.25 z_y). The message says so in the user's terms.
class LawDomainError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The requirements, one concept per group so that a compile error names what is missing.
//   name, rate_dependent                      identification; rate laws use v in force()
//   force(h, z, v)           [N]              smooth continuation on the branch of history h
//   stiffness(h, z, v)       [N/m]            dF/dz on that branch (implicit integrators, events)
//   rate_stiffness(h, z, v)  [N s/m]          dF/dv on that branch (0 for rate-independent laws)
//   segment_end(h)           [m]              z where the current loading segment ends, if any
//   next_segment(h)                           enter the next loading segment
//   begin_unloading(h, z_m)                   switch to unloading (may throw LawDomainError)
//   stored_energy(h, z)      [J]              energy recoverable from z down to zero force on
//                                             the unloading branch (bounds any rebound)
//   hysteresis_work(h)       [J]              closed-form loop area for a completed unloading
//                                             branch, or nullopt if the law has none
// Optional members, read through the traits below:
//   History<T>                                 extra history (default Branch<T>)
//   needs_yield_strength     bool             the law reads z_y/K_y (default false)
//   allows_tension           bool (member)    F may go negative; contact ends at z = 0 instead
//                                             of F = 0 (default false: F is clamped at 0)
//   unloading_slope_floor(h) [N/m]            optional<double>: a k_f > 0 with
//                                             F(z) >= k_f (z - z_f) on the whole unloading
//                                             branch above z_f (a convex unloading curve: its
//                                             slope at z_f), or nullopt. Lets the driver decide
//                                             capture exactly (impact_driver.h)
template <class L>
concept law_has_identity = requires {
  { L::name } -> std::convertible_to<std::string_view>;
  { L::rate_dependent } -> std::convertible_to<bool>;
};
template <class L>
concept law_has_force = requires(const L& law, const history_t<L, double>& h, double z, double v) {
  { law.force(h, z, v) } -> std::convertible_to<double>;
  { law.stiffness(h, z, v) } -> std::convertible_to<double>;
  { law.rate_stiffness(h, z, v) } -> std::convertible_to<double>;
};
template <class L>
concept law_has_history = requires(const L& law, history_t<L, double>& h, double z) {
  { law.segment_end(std::as_const(h)) } -> std::same_as<std::optional<double>>;
  law.next_segment(h);
  law.begin_unloading(h, z);
};
template <class L>
concept law_has_energy = requires(const L& law, const history_t<L, double>& h, double z) {
  { law.stored_energy(h, z) } -> std::convertible_to<double>;
  { law.hysteresis_work(h) } -> std::same_as<std::optional<double>>;
};
template <class L>
concept ContactLaw = std::copy_constructible<L> && law_has_identity<L> && law_has_force<L> &&
    law_has_history<L> && law_has_energy<L>;

// True when law L also runs on scalar T (the 50-digit reference, autodiff types): its members
// are templates on the scalar. An expression law runs in double only.
template <class L, class T>
concept law_supports_scalar = requires(const L& law, history_t<L, T>& h, const history_t<L, T>& ch,
                                       T z) {
  { law.force(ch, z, z) } -> std::convertible_to<T>;
  { law.stiffness(ch, z, z) } -> std::convertible_to<T>;
  { law.stored_energy(ch, z) } -> std::convertible_to<T>;
  law.begin_unloading(h, z);
};

template <class L>
constexpr bool law_needs_yield_strength() {
  if constexpr (requires { L::needs_yield_strength; })
    return L::needs_yield_strength;
  else
    return false;
}

template <class L>
bool law_allows_tension(const L& law) {
  if constexpr (requires { law.allows_tension; })
    return static_cast<bool>(law.allows_tension);
  else
    return false;
}

// The law's unloading_slope_floor(h) when it declares one (see above), else nullopt.
template <class L, class H>
std::optional<double> unloading_slope_floor(const L& law, const H& h) {
  if constexpr (requires { law.unloading_slope_floor(h); })
    return law.unloading_slope_floor(h);
  else
    return std::nullopt;
}

// z |z|^{1/2}: the Hertz power z^{3/2} continued to z < 0 as an odd, C^1 function, so that a
// step that overshoots separation (z < 0) stays finite and the sign change can be located.
template <class T>
T signed_pow_1_5(const T& z) {
  using std::abs;
  using std::sqrt;
  return z * sqrt(abs(z));
}

// x^{1/3} for any scalar: std::cbrt for built-in and multiprecision types, pow for types
// without a cbrt (automatic-differentiation scalars).
template <class T>
T cube_root(const T& x) {
  using std::cbrt;
  using std::pow;
  if constexpr (requires { cbrt(x); })
    return T(cbrt(x));
  else
    return T(pow(x, 1.0 / 3.0));
}

}  // namespace ivv
