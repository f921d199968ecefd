// Event location: the earliest signed zero crossing of g on a step's interpolant.
//
// Two levels. locate_first_crossing / solve_crossing: one scalar function g(t). locate_earliest:
// a set of root functions g_i(x) of the state on one step (SUNDIALS' shape, CVodeRootInit: the
// locator knows roots and directions, never what an event means), the earliest crossing among
// them and which roots crossed there.
//
// An event is a scalar function g(t) of the solution and a direction. A crossing in a
// subinterval [a, b] means g(a) is strictly on the pre-event side and g(b) is on the
// post-event side or zero (rising: g(a) < 0 <= g(b); falling: g(a) > 0 >= g(b)). A zero exactly
// at the start of a step therefore never fires again after a restart there.
//
// The step [t0, t1] is first sampled at `samples` equal subintervals so that two roots inside
// one step (g returning to its pre-event side before t1) are not missed; the first bracketing
// subinterval is then solved by Anderson-Bjorck regula falsi to the precision of T, or, where
// that meets a NaN or does not converge, by TOMS 748 (Alefeld, Potra & Shi, ACM TOMS 21:327,
// 1995; boost::math::tools::toms748_solve). The returned time is the post-event
// end of the final bracket, so the state there is on the event's far side. A root finder
// that runs out of iterations before the bracket is resolved throws EventLocationError (the
// driver turns it into a failed run with that reason): an event is never placed at an
// unconverged time silently.
#pragma once

#include <algorithm>
#include <array>
#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace ivv {

enum class Direction { rising, falling };

template <class T>
bool is_pre_event(const T& g, Direction d) {
  return d == Direction::rising ? g < 0 : g > 0;
}

// An event whose time could not be resolved to the requested precision.
class EventLocationError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LocatorOptions {
  static constexpr int max_samples = 16;
  int samples = 4;  // subintervals probed per step (1 ... max_samples)
  // Bits of the bracket to resolve; 0 means all but 3 of T's digits.
  int bits = 0;
  std::uintmax_t max_iterations = 200;
  bool operator==(const LocatorOptions&) const = default;
};

// The precision solve_crossing resolves a bracket to, made once: `tolerance` is
// boost::math::tools::eps_tolerance<T>(bits)'s test (|a - b| <= eps min(|a|, |b|), eps =
// max(2^(1 - bits) in float, 4 epsilon)), `nudge` half the relative width max(2^(1 - bits),
// 4 epsilon) in T (anderson_bjorck). Both widths are powers of two: for a binary T at the
// default bits (all but 3 digits) they are 8 epsilon and 4 epsilon, without ldexp.
template <class T>
struct CrossingTolerance {
  T eps;    // accepted relative width of the final bracket
  T nudge;  // the least relative distance of a secant point from a bracket's end

  static CrossingTolerance make(int bits) {
    using std::ldexp;
    constexpr int digits = std::numeric_limits<T>::digits;
    const T four_eps = 4 * std::numeric_limits<T>::epsilon();
    if constexpr (std::numeric_limits<T>::radix == 2 && std::is_floating_point_v<T>) {
      if (bits == digits - 3) return {T(2) * four_eps, four_eps};  // 2^(4 - digits), halved
    }
    const T width = std::max(T(ldexp(T(1), 1 - bits)), four_eps);
    return {std::max(T(ldexp(1.0F, 1 - bits)), four_eps), T(width / 2)};
  }
  bool operator()(const T& a, const T& b) const {
    using std::abs;
    using std::min;
    return abs(a - b) <= eps * min(abs(a), abs(b));
  }
};

// Anderson-Bjorck regula falsi on a bracket [a, b] with g(a), g(b) of opposite signs: the
// secant through the ends, the end that stays having its value scaled by 1 - g(c)/g(new end)
// (1/2 when that is not positive), so that neither end sticks (Anderson & Bjorck, BIT 13:253,
// 1973). Superlinear on a smooth root at one g and a few flops a step, where TOMS 748's
// cubic and quadratic steps cost more than the g of an interpolant (profiled, TOMS 748's own
// arithmetic was ~10 % of a sweep's instructions). The bracket has a < b. A secant point closer
// than tol.nudge times min(|a|, |b|) to an end is moved to that distance (half the relative
// width tol accepts, as Brent's method steps at least its tolerance): once the secant has the
// root to that
// precision, the next g lands on the root's other side and closes the bracket to the tolerance
// at once, where the secant alone creeps up on the root from the end it keeps (measured on the
// paper scene at 1e-8, with the g at the final bracket's end solve_crossing no longer takes:
// 7.75 g per event before, 5.0 after). The end b keeps the sign of g(b) throughout
// (post-event in solve_crossing's use). The final bracket, or nullopt when g was not a number
// somewhere or `limit` steps did not resolve it: the caller then solves the bracket by TOMS 748
// as before.
template <class T, class G>
std::optional<std::pair<T, T>> anderson_bjorck(G& g, T a, T b, T fa, T fb,
                                               const CrossingTolerance<T>& tol,
                                               std::uintmax_t limit) {
  for (std::uintmax_t k = 0; k < limit; ++k) {
    // min(|a|, |b|) once for the tolerance and the nudge, a < b throughout
    const T near = a > 0 ? a : b < 0 ? T(-b) : T(-a) < b ? T(-a) : b;
    if (b - a <= tol.eps * near) return std::pair<T, T>{a, b};  // tol(a, b)
    T c = (a * fb - b * fa) / (fb - fa);
    const T step = tol.nudge * near;
    if (c - a < step)
      c = a + step;
    else if (b - c < step)
      c = b - step;
    if (!(c > a && c < b)) c = a + (b - a) / 2;
    const T fc = g(c);
    if (!(fc == fc)) return std::nullopt;
    if (fc == 0) return std::pair<T, T>{c, c};
    if ((fc < 0) == (fb < 0)) {
      const T m = 1 - fc / fb;
      fa *= m > 0 ? m : T(0.5);
      b = c;
      fb = fc;
    } else {
      const T m = 1 - fc / fa;
      fb *= m > 0 ? m : T(0.5);
      a = c;
      fa = fc;
    }
  }
  return std::nullopt;
}

// Solves a bracket [a, b] with g(a) strictly before the event and g(b) after it (or zero) by
// anderson_bjorck, else TOMS 748, and returns the post-event end of the final bracket. When
// TOMS 748 uses up max_iterations first, bisection finishes the bracket (it halves the bracket
// whatever the rounding noise of g, which can stall TOMS 748's interpolation steps: measured, the
// 50-digit reference near capture stopped at a relative width of 1.5e-20 against 2^-165 asked).
// Throws EventLocationError if max_iterations bisections do not reach the tolerance of `bits`
// either.
template <class T, class G>
T solve_crossing(G&& g, const T& a, const T& b, const T& ga, const T& gb, Direction dir,
                 const LocatorOptions& opt = {}) {
  if (gb == 0) return b;
  const int digits = std::numeric_limits<T>::digits;
  const int bits = opt.bits > 0 ? opt.bits : digits - 3;
  const CrossingTolerance<T> tol = CrossingTolerance<T>::make(bits);
  // post-event: g(b) keeps its sign in anderson_bjorck, and is not evaluated again
  if (const auto ab = anderson_bjorck(g, a, b, ga, gb, tol, opt.max_iterations)) return ab->second;
  std::uintmax_t iterations = opt.max_iterations;
  const std::pair<T, T> bracket =
      boost::math::tools::toms748_solve(g, a, b, ga, gb, tol, iterations);
  T lo = bracket.first, hi = bracket.second;
  if (iterations >= opt.max_iterations && lo != hi && !tol(lo, hi)) {
    T g_lo = g(lo);
    for (std::uintmax_t k = 0; k < opt.max_iterations && !tol(lo, hi); ++k) {
      const T mid = lo + (hi - lo) / 2;
      if (mid == lo || mid == hi) break;  // adjacent representable numbers: resolved
      const T g_mid = g(mid);
      if ((g_mid < 0) == (g_lo < 0) && g_mid != 0) {
        lo = mid;
        g_lo = g_mid;
      } else {
        hi = mid;
      }
    }
  }
  if (lo != hi && !tol(lo, hi) && lo + (hi - lo) / 2 != lo && lo + (hi - lo) / 2 != hi) {
    std::ostringstream os;
    os.precision(17);
    os << "TOMS 748 event location did not converge in " << opt.max_iterations
       << " iterations (then as many bisections): bracket [" << static_cast<double>(lo) << ", "
       << static_cast<double>(hi) << "] of [" << static_cast<double>(a) << ", "
       << static_cast<double>(b) << "] still "
       << static_cast<double>((hi - lo) / (hi < 0 ? -hi : hi)) << " wide relative, beyond " << bits
       << " bits";
    throw EventLocationError(os.str());
  }
  if (lo == hi) return hi;
  return is_pre_event(g(hi), dir) ? lo : hi;
}

// g: callable T -> T (the event function evaluated on the interpolant).
// g0: g(t0), already known. Returns the event time in (t0, t1], or nullopt.
template <class T, class G>
std::optional<T> locate_first_crossing(G&& g, const T& t0, const T& t1, const T& g0, Direction dir,
                                       const LocatorOptions& opt = {}) {
  if (!is_pre_event(g0, dir)) return std::nullopt;
  const int n = opt.samples < 1 ? 1 : opt.samples;
  T a = t0;
  T ga = g0;
  for (int i = 1; i <= n; ++i) {
    const T b = (i == n) ? t1 : T(t0 + (t1 - t0) * i / n);
    const T gb = g(b);
    if (!is_pre_event(gb, dir)) return solve_crossing(g, a, b, ga, gb, dir, opt);
    a = b;
    ga = gb;
  }
  return std::nullopt;
}

// One root function of an event set: its direction, and whether it is monotone over any step
// on which it is active (then the signs at the step's ends decide whether it crossed, and the
// step need not be probed inside).
struct RootSpec {
  Direction direction = Direction::rising;
  bool monotone = true;
};

// At most Capacity root functions active on one step.
template <std::size_t Capacity>
struct RootSet {
  std::array<RootSpec, Capacity> roots{};
  int size = 0;
  void add(RootSpec r) { roots[size++] = r; }
};

// What locate_earliest found on one step.
template <class T, std::size_t Capacity>
struct EarliestCrossing {
  std::optional<T> t;  // the earliest crossing in (t0, t1]; nullopt when no root crossed
  int first = -1;      // the root that crossed at t (the lowest index among equal times)
  // crossing times of the roots solved in the earliest bracketing subinterval (others nullopt)
  std::array<std::optional<T>, Capacity> found{};
  std::array<bool, Capacity> armed{};  // strictly on the pre-event side at t0
  // each root's value at x1 (the next step's g at x0); set only when no root crossed (t is
  // nullopt): a step on which a root crossed is not continued from its end
  std::array<T, Capacity> g1{};
};

// The earliest crossing among the roots of `set` on one step [t0, t1] with end states x0, x1.
//   g(i, x)               value of root i at state x
//   interpolate(t, x)     the step's interpolant at t into x (at least the components g reads)
// When a non-monotone root is active and `solve` is true, the step is probed at
// opt.samples equal subintervals (a root returning to its pre-event side within the step is
// not missed); each probe state is interpolated once and shared by all roots. Only the earliest
// bracketing subinterval is solved (solve_crossing), for the roots that cross in it; the probes
// are taken in order and stop there (the later ones cannot change the answer). With `solve`
// false a crossing is placed at t1 (detection at step ends, for demonstrations).
// `g0`, when given, holds the roots' values at x0 (the previous step's g1 for the same roots
// at the same state: a step's start is the last one's end), which are then not recomputed;
// `g1` likewise at x1 (the caller has them from the stepper's derivative there). A step with
// no root armed at x0 is not probed (nothing can cross on it).
// Throws EventLocationError as solve_crossing does.
template <std::size_t Capacity, class T, class State, class Interpolate, class Root>
EarliestCrossing<T, Capacity> locate_earliest(const T& t0, const State& x0, const T& t1,
                                              const State& x1, Interpolate&& interpolate,
                                              const RootSet<Capacity>& set, Root&& g,
                                              const LocatorOptions& opt, bool solve,
                                              const std::array<T, Capacity>* g0 = nullptr,
                                              const std::array<T, Capacity>* g1 = nullptr) {
  EarliestCrossing<T, Capacity> out;
  auto values_at = [&](const State& x, std::array<T, Capacity>& values) {
    for (int i = 0; i < set.size; ++i) values[i] = g(i, x);
  };
  // the roots' values at the ends of the subinterval [ta, tb] being probed
  std::array<T, Capacity> ga, gb;
  if (g0)
    ga = *g0;
  else
    values_at(x0, ga);
  bool armed = false, probe = false;
  for (int i = 0; i < set.size; ++i) {
    out.armed[i] = is_pre_event(ga[i], set.roots[i].direction);
    armed = armed || out.armed[i];
    probe = probe || !set.roots[i].monotone;
  }
  if (!armed) {  // nothing can cross: the values at x1 only, for the next step
    if (g1)
      out.g1 = *g1;
    else
      values_at(x1, out.g1);
    return out;
  }
  const int n = solve && probe ? std::clamp(opt.samples, 1, LocatorOptions::max_samples) : 1;
  State s{};  // interpolate() may fill only the components the roots read
  T ta = t0;
  for (int k = 1; k <= n; ++k) {
    const T tb = k == n ? t1 : T(t0 + (t1 - t0) * k / n);
    if (k < n) {
      interpolate(tb, s);
      values_at(s, gb);
    } else if (g1) {
      gb = *g1;
    } else {
      values_at(x1, gb);
    }
    bool crossed = false;
    for (int i = 0; i < set.size; ++i) {
      if (!out.armed[i] || is_pre_event(gb[i], set.roots[i].direction)) continue;
      crossed = true;
      if (solve) {
        auto g_of_t = [&](T t) {
          interpolate(t, s);
          return g(i, s);
        };
        out.found[i] = solve_crossing(g_of_t, ta, tb, ga[i], gb[i], set.roots[i].direction, opt);
      } else {
        out.found[i] = t1;
      }
      if (!out.t || *out.found[i] < *out.t) {
        out.t = out.found[i];
        out.first = i;
      }
    }
    if (crossed) return out;
    ta = tb;
    ga = gb;
  }
  out.g1 = gb;
  return out;
}

}  // namespace ivv
