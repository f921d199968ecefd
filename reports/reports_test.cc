// Unit tests of the report's parts: HTML helpers, gnuplot SVG rendering and its check, the
// machine-readable companions, write_report's input errors, and
// that every figure and table of a rendered report names its cases or is labelled.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "reports/companions.h"
#include "reports/dem_benchmark.h"
#include "reports/gnuplot_svg.h"
#include "reports/html.h"
#include "reports/paper_figures.h"
#include "reports/report.h"
#include "scene/input_error.h"
#include "scene/scene.h"
#include "verification/cases.h"

namespace ivv::reports {
namespace {

namespace fs = std::filesystem;
using verification::CaseRecord;
using verification::Plot;
using verification::Series;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

Plot two_curves() {
  Plot p;
  p.id = "unit";
  p.title = "two curves";
  p.x_label = "x [m]";
  p.y_label = "y [N]";
  Series a{"a's curve", {0, 1, 2, 3}, {0, 1, 4, 9}, Series::Style::lines};
  Series b{"b", {0, 1, 2, 3}, {1, 2, 3, 4}, Series::Style::points};
  p.series = {a, b};
  return p;
}

TEST(Html, EscapesMarkupAndQuotes) {
  EXPECT_EQ(escape("<a href=\"x\">Tom & Jerry's</a>"),
            "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
}

TEST(Html, NumbersSpellOutNonFinite) {
  EXPECT_EQ(number(kNaN), "NaN");
  EXPECT_EQ(number(std::numeric_limits<double>::infinity()), "inf");
  EXPECT_EQ(number(0.125, 3), "0.125");
  EXPECT_EQ(number_html(1.115e9, 4), "1.115×10<sup>9</sup>");
  EXPECT_EQ(number_html(9.99996e8, 4), "1×10<sup>9</sup>");  // rounding carries the exponent
  EXPECT_EQ(number_html(39.16, 4), "39.16");
  EXPECT_EQ(slug("analytic.hertz undamped/x"), "analytic-hertz-undamped-x");
}

TEST(Html, PageIsSelfContained) {
  const std::string html = page("t", "<p>body</p>");
  EXPECT_NE(html.find("<!DOCTYPE html>"), std::string::npos);
  EXPECT_NE(html.find("@media print"), std::string::npos);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("http"), std::string::npos);
}

TEST(Html, SourcesAreAttributesAndVisibleLabels) {
  EXPECT_EQ(source_attribute(Source::from_cases({"trend.a", "trend.b.*"})),
            " data-source=\"cases:trend.a trend.b.*\"");
  EXPECT_EQ(source_attribute(Source{}), " data-source=\"unstated\"");
  EXPECT_EQ(source_attribute(Source::rows_are_cases()), " data-source=\"case-rows\"");
  const std::string from = source_label(Source::from_cases({"trend.a", "trend.b.*"}));
  EXPECT_NE(from.find("From cases"), std::string::npos);
  EXPECT_NE(from.find("href=\"#case-trend-a\""), std::string::npos) << "an id links to its case";
  EXPECT_EQ(from.find("href=\"#case-trend-b"), std::string::npos) << "a glob is not a link";
  EXPECT_NE(source_label(Source::illustration({"trend.a"})).find(">Illustration<"),
            std::string::npos);
  EXPECT_NE(source_label(Source::timing()).find("Timing, information only"), std::string::npos);
  const std::string t = table({"h"}, {{"1"}}, Source::timing());
  EXPECT_LT(t.find("Timing, information only"), t.find("<table")) << "label before the table";
  EXPECT_NE(t.find("<table class=\"data\" data-source=\"timing\">"), std::string::npos);
}

TEST(GnuplotScript, SkipsNonFiniteAndNonPositiveOnLogAxes) {
  Plot p = two_curves();
  p.log_y = true;
  p.series[0].y = {0, 1, kNaN, 9};  // 0 is not drawable on a log axis, NaN nowhere
  const std::string gp = gnuplot_script(p);
  EXPECT_EQ(gp.find("nan"), std::string::npos);
  EXPECT_NE(gp.find("set logscale y"), std::string::npos);
  EXPECT_NE(gp.find("'a''s curve'"), std::string::npos);  // gnuplot quoting of '
  // the surviving points of series 0: (1, 1) and, after a gap, (3, 9)
  EXPECT_NE(gp.find("$d0 << EOD\n1 1\n\n3 9\nEOD"), std::string::npos);
}

TEST(EnhancedText, TypesetsTheLabelsOfTheCases) {
  EXPECT_EQ(enhanced_text("lambda = m^{3/5} K_h^{2/5} v_0^{1/5} / c [-]"),
            "λ = m^{3/5} K_{h}^{2/5} v_{0}^{1/5} / c [-]");
  EXPECT_EQ(enhanced_text("asymptote (15/8)^(1/8) (v0/v_y)^(-1/4)"),
            "asymptote (15/8)^{1/8} (v_{0}/v_{y})^{-1/4}");
  EXPECT_EQ(enhanced_text("e^2 / gamma^2(eq. 21) - 1"), "e^{2} / γ^{2}(eq. 21) - 1");
  EXPECT_EQ(enhanced_text("normalised time τ = ω0 t [-]"), "normalised time τ = ω_{0} t [-]");
  EXPECT_EQ(enhanced_text("normalised step h = omega0 dt"), "normalised step h = ω_{0} dt");
  EXPECT_EQ(enhanced_text("data (+-1 u)"), "data (±1 u)");
  EXPECT_EQ(enhanced_text("relative error of F_max [-]"), "relative error of F_{max} [-]");
}

TEST(EnhancedText, LeavesNamesAndNumbersAlone) {
  // integrator names, exponents, decimals: no letter+0 word, no Greek name
  EXPECT_EQ(enhanced_text("odeint-dopri5, rtol 1e-12, dp45, rk4"),
            "odeint-dopri5, rtol 1e-12, dp45, rk4");
  EXPECT_EQ(enhanced_text("zeta = 0.10, v0 = 10 m/s"), "ζ = 0.10, v_{0} = 10 m/s");
  EXPECT_EQ(enhanced_text("mumble alphabet"), "mumble alphabet");
}

TEST(EnhancedText, EscapesControlCharactersThatAreNotMarkup) {
  EXPECT_EQ(enhanced_text("a@b & c~d {e} \\"), "a\\@b \\& c\\~d \\{e\\} \\\\");
  EXPECT_EQ(enhanced_text("x_ and y^"), "x\\_ and y\\^");  // nothing to lower or raise
}

TEST(GnuplotScript, FifteenSeriesDifferInColourLineOrMarker) {
  for (const auto style : {Series::Style::lines, Series::Style::linespoints, Series::Style::points,
                           Series::Style::dashed}) {
    Plot p;
    p.id = "many";
    for (int i = 0; i < 15; ++i)
      p.series.push_back({std::string(1, static_cast<char>('a' + i)), {0, 1}, {0, 1}, style});
    const std::string gp = gnuplot_script(p);
    std::set<std::string> looks;
    for (int i = 0; i < 15; ++i) {
      std::string clause = "$d";  // (built in steps: GCC 12 -Wrestrict misfires on "x" + string)
      clause += std::to_string(i);
      clause += " using 1:2 ";
      const auto at = gp.find(clause);
      ASSERT_NE(at, std::string::npos) << clause;
      const auto begin = at + clause.size();
      looks.insert(gp.substr(begin, gp.find(" title ", begin) - begin));
    }
    EXPECT_EQ(looks.size(), 15u) << gp;
  }
}

TEST(GnuplotScript, EmptyPlotIsAnError) {
  Plot p = two_curves();
  for (auto& s : p.series) s.y.assign(s.x.size(), kNaN);
  EXPECT_THROW(gnuplot_script(p), EmptyPlot);
  p.series.clear();
  EXPECT_THROW(gnuplot_script(p), EmptyPlot);
}

TEST(RenderSvg, DrawsEverySeriesWithPrefixedIds) {
  const std::string svg = render_svg(two_curves(), "fig 1");
  EXPECT_EQ(svg.rfind("<svg", 0), 0u) << "the XML prologue must be dropped for inlining";
  EXPECT_EQ(svg.find("<?xml"), std::string::npos);
  EXPECT_NE(svg.find("data-plot-id=\"unit\""), std::string::npos);
  EXPECT_NE(svg.find("id='fig-1-gpPt0'"), std::string::npos);
  EXPECT_EQ(svg.find("'#gpPt"), std::string::npos) << "unprefixed reference left";
  EXPECT_NE(svg.find("<title>a&#39;s curve</title>"), std::string::npos);
  const SvgCheck check = check_svg(svg);
  EXPECT_TRUE(check.ok());
  EXPECT_EQ(check.series, 2);
  EXPECT_EQ(check.drawn_series, 2);
}

TEST(RenderSvg, CheckSeesASeriesThatDrawsOnlyItsKey) {
  Plot p = two_curves();
  p.series[0].x = {1};  // one point drawn with lines: nothing but the key sample
  p.series[0].y = {1};
  const SvgCheck check = check_svg(render_svg(p, "k"));
  EXPECT_EQ(check.series, 2);
  EXPECT_EQ(check.drawn_series, 1);
  EXPECT_FALSE(check.ok());
  EXPECT_FALSE(check_svg("<svg></svg>").ok());
}

CaseRecord record(const verification::Case& c, verification::Outcome o, double seconds) {
  CaseRecord r;
  r.c = &c;
  r.outcome = std::move(o);
  r.seconds = seconds;
  return r;
}

TEST(Companions, ResultsJsonHasTheVerifyShape) {
  verification::Case a{
      "analytic.a", "A", verification::Tier::analytic, "because", verification::Cost::quick, {}};
  verification::Case b{
      "stability.b", "B", verification::Tier::stability, "why", verification::Cost::quick, {}};
  const std::vector<CaseRecord> records = {
      record(a, verification::relative(1.0, 1.0 + 1e-9, 1e-6, "close"), 0.5),
      record(b, verification::at_most(kNaN, 1e-3, "no measurement"), 0.25)};
  const auto json = nlohmann::json::parse(results_json(records));
  ASSERT_EQ(json.at("cases").size(), 2u);
  const auto& first = json["cases"][0];
  for (const char* key :
       {"id", "title", "tier", "passed", "measured", "reference", "tolerance", "reason"})
    EXPECT_TRUE(first.contains(key)) << key;
  EXPECT_EQ(first["id"], "analytic.a");
  EXPECT_EQ(first["tier"], "analytic");
  EXPECT_EQ(first["passed"], true);
  EXPECT_TRUE(json["cases"][1]["measured"].is_null());
  EXPECT_TRUE(json["cases"][1]["reference"].is_null());
  EXPECT_EQ(json["cases"][1]["passed"], false);
}

TEST(Companions, JunitGroupsByTierAndDetailsFailures) {
  verification::Case a{
      "analytic.a", "A", verification::Tier::analytic, "because", verification::Cost::quick, {}};
  verification::Case b{"stability.<b>",           "B", verification::Tier::stability, "why",
                       verification::Cost::quick, {}};
  const std::vector<CaseRecord> records = {
      record(a, verification::relative(1.0, 1.0, 1e-6, "exact"), 0.5),
      record(b, verification::at_most(2e-3, 1e-3, "error too large"), 0.25)};
  const std::string xml = junit_xml(records);
  EXPECT_NE(xml.find("<testsuites name=\"ivv verification\" tests=\"2\" failures=\"1\""),
            std::string::npos);
  EXPECT_NE(xml.find("<testsuite name=\"analytic\" tests=\"1\" failures=\"0\""), std::string::npos);
  EXPECT_NE(xml.find("<testsuite name=\"stability\" tests=\"1\" failures=\"1\""),
            std::string::npos);
  EXPECT_NE(xml.find("name=\"stability.&lt;b&gt;\""), std::string::npos);
  EXPECT_NE(xml.find("<failure message="), std::string::npos);
  EXPECT_NE(xml.find("error too large"), std::string::npos);
  EXPECT_EQ(xml.find("<failure", xml.find("analytic.a")), xml.find("<failure"))
      << "only the failing case has a <failure>";
}

TEST(Companions, SeriesCsvIsLongFormatWithQuoting) {
  Plot p = two_curves();
  p.series[1].label = "b, \"quoted\"";
  const std::string csv = series_csv({&p});
  EXPECT_EQ(csv.rfind("plot_id,series,x,y\n", 0), 0u);
  EXPECT_NE(csv.find("unit,a's curve,2,4\n"), std::string::npos);
  EXPECT_NE(csv.find("unit,\"b, \"\"quoted\"\"\",3,4\n"), std::string::npos);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 8);
}

TEST(PaperFigures, ParametersNameTheDashpotAndDamping) {
  const std::string html = paper_parameters_html();
  EXPECT_NE(html.find("c = 11440 N s/m"), std::string::npos);
  EXPECT_NE(html.find("ζ = 0.09998"), std::string::npos);  // sqrt(m K_y)/(2c), 4 digits
}

TEST(WriteReport, RejectsAnOutputPathThatIsAFile) {
  const fs::path file = fs::temp_directory_path() / "ivv-report-not-a-dir";
  std::ofstream(file) << "x";
  ReportOptions o;
  o.out_dir = file;
  EXPECT_THROW(write_report(o), InputError);
  o.out_dir.clear();
  EXPECT_THROW(write_report(o), InputError);
  fs::remove(file);
}

// The DEM section lists every Chung & Ooi scene with its closed form, and the verdict of the
// dem.* cases that were run (here one), with "—" for those that were not.
TEST(DemBenchmark, ShowsScenesClosedFormAndCaseVerdicts) {
  const auto cases = verification::all_cases().matching("dem.chung-ooi-2-aluminium.odeint-dopri5");
  ASSERT_EQ(cases.size(), 1u);
  const auto records = verification::run_cases(cases, 1);
  const std::string html = dem_benchmark_html(records);
  for (const auto& t : verification::chung_ooi_scenes())
    EXPECT_NE(html.find(std::string(t.scene)), std::string::npos) << t.scene;
  EXPECT_NE(html.find("0.0493088"), std::string::npos);  // z_m [mm], Al alloy on a rigid plane
  EXPECT_NE(html.find("case-dem-chung-ooi-2-aluminium-odeint-dopri5"), std::string::npos);
  EXPECT_NE(html.find("<span class=\"pass\">pass</span>"), std::string::npos);
  EXPECT_NE(html.find("—"), std::string::npos);
  EXPECT_NE(dem_benchmark_html({}).find("No <code>dem.chung-ooi-*</code> case was run"),
            std::string::npos);
}

TEST(WriteReport, RejectsAFilterMatchingNoCase) {
  ReportOptions o;
  o.out_dir = fs::temp_directory_path() / "ivv-report-empty-filter";
  o.filter = "no.such.case.*";
  try {
    write_report(o);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "--filter");
  }
  EXPECT_FALSE(fs::exists(o.out_dir / "index.html"));
  fs::remove_all(o.out_dir);
}

// Every figure and table of the rendered report either names the verification
// case(s) whose measurements it shows (ids that exist, or globs that match some) or carries a
// visible "Illustration" / "Timing, information only" label. A figure or table added without a
// Source renders data-source="unstated" and fails here.
struct Element {
  std::string tag, kind, cases, html;  // html: the element (figure) or its label and tag (table)
};

std::string attribute(const std::string& tag_text, const std::string& name) {
  const std::string key = " " + name + "=\"";
  const auto at = tag_text.find(key);
  if (at == std::string::npos) return "";
  const auto start = at + key.size();
  return tag_text.substr(start, tag_text.find('"', start) - start);
}

std::vector<Element> sourced_elements(const std::string& html) {
  std::vector<Element> out;
  for (const std::string tag : {"figure", "table"}) {
    for (auto pos = html.find("<" + tag); pos != std::string::npos;
         pos = html.find("<" + tag, pos + 1)) {
      const char next = html[pos + 1 + tag.size()];
      if (next != ' ' && next != '>') continue;  // <tablex>, <figcaption>
      const std::string open = html.substr(pos, html.find('>', pos) - pos + 1);
      const std::string source = attribute(open, "data-source");
      Element e;
      e.tag = tag;
      e.kind = source.substr(0, source.find(':'));
      e.cases = source.find(':') == std::string::npos ? "" : source.substr(source.find(':') + 1);
      if (tag == "figure") {
        e.html = html.substr(pos, html.find("</figure>", pos) - pos);
      } else {  // the label paragraph right before the table, and the tag
        const auto label = html.rfind("<p class=\"source\">", pos);
        const bool adjacent = label != std::string::npos && html.find("</p>", label) < pos &&
                              pos - html.find("</p>", label) <= 5;
        e.html = (adjacent ? html.substr(label, pos - label) : std::string()) + open;
      }
      out.push_back(e);
    }
  }
  return out;
}

TEST(WriteReport, EveryFigureAndTableNamesItsCasesOrIsLabelled) {
  ReportOptions o;
  // one directory per process: ctest runs of other build trees on this machine write the same
  // report at the same time, and a shared directory once mixed their pages
  o.out_dir = fs::temp_directory_path() / ("ivv-report-sources-" + std::to_string(getpid()));
  o.filter = "trend.paper.*";
  o.quick = true;
  o.threads = 2;
  const ReportSummary summary = write_report(o);
  std::ifstream in(summary.index_html);
  const std::string html{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const auto elements = sourced_elements(html);
  std::map<std::string, int> kinds;
  int figures = 0;
  for (const Element& e : elements) {
    figures += e.tag == "figure";
    ++kinds[e.kind];
    const std::string what = e.tag + " " + e.html.substr(0, 160);
    ASSERT_TRUE(e.kind == "cases" || e.kind == "case-rows" || e.kind == "illustration" ||
                e.kind == "timing")
        << "no source stated: " << what;
    std::istringstream ids(e.cases);
    int n = 0;
    for (std::string id; ids >> id; ++n)
      EXPECT_FALSE(verification::all_cases().matching(id).empty())
          << "names a case that does not exist: " << id << " in " << what;
    if (e.kind == "cases") {
      EXPECT_GT(n, 0) << what;
      EXPECT_NE(e.html.find("From case"), std::string::npos) << "no visible label: " << what;
    }
    if (e.kind == "illustration") {
      EXPECT_NE(e.html.find(">Illustration<"), std::string::npos) << "no visible label: " << what;
    }
    if (e.kind == "timing") {
      EXPECT_NE(e.html.find("Timing, information only"), std::string::npos)
          << "no visible label: " << what;
    }
  }
  EXPECT_EQ(static_cast<std::size_t>(figures), summary.plots) << "every plot is in a <figure>";
  EXPECT_GT(kinds["cases"], 0);
  EXPECT_GT(kinds["illustration"], 0);
  EXPECT_GT(kinds["timing"], 0);
  for (const auto& [kind, n] : kinds) std::cout << "  " << kind << ": " << n << "\n";
  fs::remove_all(o.out_dir);
}

}  // namespace
}  // namespace ivv::reports
