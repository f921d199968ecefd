#include "verification/continuity_scan.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

#include "solver/format.h"

namespace ivv::conformance {
namespace {

// A continuous F's change across the bracket falls at least by half over this many halvings
// (Hoelder exponent >= 0.1); a jump's does not fall at all.
constexpr std::size_t kRatioLevels = 10;
// Bisection of [0, h] reaches the subnormals after ~1075 halvings; nothing needs more.
constexpr std::size_t kMaxLevels = 1100;

double change(double a, double b) {
  if (!std::isfinite(a) || !std::isfinite(b)) return std::numeric_limits<double>::infinity();
  return std::abs(b - a);
}

// Bisects [a, b] (change > tau) towards the larger change; a located jump, or nullopt.
std::optional<Jump> bisect(const std::function<double(double)>& f, double a, double b, double fa,
                           double fb, double tau) {
  std::vector<double> changes{change(fa, fb)};  // the bracket's change at each level
  while (changes.size() <= kMaxLevels) {
    const double m = a + 0.5 * (b - a);
    if (!(m > a && m < b)) break;  // adjacent doubles
    const double fm = f(m);
    const double left = change(fa, fm), right = change(fm, fb);
    if (left >= right)
      b = m, fb = fm;
    else
      a = m, fa = fm;
    changes.push_back(std::max(left, right));
    if (changes.back() <= tau) return std::nullopt;
  }
  const bool finite = std::isfinite(fa) && std::isfinite(fb);
  if (finite && changes.size() > kRatioLevels) {
    const double earlier = changes[changes.size() - 1 - kRatioLevels];
    if (changes.back() < 0.5 * earlier) return std::nullopt;  // still shrinking: continuous
  }
  return Jump{a, b, fa, fb};
}

// Three significant digits: enough for a reason, short enough to read (solver/format.h).
std::string fmt3(double v) {
  return fmt(v, 3);
}

}  // namespace

bool Jump::finite() const {
  return std::isfinite(F_left) && std::isfinite(F_right);
}

double Jump::size() const {
  return change(F_left, F_right);
}

ScanResult scan_for_jumps(const std::function<double(double)>& f, double lo, double hi, int n,
                          double tau) {
  ScanResult out;
  out.intervals = n;
  out.spacing = (hi - lo) / n;
  double largest_smooth = 0.0;
  double z_a = lo, f_a = f(lo);
  for (int i = 1; i <= n; ++i) {
    const double z_b = i == n ? hi : lo + (hi - lo) * i / n;
    const double f_b = f(z_b);
    const double d = change(f_a, f_b);
    std::optional<Jump> jump;
    if (d > tau) jump = bisect(f, z_a, z_b, f_a, f_b, tau);
    if (jump) {
      ++out.jumps;
      const bool worse =
          !out.largest || (out.largest->finite() && jump->size() > out.largest->size());
      if (worse) out.largest = jump;
    } else {
      largest_smooth = std::max(largest_smooth, d);
    }
    z_a = z_b, f_a = f_b;
  }
  out.resolution = 2.0 * largest_smooth;
  return out;
}

std::string blind_spots(const ScanResult& scan) {
  return "a jump above R = " + fmt3(scan.resolution) +
         " N (twice the largest change across one of " + std::to_string(scan.intervals) +
         " sample intervals) is always located; a smaller one can be masked by the smooth change "
         "around it, and a pulse narrower than dz = " +
         fmt3(scan.spacing) + " m (a jump and its return between two samples) can be missed";
}

}  // namespace ivv::conformance
