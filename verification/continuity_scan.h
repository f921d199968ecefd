// Discontinuity scan of a force curve F(z) on [lo, hi]: does it jump anywhere, declared or not?
//
// Method. F is sampled at N + 1 equally spaced points (spacing dz = (hi - lo)/N). An interval
// whose change |F(b) - F(a)| exceeds the tolerance tau [N] is bisected, always into the half
// with the larger change, until the bracket is two adjacent doubles (or the change falls to
// tau or below: no jump there). For a continuous F the change across the bracket vanishes as it
// shrinks (|F'| h for a finite slope); across a jump of size J it tends to J. A bracket that
// ends wider than tau, and whose change did not fall by half over its last 10 halvings, is a
// located jump: z (the bracket, a few ulps wide) and the two one-sided values F(z-), F(z+).
// A value that is not finite (NaN, inf) is located the same way and reported as such.
//
// What it finds and what it cannot (the statement the check repeats):
//   - every jump larger than the resolution R = 2 max_i |F(z_{i+1}) - F(z_i)| (the largest
//     change across one sample interval without a jump): bisection follows such a jump down;
//   - a smaller jump is found unless the smooth change of F across its half-interval masks it;
//   - a pulse narrower than dz (a jump and its return between two samples) can be missed
//     entirely; so can any feature between samples whose ends agree within tau;
//   - a cusp steeper than Hoelder exponent 0.1 (|F(z) - F(z0)| ~ |z - z0|^0.1) is reported as a
//     jump: its change halves less than once in 10 halvings, as a jump's does not at all.
// Cost: N + 1 evaluations, plus about log2(change/tau) per bisected interval.
#pragma once

#include <functional>
#include <optional>
#include <string>

namespace ivv::conformance {

struct Jump {
  double z_left = 0.0, z_right = 0.0;  // the final bracket [m] (adjacent doubles, or a few ulps)
  double F_left = 0.0, F_right = 0.0;  // the one-sided values F(z-), F(z+) [N]
  bool finite() const;                 // false: F is NaN or infinite at the bracket
  double size() const;                 // |F_right - F_left| (inf when not finite)
};

struct ScanResult {
  int intervals = 0;            // N
  double spacing = 0.0;         // dz [m]
  double resolution = 0.0;      // R [N]: jumps above it are certainly located
  int jumps = 0;                // located jumps (and non-finite values)
  std::optional<Jump> largest;  // the largest located jump (a non-finite value first)
};

// Scans f on [lo, hi] (lo < hi, both finite) with n >= 1 intervals; tau > 0 [N].
ScanResult scan_for_jumps(const std::function<double(double)>& f, double lo, double hi, int n,
                          double tau);

// "a jump is located when it exceeds R = ... N; a pulse narrower than dz = ... m can be
// missed" - what the scan could not see, in the scan's own numbers.
std::string blind_spots(const ScanResult& scan);

}  // namespace ivv::conformance
