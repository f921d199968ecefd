// A conformance result reports itself: one line, the full list, the plots and JSON, so that the
// command line, the HTML report, JSON and GoogleTest print the same words.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "verification/conformance_internal.h"

namespace ivv::conformance {

using detail::fmt;

namespace {

// "0.2529 F_ref (3180 N)", "1e-09", "0.0125 E0"
std::string with_unit(double v, const Check& c) {
  std::string text = fmt(v, 4);
  if (c.unit == "-" || c.unit.empty()) return text;
  text += " " + c.unit;
  if (std::isfinite(c.unit_si) && std::isfinite(v))
    text += " (" + fmt(v * c.unit_si, 4) + " " + c.si_unit + ")";
  return text;
}

}  // namespace

std::string Check::measured_text() const {
  return with_unit(measured, *this);
}

std::string Check::reference_text() const {
  std::string text = with_unit(reference, *this);
  if (reference_value)
    text += "; compared: " + fmt(value.value_or(NAN), 10) + " against " +
            fmt(*reference_value, 10) + (value_unit == "-" ? "" : " " + value_unit);
  return text;
}

std::string Check::tolerance_text() const {
  return std::string(bound == Bound::at_most ? "<= " : ">= ") + with_unit(tolerance, *this);
}

std::string Check::line() const {
  std::ostringstream os;
  os << (passed ? "pass" : "FAIL") << "  " << std::left << std::setw(26) << id << " " << detail
     << " (measured " << measured_text() << ", tolerance " << tolerance_text() << ")";
  return os.str();
}

std::string CorPoint::damping_label() const {
  if (finite_plate) return "finite plate";
  if (std::isinf(c)) return "no dashpot";
  if (std::isfinite(zeta)) return "zeta = " + fmt(zeta);
  return "c = " + fmt(c) + " N s/m";
}

bool ConformanceResult::passed() const {
  return !checks.empty() &&
         std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.passed; });
}

const Check* ConformanceResult::find(std::string_view id) const {
  for (const Check& c : checks)
    if (c.id == id) return &c;
  return nullptr;
}

const Skipped* ConformanceResult::find_skipped(std::string_view id) const {
  for (const Skipped& s : skipped)
    if (s.id == id) return &s;
  return nullptr;
}

std::string ConformanceResult::brief() const {
  std::ostringstream os;
  int failed = 0;
  for (const Check& c : checks) failed += !c.passed;
  os << "law " << law << ": " << (passed() ? "PASS" : "FAIL") << " (" << checks.size() - failed
     << " of " << checks.size() << " checks passed, " << skipped.size() << " skipped";
  if (!notes.empty()) os << ", " << notes.size() << " integrator-accuracy note(s)";
  if (failed) {
    os << "; failed:";
    for (const Check& c : checks)
      if (!c.passed) os << ' ' << c.id;
  }
  os << ")";
  return os.str();
}

std::string IntegratorNote::line() const {
  std::ostringstream os;
  os << "note  " << std::left << std::setw(26) << check << " " << integrator
     << " at v0 = " << fmt(v0) << " m/s, " << damping << ": " << detail << " (";
  if (std::isfinite(error))
    os << "measured " << fmt(error, 4);
  else
    os << "nothing measured: the run did not reach the end";
  os << ", tolerance " << fmt(tolerance, 4);
  if (std::isfinite(error_tight)) os << "; repeated tighter " << fmt(error_tight, 4);
  os << ")";
  return os.str();
}

std::string ConformanceResult::notes_text() const {
  if (notes.empty()) return "";
  std::ostringstream os;
  os << "integrator accuracy, not the law's (" << notes.size()
     << " note(s): a difference the integrator's tolerance explains, gone when the run was "
        "repeated tighter, a capture bound looser than the check's tolerance, or a run the "
        "integrator could not finish where the reference did):\n";
  for (const IntegratorNote& n : notes) os << "  " << n.line() << "\n";
  return os.str();
}

std::string ConformanceResult::cor_grid() const {
  std::vector<std::string> dampings;
  for (const CorPoint& c : cor)
    if (std::find(dampings.begin(), dampings.end(), c.damping_label()) == dampings.end())
      dampings.push_back(c.damping_label());
  std::size_t width = 0;
  for (const std::string& d : dampings) width = std::max(width, d.size());
  std::ostringstream os;
  for (const std::string& d : dampings) {
    os << "  " << std::left << std::setw(static_cast<int>(width)) << d << " ";
    bool first = true;
    for (const CorPoint& c : cor) {
      if (c.damping_label() != d) continue;
      os << (first ? " " : ", ") << fmt(c.v0, 4) << ": ";
      first = false;
      if (!c.e)
        os << "failed";
      else if (c.e_bound && c.status == "captured")
        os << "0 (captured, e <= " << fmt(*c.e_bound, 2) << ")";
      else
        os << fmt(*c.e, 8);
    }
    os << "\n";
  }
  return os.str();
}

std::string ConformanceResult::full() const {
  std::ostringstream os;
  os << "law " << law << ": " << description << "\n";
  for (const Check& c : checks) os << "  " << c.line() << "\n";
  for (const Skipped& s : skipped)
    os << "  SKIP  " << std::left << std::setw(26) << s.id << " " << s.why << "\n";
  if (!cor.empty())
    os << "e(v0) of the reference runs, per damping (v0 [m/s]: e), as the trend checks used "
          "it:\n"
       << cor_grid();
  os << notes_text();
  os << brief() << "\n";
  return os.str();
}

namespace {

std::string plot_id(const std::string& prefix, const std::string& law) {
  std::string id = prefix + law;
  for (char& c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-') c = '-';
  return id;
}

verification::Plot cor_plot(const ConformanceResult& r) {
  using verification::Series;
  verification::Plot p;
  p.id = plot_id("conformance-cor-", r.law);
  p.title = "COR delivered by " + r.law;
  p.x_label = "impact velocity v0 [m/s]";
  p.y_label = "coefficient of restitution e";
  p.log_x = true;
  p.margins = true;  // a constant e (an elastic law: e = 1) stays off the frame
  std::vector<std::string> dampings;
  for (const CorPoint& c : r.cor)
    if (std::find(dampings.begin(), dampings.end(), c.damping_label()) == dampings.end())
      dampings.push_back(c.damping_label());
  for (const std::string& d : dampings) {
    Series s;
    s.label = d;
    s.style = Series::Style::linespoints;
    for (const CorPoint& c : r.cor)
      if (c.damping_label() == d && c.e) s.x.push_back(c.v0), s.y.push_back(*c.e);
    p.series.push_back(std::move(s));
  }
  if (!r.cor.empty()) {
    const auto [lo, hi] = std::minmax_element(r.cor.begin(), r.cor.end(),
                                              [](auto& a, auto& b) { return a.v0 < b.v0; });
    p.series.push_back({"e = 1 (elastic)", {lo->v0, hi->v0}, {1.0, 1.0}, Series::Style::lines});
  }
  Series expected;
  expected.label = "claimed COR";
  expected.style = Series::Style::dashed;  // drawn last: on top of a curve it coincides with
  for (const CorPoint& c : r.cor)
    if (c.expected) expected.x.push_back(c.v0), expected.y.push_back(*c.expected);
  if (!expected.x.empty()) p.series.push_back(std::move(expected));
  return p;
}

verification::Plot loop_plot(const ConformanceResult& r) {
  using verification::Series;
  verification::Plot p;
  p.id = plot_id("conformance-loop-", r.law);
  p.title = "Force-deformation loop of " + r.law;
  p.x_label = "spring deformation z [mm]";
  p.y_label = "contact force F [N]";
  p.margins = true;
  for (const ForceLoop& loop : r.loops) {
    Series s;
    s.label = loop.damping + ", v0 = " + fmt(loop.v0) + " m/s";
    for (std::size_t i = 0; i < loop.z.size(); ++i)
      s.x.push_back(loop.z[i] * 1e3), s.y.push_back(loop.F[i]);
    p.series.push_back(std::move(s));
  }
  return p;
}

}  // namespace

std::vector<verification::Plot> ConformanceResult::plots() const {
  std::vector<verification::Plot> out = {cor_plot(*this)};
  if (!loops.empty()) out.push_back(loop_plot(*this));
  return out;
}

nlohmann::json to_json(const ConformanceResult& result) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  auto opt = [&](const std::optional<double>& v) { return v ? num(*v) : nlohmann::json(); };
  nlohmann::json checks = nlohmann::json::array();
  for (const Check& c : result.checks)
    checks.push_back({{"id", c.id},
                      {"passed", c.passed},
                      {"measured", num(c.measured)},
                      {"reference", num(c.reference)},
                      {"tolerance", num(c.tolerance)},
                      {"bound", c.bound == Bound::at_most ? "at_most" : "at_least"},
                      {"unit", c.unit},
                      {"unit_si", num(c.unit_si)},
                      {"si_unit", c.si_unit},
                      {"value", opt(c.value)},
                      {"reference_value", opt(c.reference_value)},
                      {"value_unit", c.value_unit},
                      {"why", c.why},
                      {"detail", c.detail}});
  nlohmann::json skipped = nlohmann::json::array();
  for (const Skipped& s : result.skipped) skipped.push_back({{"id", s.id}, {"why", s.why}});
  nlohmann::json cor = nlohmann::json::array();
  for (const CorPoint& c : result.cor)
    cor.push_back({{"v0", c.v0},
                   {"zeta", num(c.zeta)},
                   {"c", num(c.c)},
                   {"e", opt(c.e)},
                   {"e_bound", opt(c.e_bound)},
                   {"expected", opt(c.expected)},
                   {"status", c.status}});
  nlohmann::json notes = nlohmann::json::array();
  for (const IntegratorNote& n : result.notes)
    notes.push_back({{"check", n.check},
                     {"integrator", n.integrator},
                     {"v0", n.v0},
                     {"damping", n.damping},
                     {"error", num(n.error)},
                     {"tolerance", num(n.tolerance)},
                     {"error_tight", num(n.error_tight)},
                     {"detail", n.detail}});
  return {{"verdict", result.passed() ? "pass" : "fail"},
          {"integrator_notes", notes},
          {"brief", result.brief()},
          {"law", {{"name", result.law}, {"description", result.description}}},
          {"checks", checks},
          {"skipped", skipped},
          {"not_applicable", skipped},
          {"cor", cor}};
}

}  // namespace ivv::conformance
