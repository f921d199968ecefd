#include "reports/companions.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <nlohmann/json.hpp>

#include "reports/html.h"

namespace ivv::reports {
namespace {

using verification::CaseRecord;
using verification::Comparison;

nlohmann::json finite_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

std::string csv_field(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char ch : s) out += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return out + "\"";
}

std::string csv_number(double v) {
  if (!std::isfinite(v)) return number(v);
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string comparison_text(const verification::Outcome& o) {
  const std::string err = number(o.error(), 3), tol = number(o.tolerance, 3);
  const std::string le = o.passed ? " ≤ " : " > ", ge = o.passed ? " ≥ " : " < ";
  switch (o.comparison) {
    case Comparison::relative:
      return "|measured − reference|/|reference| = " + err + le + tol;
    case Comparison::absolute:
      return "|measured − reference| = " + err + le + tol;
    case Comparison::at_most:
      return "measured = " + err + le + tol;
    case Comparison::at_least:
      return "measured = " + number(o.measured, 3) + ge + tol;
  }
  return "";
}

std::string results_json(const std::vector<CaseRecord>& records) {
  nlohmann::json cases = nlohmann::json::array();
  for (const auto& r : records) {
    const auto& o = r.outcome;
    cases.push_back({{"id", r.c->id},
                     {"title", r.c->title},
                     {"tier", std::string(verification::to_string(r.c->tier))},
                     {"passed", o.passed},
                     {"measured", finite_or_null(o.measured)},
                     {"reference", finite_or_null(o.reference)},
                     {"tolerance", finite_or_null(o.tolerance)},
                     {"reason", r.c->reason},
                     {"comparison", std::string(verification::to_string(o.comparison))},
                     {"margin", finite_or_null(o.margin())},
                     {"detail", o.detail},
                     {"slow", r.c->slow()},
                     {"seconds", r.seconds}});
  }
  return nlohmann::json{{"cases", cases}}.dump(2) + "\n";
}

std::string series_csv(const std::vector<const verification::Plot*>& plots) {
  std::string out = "plot_id,series,x,y\n";
  for (const auto* p : plots) {
    const std::string id = csv_field(p->id);
    for (const auto& s : p->series) {
      const std::string label = csv_field(s.label);
      const std::size_t n = std::min(s.x.size(), s.y.size());
      for (std::size_t i = 0; i < n; ++i)
        out += id + "," + label + "," + csv_number(s.x[i]) + "," + csv_number(s.y[i]) + "\n";
    }
  }
  return out;
}

std::string junit_xml(const std::vector<CaseRecord>& records) {
  std::map<verification::Tier, std::vector<const CaseRecord*>> by_tier;
  for (const auto& r : records) by_tier[r.c->tier].push_back(&r);
  std::size_t failures = 0;
  double seconds = 0;
  for (const auto& r : records) {
    failures += r.outcome.passed ? 0 : 1;
    seconds += r.seconds;
  }
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<testsuites name=\"ivv verification\" tests=\"" + std::to_string(records.size()) +
         "\" failures=\"" + std::to_string(failures) + "\" time=\"" + number(seconds, 6) + "\">\n";
  for (verification::Tier tier : verification::all_tiers()) {
    const auto it = by_tier.find(tier);
    if (it == by_tier.end()) continue;
    const std::string name(verification::to_string(tier));
    std::size_t tier_failures = 0;
    double tier_seconds = 0;
    for (const auto* r : it->second) {
      tier_failures += r->outcome.passed ? 0 : 1;
      tier_seconds += r->seconds;
    }
    out += "  <testsuite name=\"" + escape(name) + "\" tests=\"" +
           std::to_string(it->second.size()) + "\" failures=\"" + std::to_string(tier_failures) +
           "\" errors=\"0\" time=\"" + number(tier_seconds, 6) + "\">\n";
    for (const auto* r : it->second) {
      const auto& o = r->outcome;
      out += "    <testcase classname=\"ivv." + escape(name) + "\" name=\"" + escape(r->c->id) +
             "\" time=\"" + number(r->seconds, 6) + "\">";
      if (!o.passed) {
        const std::string message = "measured " + number(o.measured, 10) + ", reference " +
                                    number(o.reference, 10) + ", tolerance " +
                                    number(o.tolerance, 4) + " (" +
                                    std::string(verification::to_string(o.comparison)) + ")";
        out += "\n      <failure message=\"" + escape(message) + "\" type=\"" +
               escape(std::string(verification::to_string(o.comparison))) + "\">" +
               escape(r->c->title + "\n" + comparison_text(o) + "\n" + o.detail +
                      "\nWhy this tolerance: " + r->c->reason) +
               "</failure>\n    ";
      }
      out += "</testcase>\n";
    }
    out += "  </testsuite>\n";
  }
  out += "</testsuites>\n";
  return out;
}

}  // namespace ivv::reports
