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
  return run_label(r, who);
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

// The three measures of one run that the ledger checks bound (inf for a failed run).
struct LedgerMeasures {
  double energy = 0, range = 0, definitions = 0;
};
LedgerMeasures ledger_measures(const ImpactResult& x) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if (!x.ok()) return {inf, inf, inf};
  LedgerMeasures m;
  m.energy = std::abs(x.energy.residual) / x.energy.initial;
  m.range = std::max(-x.e, x.e - 1.0);
  if (x.separated())
    m.definitions = std::max(std::abs(x.e - x.e_poisson), std::abs(x.e - x.e_energetic));
  return m;
}

IntegratorNote make_note(std::string check, const Run& r, std::string_view who, double error,
                         double tolerance, double tight, std::string detail) {
  IntegratorNote n;
  n.check = std::move(check);
  n.integrator = std::string(who);
  n.v0 = r.v0;
  n.damping = damping_label(r.damping);
  n.error = error;
  n.tolerance = tolerance;
  n.error_tight = tight;
  n.detail = std::move(detail);
  return n;
}

// An integrator that stopped at its step limit against a dashpot where the reference ended:
// an explicit stepper held by stability to the dashpot's time scale (solver/driver/
// dashpot_stall.h), which says nothing about the law.
bool stiff_for_integrator(const Run& r, const ImpactResult& x) {
  return !x.ok() && x.failure == FailureKind::step_limit && r.damping.kind != Damping::Kind::none &&
         r.reference.ok();
}
IntegratorNote stiffness_note(std::string check, const Run& r, std::string_view who,
                              double tolerance, const ImpactResult& x) {
  return make_note(std::move(check), r, who, std::numeric_limits<double>::infinity(), tolerance,
                   NAN,
                   "the integrator cannot run this point (" + x.reason + "); the reference, " +
                       std::string(r.reference.integrator) +
                       ", ended it: the integrator's limit, not the law's");
}

// The worst of one ledger measure over the runs that the law is blamed for.
struct Worst {
  double value = 0;
  std::string at = "every run";
  void add(double v, std::string where) {
    if (v >= value) value = v, at = std::move(where);
  }
};

// The ledger checks (energy, cor_range, cor_definitions). A run over a tolerance, or failed, is
// repeated tighter (Rechecks); where the measure then meets the tolerance the run's excess is
// the integrator's accuracy (a note), else the law's.
class LedgerJudge {
 public:
  LedgerJudge(Rechecks& rechecks, ConformanceResult& result, double tolerance)
      : rechecks_(rechecks), result_(result), tol_(tolerance) {}

  void judge(const Run& r, std::optional<IntegratorKind> k, const ImpactResult& x) {
    const std::string who = k ? std::string(to_string(*k)) : "reference";
    if (k && stiff_for_integrator(r, x)) {
      result_.notes.push_back(stiffness_note("dynamic.energy", r, who, tol_, x));
      ++stopped_;  // no ledger to judge: the run did not reach the end
      return;
    }
    const LedgerMeasures m = ledger_measures(x);
    if (!x.ok() || m.energy > tol_ || m.range > tol_ || m.definitions > tol_) {
      const ImpactResult& tight = k ? rechecks_.integrator(r, *k) : rechecks_.reference(r);
      const LedgerMeasures t = ledger_measures(tight);
      if (t.energy <= tol_ && t.range <= tol_ && t.definitions <= tol_) {
        excuse(r, who, x, m, t, k);
        return;
      }
    }
    if (!x.ok()) {
      if (failed_++ == 0) first_failure_ = label(r, who) + ": " + x.reason;
      return;
    }
    energy_.add(m.energy, label(r, who));
    range_.add(m.range, label(r, who) + ", e = " + fmt(x.e, 12));
    if (x.separated())
      definitions_.add(m.definitions, label(r, who) + ": Newton " + fmt(x.e, 12) + ", Poisson " +
                                          fmt(x.e_poisson, 12) + ", energetic " +
                                          fmt(x.e_energetic, 12));
  }

  void report(const std::vector<Run>& runs, const std::string& reason) {
    const std::string failures =
        (failed_ ? "; " + std::to_string(failed_) + " run(s) failed, first: " + first_failure_
                 : "") +
        domain_note(runs);
    Check& en = result_.checks.emplace_back(make_check(
        "dynamic.energy", energy_.value, 0.0, tol_, energy_.value <= tol_ && failed_ == 0, reason,
        "largest |ledger residual| / E0 = " + fmt(energy_.value) + " (" + energy_.at + ")" +
            failures + notes_text("dynamic.energy") + stopped_text()));
    en.unit = "E0", en.unit_si = NAN, en.si_unit = "J (E0 = m v0^2/2 of each run)";
    result_.checks.push_back(make_check(
        "dynamic.cor_range", range_.value, 0.0, tol_, range_.value <= tol_ && failed_ == 0,
        "e outside [0, 1] by more than the integration error of e (as for the ledger)",
        (range_.value > 0
             ? "largest excursion outside [0, 1]: " + fmt(range_.value) + " (" + range_.at + ")"
             : "0 <= e <= 1 in every run") +
            failures + notes_text("dynamic.cor_range")));
    result_.checks.push_back(make_check(
        "dynamic.cor_definitions", definitions_.value, 0.0, tol_,
        definitions_.value <= tol_ && failed_ == 0,
        "for a frictionless central impact of a point mass the three CORs are equal; they are "
        "integrated quantities with the error of the ledger",
        "largest difference " + fmt(definitions_.value) + " (" + definitions_.at + ")" + failures +
            notes_text("dynamic.cor_definitions")));
  }

 private:
  void excuse(const Run& r, const std::string& who, const ImpactResult& x, const LedgerMeasures& m,
              const LedgerMeasures& t, std::optional<IntegratorKind> k) {
    const std::string settings = k ? rechecks_.settings(*k) : "the reference repeated tighter";
    if (!x.ok()) {
      result_.notes.push_back(make_note("dynamic.energy", r, who, m.energy, tol_, t.energy,
                                        "the run failed (" + x.reason + "); repeated with " +
                                            settings + " it succeeds and its ledger closes"));
      ++excused_["dynamic.energy"];
      return;
    }
    const std::pair<const char*, std::pair<double, double>> measures[] = {
        {"dynamic.energy", {m.energy, t.energy}},
        {"dynamic.cor_range", {m.range, t.range}},
        {"dynamic.cor_definitions", {m.definitions, t.definitions}}};
    for (const auto& [id, values] : measures)
      if (values.first > tol_) {
        result_.notes.push_back(make_note(id, r, who, values.first, tol_, values.second,
                                          fmt(values.first) + " at the grid's settings, " +
                                              fmt(values.second) + " with " + settings));
        ++excused_[id];
      }
  }
  // Runs an explicit integrator stopped short (the stiffness bound): not in the ledger's worst.
  std::string stopped_text() const {
    return stopped_ ? "; " + std::to_string(stopped_) +
                          " run(s) stopped by the integrator before the end (a dashpot too stiff "
                          "for an explicit stepper; the reference ended them): no ledger to "
                          "judge, not an energy defect (integrator notes)"
                    : "";
  }
  std::string notes_text(const std::string& id) const {
    const auto it = excused_.find(id);
    return it != excused_.end() ? "; " + std::to_string(it->second) +
                                      " excess(es) of the integrators' accuracy, gone when "
                                      "repeated tighter (integrator notes)"
                                : "";
  }

  Rechecks& rechecks_;
  ConformanceResult& result_;
  double tol_;
  Worst energy_, range_, definitions_;
  int failed_ = 0;
  int stopped_ = 0;                     // runs the stiffness bound stopped (stiff_for_integrator)
  std::map<std::string, int> excused_;  // per check id
  std::string first_failure_;
};

void ledger_checks(Rechecks& rechecks, const std::vector<Run>& runs, ConformanceResult& result) {
  const auto tol = verification::conservation_tolerance(IntegratorKind::odeint_dopri5);
  LedgerJudge judge(rechecks, result, tol.value);
  for (const Run& r : runs) {
    if (outside_domain(r)) continue;
    judge.judge(r, std::nullopt, r.reference);
    for (const auto& [k, x] : r.runs) judge.judge(r, k, x);
  }
  judge.report(runs, tol.reason);
}

// How far run x is from the reference: e always, F_max relative, and t_contact relative only
// when both separated (a captured run's end is the moment a capture criterion was met, not a
// contact time). A captured run states e = 0 with the true e in [0, e_bound]: e is then the
// distance between what the two runs state (0 when both are captured, or when a separated e
// lies within the other's bound), and `looseness` the capture bound beyond that agreement,
// which is the integrator's precision, not a difference. nullopt: the two outcomes contradict
// each other.
struct Difference {
  double e = 0, F = 0, t = NAN;
  double looseness = 0;
  double worst() const { return std::max({e, F, std::isnan(t) ? 0.0 : t}); }
};
std::optional<Difference> difference(const ImpactResult& x, const ImpactResult& ref,
                                     double tolerance) {
  if (!x.ok() || !ref.ok()) return std::nullopt;
  Difference d;
  d.F = std::abs(x.F_max - ref.F_max) / std::abs(ref.F_max);
  if (x.separated() && ref.separated()) {
    d.e = std::abs(x.e - ref.e);
    d.t = std::abs(x.t_contact - ref.t_contact) / std::abs(ref.t_contact);
    return d;
  }
  if (!x.separated() && !ref.separated()) {  // both state e = 0
    d.e = std::abs(x.e - ref.e);
    d.looseness = std::max(x.e_bound, ref.e_bound);
    return d;
  }
  // one separated with e_s, the other captured with bound b: consistent when e_s <= b (within
  // the tolerance)
  const double e_s = x.separated() ? x.e : ref.e;
  const double b = x.separated() ? ref.e_bound : x.e_bound;
  if (e_s > b + tolerance) return std::nullopt;
  d.e = std::max(0.0, e_s - b);
  d.looseness = b;
  return d;
}

std::string difference_text(const Difference& d) {
  return "|de| " + fmt(d.e) + ", F_max " + fmt(d.F) +
         (std::isnan(d.t) ? ", t_contact not compared (captured)" : ", t_contact " + fmt(d.t)) +
         " relative";
}

std::string outcome_text(const ImpactResult& x) {
  return std::string(to_string(x.status)) + (x.reason.empty() ? "" : " (" + x.reason + ")") +
         " with e = " + fmt(x.e) + (x.separated() ? "" : " <= " + fmt(x.e_bound));
}

// The integrators against the reference; a difference over the tolerance is repeated tighter
// (Rechecks), and one that is gone there is a note, not the law's.
class IntegratorJudge {
 public:
  IntegratorJudge(Rechecks& rechecks, ConformanceResult& result, double tolerance)
      : rechecks_(rechecks), result_(result), tol_(tolerance) {}

  void judge(const Run& r, IntegratorKind k, const ImpactResult& x) {
    if (stiff_for_integrator(r, x)) {
      result_.notes.push_back(stiffness_note("dynamic.integrators", r, to_string(k), tol_, x));
      ++stopped_;
      return;
    }
    const auto d = difference(x, r.reference, tol_);
    if (d && d->worst() <= tol_) {
      count(*d);
      if (d->worst() >= worst_)
        worst_ = d->worst(), worst_at_ = label(r, to_string(k)) + ": " + difference_text(*d);
      if (d->looseness > tol_)
        note(r, k, d->looseness, NAN,
             "captured: e = 0 agrees with the reference (" + outcome_text(r.reference) + "), but " +
                 std::string(to_string(k)) + " bounds e only by " + fmt(d->looseness) + " (" +
                 outcome_text(x) + "): a looser statement of the same outcome, not a difference");
      return;
    }
    const auto tight = difference(rechecks_.integrator(r, k), rechecks_.reference(r), tol_);
    if (tight && tight->worst() <= tol_) {
      count(*tight);
      note(r, k, d ? d->worst() : std::numeric_limits<double>::infinity(), tight->worst(),
           (d ? difference_text(*d)
              : "ended " + outcome_text(x) + ", the reference " + outcome_text(r.reference)) +
               " at the grid's settings; " + difference_text(*tight) + " with " +
               rechecks_.settings(k));
      return;
    }
    if (!d) {
      if (mismatch_.empty())
        mismatch_ = label(r, to_string(k)) + " ended " + outcome_text(x) + ", the reference " +
                    outcome_text(r.reference) +
                    "; repeated tighter: " + outcome_text(rechecks_.integrator(r, k)) +
                    " against " + outcome_text(rechecks_.reference(r));
      return;
    }
    count(*d);
    if (d->worst() >= worst_)
      worst_ = d->worst(), worst_at_ = label(r, to_string(k)) + ": " + difference_text(*d) +
                                       "; still " + fmt(tight ? tight->worst() : NAN) +
                                       " repeated with " + rechecks_.settings(k);
  }

  void report(const LawUnderTest& law, const std::vector<Run>& runs, double reference_error,
              int implicit_references, const std::string& reason) {
    result_.checks.push_back(make_check(
        "dynamic.integrators", worst_, 0.0, tol_,
        worst_ <= tol_ && mismatch_.empty() && compared_ > 0, reason,
        std::to_string(compared_) + " runs against " +
            (law.runs_in_reference ? "mp50 (50 digits, tol 1e-26)"
                                   : "dp45 at rtol 1e-13 (its own error estimated at " +
                                         fmt(reference_error) + " in e from its run at 1e-12)") +
            (implicit_references ? " (at " + std::to_string(implicit_references) +
                                       " point(s) rodas4 at the same tolerances: the dashpot "
                                       "is too stiff for dp45's steps)"
                                 : "") +
            (captured_ ? " (" + std::to_string(captured_) +
                             " captured: e = 0 agreed within the capture bounds, no contact "
                             "time)"
                       : "") +
            "; largest difference at " + worst_at_ + (mismatch_.empty() ? "" : "; " + mismatch_) +
            (excused_
                 ? "; " + std::to_string(excused_) + " integrator-accuracy note(s), not the law's"
                 : "") +
            (stopped_ ? "; " + std::to_string(stopped_) +
                            " run(s) stopped by the integrator before the end (a dashpot too "
                            "stiff for an explicit stepper), not compared (integrator notes)"
                      : "") +
            domain_note(runs)));
  }

 private:
  void count(const Difference& d) {
    ++compared_;
    captured_ += std::isnan(d.t);
  }
  void note(const Run& r, IntegratorKind k, double error, double tight, std::string detail) {
    result_.notes.push_back(
        make_note("dynamic.integrators", r, to_string(k), error, tol_, tight, std::move(detail)));
    ++excused_;
  }

  Rechecks& rechecks_;
  ConformanceResult& result_;
  double tol_;
  double worst_ = 0;
  std::string worst_at_ = "no comparison", mismatch_;
  int compared_ = 0, captured_ = 0, excused_ = 0;
  int stopped_ = 0;  // runs the stiffness bound stopped (stiff_for_integrator)
};

void integrator_check(Rechecks& rechecks, const LawUnderTest& law, const std::vector<Run>& runs,
                      ConformanceResult& result) {
  const auto itol = verification::default_settings_tolerance(IntegratorKind::odeint_dopri5);
  IntegratorJudge judge(rechecks, result, itol.value);
  double reference_error = 0;
  int implicit_references = 0;
  for (const Run& r : runs) {
    reference_error = std::max(reference_error, r.reference_error);
    implicit_references += r.reference.integrator == to_string(IntegratorKind::rodas4);
    if (!r.reference.ok()) continue;
    for (const auto& [k, x] : r.runs) judge.judge(r, k, x);
  }
  judge.report(law, runs, reference_error, implicit_references, itol.reason);
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
    result.skipped.push_back(
        {"dynamic.monotone_v0", claims.cor_nondecreasing_in_v0
                                    ? "not claimed: the law claims e rising with v0 instead "
                                      "(dynamic.increasing_v0)"
                                    : "not claimed"});
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

// How far the delivered e of a grid point is from the claimed one: |e - expected| for a
// rebound, and for a captured run (e = 0, the true e in [0, e_bound]) the distance from the
// claim to that interval, so that a claim of 0 is judged against the capture.
double claim_miss(const CorPoint& c) {
  if (c.status == "captured" && c.e_bound) return std::max(0.0, *c.expected - *c.e_bound);
  return *c.e - *c.expected;
}

void expected_cor_check(const Claims& claims, ConformanceResult& result) {
  if (!claims.expected_cor) {
    result.skipped.push_back({"dynamic.expected_cor", "no COR claimed (--expect-cor)"});
    return;
  }
  double miss = 0, signed_miss = 0;
  std::optional<std::pair<double, double>> worst;  // delivered, expected
  std::string at = "no run", not_judged;
  int n = 0, captured = 0, failed = 0;
  for (const CorPoint& c : result.cor) {
    if (!c.expected) continue;
    if (!c.e) {  // the reference failed: the claim cannot be judged there, which is no pass
      if (failed++ == 0) not_judged = "v0 = " + fmt(c.v0) + " m/s: " + c.status;
      continue;
    }
    ++n;
    captured += c.status == "captured";
    const double d = claim_miss(c);
    const std::string where =
        "v0 = " + fmt(c.v0) + " m/s: delivered e = " + fmt(*c.e, 10) +
        (c.status == "captured" ? " (captured, e <= " + fmt(c.e_bound.value_or(0.0)) + ")" : "") +
        ", expected " + fmt(*c.expected, 10);
    if (!std::isfinite(d)) {  // never a silent pass on a NaN (run_conformance refuses those)
      miss = signed_miss = std::numeric_limits<double>::infinity();
      at = where;
      break;
    }
    if (std::abs(d) >= miss)
      miss = std::abs(d), signed_miss = d, worst = std::pair{*c.e, *c.expected}, at = where;
  }
  Check& c = result.checks.emplace_back(make_check(
      "dynamic.expected_cor", miss, 0.0, claims.cor_tolerance,
      n > 0 && failed == 0 && miss <= claims.cor_tolerance, claims.cor_tolerance_reason,
      "largest |e - (" + claims.expected_cor_text + ")| = " + fmt(miss) + " (" +
          (signed_miss > 0 ? "over" : "under") + "), at " + at + "; " + std::to_string(n) +
          " velocities judged (" + std::to_string(captured) +
          " captured: the claim against the interval [0, e_bound])" +
          (failed ? "; " + std::to_string(failed) +
                        " not judged because the reference failed, first at " + not_judged
                  : "")));
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

// The double-precision reference of a law that does not run in 50 digits, at one point: dp45
// at `o`; where dp45 stops because the dashpot is too stiff for an explicit stepper (step_limit:
// it cannot reach the end within max_steps, solver/driver/dashpot_stall.h), rodas4 (L-stable,
// its steps not held by the dashpot's time scale) at the same tolerances.
ImpactResult double_reference(const LawUnderTest& law, const Scene& s, const IntegratorOptions& o) {
  ImpactResult r = law.simulate(s, IntegratorKind::dp45, o);
  if (r.ok() || r.failure != FailureKind::step_limit || s.damping.kind == Damping::Kind::none)
    return r;
  ImpactResult implicit = law.simulate(s, IntegratorKind::rodas4, o);
  return implicit.ok() ? implicit : r;
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
        r.reference = double_reference(law, s, tight);
        tight.rtol = 1e-12;
        tight.atol = 1e-14;
        const ImpactResult looser = double_reference(law, s, tight);
        r.reference_error = std::abs(looser.e - r.reference.e);
      }
      for (IntegratorKind k : grid.integrators)
        r.runs.push_back({k, law.simulate(s, k, grid.options)});
      runs.push_back(std::move(r));
    }
  }
  return runs;
}

std::string run_label(const Run& r, std::string_view who) {
  return std::string(who) + " at v0 = " + fmt(r.v0) + " m/s, " + damping_label(r.damping);
}

IntegratorOptions Rechecks::tight_options(IntegratorKind) const {
  IntegratorOptions o = grid_.options;
  o.rtol = std::max(1e-3 * o.rtol, 1e-13);
  o.atol = std::max(1e-3 * o.atol, 1e-15);
  return o;
}

IntegratorOptions Rechecks::tight_reference_options() const {
  IntegratorOptions o = grid_.options;
  if (law_.runs_in_reference) {
    o.reference_tolerance *= 1e-4;
  } else {
    o.rtol = 1e-14;
    o.atol = 1e-16;
  }
  return o;
}

std::string Rechecks::settings(IntegratorKind k) const {
  const IntegratorOptions o = tight_options(k), ref = tight_reference_options();
  return std::string(to_string(k)) + " at rtol " + fmt(o.rtol) + ", atol " + fmt(o.atol) +
         " against " +
         (law_.runs_in_reference ? "mp50 at tol " + fmt(ref.reference_tolerance)
                                 : "dp45 at rtol " + fmt(ref.rtol) + ", atol " + fmt(ref.atol));
}

const ImpactResult& Rechecks::integrator(const Run& r, IntegratorKind k) {
  const auto key = std::tuple{r.v0, r.c, static_cast<int>(k)};
  if (auto it = runs_.find(key); it != runs_.end()) return it->second;
  return runs_[key] = law_.simulate(at(grid_.scene, r.v0, r.damping), k, tight_options(k));
}

const ImpactResult& Rechecks::reference(const Run& r) {
  const auto key = std::tuple{r.v0, r.c, -1};
  if (auto it = runs_.find(key); it != runs_.end()) return it->second;
  const Scene s = at(grid_.scene, r.v0, r.damping);
  return runs_[key] = law_.runs_in_reference
                          ? law_.simulate(s, IntegratorKind::mp50, tight_reference_options())
                          : double_reference(law_, s, tight_reference_options());
}

void dynamic_checks(const LawUnderTest& law, const Claims& claims, const Grid& grid,
                    const std::vector<Run>& runs, ConformanceResult& result) {
  cor_curve(claims, runs, result);
  Rechecks rechecks(law, grid);
  ledger_checks(rechecks, runs, result);
  integrator_check(rechecks, law, runs, result);
  monotone_checks(law, claims, grid, runs, result);
  low_speed_check(claims, grid, runs, result);
  adhesive_claim_checks(claims, grid, runs, result);
  expected_cor_check(claims, result);
}

}  // namespace ivv::conformance::detail
