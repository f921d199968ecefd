#include "verification/registry.h"

#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <stdexcept>

#include "scene/input_error.h"
#include "solver/parallel.h"

namespace ivv::verification {

namespace {
constexpr std::array kTiers = {Tier::analytic,     Tier::cross_implementation,
                               Tier::conservation, Tier::published_trend,
                               Tier::convergence,  Tier::stability,
                               Tier::validation};
}  // namespace

std::span<const Tier> all_tiers() {
  return kTiers;
}

std::string_view to_string(Tier t) {
  switch (t) {
    case Tier::analytic:
      return "analytic";
    case Tier::cross_implementation:
      return "cross-implementation";
    case Tier::conservation:
      return "conservation";
    case Tier::published_trend:
      return "published-trend";
    case Tier::convergence:
      return "convergence";
    case Tier::stability:
      return "stability";
    case Tier::validation:
      return "validation";
  }
  return "?";
}

std::string_view to_string(Comparison c) {
  switch (c) {
    case Comparison::relative:
      return "relative";
    case Comparison::absolute:
      return "absolute";
    case Comparison::at_most:
      return "at most";
    case Comparison::at_least:
      return "at least";
  }
  return "?";
}

double Outcome::error() const {
  switch (comparison) {
    case Comparison::relative:
      return reference == 0 ? std::abs(measured)
                            : std::abs(measured - reference) / std::abs(reference);
    case Comparison::absolute:
      return std::abs(measured - reference);
    case Comparison::at_most:
    case Comparison::at_least:
      return measured;
  }
  return measured;
}

double Outcome::margin() const {
  const double err = error();
  if (comparison == Comparison::at_least) return measured / tolerance;
  if (err == 0) return std::numeric_limits<double>::infinity();
  return tolerance / err;
}

namespace {
Outcome make(double measured, double reference, double tolerance, Comparison c,
             std::string detail) {
  Outcome o;
  o.measured = measured;
  o.reference = reference;
  o.tolerance = tolerance;
  o.comparison = c;
  o.detail = std::move(detail);
  const double err = o.error();
  switch (c) {
    case Comparison::relative:
    case Comparison::absolute:
    case Comparison::at_most:
      o.passed = std::isfinite(err) && err <= tolerance;
      break;
    case Comparison::at_least:
      o.passed = std::isfinite(measured) && measured >= tolerance;
      break;
  }
  return o;
}
}  // namespace

Outcome relative(double measured, double reference, double tolerance, std::string detail) {
  return make(measured, reference, tolerance, Comparison::relative, std::move(detail));
}
Outcome absolute(double measured, double reference, double tolerance, std::string detail) {
  return make(measured, reference, tolerance, Comparison::absolute, std::move(detail));
}
Outcome at_most(double measured, double bound, std::string detail) {
  return make(measured, std::numeric_limits<double>::quiet_NaN(), bound, Comparison::at_most,
              std::move(detail));
}
Outcome at_least(double measured, double bound, std::string detail) {
  return make(measured, std::numeric_limits<double>::quiet_NaN(), bound, Comparison::at_least,
              std::move(detail));
}

void Registry::add(Case c) {
  if (c.id.empty() || !c.run) throw std::logic_error("verification case without id or body");
  if (c.reason.empty())
    throw std::logic_error("case " + c.id + " does not say why its tolerance is what it is");
  for (const auto& existing : cases_)
    if (existing.id == c.id) throw std::logic_error("duplicate verification case id " + c.id);
  cases_.push_back(std::move(c));
}

bool glob_match(std::string_view p, std::string_view s) {
  std::size_t pi = 0, si = 0, star = std::string_view::npos, mark = 0;
  while (si < s.size()) {
    if (pi < p.size() && (p[pi] == '?' || p[pi] == s[si])) {
      ++pi;
      ++si;
    } else if (pi < p.size() && p[pi] == '*') {
      star = pi++;
      mark = si;
    } else if (star != std::string_view::npos) {
      pi = star + 1;
      si = ++mark;
    } else {
      return false;
    }
  }
  while (pi < p.size() && p[pi] == '*') ++pi;
  return pi == p.size();
}

std::vector<const Case*> Registry::matching(std::string_view glob) const {
  std::vector<const Case*> out;
  for (const auto& c : cases_)
    if (glob.empty() || glob_match(glob, c.id)) out.push_back(&c);
  return out;
}

CaseRecord run_case(const Case& c) {
  CaseRecord rec;
  rec.c = &c;
  const auto start = std::chrono::steady_clock::now();
  try {
    rec.outcome = c.run();
  } catch (const std::exception& e) {
    rec.outcome = Outcome{};
    rec.outcome.passed = false;
    rec.outcome.detail = std::string("the case threw: ") + e.what();
  }
  rec.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return rec;
}

std::vector<CaseRecord> run_cases(
    const std::vector<const Case*>& cases, int threads,
    const std::function<void(std::size_t, std::size_t, const Case&)>& progress) {
  validate_threads(threads);
  std::vector<CaseRecord> records(cases.size());
  std::size_t done = 0;
  std::mutex mutex;
  // run_case turns a throwing case into a failed record, so the loop itself does not throw.
  parallel_for(cases.size(), threads, [&](std::size_t i) {
    records[i] = run_case(*cases[i]);
    if (progress) {
      std::lock_guard lock(mutex);
      progress(++done, cases.size(), *cases[i]);
    }
  });
  return records;
}

std::vector<const Case*> select_cases(const std::string& filter) {
  auto selected = all_cases().matching(filter);
  if (selected.empty())
    throw InputError("--filter", "no verification case id matches '" + filter +
                                     "' (shell-style glob with * and ?)");
  return selected;
}

BatteryResult run_battery(
    const std::vector<const Case*>& cases, int threads,
    const std::function<void(std::size_t, std::size_t, const Case&)>& progress) {
  const auto start = std::chrono::steady_clock::now();
  BatteryResult battery;
  battery.records = run_cases(cases, threads, progress);
  for (const CaseRecord& r : battery.records)
    if (!r.outcome.passed) ++battery.failed;
  battery.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return battery;
}

}  // namespace ivv::verification
