// The registry of verification cases: one list that feeds both ctest (verification_test, one
// gtest per case) and `ivv verify` / `ivv report`, so the two can never disagree (docs/design.md
// §4).
//
// A case measures one number, compares it with a reference under a tolerance whose reason is
// stated, and may carry plot data. Cases are plain functions registered explicitly by
// register_all_cases(); running one never throws (an exception is a failed case whose detail
// says what went wrong).
#pragma once

#include <functional>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "verification/plot_data.h"

namespace ivv::verification {

enum class Tier {
  analytic,
  cross_implementation,
  conservation,
  published_trend,
  convergence,
  stability,
  validation  // calibration against (synthetic) measurements: recovery, coverage, ranking
};
std::span<const Tier> all_tiers();
std::string_view to_string(Tier t);

// How `measured` is judged against `reference` and `tolerance`.
enum class Comparison {
  relative,  // |measured - reference| <= tolerance * |reference|
  absolute,  // |measured - reference| <= tolerance
  at_most,   // measured <= tolerance          (reference unused: e.g. a maximum error)
  at_least,  // measured >= tolerance          (e.g. a margin that must stay positive)
};
std::string_view to_string(Comparison c);

struct Outcome {
  double measured = std::numeric_limits<double>::quiet_NaN();
  double reference = std::numeric_limits<double>::quiet_NaN();
  double tolerance = std::numeric_limits<double>::quiet_NaN();
  Comparison comparison = Comparison::relative;
  bool passed = false;
  std::string detail;  // what exactly was measured, in a sentence; failures say what fell short
  std::vector<Plot> plots;

  // The deviation in the units of the tolerance (relative or absolute error, or measured).
  double error() const;
  // tolerance / error for relative/absolute/at_most (> 1 passes), measured / tolerance for
  // at_least; +inf for an exact match.
  double margin() const;
};

// Builders that set `passed` from the comparison. NaN measurements always fail.
Outcome relative(double measured, double reference, double tolerance, std::string detail);
Outcome absolute(double measured, double reference, double tolerance, std::string detail);
Outcome at_most(double measured, double bound, std::string detail);
Outcome at_least(double measured, double bound, std::string detail);

// Whether the default ctest run includes a case: a slow one carries the ctest label "slow" and
// runs under `make test-all` (and always in `ivv verify` and `ivv report`).
enum class Cost { quick, slow };

struct Case {
  std::string id;     // dotted, stable: "analytic.hertz.undamped.odeint-dopri5"
  std::string title;  // one line for people
  Tier tier = Tier::analytic;
  std::string reason;  // why the tolerance is what it is
  Cost cost = Cost::quick;
  std::function<Outcome()> run;
  bool slow() const { return cost == Cost::slow; }
};

class Registry {
 public:
  void add(Case c);  // throws std::logic_error on a duplicate id or a missing reason
  const std::vector<Case>& cases() const { return cases_; }
  // Cases whose id matches a shell-style glob (* and ?); "" or "*" matches all.
  std::vector<const Case*> matching(std::string_view glob) const;

 private:
  std::vector<Case> cases_;
};

// Every case of the battery (verification/cases_*.cc).
const Registry& all_cases();

struct CaseRecord {
  const Case* c = nullptr;
  Outcome outcome;
  double seconds = 0.0;  // wall time of the run (information only, never judged)
};

// Runs one case; an exception becomes a failed outcome naming it.
CaseRecord run_case(const Case& c);

// Runs cases on `threads` workers (0: all cores); records come back in the given order.
// `progress(done, total, case)` is called serialised after each case.
std::vector<CaseRecord> run_cases(
    const std::vector<const Case*>& cases, int threads = 0,
    const std::function<void(std::size_t, std::size_t, const Case&)>& progress = {});

// The battery: every case whose id matches `filter` (a glob; "" or "*": all), run on `threads`
// workers. `ivv verify` and `ivv report` both run it and write its records with the same
// writer (reports/companions.h); the report then only draws what it holds.
struct BatteryResult {
  std::vector<CaseRecord> records;  // in registry order
  std::size_t failed = 0;
  double seconds = 0.0;  // wall time of the battery (information only)
  std::size_t passed() const { return records.size() - failed; }
};

// The cases whose id matches `filter`, in registry order; InputError("--filter") when none.
std::vector<const Case*> select_cases(const std::string& filter);

// Runs `cases` (select_cases()); InputError("--threads") for threads < 0.
BatteryResult run_battery(
    const std::vector<const Case*>& cases, int threads,
    const std::function<void(std::size_t, std::size_t, const Case&)>& progress = {});

bool glob_match(std::string_view pattern, std::string_view text);

}  // namespace ivv::verification
