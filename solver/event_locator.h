// Event location: the earliest signed zero crossing of g on a step's interpolant.
//
// An event is a scalar function g(t) of the solution and a direction. A crossing in a
// subinterval [a, b] means g(a) is strictly on the pre-event side and g(b) is on the
// post-event side or zero (rising: g(a) < 0 <= g(b); falling: g(a) > 0 >= g(b)). A zero exactly
// at the start of a step therefore never fires again after a restart there.
//
// The step [t0, t1] is first sampled at `samples` equal subintervals so that two roots inside
// one step (g returning to its pre-event side before t1) are not missed; the first bracketing
// subinterval is then solved with TOMS 748 (Alefeld, Potra & Shi, ACM TOMS 21:327, 1995;
// boost::math::tools::toms748_solve) to the precision of T. The returned time is the post-event
// end of the final bracket, so the state there is on the event's far side. A root finder
// that runs out of iterations before the bracket is resolved throws EventLocationError (the
// driver turns it into a failed run with that reason): an event is never placed at an
// unconverged time silently.
#pragma once

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

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
};

// Solves a bracket [a, b] with g(a) strictly before the event and g(b) after it (or zero) by
// TOMS 748 and returns the post-event end of the final bracket. When TOMS 748 uses up
// max_iterations first, bisection finishes the bracket (it halves the bracket whatever the
// rounding noise of g, which can stall TOMS 748's interpolation steps: measured, the 50-digit
// reference near capture stopped at a relative width of 1.5e-20 against 2^-165 asked). Throws
// EventLocationError if max_iterations bisections do not reach the tolerance of `bits` either.
template <class T, class G>
T solve_crossing(G&& g, const T& a, const T& b, const T& ga, const T& gb, Direction dir,
                 const LocatorOptions& opt = {}) {
  if (gb == 0) return b;
  const int digits = std::numeric_limits<T>::digits;
  const int bits = opt.bits > 0 ? opt.bits : digits - 3;
  boost::math::tools::eps_tolerance<T> tol(bits);
  std::uintmax_t iterations = opt.max_iterations;
  const auto bracket = boost::math::tools::toms748_solve(g, a, b, ga, gb, tol, iterations);
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

}  // namespace ivv
