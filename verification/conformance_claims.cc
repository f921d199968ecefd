// The claims on the trend of e an adhesive law's author makes (conformance.h: Claims), judged on
// the reference runs of the grid:
//   dynamic.captured_below   captured (e = 0) at every grid velocity below V, at every damping;
//                            without a dashpot, rebounding at every grid velocity at or above V
//   dynamic.increasing_v0    e non-decreasing in v0 at each damping (in place of
//                            dynamic.monotone_v0): an adhesive well traps the slow impacts
#include <algorithm>
#include <cmath>
#include <optional>

#include "verification/conformance_internal.h"

namespace ivv::conformance::detail {
namespace {

// The reference's e at v0 with dashpot c (inf: none), when it ran.
std::optional<double> reference_e(const std::vector<Run>& runs, double v0, double c) {
  for (const Run& r : runs)
    if (r.v0 == v0 && r.c == c && r.reference.ok()) return r.reference.e;
  return std::nullopt;
}

std::vector<double> dashpots(const std::vector<Run>& runs) {
  std::vector<double> cs;
  for (const Run& r : runs)
    if (std::find(cs.begin(), cs.end(), r.c) == cs.end()) cs.push_back(r.c);
  std::sort(cs.begin(), cs.end(), std::greater<>());
  return cs;
}

void captured_below_check(double V, const std::vector<Run>& runs, ConformanceResult& result) {
  int below = 0, above = 0, violations = 0;
  std::string first;
  for (const Run& r : runs) {
    const bool is_below = r.v0 < V;
    if (!is_below && !std::isinf(r.c)) continue;  // a dashpot may capture faster impacts too
    (is_below ? below : above) += 1;
    const ImpactResult& x = r.reference;
    const bool as_claimed = x.ok() && (is_below ? !x.separated() : x.separated());
    if (as_claimed) continue;
    if (violations++ == 0)
      first = run_label(r, "the reference") + " " +
              (x.ok() ? std::string(x.separated() ? "separated with e = " + fmt(x.e, 10)
                                                  : "was captured (e <= " + fmt(x.e_bound) + ")")
                      : "failed: " + x.reason);
  }
  std::string detail;
  if (below == 0)
    detail = "no grid velocity lies below " + fmt(V) +
             " m/s: the claim is not tested (give --v0 with velocities below it)";
  else if (violations == 0)
    detail = "captured at all " + std::to_string(below) + " run(s) below " + fmt(V) +
             " m/s (every damping), rebounding at all " + std::to_string(above) +
             " run(s) without a dashpot at or above it";
  else
    detail = std::to_string(violations) + " run(s) against the claim, first: " + first + " (" +
             std::to_string(below) + " below " + fmt(V) + " m/s, " + std::to_string(above) +
             " at or above it without a dashpot)";
  Check& c = result.checks.emplace_back(make_check(
      "dynamic.captured_below", violations, 0.0, 0.0, below > 0 && violations == 0,
      "capture is an outcome, not a number: each run below the claimed speed must be captured "
      "and, without a dashpot, each run at or above it must rebound (runs that contradict the "
      "claim are counted)",
      detail));
  c.unit = "runs";
  c.unit_si = NAN;
}

void increasing_check(const Grid& grid, const std::vector<Run>& runs, ConformanceResult& result) {
  double fall = 0;
  std::string at = "e never falls as v0 rises";
  for (double c : dashpots(runs))
    for (std::size_t i = 1; i < grid.velocities.size(); ++i) {
      const auto a = reference_e(runs, grid.velocities[i - 1], c);
      const auto b = reference_e(runs, grid.velocities[i], c);
      if (a && b && *a - *b > fall)
        fall = *a - *b,
        at = "e falls by " + fmt(fall) + " from v0 = " + fmt(grid.velocities[i - 1]) + " to " +
             fmt(grid.velocities[i]) + " m/s with " +
             (std::isinf(c) ? std::string("no dashpot") : "c = " + fmt(c) + " N s/m");
    }
  result.checks.push_back(make_check(
      "dynamic.increasing_v0", fall, 0.0, kMonotone, fall <= kMonotone,
      "claimed (--cor-increasing-in-v0): e non-decreasing in v0; a captured run counts as e = 0; "
      "the reference's error in e is at most 1e-10, so a fall above 1e-9 is the law's",
      at));
}

}  // namespace

void adhesive_claim_checks(const Claims& claims, const Grid& grid, const std::vector<Run>& runs,
                           ConformanceResult& result) {
  if (claims.cor_nondecreasing_in_v0)
    increasing_check(grid, runs, result);
  else
    result.skipped.push_back({"dynamic.increasing_v0", "not claimed (--cor-increasing-in-v0)"});
  if (claims.captured_below)
    captured_below_check(*claims.captured_below, runs, result);
  else
    result.skipped.push_back({"dynamic.captured_below", "not claimed (--captured-below V)"});
}

}  // namespace ivv::conformance::detail
