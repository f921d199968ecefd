// Elastoplastic contact law (paper eqs 8-12; Majeed, Yigit & Christoforou, Nonlinear Dyn.):
//
//   I   Hertz loading          F = K_h z^{3/2}                                  0 <= z <= z_y
//   II  elastic-plastic        F = K_y (z - z_y) + K_h z_y^{3/2}                z_y <= z <= z_m
//   III Hertz unloading        F = K_h (z^{3/2} - z_m^{3/2} + z_y^{3/2}) + K_y (z_m - z_y)
//
// K_h [N/m^1.5], z_y [m], K_y = 1.5 K_h sqrt(z_y) [N/m]. Unloading from z_m <= z_y (no
// yield) follows the Hertz curve. The unloading force vanishes at the permanent set
//   z_f = (z_m^{3/2} - F_m/K_h)^{2/3},  F_m = F(z_m),
// and the loop area (plastic work) is  W_p = int_0^{z_m} F_load dz - int_{z_f}^{z_m} F_unload dz.
//
// Without cancellation. Far above yield (z_m >> z_y) the unloading force F_m is a small
// difference of large numbers, K_h z^{3/2} - K_h z_f^{3/2}, and so is the stored energy; written
// that way they lose sqrt(z_m/z_y) of their relative accuracy (at v0 = 1e16 m/s on the paper
// scene the stored energy came out ~1e23 J wrong). With a = sqrt(z_m), b = sqrt(z_y),
// A = sqrt(z), B = sqrt(z_f) the same quantities are computed from factored forms whose terms
// all have one sign:
//   z_f^{3/2}  = (a - b)^2 (a + b/2),            a - b = (z_m - z_y)/(a + b)
//   z_m - z_f  = (F_m/K_h) (a + B) / (a^2 + a B + B^2)
//   F_unload   = K_h (z - z_f) (A^2 + A B + B^2)/(A + B),   z - z_f = (z - z_m) + (z_m - z_f)
//   int_{z_f}^{z} F_unload = (K_h/5) (A - B)^2 (2A^3 + 4A^2 B + 6A B^2 + 3B^3),
//                            A - B = (z - z_f)/(A + B)
// (the last by dividing (2/5)(A^5 - B^5) - B^3 (A^2 - B^2) twice by A - B; it has a double
// root at z_f because the force vanishes there).
//
// Plain where it costs nothing. The factored unloading force has a square root and a division
// in series, on the critical path of every stage of an explicit step (z -> F -> the stage's
// derivative -> the next stage's z). Written plainly, F = K_h z^{3/2} + hertz_offset, it has the
// root alone, and its rounding error is at most about g ulps of F_m, g = K_h z_m^{3/2} / F_m (the
// cancellation's gain; (2/3) sqrt(z_m/z_y) far above yield). Where g <= kPlainUnloadingGain the
// branch takes the plain form: on the paper scene that is every v0 up to 100 m/s (g = 1.0 at
// 0.15 m/s, 1.7 at 1, 5.0 at 10, 15.8 at 100), and the force is within 16 ulps of F_m, below
// the tightest tolerance a run accepts (rtol 1e-15 is 4.5 ulps; the integrator's own rounding
// is of that order). Far above yield (the v0 = 1e16 m/s hard case) the factored form is kept.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "scene/scene.h"
#include "solver/laws/law.h"
#include "solver/laws/law_kind.h"
#include "solver/laws/law_parameters.h"

namespace ivv {

struct ElastoplasticLaw {
  static constexpr std::string_view name = "elastoplastic";
  static constexpr LawKind kind = LawKind::elastoplastic;  // its row in the registry
  static constexpr bool rate_dependent = false;
  static constexpr ScaleBasis scale_basis = ScaleBasis::yield;
  static constexpr bool needs_yield_strength = true;
  // Unloading F = K_h (z^{3/2} - z_f^{3/2}) rises with z through zero at z_f = z_perm, and its
  // continuation below z = 0, K_h z |z|^{1/2} - K_h z_f^{3/2}, is negative (law.h)
  static constexpr bool separates_at_z_perm = true;
  static constexpr std::string_view summary =
      "Hertz to z_y, then linear K_y; Hertz-shaped unloading (paper eqs 8-10)";
  static constexpr std::array<ParameterSpec, 0> parameters{};
  static ElastoplasticLaw make(const LawParameters&, const DerivedParameters& p) {
    return {p.K_h, p.z_y, p.K_y};
  }

  // Unloading is "Hertz plus a constant": F = K_h z^{3/2} + hertz_offset.
  template <class T>
  struct History : Branch<T> {
    T hertz_offset = 0;    // F_m - K_h z_m^{3/2} [N] (<= 0; 0 when unloading from z_m <= z_y)
    T unloading_span = 0;  // z_m - z_f [m], computed without cancellation
    T sqrt_z_perm = 0;     // sqrt(z_f) [m^0.5]
    // F = K_h z^{3/2} + hertz_offset for every z (the header: g <= kPlainUnloadingGain), else
    // the factored form for z > 0
    bool plain_unloading = false;
  };
  // The cancellation gain K_h z_m^{3/2} / F_m up to which the unloading force is computed plainly
  // (header): at most 4 bits of F_m's accuracy given for one division fewer per evaluation.
  static constexpr double kPlainUnloadingGain = 16.0;

  double K_h = 0.0;  // [N/m^1.5]
  double z_y = 0.0;  // [m]
  double K_y = 0.0;  // [N/m]

  // Hertzian up to yield (region I above; law.h).
  HertzianOnset hertzian_onset() const { return {K_h, z_y}; }

  // Region II, linear in z (law.h: linear_segment): crossed in closed form from the yield.
  template <class T>
  std::optional<LinearSegment> linear_segment(const History<T>& b) const {
    if (b.phase == Phase::loading && b.segment == 1) return LinearSegment{K_y, z_y, yield_force()};
    return std::nullopt;
  }

  // Hertz force at the yield point, K_h z_y^{3/2} [N].
  double yield_force() const { return K_h * z_y * std::sqrt(z_y); }

  // K_h z |z|^{1/2} + offset [N]: Hertz loading (offset 0), the plain unloading and the tension
  // side. Written (K_h z) |z|^{1/2} + offset, the product K_h z is formed while the root is
  // taken, and the root is followed by one multiply-add (fused where the unit has FMA) on the
  // path from z to the force that every stage of an explicit step waits for.
  template <class T>
  T hertz_form(const T& z, const T& offset) const {
    using std::abs;
    using std::sqrt;
    return (K_h * z) * sqrt(abs(z)) + offset;
  }
  template <class T>
  T force(const History<T>& b, const T& z, const T&) const {
    using std::sqrt;
    if (b.phase == Phase::loading) {
      if (b.segment == 1) return K_y * (z - z_y) + yield_force();
      return hertz_form(z, T(0));
    }
    // plain (header), and below z = 0 the tension side
    if (b.plain_unloading || !(z > T(0))) return hertz_form(z, b.hertz_offset);
    const T A = sqrt(z);
    const T& B = b.sqrt_z_perm;
    return K_h * ((z - b.z_max) + b.unloading_span) * (z + A * B + B * B) / (A + B);
  }
  // The same force in the lanes of a SIMD vector: one impact per lane, each with its own law
  // parameters and branch (solver/steppers/dop853_lanes.h runs L impacts' steps at once).
  // `Lanes` is the lane arithmetic: Lanes::vector (L doubles with +, -, *, /, comparisons),
  // Lanes::mask (what a comparison of two vectors gives), Lanes::sqrt, Lanes::abs (|v| by the
  // sign bit, as fabs), Lanes::select(mask, where_true, where_false) and Lanes::any(mask). Every
  // lane evaluates the formulas of force() above, written exactly as there (the factored one
  // only when some lane takes it), and keeps the one of its branch:
  //   loading, segment 0, plain unloading, and the tension side (unloading, z <= 0):
  //        (K_h z) |z|^{1/2} + offset   [N]   offset = hertz_offset unloading, 0 loading
  //   loading, segment 1:                K_y (z - z_y) + K_h z_y^{3/2}
  //   factored unloading, z > 0:         K_h ((z - z_m) + (z_m - z_f)) (z + A B + B^2) / (A + B)
  // so each lane's value is force()'s to the last bit where the compiler treats the two alike
  // (a loading lane adds its offset 0 as hertz_form does; a lane whose formula is not taken may
  // compute NaN, which select() drops).
  template <class Lanes>
  struct LaneBranches {
    using V = typename Lanes::vector;
    V K_h{}, K_y{}, z_y{};        // [N/m^1.5], [N/m], [m]
    V yield_force{};              // K_h z_y^{3/2} [N], as yield_force()
    V hertz_offset{};             // the branch's hertz_offset where unloading, 0 where loading [N]
    V z_max{}, unloading_span{};  // [m]
    V sqrt_z_perm{};              // [m^0.5]
    typename Lanes::mask plastic{};   // loading, segment 1
    typename Lanes::mask factored{};  // phase unloading, not plain_unloading

    // Lane i takes `law` on branch `b`.
    void set_lane(std::size_t i, const ElastoplasticLaw& law, const History<double>& b) {
      const bool unload = b.phase == Phase::unloading;
      K_h[i] = law.K_h;
      K_y[i] = law.K_y;
      z_y[i] = law.z_y;
      yield_force[i] = law.yield_force();
      hertz_offset[i] = unload ? b.hertz_offset : 0.0;
      z_max[i] = b.z_max;
      unloading_span[i] = b.unloading_span;
      sqrt_z_perm[i] = b.sqrt_z_perm;
      plastic[i] = !unload && b.segment == 1 ? -1 : 0;  // a mask lane is all ones where true
      factored[i] = unload && !b.plain_unloading ? -1 : 0;
    }
  };
  template <class Lanes>
  static typename Lanes::vector force_lanes(const LaneBranches<Lanes>& c,
                                            const typename Lanes::vector& z) {
    using V = typename Lanes::vector;
    const V hertz = (c.K_h * z) * Lanes::sqrt(Lanes::abs(z)) + c.hertz_offset;
    const V plastic = c.K_y * (z - c.z_y) + c.yield_force;
    const V loading = Lanes::select(c.plastic, plastic, hertz);
    // the factored form's root and division only where a lane takes it (far above yield)
    if (!Lanes::any(c.factored)) return loading;
    const V A = Lanes::sqrt(z);
    const V& B = c.sqrt_z_perm;
    const V unload = c.K_h * ((z - c.z_max) + c.unloading_span) * (z + A * B + B * B) / (A + B);
    return Lanes::select(c.factored & (z > V{}), unload, loading);
  }

  template <class T>
  T stiffness(const History<T>& b, const T& z, const T&) const {
    using std::abs;
    using std::sqrt;
    if (b.phase == Phase::loading && b.segment == 1) return T(K_y);
    return 1.5 * K_h * sqrt(abs(z));
  }
  template <class T>
  T rate_stiffness(const History<T>&, const T&, const T&) const {
    return T(0);
  }
  template <class T>
  std::optional<double> segment_end(const History<T>& b) const {
    if (b.phase == Phase::loading && b.segment == 0) return z_y;
    return std::nullopt;
  }
  template <class T>
  void next_segment(History<T>& b) const {
    ++b.segment;
  }
  // Inlined always: the AVX2 + FMA copy of the dop853 run (dop853_fma.cc) must not emit it out
  // of line under its shared name (check_clone_symbols.py), which GCC did once the driver called
  // it from a second place (the closed-form crossing of region II, impact_driver.h).
  template <class T>
  [[gnu::always_inline]] inline void begin_unloading(History<T>& b, const T& z_m) const {
    using std::sqrt;
    const bool yielded = b.segment == 1;
    b.phase = Phase::unloading;
    b.z_max = z_m;
    if (!yielded) {  // elastic: back down the Hertz curve
      b.hertz_offset = T(0);
      b.z_perm = T(0);
      b.sqrt_z_perm = T(0);
      b.unloading_span = z_m;
      b.plain_unloading = true;  // g = 1: K_h z^{3/2} + 0
      return;
    }
    const double b_y = sqrt(z_y);
    const T a = sqrt(z_m);
    const T a_minus_b = (z_m - z_y) / (a + b_y);
    const T zf_1_5 = a_minus_b * a_minus_b * (a + 0.5 * b_y);  // z_f^{3/2}
    b.hertz_offset = -K_h * zf_1_5;
    b.z_perm = cube_root(T(zf_1_5 * zf_1_5));
    b.sqrt_z_perm = sqrt(b.z_perm);
    const T& B = b.sqrt_z_perm;
    const T F_m_over_K_h = (K_y * (z_m - z_y) + yield_force()) / K_h;
    b.unloading_span = F_m_over_K_h * (a + B) / (a * a + a * B + B * B);
    b.plain_unloading = a * a * a <= kPlainUnloadingGain * F_m_over_K_h;  // g (header)
  }
  // Unloading F = K_h (z^{3/2} - z_f^{3/2}) is convex, so F >= F'(z_f) (z - z_f) with
  // F'(z_f) = 1.5 K_h sqrt(z_f) [N/m]; nothing useful (0) after an elastic impact (z_f = 0).
  template <class T>
  std::optional<double> unloading_slope_floor(const History<T>& b) const {
    if (b.phase != Phase::unloading || !(b.z_perm > 0)) return std::nullopt;
    return 1.5 * K_h * static_cast<double>(b.sqrt_z_perm);
  }
  // int_{z_f}^{z} F_unload ds, factored (see the header comment)
  template <class T>
  T stored_energy(const History<T>& b, const T& z) const {
    using std::sqrt;
    if (z <= b.z_perm) return T(0);
    const T A = sqrt(z);
    const T& B = b.sqrt_z_perm;
    const T A_minus_B = ((z - b.z_max) + b.unloading_span) / (A + B);
    return 0.2 * K_h * A_minus_B * A_minus_B *
           (((2.0 * A + 4.0 * B) * A + 6.0 * B * B) * A + 3.0 * B * B * B);
  }
  // Inlined always, as begin_unloading: GCC emitted it out of line in the AVX2 + FMA copy of the
  // dop853 run once the stage arithmetic changed around it (dop853_stage_argument), under the
  // name the baseline code shares (check_clone_symbols.py).
  template <class T>
  [[gnu::always_inline]] inline std::optional<double> hysteresis_work(const History<T>& b) const {
    using std::sqrt;
    const double z_m = static_cast<double>(b.z_max);
    double loading;
    if (z_m <= z_y || b.segment == 0) {
      loading = 0.4 * K_h * z_m * z_m * sqrt(z_m);
    } else {
      const double d = z_m - z_y;
      loading = 0.4 * K_h * z_y * z_y * sqrt(z_y) + yield_force() * d + 0.5 * K_y * d * d;
    }
    return loading - static_cast<double>(stored_energy(b, b.z_max));
  }
};

}  // namespace ivv
