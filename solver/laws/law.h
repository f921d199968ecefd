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

#include <cmath>
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

// The requirements, with the return types the driver relies on, for scalar T (double, and the
// 50-digit scalar and automatic-differentiation types when the members are templates on it):
//   name                     std::string_view  identification (static constexpr)
//   rate_dependent           bool              rate laws use v in force() (static constexpr)
//   force(h, z, v)           -> T [N]          smooth continuation on the branch of history h
//   stiffness(h, z, v)       -> T [N/m]        dF/dz on that branch (implicit integrators, events)
//   rate_stiffness(h, z, v)  -> T [N s/m]      dF/dv on that branch (0 for rate-independent laws)
//   stored_energy(h, z)      -> T [J]          energy recoverable from z down to zero force on
//                                              the unloading branch, the area under it from z_f
//                                              to z (during first loading: the area under the
//                                              loading curve from 0 to z, the energy a reversal
//                                              there could at most return); it bounds any rebound
//   hysteresis_work(h)       -> std::optional<double> [J]
//                                              closed-form loop area for a completed unloading
//                                              branch, or nullopt if the law has none
// Here h is history_t<L, T> (const, except for next_segment and begin_unloading), z and v are T.
// segment_end and hysteresis_work return std::optional<double> for every T (not optional<T>).
// Optional members, read through the helpers below (a law with one loading curve and no extra
// history - hertz, hunt-crossley, kuwabara-kono - declares none of the first three):
//   segment_end(h)           -> std::optional<double> [m]
//                                              z where the current loading segment ends, if any
//                                              (default: none, one loading segment)
//   next_segment(h)                            enter the next loading segment (default: nothing
//                                              to do; only called after a segment_end)
//   begin_unloading(h, z_m)                    switch to unloading (may throw LawDomainError);
//                                              default: phase = unloading, z_max = z_m,
//                                              z_perm = 0 (the unloading curve retraces the
//                                              loading curve)
//   History<T>                                 extra history (default Branch<T>)
//   needs_yield_strength     bool             the law reads z_y/K_y (default false)
//   allows_tension           bool (member)    F may go negative; contact ends at z = 0 instead
//                                             of F = 0 (default false: F is clamped at 0)
//   unloading_slope_floor(h) [N/m]            optional<double>: a k_f > 0 with
//                                             F(z) >= k_f (z - z_f) on the whole unloading
//                                             branch above z_f (a convex unloading curve: its
//                                             slope at z_f), or nullopt. Lets the driver decide
//                                             capture exactly (impact_driver.h)
//   linear_segment(h)                         optional<LinearSegment>: F = K (z - z_ref) +
//                                             F_ref exactly on the loading segment of h, so the
//                                             driver may cross it in closed form
//                                             (solver/driver/linear_phase.h); rate-independent
//                                             laws only
//   hertzian_onset()                          HertzianOnset: F = K z^{3/2} exactly on first
//                                             loading for 0 <= z <= z_end, so the driver may
//                                             start the integration from the onset series
//                                             (solver/driver/onset_series.h); rate-independent laws
//                                             only
//   onset_force()            [N]              std::optional<double> (or double): the force the
//                                             law intends at z = 0 on first loading, an adhesive
//                                             law's jump-in (DMT: -F_ad). A declaration for the
//                                             conformance check static.onset, which then holds
//                                             F(0) to it instead of 0; the driver does not read it
//                                             (onset is the initial state whatever F(0) is)
//   separates_at_z_perm      bool             on every unloading branch F has the sign of
//                                             z - z_perm wherever it is evaluated (F rises
//                                             with z through zero at the permanent set, and
//                                             its continuation below stays negative), so
//                                             the separation event may use z - z_perm as its
//                                             root (impact_events.h); rate-independent laws
//                                             without tension only (default false: F itself)
//   separation_work(h, z)    [J]              std::optional<double>: for a law that allows
//                                             tension, int_0^z F(s, 0) ds on the unloading branch
//                                             h, the work the contact force does on the impactor
//                                             as the spring relaxes from z to separation at
//                                             z = 0 (negative where an attractive well takes more
//                                             than the spring returns); nullopt where not known.
//                                             Lets the driver decide capture in the well without
//                                             a dashpot (capture.h, criterion 4)
//
// One concept per member, so that assert_contact_law (below) names the member at fault in the
// first line of a compile error. An optional member is detected by a call with the arguments
// the driver passes; one declared with other parameters is not seen and the default applies
// (the conformance checks, verification/conformance.h, then judge the law as it behaves).
template <class L>
concept law_has_name = requires {
  { L::name } -> std::convertible_to<std::string_view>;
};
template <class L>
concept law_has_rate_flag = requires {
  { L::rate_dependent } -> std::convertible_to<bool>;
};
template <class L, class T = double>
concept law_has_force_member = requires(const L& law, const history_t<L, T>& h, T z) {
  { law.force(h, z, z) } -> std::convertible_to<T>;
};
template <class L, class T = double>
concept law_has_stiffness_member = requires(const L& law, const history_t<L, T>& h, T z) {
  { law.stiffness(h, z, z) } -> std::convertible_to<T>;
};
template <class L, class T = double>
concept law_has_rate_stiffness_member = requires(const L& law, const history_t<L, T>& h, T z) {
  { law.rate_stiffness(h, z, z) } -> std::convertible_to<T>;
};
template <class L, class T = double>
concept law_declares_segment_end = requires(const L& law, const history_t<L, T>& h) {
  law.segment_end(h);
};
template <class L, class T = double>
concept law_has_segment_end_member =
    !law_declares_segment_end<L, T> || requires(const L& law, const history_t<L, T>& h) {
  { law.segment_end(h) } -> std::same_as<std::optional<double>>;
};
template <class L, class T = double>
concept law_declares_next_segment = requires(const L& law, history_t<L, T>& h) {
  law.next_segment(h);
};
template <class L, class T = double>
concept law_declares_begin_unloading = requires(const L& law, history_t<L, T>& h, T z) {
  law.begin_unloading(h, z);
};
template <class L, class T = double>
concept law_has_stored_energy_member = requires(const L& law, const history_t<L, T>& h, T z) {
  { law.stored_energy(h, z) } -> std::convertible_to<T>;
};
template <class L, class T = double>
concept law_has_hysteresis_work_member = requires(const L& law, const history_t<L, T>& h) {
  { law.hysteresis_work(h) } -> std::same_as<std::optional<double>>;
};

// The groups (each a conjunction of the members above).
template <class L>
concept law_has_identity = law_has_name<L> && law_has_rate_flag<L>;
template <class L>
concept law_has_force =
    law_has_force_member<L> && law_has_stiffness_member<L> && law_has_rate_stiffness_member<L>;
template <class L>
concept law_has_history = law_has_segment_end_member<L>;  // the others may be absent
template <class L>
concept law_has_energy = law_has_stored_energy_member<L> && law_has_hysteresis_work_member<L>;
template <class L>
concept ContactLaw = std::copy_constructible<L> && law_has_identity<L> && law_has_force<L> &&
    law_has_history<L> && law_has_energy<L>;

// True when the law's force is a template on its scalar (it accepts history_t<L, T> and T):
// then every member must hold for T too (law_supports_scalar).
template <class L, class T>
concept law_templated_on = requires(const L& law, const history_t<L, T>& h, T z) {
  law.force(h, z, z);
};

// True when law L also runs on scalar T (the 50-digit reference, autodiff types): its members
// are templates on the scalar. An expression law runs in double only.
template <class L, class T>
concept law_supports_scalar = law_has_force_member<L, T> && law_has_stiffness_member<L, T> &&
    law_has_stored_energy_member<L, T>;

// One static_assert per requirement, each naming its member: called by ivv::simulate(law, ...)
// and the conformance API on double and, for a law templated on its scalar, on the 50-digit
// scalar, so that a missing or mistyped member stops compilation with its name in the first
// error line instead of deep inside the driver. `true` when L models ContactLaw on T.
template <class L, class T = double>
constexpr bool assert_contact_law() {
  static_assert(law_has_name<L>,
                "ivv::ContactLaw: member `name` missing or mistyped (static constexpr "
                "std::string_view name = \"my-law\";)");
  static_assert(law_has_rate_flag<L>,
                "ivv::ContactLaw: member `rate_dependent` missing or mistyped (static constexpr "
                "bool rate_dependent = false;)");
  static_assert(std::copy_constructible<L>, "ivv::ContactLaw: the law must be copy-constructible");
  static_assert(law_has_force_member<L, T>,
                "ivv::ContactLaw: member `force(h, z, v)` missing or mistyped: it must take "
                "(const history_t<L, T>&, T z, T v) and return T [N]");
  static_assert(law_has_stiffness_member<L, T>,
                "ivv::ContactLaw: member `stiffness(h, z, v)` missing or mistyped: it must take "
                "(const history_t<L, T>&, T z, T v) and return T [N/m]");
  static_assert(law_has_rate_stiffness_member<L, T>,
                "ivv::ContactLaw: member `rate_stiffness(h, z, v)` missing or mistyped: it must "
                "take (const history_t<L, T>&, T z, T v) and return T [N s/m]");
  static_assert(law_has_segment_end_member<L, T>,
                "ivv::ContactLaw: member `segment_end(h)` mistyped: it must take "
                "(const history_t<L, T>&) and return std::optional<double> [m] for every T (or be "
                "left out: one loading segment)");
  static_assert(law_has_stored_energy_member<L, T>,
                "ivv::ContactLaw: member `stored_energy(h, z)` missing or mistyped: it must take "
                "(const history_t<L, T>&, T z) and return T [J]");
  static_assert(law_has_hysteresis_work_member<L, T>,
                "ivv::ContactLaw: member `hysteresis_work(h)` missing or mistyped: it must take "
                "(const history_t<L, T>&) and return std::optional<double> [J] for every T (not "
                "std::optional<T>)");
  return true;
}

// The law's segment_end(h) when it declares one, else nullopt (one loading segment).
template <class L, class H>
std::optional<double> law_segment_end(const L& law, const H& h) {
  if constexpr (requires { law.segment_end(h); })
    return law.segment_end(h);
  else
    return std::nullopt;
}

// The law's next_segment(h) when it declares one, else nothing (there is no next segment).
template <class L, class H>
void law_next_segment(const L& law, H& h) {
  if constexpr (requires { law.next_segment(h); }) law.next_segment(h);
}

// The law's begin_unloading(h, z_m) when it declares one, else the unloading curve that
// retraces the loading curve: phase unloading, z_max = z_m, no permanent set.
template <class L, class H, class T>
void law_begin_unloading(const L& law, H& h, const T& z_m) {
  if constexpr (requires { law.begin_unloading(h, z_m); }) {
    law.begin_unloading(h, z_m);
  } else {
    h.phase = Phase::unloading;
    h.z_max = z_m;
    h.z_perm = decltype(h.z_perm)(0);
  }
}

template <class L>
constexpr bool law_needs_yield_strength() {
  if constexpr (requires { L::needs_yield_strength; })
    return L::needs_yield_strength;
  else
    return false;
}

// True when the law declares separates_at_z_perm (above) and is rate-independent.
template <class L>
constexpr bool law_separates_at_z_perm() {
  if constexpr (requires { L::separates_at_z_perm; })
    return L::separates_at_z_perm && !L::rate_dependent;
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

// What a law declares about a loading segment linear in z (linear_segment(h) above).
struct LinearSegment {
  double K = 0.0;      // [N/m]: F = K (z - z_ref) + F_ref on the segment
  double z_ref = 0.0;  // [m]
  double F_ref = 0.0;  // [N]
};

// The law's linear_segment(h) when it declares one and is rate-independent, else nullopt.
template <class L, class H>
std::optional<LinearSegment> law_linear_segment(const L& law, const H& h) {
  if constexpr (requires { law.linear_segment(h); } && !L::rate_dependent)
    return law.linear_segment(h);
  else
    return std::nullopt;
}

// What a law declares about its onset (hertzian_onset() above).
struct HertzianOnset {
  double K = 0.0;      // [N/m^1.5]: F = K z^{3/2} ...
  double z_end = 0.0;  // [m] ... for 0 <= z <= z_end on first loading (inf: no end)
};

// The law's hertzian_onset() when it declares one and is rate-independent, else nullopt.
template <class L>
std::optional<HertzianOnset> hertzian_onset(const L& law) {
  if constexpr (requires { law.hertzian_onset(); } && !L::rate_dependent)
    return law.hertzian_onset();
  else
    return std::nullopt;
}

// The law's declared onset force (see above), else nullopt.
template <class L>
std::optional<double> declared_onset_force(const L& law) {
  if constexpr (requires { law.onset_force(); })
    return std::optional<double>(law.onset_force());
  else
    return std::nullopt;
}

// The law's separation_work(h, z) when it declares one and allows tension (see above), else
// nullopt.
template <class L, class H>
std::optional<double> separation_work(const L& law, const H& h, double z) {
  if constexpr (requires { law.separation_work(h, z); }) {
    if (!law_allows_tension(law)) return std::nullopt;
    return law.separation_work(h, z);
  } else {
    return std::nullopt;
  }
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
