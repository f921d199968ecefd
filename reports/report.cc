#include "reports/report.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "closed_forms/hunt_crossley.h"
#include "reports/calibration_report.h"
#include "reports/companions.h"
#include "reports/dem_benchmark.h"
#include "reports/figure.h"
#include "reports/gnuplot_svg.h"
#include "reports/html.h"
#include "reports/law_report.h"
#include "reports/paper_figures.h"
#include "reports/plate_regime_section.h"
#include "reports/provenance.h"
#include "reports/restitution.h"
#include "reports/speed_error.h"
#include "reports/structure_section.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"
#include "solver/parallel.h"
#include "validation/example.h"
#include "verification/examples.h"
#include "verification/registry.h"

namespace ivv::reports {
namespace {

namespace fs = std::filesystem;
using verification::CaseRecord;
using verification::Plot;
using verification::Tier;

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Every figure of the page: ids made unique, drawn in parallel, put in place of placeholders.
class FigureBook {
 public:
  // Returns the placeholder to put in the HTML where the figure goes. A figure placed side by
  // side with another (in a .grid2) is drawn on a smaller canvas so that its text, scaled
  // down with it, stays legible.
  std::string add(Figure f, bool side_by_side = false) {
    std::string id = slug(f.plot.id.empty() ? "plot" : f.plot.id);
    for (int n = 2; ids_.count(id); ++n) id = slug(f.plot.id) + "-" + std::to_string(n);
    ids_.insert(id);
    f.plot.id = id;
    figures_.push_back(std::move(f));
    sizes_.push_back(side_by_side ? kSideBySideSize : kAloneSize);
    return placeholder(figures_.size() - 1);
  }

  // Two figures side by side on one row (a .grid2), each drawn on the side-by-side canvas.
  std::string side_by_side(Figure left, Figure right) {
    return "<div class=\"grid2\">\n" + add(std::move(left), true) + add(std::move(right), true) +
           "</div>\n";
  }

  // Draws every figure with gnuplot on `threads` workers.
  void render(int threads, const SectionOptions& say) {
    svgs_.assign(figures_.size(), {});
    errors_.assign(figures_.size(), {});
    say.say("drawing " + std::to_string(figures_.size()) + " plots with gnuplot");
    // Each figure's error is recorded in its slot, so the loop itself does not throw.
    parallel_for(figures_.size(), threads, [&](std::size_t i) {
      try {
        svgs_[i] = render_svg(figures_[i].plot, "p" + std::to_string(i) + "-" + figures_[i].plot.id,
                              sizes_[i]);
        const SvgCheck check = check_svg(svgs_[i]);
        if (!check.ok())
          errors_[i] = "gnuplot drew " + std::to_string(check.drawn_series) + " of " +
                       std::to_string(check.series) + " series";
      } catch (const std::exception& e) {
        errors_[i] = e.what();
      }
    });
  }

  std::string resolve(std::string html) const {
    for (std::size_t i = 0; i < figures_.size(); ++i) {
      const std::string key = placeholder(i);
      const auto pos = html.find(key);
      if (pos != std::string::npos) html.replace(pos, key.size(), figure_html(i));
    }
    return html;
  }

  std::vector<const Plot*> plots() const {
    std::vector<const Plot*> out;
    for (const auto& f : figures_) out.push_back(&f.plot);
    return out;
  }
  std::size_t size() const { return figures_.size(); }
  std::size_t errors() const {
    return static_cast<std::size_t>(
        std::count_if(errors_.begin(), errors_.end(), [](const auto& e) { return !e.empty(); }));
  }

 private:
  static std::string placeholder(std::size_t i) {
    return "<!--ivv-figure-" + std::to_string(i) + "-->";
  }
  std::string figure_html(std::size_t i) const {
    const Figure& f = figures_[i];
    std::string out = "<figure id=\"fig-" + f.plot.id + "\"" +
                      (f.full_width ? " class=\"wide\"" : "") + source_attribute(f.source) + ">\n";
    if (errors_[i].empty()) {
      out += svgs_[i];
    } else {
      out += "<div class=\"plot-error\" data-plot-id=\"" + escape(f.plot.id) +
             "\">This plot could not be drawn: " + escape(errors_[i]) + "</div>";
    }
    const std::string label = source_label(f.source);
    out += "\n<figcaption><b class=\"ftitle\">" + escape(f.plot.title) + "</b>" +
           (label.empty() ? "" : label + "<br>") + f.caption + "</figcaption>\n";
    out += "</figure>\n";
    return out;
  }

  std::vector<Figure> figures_;
  std::vector<SvgSize> sizes_;
  std::set<std::string> ids_;
  std::vector<std::string> svgs_, errors_;
};

std::string pass_fail(bool passed) {
  return passed ? "<span class=\"pass\">pass</span>" : "<span class=\"fail\">FAIL</span>";
}

std::string num_cell(double v, int digits = 6) {
  return std::isnan(v) ? std::string("—") : number(v, digits);
}

std::string case_anchor(const std::string& id) {
  return "case-" + slug(id);
}

// A computation of one section that may throw: its HTML, or an error box.
struct SectionResult {
  std::string html;
  std::optional<std::string> error;
};

template <class F>
SectionResult guarded(const std::string& name, const SectionOptions& so, F&& f) {
  SectionResult r;
  try {
    r.html = f();
  } catch (const std::exception& e) {
    r.error = e.what();
    r.html = "<div class=\"plot-error\">The " + escape(name) +
             " section could not be computed: " + escape(e.what()) + "</div>\n";
    so.say(name + ": FAILED: " + e.what());
  }
  return r;
}

// ---- section 1 ---------------------------------------------------------------------------

// The cases per evidence tier, passed and failed.
std::string tier_counts_html(const std::vector<CaseRecord>& records) {
  std::vector<std::vector<std::string>> rows;
  for (Tier t : verification::all_tiers()) {
    std::size_t n = 0, pass = 0;
    for (const auto& r : records) {
      if (r.c->tier != t) continue;
      ++n;
      pass += r.outcome.passed ? 1 : 0;
    }
    if (n == 0) continue;
    rows.push_back(
        {"<a href=\"#tier-" + slug(std::string(verification::to_string(t))) + "\">" +
             escape(std::string(verification::to_string(t))) + "</a>",
         std::to_string(n), std::to_string(pass),
         n == pass ? "0" : "<span class=\"fail\">" + std::to_string(n - pass) + "</span>"});
  }
  return "<h3>Cases per evidence tier</h3>\n" + table({"tier", "cases", "passed", "failed"}, rows,
                                                      Source::rows_are_cases(), "data counts");
}

// What produced the report: commit, compiler, libraries, machine, command and run time.
std::string provenance_html(const Provenance& prov, const ReportOptions& opt,
                            const std::vector<std::pair<std::string, double>>& stage_seconds) {
  std::string out;
  out += "<h3>Provenance</h3>\n<dl class=\"prov\">\n";
  auto item = [&](const std::string& k, const std::string& v) {
    out += "<dt>" + escape(k) + "</dt><dd>" + v + "</dd>\n";
  };
  item("git commit", "<code>" + escape(prov.git_commit) + "</code>" +
                         (prov.git_dirty ? " (working tree with uncommitted changes)" : ""));
  item("compiler", escape(prov.compiler));
  item("flags", "<code>" + escape(prov.flags.empty() ? "(none)" : prov.flags) + "</code>");
  item("build type", escape(prov.build_type.empty() ? "(unspecified)" : prov.build_type));
  std::string libs;
  for (const auto& [name, version] : prov.libraries)
    libs += (libs.empty() ? "" : ", ") + escape(name) + " " + escape(version);
  item("libraries", libs);
  item("date (UTC)", escape(prov.date_utc));
  item("machine", escape(prov.cpu_model) + ", " + std::to_string(prov.logical_cores) +
                      " logical cores, host " + escape(prov.host));
  item("command", "<code>" + escape(prov.command_line.empty() ? "(not given)" : prov.command_line) +
                      "</code>");
  std::string stages;
  double total = 0;
  for (const auto& [name, s] : stage_seconds) {
    stages += (stages.empty() ? "" : "; ") + escape(name) + " " + number(s, 3) + " s";
    total += s;
  }
  item("run time",
       number(total, 3) + " s (" + stages + "), " +
           std::to_string(worker_count(std::numeric_limits<std::size_t>::max(), opt.threads)) +
           " threads" + (opt.quick ? ", quick mode (fewer benchmark points)" : ""));
  out += "</dl>\n";
  return out;
}

// What the report verifies, and where the model stops applying: the first thing a reader
// needs, before any figure. Words and links only; the numbers are in the sections and cases
// linked.
std::string scope_html() {
  return "<h3 id=\"scope\">What is verified</h3>\n<ul class=\"scope\">\n"
         "<li><b>The solvers against closed forms</b> (tier analytic): Hertz, the undamped "
         "elastoplastic impact by energy, the linearized model (paper eqs 22-25), Hunt-Crossley "
         "by the Lambert W function, Zener's sphere on a plate.</li>\n"
         "<li><b>Independent implementations against each other</b> (cross-implementation): "
         "odeint, a hand-written Runge-Kutta, GSL, SUNDIALS and a 50-digit reference share the "
         "contact laws and nothing else; a finite plate's modes against a convolution "
         "oracle.</li>\n"
         "<li><b>Energy and momentum</b> (conservation): the energy ledger and the impulse of "
         "every run.</li>\n"
         "<li><b>The paper's and the literature's trends</b> (published-trend, <a "
         "href=\"#paper\">the paper reproduced</a>, <a href=\"#restitution\">restitution "
         "trends</a>): the paper's "
         "claims, Thornton (1997), the v<sub>0</sub><sup>-1/4</sup> limit, the Hunt-Crossley "
         "damping maps.</li>\n"
         "<li><b>The numerics</b> (convergence, stability, <a href=\"#speed\">speed against "
         "error</a>): "
         "convergence orders, events located on the interpolant, the hard scenes of "
         "docs/design.md §6.</li>\n</ul>\n"
         "<h3 id=\"limits\">Where the model stops applying</h3>\n<ul class=\"scope\">\n"
         "<li><b>A frictionless central impact</b> of a sphere on a half-space or a large "
         "structure: one contact spring in series with one dashpot. No friction, rotation or "
         "oblique impact.</li>\n"
         "<li><b>The linearized law</b> (eqs 15-18) is undefined when the compression stays "
         "below 2.25 z<sub>y</sub> (elastic impacts and those just above yield); ivv says so "
         "instead of returning a number, and the paper's figures draw no linearized curve "
         "there.</li>\n"
         "<li><b>The dashpot from the structure is the infinite plate's</b> (<a "
         "href=\"#structure\">damping from the structure</a>): c = 8&radic;(&rho;hD*) holds while "
         "no bending wave "
         "returns from the plate's edges during the contact. The e = 0 of thin plates there is "
         "that idealisation's capture; a finite plate (scene keys <code>length_x</code>, "
         "<code>length_y</code>) keeps the energy in its modes and may rebound, after one or "
         "several contacts (cases <code>plate.*</code>; <a href=\"#plate-regime\">where the "
         "infinite plate stops</a>).</li>\n"
         "<li><b>Strong damping captures the sphere</b> (e = 0): a physical outcome of the "
         "model, reported as captured, not a failure.</li>\n"
         "<li><b>Validation against measurements is not shown</b>: no digitised experimental "
         "restitution data is at hand; <a href=\"#validation\">validation</a> demonstrates the "
         "method on synthetic data.</li>\n</ul>\n";
}

std::string summary_html(const std::vector<CaseRecord>& records, const Provenance& prov,
                         const ReportOptions& opt, const std::vector<std::string>& section_errors,
                         const std::vector<std::pair<std::string, double>>& stage_seconds) {
  std::size_t failed = 0;
  for (const auto& r : records) failed += r.outcome.passed ? 0 : 1;
  const bool ok = failed == 0 && section_errors.empty();
  std::string out =
      std::string("<div class=\"verdict ") + (ok ? "pass" : "fail") + "\" id=\"verdict\">";
  if (ok) {
    out += "PASS: all " + std::to_string(records.size()) + " verification cases passed";
  } else {
    out += "FAIL: " + std::to_string(failed) + " of " + std::to_string(records.size()) +
           " verification cases failed";
    if (!section_errors.empty())
      out +=
          ", " + std::to_string(section_errors.size()) + " report section(s) could not be computed";
  }
  out += "</div>\n";
  if (opt.allow_failures && !ok)
    out +=
        "<p class=\"note\">Written with --allow-failures: failures do not change the exit "
        "status of this run.</p>\n";
  if (!opt.filter.empty() && opt.filter != "*")
    out += "<p class=\"note\">Only the cases matching <code>" + escape(opt.filter) +
           "</code> were run.</p>\n";

  if (failed > 0 || !section_errors.empty()) {
    out += "<h3 id=\"failures\">What fell short</h3>\n";
    std::vector<std::vector<std::string>> frows;
    for (const auto& r : records) {
      if (r.outcome.passed) continue;
      frows.push_back({"<a href=\"#" + case_anchor(r.c->id) + "\"><code>" + escape(r.c->id) +
                           "</code></a><br>" + escape(r.c->title),
                       escape(comparison_text(r.outcome)), escape(r.outcome.detail)});
    }
    for (const auto& e : section_errors) frows.push_back({"report section", "", escape(e)});
    out +=
        table({"case", "comparison", "detail"}, frows, Source::rows_are_cases(), "data failures");
  }
  out += scope_html();
  out += tier_counts_html(records);
  out += provenance_html(prov, opt, stage_seconds);
  return out;
}

// ---- every verification case -----------------------------------------------------------

// The rows of one case: its measurement and verdict, then its detail and plots (collapsed
// when it passed).
std::string case_rows(const CaseRecord& r, FigureBook& book) {
  const auto& o = r.outcome;
  std::string out = std::string("<tr id=\"") + case_anchor(r.c->id) + "\"" +
                    (o.passed ? "" : " class=\"failed\"") + "><td><code>" + escape(r.c->id) +
                    "</code><br>" + escape(r.c->title) + "</td>" + "<td class=\"num\">" +
                    num_cell(o.measured, 6) + "</td><td class=\"num\">" + num_cell(o.reference, 6) +
                    "</td><td class=\"num\">" + num_cell(o.tolerance, 3) + "</td><td>" +
                    escape(std::string(verification::to_string(o.comparison))) +
                    "</td><td class=\"reason\">" + escape(r.c->reason) + "</td><td class=\"num\">" +
                    number(o.margin(), 3) + "</td><td>" + pass_fail(o.passed) + "</td></tr>\n";
  std::string detail = "<p>" + escape(o.detail) + "</p><p>" + escape(comparison_text(o)) +
                       "; run time " + number(r.seconds, 3) + " s.</p>\n";
  for (std::size_t i = 0; i < o.plots.size(); ++i) {
    Figure f{.plot = o.plots[i], .caption = "", .source = Source::from_cases({r.c->id})};
    f.plot.id = r.c->id + "." + (f.plot.id.empty() ? "plot" + std::to_string(i) : f.plot.id);
    detail += book.add(std::move(f));
  }
  const std::string what = o.plots.empty() ? "detail"
                                           : "detail and " + std::to_string(o.plots.size()) +
                                                 (o.plots.size() == 1 ? " plot" : " plots");
  out += std::string("<tr class=\"detail") + (o.passed ? "" : " failed") +
         "\"><td colspan=\"8\"><details class=\"case\"" + (o.passed ? "" : " open") + "><summary>" +
         what + "</summary><div>" + detail + "</div></details></td></tr>\n";
  return out;
}

// The table of every case, one collapsed block per evidence tier (open when one of its cases
// failed), failures first within a tier.
std::string cases_html(const std::vector<CaseRecord>& records, FigureBook& book) {
  std::string out =
      "<p>Each case measures one number and compares it with a reference under a tolerance "
      "whose reason is stated (<code>verification/</code>, the same registry that ctest "
      "runs). <i>Margin</i> is tolerance/error for ≤ comparisons and measured/bound for ≥ "
      "ones: above 1 passes. Expand a tier for its table, a row for the detail and the case's "
      "plots; a tier with a failed case is open.</p>\n";
  if (records.empty()) out += "<p>No case was run.</p>\n";
  for (Tier t : verification::all_tiers()) {
    std::vector<const CaseRecord*> in_tier;
    for (const auto& r : records)
      if (r.c->tier == t) in_tier.push_back(&r);
    if (in_tier.empty()) continue;
    const auto passed_end = std::stable_partition(
        in_tier.begin(), in_tier.end(), [](const CaseRecord* r) { return !r->outcome.passed; });
    const std::size_t failed = static_cast<std::size_t>(passed_end - in_tier.begin());
    const std::string tier(verification::to_string(t));
    out += std::string("<details class=\"tier\"") + (failed > 0 ? " open" : "") +
           "><summary><h3 id=\"tier-" + slug(tier) + "\">" + escape(tier) + " (" +
           std::to_string(in_tier.size()) + " cases" +
           (failed > 0 ? ", <span class=\"fail\">" + std::to_string(failed) + " failed</span>"
                       : std::string()) +
           ")</h3></summary>\n";
    out += table_open(Source::rows_are_cases(), "data cases") +
           "<colgroup><col class=\"c-id\"><col class=\"c-num\">"
           "<col class=\"c-num\"><col class=\"c-tol\"><col class=\"c-cmp\"><col class=\"c-reason\">"
           "<col class=\"c-margin\"><col class=\"c-verdict\"></colgroup>\n<thead><tr><th>case</th>"
           "<th class=\"num\">measured</th><th class=\"num\">reference</th>"
           "<th class=\"num\">tolerance</th><th>comparison</th><th>why this tolerance</th>"
           "<th class=\"num\">margin</th><th>verdict</th></tr></thead>\n<tbody>\n";
    for (const CaseRecord* r : in_tier) out += case_rows(*r, book);
    out += "</tbody></table>\n</details>\n";
  }
  return out;
}

// ---- sections 2, 3, 5 --------------------------------------------------------------------

// Figures in order: consecutive half-width ones side by side in a two-column grid, full-width
// ones alone.
std::string figures_html(const std::vector<Figure>& figures, FigureBook& book) {
  std::string out;
  bool in_grid = false;
  for (const auto& f : figures) {
    if (f.full_width == in_grid) {
      out += in_grid ? "</div>\n" : "<div class=\"grid2\">\n";
      in_grid = !in_grid;
    }
    out += book.add(f, in_grid);
  }
  return out + (in_grid ? "</div>\n" : "");
}

std::string paper_html(const SectionOptions& so, FigureBook& book) {
  std::string out =
      "<p>The figures of the paper (<i>A nonlinear visco-elastoplastic impact model and the "
      "coefficient of restitution</i>, Table 1 scene) recomputed by this library: the nonlinear "
      "model by numerical integration (odeint-dopri5, rtol 1e-12, events located), the "
      "linearized model in closed form, Hunt-Crossley fitted by <code>fit_hunt_crossley</code>. "
      "The paper's own fitted Hunt-Crossley values are withheld; nothing here uses them. Where "
      "the paper does not state a parameter (the S<sub>y</sub> and mass values of Figs 8-9, the "
      "velocities and damping ratios of Figs 10-14) the captions say which were used.</p>\n"
      "<p>" +
      paper_parameters_html() + "</p>\n";
  return out + figures_html(paper_figures(so), book);
}

// One row of a "delivered e at v0 = 1" table: the reference run's e at 1 m/s of a worked
// example claiming the COR e_t, its miss and the verdict of its dynamic.expected_cor check.
std::vector<std::string> delivered_row(std::vector<std::string> leading,
                                       const verification::ExampleRun& run, double e_t) {
  const auto* c = verification::find_check(run.report, "dynamic.expected_cor");
  std::optional<double> e;
  for (const auto& p : run.report.cor)
    if (std::abs(p.v0 - 1.0) < 1e-12 && p.e) e = p.e;
  leading.push_back(number_html(e_t));
  leading.push_back(e ? number_html(*e, 7) : "failed");
  leading.push_back(e ? number_html(*e - e_t, 3) : "");
  leading.push_back(c && c->passed ? "<span class=\"pass\">delivers</span>"
                                   : "<span class=\"fail\">misses</span>");
  return leading;
}

// The Hunt-Crossley worked example: what each published mu(e) map delivers at each target.
std::string hunt_crossley_maps_example_html(const SectionOptions& so) {
  so.say("worked examples: Hunt-Crossley damping maps");
  std::string out =
      "<h3 id=\"example-hunt-crossley\">Hunt-Crossley with the published &mu;(e) maps</h3>\n"
      "<p>F = K<sub>h</sub> z<sup>3/2</sup>(1 + &mu; dz/dt) with &mu; from each map for a "
      "target e, put through <code>check-law --expect-cor</code> (e.g. <code>" +
      escape(verification::hunt_crossley_map_example("hunt-crossley", 0.5).command) +
      "</code>). Delivered e: the reference run at v<sub>0</sub> = 1 m/s (it is the same at "
      "every v<sub>0</sub>: &mu;v<sub>0</sub> is fixed). A map delivers its target when the "
      "miss is within 10<sup>-6</sup>.</p>\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& map : closed_forms::damping_maps())
    for (double e_t : verification::example_target_cors())
      rows.push_back(
          delivered_row({escape(map.name), escape(map.formula)},
                        verification::hunt_crossley_map_example(std::string(map.name), e_t), e_t));
  return out + table({"map", "&mu;(e)", "target e", "delivered e", "miss", "verdict"}, rows,
                     Source::from_cases({"examples.hunt-crossley.*"}));
}

// The Tsuji-type damping worked example: the delivered e, clamped and with tension.
std::string tsuji_example_html(const SectionOptions& so) {
  so.say("worked examples: Tsuji-type damping");
  std::string out =
      "<h3 id=\"example-tsuji\">Hertz with Tsuji-type damping (DEM codes)</h3>\n"
      "<p>F = K<sub>h</sub> z<sup>3/2</sup> + &gamma;<sub>n</sub> dz/dt, &gamma;<sub>n</sub> = "
      "-2&radic;(5/6) &beta; &radic;(S<sub>n</sub> m), S<sub>n</sub> = 2E*&radic;(R z), "
      "&beta; = ln e<sub>t</sub>/&radic;(ln&sup2; e<sub>t</sub> + &pi;&sup2;) (LIGGGHTS "
      "<code>model hertz</code>), once with the force clamped at F &ge; 0 (contact ends at "
      "F = 0, LIGGGHTS <code>limitForce on</code>) and once with tension until z = 0. "
      "Delivered e at v<sub>0</sub> = 1 m/s (independent of v<sub>0</sub>: case "
      "<code>examples.tsuji.*</code>).</p>\n";
  std::vector<std::vector<std::string>> rows;
  for (bool tension : {false, true})
    for (double e_t : verification::example_target_cors())
      rows.push_back(delivered_row({tension ? "tension until z = 0" : "clamped, F &ge; 0"},
                                   verification::tsuji_example(e_t, tension), e_t));
  return out + table({"contact end", "target e<sub>t</sub>", "delivered e", "miss", "verdict"},
                     rows, Source::from_cases({"examples.tsuji.*"}));
}

// The adhesive worked examples on the shipped glass bead: a DMT-type law with its declared jump
// at onset (and the same law undeclared, rejected), a JKR-type hysteresis captured in its well.
std::string adhesive_examples_html(const SectionOptions& so,
                                   const std::function<PlacePlot(const std::string&)>& place) {
  using verification::ExampleRun;
  so.say("worked examples: adhesive laws");
  const auto command = [](const ExampleRun& run) {
    return "<p>The same check from the command line: <code>" + escape(run.command) +
           "</code></p>\n";
  };
  const ExampleRun& dmt = verification::dmt_example(verification::OnsetDeclaration::declared);
  const ExampleRun& undeclared =
      verification::dmt_example(verification::OnsetDeclaration::undeclared);
  const ExampleRun& jkr = verification::jkr_example();
  const double v_c = verification::jkr_capture_speed(verification::glass_bead_scene());
  std::string out =
      "<h3 id=\"example-adhesive\">Adhesive laws on a 100 &micro;m glass bead</h3>\n"
      "<p>The shipped scene <code>glass-bead</code> (R = 50 &micro;m, m = 1.466e-9 kg, the "
      "glass of Chung &amp; Ooi 2011, on a glass flat, no dashpot) with a pull-off force "
      "F<sub>ad</sub> = " +
      number_html(verification::kBeadPullOff) +
      " N (illustrative, not measured), tension allowed until z = 0.</p>\n"
      "<h4>DMT-type: K<sub>h</sub>z<sup>3/2</sup> - F<sub>ad</sub>, jump at onset declared</h4>\n" +
      law_section_html(dmt.report, "examples-dmt",
                       command(dmt) +
                           "<p>Conservative: e = 1 at every v<sub>0</sub>. Without "
                           "<code>--onset-force=-Fad</code> the same law fails "
                           "<code>static.onset</code> (case "
                           "<code>examples.dmt.undeclared-jump-rejected</code>): " +
                           escape(undeclared.report.brief()) + ".</p>\n",
                       place("examples.dmt.*"), Source::from_cases({"examples.dmt.*"}));
  out +=
      "<h4>JKR-type: Hertz loading, unloading K<sub>h</sub>z<sup>3/2</sup> - "
      "F<sub>ad</sub>(1 - z/z<sub>m</sub>)</h4>\n" +
      law_section_html(
          jkr.report, "examples-jkr",
          command(jkr) +
              "<p>Energy balance: e&sup2; = 1 - 5F<sub>ad</sub>/(4F<sub>max</sub>) "
              "(F<sub>max</sub> the Hertz peak force), captured in the well (e = 0, decided at "
              "the first unloading step: case <code>examples.jkr.captured-in-well</code>) below "
              "v<sub>c</sub> = " +
              number_html(v_c, 4) + " m/s.</p>\n",
          place("examples.jkr.*"), Source::from_cases({"examples.jkr.*"}));
  return out;
}

// Contact-law worked examples: the same memoised conformance runs the example cases judge.
std::string examples_html(const SectionOptions& so, FigureBook& book) {
  using verification::ExampleRun;
  // the conformance plots of one example, from its cases
  const auto place = [&book](const std::string& cases) -> PlacePlot {
    return [&book, cases](const Plot& p, const std::string& caption) {
      return book.add({p, escape(caption), false, Source::from_cases({cases})});
    };
  };
  auto command = [](const ExampleRun& run) {
    return run.command.empty() ? std::string()
                               : "<p>The same check from the command line: <code>" +
                                     escape(run.command) + "</code></p>\n";
  };
  std::string out =
      "<p>What a contact-law author gets from <code>ivv check-law</code> and the C++ "
      "conformance API (<code>verification/conformance.h</code>): static checks of the law's "
      "equations (among them reloading: unloaded from z<sub>m</sub> to z<sub>1</sub> and "
      "reloaded on its unloading branch, the law creates no energy over the cycle and meets its "
      "loading curve at z<sub>m</sub>), then dynamic checks over v<sub>0</sub> = 0.01-10 m/s "
      "with and without the series dashpot, or, on a scene with a finite plate, striking the "
      "plate (its vibration energy in the ledger, the final e). Each example below is judged by "
      "the cases <code>examples.*</code>; the tables are those cases' measurements.</p>\n";
  so.say("worked examples: Thornton");
  const ExampleRun& thornton = verification::thornton_example();
  out +=
      "<h3 id=\"example-thornton\">Thornton (1997), elastic-perfectly-plastic (C++)</h3>\n" +
      law_section_html(thornton.report, "examples-thornton",
                       "<p>Source: <code>examples/laws/thornton.h</code>; claimed COR: "
                       "Thornton's closed form (docs/design.md §3).</p>\n",
                       place("examples.thornton.*"), Source::from_cases({"examples.thornton.*"}));
  so.say("worked examples: Kuwabara-Kono");
  const ExampleRun& kk = verification::kuwabara_kono_example();
  out += "<h3 id=\"example-kuwabara-kono\">Kuwabara-Kono viscoelastic Hertz (C++)</h3>\n" +
         law_section_html(kk.report, "examples-kuwabara-kono",
                          "<p>Source: <code>examples/laws/kuwabara_kono.h</code>; claimed COR: "
                          "the Muller-Poschel Pade form (docs/design.md §3).</p>\n",
                          place("examples.kuwabara-kono.*"),
                          Source::from_cases({"examples.kuwabara-kono.*"}));
  so.say("worked examples: Kelvin-Voigt");
  const ExampleRun& kv = verification::kelvin_voigt_example();
  out +=
      "<h3 id=\"example-kelvin-voigt\">Kelvin-Voigt k z + c dz/dt (expression): rejected</h3>\n" +
      law_section_html(kv.report, "examples-kelvin-voigt", command(kv),
                       place("examples.kelvin-voigt.rejected"),
                       Source::from_cases({"examples.kelvin-voigt.rejected"}));

  return out + hunt_crossley_maps_example_html(so) + tsuji_example_html(so) +
         adhesive_examples_html(so, place);
}

std::string restitution_html(const SectionOptions& so, FigureBook& book) {
  const RestitutionSection r = restitution_section(so);
  std::string out =
      "<p>Restitution of the elastoplastic law against the published trends "
      "(docs/design.md §3).</p>\n";
  out += book.add(r.figures.at(0));
  std::string t =
      table_open(Source::from_cases({"trend.cor-undamped-simulated-is-closed-form",
                                     "trend.cor-slope-simulated-is-closed-form",
                                     "trend.cor-slope-near-yield", "trend.cor-slope-minus-quarter",
                                     "trend.cor-undamped-asymptote"}),
                 "data slopes") +
      "<thead><tr><th class=\"num\">v0/v_y</th>"
      "<th class=\"num\">e (closed form)</th><th class=\"num\">e (simulated)</th>"
      "<th class=\"num\">d ln e/d ln v0 (closed form)</th><th class=\"num\">d ln e/d ln v0 "
      "(simulated)</th><th class=\"num\">e / asymptote</th></tr></thead><tbody>\n";
  for (const auto& s : r.slopes)
    t += "<tr><td class=\"num\">" + number(s.ratio, 4) + "</td><td class=\"num\">" +
         number(s.e_closed_form, 6) + "</td><td class=\"num\">" + number(s.e_simulated, 6) +
         "</td><td class=\"num\">" + number(s.slope_closed_form, 5) + "</td><td class=\"num\">" +
         number(s.slope_simulated, 5) + "</td><td class=\"num\">" +
         number(s.e_closed_form / s.asymptote, 5) + "</td></tr>\n";
  t += "</tbody></table>\n";
  out +=
      "<h3>Local slope of the undamped COR</h3>\n<p>Central differences over v<sub>0</sub>(1 ± " +
      number(r.log_step) +
      "), of the closed form and of simulations (odeint-dopri5, rtol 1e-12, atol 1e-14); the "
      "one slope computation of ivv (<code>verification::undamped_cor_study</code>), read by "
      "the cases below. The slope tends to −1/4 from below only slowly; it is not −1/4 just "
      "above yield.</p>\n" +
      t;
  out += figures_html({r.figures.begin() + 1, r.figures.end()}, book);
  std::string mt = table_open(Source::from_cases({"trend.hunt-crossley-map.*"}), "data maps") +
                   "<thead><tr><th>map</th><th>μ(e, v0)</th>";
  for (double e : r.map_targets) mt += "<th class=\"num\">target e = " + number(e) + "</th>";
  mt += "</tr></thead><tbody>\n";
  for (const auto& m : r.maps) {
    mt += "<tr><td>" + escape(m.name) + "</td><td><code>" + escape(m.formula) + "</code></td>";
    for (double d : m.delivered) mt += "<td class=\"num\">" + number(d, 4) + "</td>";
    mt += "</tr>\n";
  }
  mt += "</tbody></table>\n";
  out +=
      "<h3>What each Hunt-Crossley damping map delivers</h3>\n<p>Simulated (odeint-dopri5, "
      "rtol 1e-12) at v<sub>0</sub> = 1 m/s with the μ each map picks.</p>\n" +
      mt;
  return out;
}

std::string structure_html(const SectionOptions& so, FigureBook& book) {
  const StructureSection s = structure_section(so);
  std::string out = s.intro_html;
  out += book.add(s.figures.at(0));
  out += "<h3>Similarity: four scenes at the same lambda</h3>\n" + s.similarity_table_html;
  out += "<h3>The paper's impactor on a plate</h3>\n" + book.add(s.figures.at(1));
  out += s.plate_properties_html;
  const PlateRegimeSection p = plate_regime_section(so);
  out += "<h3 id=\"plate-regime\">Where the infinite plate stops</h3>\n" + p.intro_html;
  out += book.side_by_side(p.figures.at(0), p.figures.at(1)) + book.add(p.figures.at(2)) +
         p.models_table_html;
  return out;
}

std::string status_cell(const verification::HardCaseCell& c) {
  const ImpactResult& r = c.result;
  std::string s = "<b>" + escape(std::string(to_string(r.status))) + "</b>";
  if (r.ok())
    s += "<br>e = " + number(r.e, 8);
  else
    s += "<br><small>" + escape(r.reason) + "</small>";
  s += "<br>" + std::to_string(r.steps) + " steps, " + number(c.seconds * 1e3, 3) +
       " ms <small>(time: information)</small>";
  return s;
}

std::string speed_html(const SectionOptions& so, FigureBook& book) {
  const SpeedSection s = speed_section(so);
  std::string out = "<p>Timings: single-threaded wall clock on " + escape(s.machine.cpu_model) +
                    " (" + std::to_string(s.machine.logical_cores) + " logical cores), " +
                    escape(s.machine.compiler) + ", " + escape(s.machine.build_type) +
                    " build. They are information, never pass/fail; compare integrators "
                    "within one study rather than absolute times across machines.</p>\n";
  std::size_t fig = 0;
  for (const auto& study : s.studies) {
    // one integrator per series, up to 13: each plot alone on its row, its key legible
    out += "<h3>Work-precision: " + escape(study.label) + "</h3>\n";
    out += book.add(s.figures.at(fig++));
    out += book.add(s.figures.at(fig++));
    std::string t = table_open(Source::timing({"cross.*"})) +
                    "<thead><tr><th>integrator</th><th class=\"num\">"
                    "tolerance</th><th class=\"num\">time/impact [s]</th><th class=\"num\">"
                    "error e</th><th class=\"num\">error F_max</th><th class=\"num\">error "
                    "t_f</th><th class=\"num\">steps</th><th class=\"num\">RHS evals</th>"
                    "<th>status</th></tr></thead><tbody>\n";
    for (const auto& series : study.series)
      for (const auto& p : series.points)
        t += "<tr><td>" + escape(std::string(to_string(series.integrator))) +
             "</td><td class=\"num\">" + number(p.tolerance, 3) + "</td><td class=\"num\">" +
             number(p.seconds_per_impact, 3) + "</td><td class=\"num\">" + number(p.error_e, 3) +
             "</td><td class=\"num\">" + number(p.error_F_max, 3) + "</td><td class=\"num\">" +
             number(p.error_t_contact, 3) + "</td><td class=\"num\">" + std::to_string(p.steps) +
             "</td><td class=\"num\">" + std::to_string(p.rhs_evaluations) + "</td><td>" +
             (p.ok ? std::string("ok") : "<span class=\"fail\">" + escape(p.reason) + "</span>") +
             "</td></tr>\n";
    t += "</tbody></table>\n";
    out += "<details class=\"case\"><summary>every point of this study</summary><div>" + t +
           "</div></details>\n";
    if (&study == &s.studies.front() && !s.ratios.empty())
      out += "<h4>ivv against the peers</h4>\n" + ratio_table_html(s);
  }
  out += "<h3>Convergence order</h3>\n";
  out += book.add(s.figures.at(fig++));
  std::vector<std::vector<std::string>> crows;
  for (const auto& c : s.convergence)
    crows.push_back({escape(std::string(to_string(c.integrator))),
                     c.events_located ? "located on the interpolant" : "at step ends only",
                     number(c.fitted_order, 4)});
  out += table({"integrator", "events", "fitted order"}, crows,
               Source::from_cases({"convergence.rk4.events-at-step-ends",
                                   "convergence.dp45.events-at-step-ends"}));

  out +=
      "<h3>Hard cases</h3>\n<p>Each integrator with its defaults (rtol 1e-10; rk4 dt = 1e-3 "
      "in τ) on the hard scenes of docs/design.md §6: status, e, accepted steps and the wall time "
      "of "
      "the one run (information only: measured while other cases may run on other threads, "
      "never judged). A solver that cannot meet its tolerance must say so (status failed), "
      "never return a silently wrong COR.</p>\n";
  std::string t = table_open(Source::from_cases({"stability.hard-cases.named-or-within-tolerance"}),
                             "data hard") +
                  "<thead><tr><th>scene</th><th>independent e</th>";
  if (!s.hard_cases.empty())
    for (const auto& c : s.hard_cases.front().cells)
      t += "<th>" + escape(std::string(to_string(c.integrator))) + "</th>";
  t += "</tr></thead><tbody>\n";
  for (const auto& row : s.hard_cases) {
    t += "<tr><td><b>" + escape(row.name) + "</b><br><small>" + escape(row.description) +
         "</small></td><td>" + num_cell(row.reference_e, 10) + "<br><small>" +
         escape(row.reference_source) + "</small></td>";
    for (const auto& c : row.cells) t += "<td>" + status_cell(c) + "</td>";
    t += "</tr>\n";
  }
  t += "</tbody></table>\n";
  return out + t;
}

// ---- section 8: validation against measurements (the shipped example) -------------------

std::string validation_html(const SectionOptions& so, FigureBook& book) {
  so.say("validation: the shipped calibration example");
  const validation::ShippedExample& x = validation::shipped_example();
  const Source source = Source::from_cases({"validation.example.*"});
  const PlacePlot place = [&book, source](const Plot& p, const std::string& caption) {
    return book.add({p, escape(caption), false, source});
  };
  reports::CalibrationView view{&x.problem,    &x.fit,     &x.band,
                                &x.validation, &x.ranking, &x.ranking_curves};
  return "<p>What <code>ivv calibrate</code> and <code>ivv predict</code> give an analyst with "
         "measured restitution. The data are <b>SYNTHETIC</b> (no digitised experimental COR "
         "data is at hand): <code>reference_data/calibration_example.csv</code>, generated by "
         "<code>reference_data/generate_calibration_example.py</code> from the scene "
         "<code>paper-damped</code> (c = 11440 N s/m, S<sub>y</sub> = 202 MPa) with Gaussian "
         "noise u<sub>e</sub> = 0.01. The fit starts from c = 8000 N s/m, S<sub>y</sub> = 300 MPa. "
         "Judged by the cases <code>validation.example.*</code>; the method by "
         "<code>validation.calibrate.*</code>, <code>validation.identifiability.*</code> and "
         "<code>validation.wrong-model.*</code>.</p>\n" +
         calibration_section_html(view, "validation-example", place, source);
}

std::string companions_html() {
  return "<p>Beside this page, in the same directory:</p><ul>\n"
         "<li><a href=\"results.json\"><code>results.json</code></a>: "
         "<code>{\"cases\": [{\"id\", \"title\", \"tier\", \"passed\", \"measured\", "
         "\"reference\", \"tolerance\", \"reason\", \"comparison\", \"margin\", \"detail\", "
         "\"slow\", \"seconds\"}]}</code>, the shape of <code>ivv verify</code> (non-finite "
         "numbers are "
         "null).</li>\n"
         "<li><a href=\"series.csv\"><code>series.csv</code></a>: every plotted series of this "
         "page, one row per point, columns <code>plot_id,series,x,y</code>; "
         "<code>plot_id</code> is the <code>data-plot-id</code> of the plot's SVG and the "
         "anchor <code>#fig-&lt;plot_id&gt;</code>.</li>\n"
         "<li><a href=\"junit.xml\"><code>junit.xml</code></a>: one test suite per evidence "
         "tier, one test case per verification case, failures with their detail.</li>\n"
         "</ul>\n";
}

void check_out_dir(const fs::path& dir) {
  if (dir.empty()) throw InputError("--out", "an output directory is required");
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError("--out", "'" + dir.string() + "' exists and is not a directory");
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError("--out", "cannot create the directory '" + dir.string() +
                                  "': " + (ec ? ec.message() : std::string("not a directory")));
}

// One numbered section of the page: its anchor, its heading and its body.
struct PageSection {
  std::string id, title, html;
};

// The page's heading (with its provenance), the table of contents and the numbered sections,
// in the order of the list.
std::string report_body(const Provenance& prov, const std::vector<PageSection>& sections) {
  std::string body =
      "<header><h1>ivv verification report</h1>\n<p class=\"lead\">"
      "Visco-elastoplastic impact model: verification cases, the paper's figures, "
      "restitution trends and speed against error. Generated " +
      escape(prov.date_utc) + " from commit <code>" + escape(prov.git_commit.substr(0, 12)) +
      "</code>. Every figure and table says where its numbers come from: the verification "
      "cases whose measurements it shows, or the label <i>Illustration</i> or <i>Timing, "
      "information only</i>.</p></header>\n";
  body += "<nav class=\"toc\"><b>Contents</b><ol>";
  for (const auto& s : sections) body += "<li><a href=\"#" + s.id + "\">" + s.title + "</a></li>";
  body += "</ol></nav>\n";
  for (std::size_t i = 0; i < sections.size(); ++i)
    body += "<section class=\"part\"><h2 id=\"" + sections[i].id + "\"" +
            (i == 0 ? " class=\"first\"" : "") + ">" + std::to_string(i + 1) + ". " +
            sections[i].title + "</h2>\n" + sections[i].html + "</section>\n";
  return body;
}

// index.html, results.json, series.csv and junit.xml, staged and committed together.
void write_files(const fs::path& out_dir, const std::vector<verification::CaseRecord>& records,
                 const FigureBook& book, const std::string& html, const SectionOptions& so) {
  so.say("writing index.html, results.json, series.csv, junit.xml to " + out_dir.string());
  {
    // all four written first, then renamed into place: a full disk or any write error leaves
    // none of them (a full disk once left results.json without index.html)
    StagedFile results(out_dir / "results.json",
                       [&](std::ostream& os) { os << results_json(records); });
    StagedFile series(out_dir / "series.csv",
                      [&](std::ostream& os) { os << series_csv(book.plots()); });
    StagedFile junit(out_dir / "junit.xml", [&](std::ostream& os) { os << junit_xml(records); });
    StagedFile index(out_dir / "index.html", [&](std::ostream& os) { os << html; });
    for (StagedFile* f : {&results, &series, &junit, &index}) f->commit();
  }
}

}  // namespace

ReportSummary write_report(const ReportOptions& opt) {
  if (opt.out_dir.empty()) throw InputError("--out", "an output directory is required");
  validate_threads(opt.threads);
  const auto selected = verification::select_cases(opt.filter);
  check_out_dir(opt.out_dir);
  auto say = [&](const std::string& line) {
    if (opt.progress) opt.progress(line);
  };
  say("verification cases: running " + std::to_string(selected.size()) + " on " +
      (opt.threads > 0 ? std::to_string(opt.threads) : std::string("all")) + " threads");
  const verification::BatteryResult battery = verification::run_battery(
      selected, opt.threads, [&](std::size_t done, std::size_t total, const verification::Case& c) {
        say("case " + std::to_string(done) + "/" + std::to_string(total) + " done: " + c.id);
      });
  for (const auto& r : battery.records)
    if (!r.outcome.passed) say("case FAILED: " + r.c->id + ": " + r.outcome.detail);
  return render(battery, opt);
}

ReportSummary render(const verification::BatteryResult& battery, const ReportOptions& opt) {
  const auto start = Clock::now();
  check_out_dir(opt.out_dir);
  const auto& records = battery.records;
  const std::size_t failed = battery.failed;

  SectionOptions so;
  so.quick = opt.quick;
  so.threads = opt.threads;
  so.progress = opt.progress;
  std::vector<std::pair<std::string, double>> stages;
  stages.emplace_back("cases", battery.seconds);

  so.say("provenance");
  const Provenance prov = collect_provenance(opt.command_line);

  FigureBook book;
  std::vector<std::string> section_errors;
  auto section = [&](const std::string& name, auto&& body) {
    const auto t = Clock::now();
    SectionResult r = guarded(name, so, [&] { return body(so, book); });
    stages.emplace_back(name, seconds_since(t));
    if (r.error) section_errors.push_back(name + ": " + *r.error);
    return r.html;
  };
  const std::string paper = section("paper figures", paper_html);
  const std::string restitution = section("restitution trends", restitution_html);
  const std::string examples = section("contact-law worked examples", examples_html);
  const std::string cases = cases_html(records, book);
  const std::string speed = section("speed against error", speed_html);
  const std::string structure = section("damping from the structure", structure_html);
  const std::string dem = section("DEM benchmark", [&](const SectionOptions&, FigureBook&) {
    return dem_benchmark_html(records);
  });
  const std::string validation = section("validation against measurements", validation_html);

  const auto t0 = Clock::now();
  book.render(opt.threads, so);
  stages.emplace_back("plots", seconds_since(t0));

  // The order a reader needs: the verdict, what is verified and where the model stops
  // applying; the results; the worked examples and the numerics; every case last (collapsed).
  // The sections were computed above in a fixed order, which fixes the plots' ids.
  const std::vector<PageSection> page_sections = {
      {"summary", "Summary: what is verified, where the model stops applying",
       summary_html(records, prov, opt, section_errors, stages)},
      {"paper", "The paper reproduced", paper},
      {"restitution", "Restitution trends", restitution},
      {"structure", "Damping from the structure", structure},
      {"validation", "Validation against measurements (synthetic example)", validation},
      {"examples", "Contact-law worked examples", examples},
      {"speed", "Speed against error", speed},
      {"dem", "DEM benchmark: Chung &amp; Ooi (2011)", dem},
      {"cases", "Every verification case", cases},
      {"companions", "Machine-readable companions", companions_html()},
  };
  const std::string body = report_body(prov, page_sections);
  const std::string html = page("ivv verification report", book.resolve(body));

  write_files(opt.out_dir, records, book, html, so);

  ReportSummary summary;
  summary.cases = records.size();
  summary.failed = failed;
  summary.passed = records.size() - failed;
  summary.plots = book.size();
  summary.plot_errors = book.errors();
  summary.section_errors = section_errors.size();
  summary.seconds = battery.seconds + seconds_since(start);
  summary.index_html = opt.out_dir / "index.html";
  so.say("report written: " + summary.index_html.string() + " (" + number(summary.seconds, 3) +
         " s)");
  return summary;
}

}  // namespace ivv::reports
