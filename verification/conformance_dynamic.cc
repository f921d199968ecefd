// The dynamic checks of a contact law: impacts over a grid of velocities and dashpots, each run
// by the reference and by every integrator under comparison (verification/conformance.h lists
// each check with its tolerance and why).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <string_view>

#include "verification/conformance_internal.h"
#include "verification/tolerances.h"

namespace ivv::conformance::detail {
namespace {

std::string label(const Run& r, std::string_view who) {
  return std::string(who) + " at v0 = " + fmt(r.v0) + " m/s, " + damping_label(r.damping);
}

// The reference and every integrator stopped because the law is not defined there.
bool outside_domain(const Run& r) {
  if (r.reference.ok() || r.reference.failure != FailureKind::law_domain) return false;
  return std::all_of(r.runs.begin(), r.runs.end(), [](const auto& kr) {
    return !kr.second.ok() && kr.second.failure == FailureKind::law_domain;
  });
}

std::string domain_note(const std::vector<Run>& runs) {
  int n = 0;
  std::string first;
  for (const Run& r : runs)
    if (outside_domain(r) && n++ == 0) first = label(r, "first") + ": " + r.reference.reason;
  return n == 0 ? ""
                : "; " + std::to_string(n) +
                      " grid point(s) outside the law's domain, not judged (" + first + ")";
}

void ledger_checks(const std::vector<Run>& runs, ConformanceResult& result) {
  double energy = 0, range = 0, definitions = 0;
  std::string energy_at = "every run", range_at = "every run", definitions_at = "every run";
  int failed = 0;
  std::string first_failure;
  auto judge = [&](const Run& r, std::string_view who, const ImpactResult& x) {
    if (!x.ok()) {
      if (failed++ == 0) first_failure = label(r, who) + ": " + x.reason;
      return;
    }
    const double res = std::abs(x.energy.residual) / x.energy.initial;
    if (res >= energy) energy = res, energy_at = label(r, who);
    const double out = std::max(-x.e, x.e - 1.0);
    if (out >= range) range = out, range_at = label(r, who) + ", e = " + fmt(x.e, 12);
    if (x.separated()) {
      const double d = std::max(std::abs(x.e - x.e_poisson), std::abs(x.e - x.e_energetic));
      if (d >= definitions)
        definitions = d, definitions_at = label(r, who) + ": Newton " + fmt(x.e, 12) +
                                          ", Poisson " + fmt(x.e_poisson, 12) + ", energetic " +
                                          fmt(x.e_energetic, 12);
    }
  };
  for (const Run& r : runs) {
    if (outside_domain(r)) continue;
    judge(r, "reference", r.reference);
    for (const auto& [k, x] : r.runs) judge(r, to_string(k), x);
  }
  const auto tol = verification::conservation_tolerance(IntegratorKind::odeint_dopri5);
  const std::string failures =
      (failed ? "; " + std::to_string(failed) + " run(s) failed, first: " + first_failure : "") +
      domain_note(runs);
  Check& en = result.checks.emplace_back(make_check(
      "dynamic.energy", energy, 0.0, tol.value, energy <= tol.value && failed == 0, tol.reason,
      "largest |ledger residual| / E0 = " + fmt(energy) + " (" + energy_at + ")" + failures));
  en.unit = "E0", en.unit_si = NAN, en.si_unit = "J (E0 = m v0^2/2 of each run)";
  result.checks.push_back(make_check(
      "dynamic.cor_range", range, 0.0, tol.value, range <= tol.value && failed == 0,
      "e outside [0, 1] by more than the integration error of e (as for the ledger)",
      range > 0 ? "largest excursion outside [0, 1]: " + fmt(range) + " (" + range_at + ")"
                : "0 <= e <= 1 in every run" + failures));
  result.checks.push_back(make_check(
      "dynamic.cor_definitions", definitions, 0.0, tol.value,
      definitions <= tol.value && failed == 0,
      "for a frictionless central impact of a point mass the three CORs are equal; they are "
      "integrated quantities with the error of the ledger",
      "largest difference " + fmt(definitions) + " (" + definitions_at + ")" + failures));
}

// How far run x is from the reference: e always (a captured run: e = 0 up to its capture bound
// e_bound, so the true values may differ by the larger bound), F_max relative, and t_contact
// relative only when both separated (a captured run's end is the moment a capture criterion
// was met, not a contact time). nullopt: the two outcomes contradict each other.
struct Difference {
  double e = 0, F = 0, t = NAN;
  double worst() const { return std::max({e, F, std::isnan(t) ? 0.0 : t}); }
};
std::optional<Difference> difference(const ImpactResult& x, const ImpactResult& ref,
                                     double tolerance) {
  Difference d;
  d.F = std::abs(x.F_max - ref.F_max) / std::abs(ref.F_max);
  if (x.separated() && ref.separated()) {
    d.e = std::abs(x.e - ref.e);
    d.t = std::abs(x.t_contact - ref.t_contact) / std::abs(ref.t_contact);
    return d;
  }
  // at least one captured: its true e lies in [0, e_bound]
  if (!x.separated() && !ref.separated()) {
    d.e = std::max({std::abs(x.e - ref.e), x.e_bound, ref.e_bound});
    return d;
  }
  // one separated with e_s, the other captured with bound b: consistent when e_s <= b (within
  // the tolerance); the true values then differ by at most max(e_s, b)
  const double e_s = x.separated() ? x.e : ref.e;
  const double b = x.separated() ? ref.e_bound : x.e_bound;
  if (e_s > b + tolerance) return std::nullopt;
  d.e = std::max(e_s, b);
  return d;
}

void integrator_check(const LawUnderTest& law, const std::vector<Run>& runs,
                      ConformanceResult& result) {
  const auto itol = verification::default_settings_tolerance(IntegratorKind::odeint_dopri5);
  double worst = 0, reference_error = 0;
  std::string worst_at = "no comparison", mismatch;
  int compared = 0, captured = 0;
  for (const Run& r : runs) {
    reference_error = std::max(reference_error, r.reference_error);
    if (!r.reference.ok()) continue;
    for (const auto& [k, x] : r.runs) {
      const auto d = x.ok() ? difference(x, r.reference, itol.value) : std::nullopt;
      if (!d) {
        if (mismatch.empty())
          mismatch = label(r, to_string(k)) + " ended " + std::string(to_string(x.status)) +
                     (x.reason.empty() ? "" : " (" + x.reason + ")") + " with e = " + fmt(x.e) +
                     ", the reference " + std::string(to_string(r.reference.status)) +
                     " with e = " + fmt(r.reference.e);
        continue;
      }
      ++compared;
      captured += std::isnan(d->t);
      if (d->worst() >= worst)
        worst = d->worst(), worst_at = label(r, to_string(k)) + ": |de| " + fmt(d->e) + ", F_max " +
                                       fmt(d->F) +
                                       (std::isnan(d->t) ? ", t_contact not compared (captured)"
                                                         : ", t_contact " + fmt(d->t)) +
                                       " relative";
    }
  }
  result.checks.push_back(make_check(
      "dynamic.integrators", worst, 0.0, itol.value,
      worst <= itol.value && mismatch.empty() && compared > 0, itol.reason,
      std::to_string(compared) + " runs against " +
          (law.runs_in_reference ? "mp50 (50 digits, tol 1e-26)"
                                 : "dp45 at rtol 1e-13 (its own error estimated at " +
                                       fmt(reference_error) + " in e from its run at 1e-12)") +
          (captured ? " (" + std::to_string(captured) +
                          " captured: e within the capture bound, no contact time)"
                    : "") +
          "; largest difference at " + worst_at + (mismatch.empty() ? "" : "; " + mismatch) +
          domain_note(runs)));
}

// The reference's e at one grid point (dashpot c [N s/m], inf: none), when it ran.
std::optional<double> e_of(const std::vector<Run>& runs, double v0, double c) {
  for (const Run& r : runs)
    if (r.v0 == v0 && r.c == c && r.reference.ok()) return r.reference.e;
  return std::nullopt;
}

// The dashpots of the runs, weakest first (c = inf, no dashpot, first).
std::vector<double> dashpots_of(const std::vector<Run>& runs) {
  std::vector<double> cs;
  for (const Run& r : runs)
    if (std::find(cs.begin(), cs.end(), r.c) == cs.end()) cs.push_back(r.c);
  std::sort(cs.begin(), cs.end(), std::greater<>());
  return cs;
}

std::string dashpot_text(double c) {
  return std::isinf(c) ? "no dashpot" : "c = " + fmt(c) + " N s/m";
}

void monotone_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                     const std::vector<Run>& runs, ConformanceResult& result) {
  const std::vector<double> cs = dashpots_of(runs);
  if (claims.cor_nonincreasing_in_v0) {
    double rise = 0;
    std::string at = "e never rises with v0";
    for (double c : cs)
      for (std::size_t i = 1; i < grid.velocities.size(); ++i) {
        const auto a = e_of(runs, grid.velocities[i - 1], c);
        const auto b = e_of(runs, grid.velocities[i], c);
        if (a && b && *b - *a > rise)
          rise = *b - *a, at = "e rises by " + fmt(rise) +
                               " from v0 = " + fmt(grid.velocities[i - 1]) + " to " +
                               fmt(grid.velocities[i]) + " m/s with " + dashpot_text(c);
      }
    result.checks.push_back(make_check(
        "dynamic.monotone_v0", rise, 0.0, kMonotone, rise <= kMonotone,
        "the reference's error in e is at most 1e-10; a rise above 1e-9 is the law's", at));
  } else {
    result.skipped.push_back({"dynamic.monotone_v0", "not claimed"});
  }
  if (claims.cor_nonincreasing_in_damping && cs.size() > 1) {
    double rise = 0;
    std::string at = "e never rises with the damping";
    for (double v0 : grid.velocities)
      for (std::size_t i = 1; i < cs.size(); ++i) {
        const auto a = e_of(runs, v0, cs[i - 1]), b = e_of(runs, v0, cs[i]);
        if (a && b && *b - *a > rise)
          rise = *b - *a, at = "e rises by " + fmt(rise) + " from " + dashpot_text(cs[i - 1]) +
                               " to " + dashpot_text(cs[i]) + " at v0 = " + fmt(v0) + " m/s";
      }
    result.checks.push_back(make_check(
        "dynamic.monotone_damping", rise, 0.0, kMonotone, rise <= kMonotone,
        "the reference's error in e is at most 1e-10; a rise above 1e-9 is the law's", at));
  } else {
    result.skipped.push_back(
        {"dynamic.monotone_damping",
         law.rate_dependent ? "the law carries its own damping: no series dashpot to vary"
         : cs.size() <= 1   ? "the grid has one damping only (give --zeta or --c with two)"
                            : "not claimed"});
  }
}

void low_speed_check(const Claims& claims, const Grid& grid, const std::vector<Run>& runs,
                     ConformanceResult& result) {
  if (!claims.elastic_at_low_speed) {
    result.skipped.push_back({"dynamic.low_speed", "not claimed (--elastic-at-low-speed)"});
    return;
  }
  // 1 - e at the three lowest velocities: zero within the reference's error, or falling as a
  // power of v0 (viscoelastic laws: 1 - e ~ v0^{1/5}); any exponent the reference's error
  // cannot explain is a fall, since the claim is only that the loss vanishes as v0 -> 0
  const double none = std::numeric_limits<double>::infinity();
  std::vector<double> lv, lq;
  for (std::size_t i = 0; i < std::min<std::size_t>(3, grid.velocities.size()); ++i)
    if (auto e = e_of(runs, grid.velocities[i], none)) {
      lv.push_back(std::log(grid.velocities[i]));
      lq.push_back(std::log(std::max(1.0 - *e, 1e-300)));
    }
  const auto e_low = e_of(runs, grid.velocities.front(), none);
  const double loss = e_low ? 1.0 - *e_low : NAN;
  double slope = NAN, slope_noise = NAN;
  if (lv.size() >= 2) {
    slope = (lq.back() - lq.front()) / (lv.back() - lv.front());
    // the reference's error kMonotone in e moves ln(1 - e) by kMonotone/(1 - e) at each end
    const double smallest_loss = std::exp(std::min(lq.front(), lq.back()));
    slope_noise = 2.0 * kMonotone / smallest_loss / (lv.back() - lv.front());
  }
  const bool exact = e_low && loss <= kMonotone;
  const bool vanishing = std::isfinite(slope) && slope > slope_noise;
  Check& c = result.checks.emplace_back(make_check(
      "dynamic.low_speed", exact ? loss : slope, exact ? 0.0 : slope_noise,
      exact ? kMonotone : slope_noise, exact || vanishing,
      "elastic at low speed: 1 - e within the reference's error of e (1e-9) at the lowest v0, "
      "or 1 - e falling with v0 over the three lowest: its local exponent above what the "
      "reference's error alone could produce, 2e-9/((1 - e) ln(v_3/v_1)) (viscoelastic laws: "
      "1/5)",
      "1 - e = " + fmt(loss) + " at v0 = " + fmt(grid.velocities.front()) +
          " m/s; local exponent of 1 - e in v0: " + fmt(slope, 4) +
          (std::isfinite(slope_noise) ? " (noise bound " + fmt(slope_noise, 3) + ")" : "")));
  if (!exact) c.bound = Bound::at_least;
  if (e_low) c.value = *e_low, c.reference_value = 1.0, c.value_unit = "-";
}

void expected_cor_check(const Claims& claims, ConformanceResult& result) {
  if (!claims.expected_cor) {
    result.skipped.push_back({"dynamic.expected_cor", "no COR claimed (--expect-cor)"});
    return;
  }
  double miss = 0, signed_miss = 0;
  std::optional<std::pair<double, double>> worst;  // delivered, expected
  std::string at = "no separated run";
  int n = 0;
  for (const CorPoint& c : result.cor) {
    if (!c.expected || !c.e) continue;
    ++n;
    const double d = *c.e - *c.expected;
    if (!std::isfinite(d)) {  // never a silent pass on a NaN (run_conformance refuses those)
      miss = signed_miss = std::numeric_limits<double>::infinity();
      at = "v0 = " + fmt(c.v0) + " m/s: delivered e = " + fmt(*c.e, 10) + ", expected " +
           fmt(*c.expected, 10);
      break;
    }
    if (std::abs(d) >= miss)
      miss = std::abs(d), signed_miss = d, worst = std::pair{*c.e, *c.expected},
      at = "v0 = " + fmt(c.v0) + " m/s: delivered e = " + fmt(*c.e, 10) + ", expected " +
           fmt(*c.expected, 10);
  }
  Check& c = result.checks.emplace_back(
      make_check("dynamic.expected_cor", miss, 0.0, claims.cor_tolerance,
                 n > 0 && miss <= claims.cor_tolerance, claims.cor_tolerance_reason,
                 "largest |e - (" + claims.expected_cor_text + ")| = " + fmt(miss) + " (" +
                     (signed_miss > 0 ? "over" : "under") + "), at " + at + "; " +
                     std::to_string(n) + " velocities"));
  if (worst) c.value = worst->first, c.reference_value = worst->second, c.value_unit = "-";
}

void cor_curve(const Claims& claims, const std::vector<Run>& runs, ConformanceResult& result) {
  for (const Run& r : runs) {
    CorPoint c;
    c.v0 = r.v0, c.zeta = r.zeta, c.c = r.c;
    c.status = std::string(to_string(r.reference.status));
    if (r.reference.ok()) {
      c.e = r.reference.e;
      if (!r.reference.separated()) c.e_bound = r.reference.e_bound;
    } else {
      c.status = r.reference.reason;
    }
    if (claims.expected_cor && std::isinf(r.c)) c.expected = claims.expected_cor(r.v0);
    result.cor.push_back(c);
  }
}

}  // namespace

std::string damping_label(const Damping& d) {
  switch (d.kind) {
    case Damping::Kind::none:
      return "no dashpot";
    case Damping::Kind::ratio:
      return "zeta = " + fmt(d.value);
    case Damping::Kind::coefficient:
      return "c = " + fmt(d.value) + " N s/m";
    case Damping::Kind::zener_lambda:
      return "lambda = " + fmt(d.value);
    case Damping::Kind::structure:
      return "the structure's dashpot";
  }
  return "?";
}

Scene at(const Scene& base, double v0, const Damping& damping) {
  Scene s = base;
  s.velocity = v0;
  s.damping =
      damping.kind == Damping::Kind::ratio && damping.value == 0 ? Damping::none() : damping;
  return s;
}

std::vector<Run> run_grid(const LawUnderTest& law, const Grid& grid) {
  std::vector<Damping> dampings;
  for (double z : grid.zetas) dampings.push_back(z == 0 ? Damping::none() : Damping::ratio(z));
  for (double c : grid.dashpots) dampings.push_back(Damping::coefficient(c));
  std::vector<Run> runs;
  for (const Damping& damping : dampings) {
    if (law.rate_dependent && damping.kind != Damping::Kind::none) continue;
    for (double v0 : grid.velocities) {
      Run r;
      r.v0 = v0;
      const Scene s = at(grid.scene, v0, damping);
      r.damping = s.damping;
      const DerivedParameters p = derive(s);
      r.zeta = p.zeta, r.c = p.c;
      if (law.runs_in_reference) {
        r.reference = law.simulate(s, IntegratorKind::mp50, grid.options);
      } else {
        IntegratorOptions tight = grid.options;
        tight.rtol = 1e-13;
        tight.atol = 1e-15;
        r.reference = law.simulate(s, IntegratorKind::dp45, tight);
        tight.rtol = 1e-12;
        tight.atol = 1e-14;
        const ImpactResult looser = law.simulate(s, IntegratorKind::dp45, tight);
        r.reference_error = std::abs(looser.e - r.reference.e);
      }
      for (IntegratorKind k : grid.integrators)
        r.runs.push_back({k, law.simulate(s, k, grid.options)});
      runs.push_back(std::move(r));
    }
  }
  return runs;
}

void dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                    const std::vector<Run>& runs, ConformanceResult& result) {
  cor_curve(claims, runs, result);
  ledger_checks(runs, result);
  integrator_check(law, runs, result);
  monotone_checks(law, claims, grid, runs, result);
  low_speed_check(claims, grid, runs, result);
  expected_cor_check(claims, result);
}

}  // namespace ivv::conformance::detail
