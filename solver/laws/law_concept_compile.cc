// Compile-time test of the ContactLaw requirements (solver/laws/law.h): a law missing or mistyping
// one member must fail to compile with that member's name in the first error line. This file
// is compiled, never linked, once per IVV_BAD_MEMBER by law_concept_compile.cmake (ctest
// law_concept_compile), which checks the first line that says "error". IVV_BAD_MEMBER = 0 is the
// good law: it must compile; so must 7, 8 and 12, which leave out the optional members
// next_segment, begin_unloading and segment_end (law.h's defaults apply).
#include <optional>
#include <string_view>

#if IVV_THROUGH_SIMULATE
#include "solver/simulate_law.h"
#else
#include "solver/laws/law.h"
#endif

namespace {

// Hertz, written out; each IVV_BAD_MEMBER removes or mistypes one member.
struct Law {
#if IVV_BAD_MEMBER != 1
  static constexpr std::string_view name = "concept-test";
#endif
#if IVV_BAD_MEMBER != 2
  static constexpr bool rate_dependent = false;
#endif
  double K = 1e9;
#if IVV_BAD_MEMBER != 3
  template <class T>
  T force(const ivv::Branch<T>&, const T& z, const T&) const {
    return K * ivv::signed_pow_1_5(z);
  }
#endif
#if IVV_BAD_MEMBER == 4
  template <class T>
  std::string_view stiffness(const ivv::Branch<T>&, const T&, const T&) const {  // mistyped
    return "stiff";
  }
#else
  template <class T>
  T stiffness(const ivv::Branch<T>&, const T& z, const T&) const {
    using std::abs, std::sqrt;
    return 1.5 * K * sqrt(abs(z));
  }
#endif
#if IVV_BAD_MEMBER != 5
  template <class T>
  T rate_stiffness(const ivv::Branch<T>&, const T&, const T&) const {
    return T(0);
  }
#endif
#if IVV_BAD_MEMBER == 6
  template <class T>
  std::optional<T> segment_end(const ivv::Branch<T>&) const {  // optional<T>, not <double>
    return std::nullopt;
  }
#elif IVV_BAD_MEMBER != 12
  template <class T>
  std::optional<double> segment_end(const ivv::Branch<T>&) const {
    return std::nullopt;
  }
#endif
#if IVV_BAD_MEMBER != 7
  template <class T>
  void next_segment(ivv::Branch<T>&) const {}
#endif
#if IVV_BAD_MEMBER != 8
  template <class T>
  void begin_unloading(ivv::Branch<T>& h, const T& z_m) const {
    h.phase = ivv::Phase::unloading;
    h.z_max = z_m;
  }
#endif
#if IVV_BAD_MEMBER != 9
  template <class T>
  T stored_energy(const ivv::Branch<T>&, const T& z) const {
    using std::abs, std::sqrt;
    return 0.4 * K * z * z * sqrt(abs(z));
  }
#endif
#if IVV_BAD_MEMBER == 10
  // a law author's mistake, found in use: right for double, wrong (optional<T>) for the
  // 50-digit scalar, once reported 41 lines deep in simulate_impl.h
  template <class T>
  std::optional<T> hysteresis_work(const ivv::Branch<T>&) const {
    return T(0);
  }
#elif IVV_BAD_MEMBER != 11
  template <class T>
  std::optional<double> hysteresis_work(const ivv::Branch<T>&) const {
    return 0.0;
  }
#endif
};

#if IVV_THROUGH_SIMULATE
[[maybe_unused]] ivv::ImpactResult run() {
  return ivv::simulate(Law{}, ivv::paper_scene());
}
#else
static_assert(ivv::assert_contact_law<Law>());
#endif

}  // namespace
