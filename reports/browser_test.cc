// The report as a user sees it: a quick report (a small case filter) is generated into a
// temporary directory once per test program and rendered in headless Chromium.
//
// RendersEveryPlotWithoutErrors fails when a plot is missing or empty (in the HTML, checked in
// C++, and as rendered), when the page has a script or resource error, a layout overflow
// (content wider than the page or than its box), an error marker (.plot-error), or when the
// companions disagree with the page. The rendering check injects a small script into a copy of
// the page (the report itself has none) that opens every <details>, measures every plot and
// reports in a <pre> element read back from --dump-dom. A full-page screenshot is taken of the
// report itself.
//
// EverySectionRendersAtItsAnchor opens the report at each section's anchor (#structure, ...),
// as a link or a bookmark does, and at a case's row in its collapsed tier (where the links
// under the figures lead), screenshots the window and fails on a blank image.
//
// PlotTextIsLegibleAtThePageWidth measures the displayed size of every plot's text (the SVG
// font size times the scale from the viewBox to the screen) at two window widths.
//
// Without Chromium (scripts/install-deps.sh installs it) the tests are skipped with that
// reason, which ctest shows as "Skipped".
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <zlib.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "reports/gnuplot_svg.h"
#include "reports/report.h"

namespace ivv::reports {
namespace {

namespace fs = std::filesystem;

// Trend cases: they carry plots, and run in about a second.
constexpr const char* kFilter = "trend.*";
constexpr int kChromiumTimeoutSeconds = 180;

// The windows the report is looked at in [CSS px]: a common desktop width, and the narrowest
// that still puts two plots side by side (.grid2: two columns of at least 480 px plus the
// 1 rem gap, inside 2 x 2 rem of page padding and a 15 px scrollbar: 1055 px).
constexpr int kDesktopWidth = 1280;
constexpr int kNarrowestTwoColumnWidth = 1060;
constexpr int kWindowHeight = 900;

// The smallest plot text a reader takes in without effort at arm's length, in CSS px: the
// floor the report promises for axis, tick and key text (gnuplot_svg.h, SvgSize).
constexpr double kMinDisplayedFontPx = 11.0;

// A screenshot of a section opened at its anchor is blank when fewer than this share of its
// pixels differ from white. The smallest section seen (the companions: a heading and three
// lines) covers about 5 % of a 1280 x 900 window; a blank capture covers 0.
constexpr double kMinInkShare = 0.01;

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

// The Chromium found at configure time, or empty when there is none.
std::string chromium_path() {
  const std::string path = IVV_CHROMIUM;
  return !path.empty() && fs::exists(path) ? path : std::string();
}

// Runs headless Chromium on `url` with `mode` (--dump-dom or --screenshot=...) in a window
// `width` x `height`; stdout to `out`. Returns the exit status.
int chromium(const std::string& mode, const std::string& url, const fs::path& profile,
             const fs::path& out, const fs::path& err, int width = kDesktopWidth,
             int height = 4000) {
  const std::string cmd =
      "timeout " + std::to_string(kChromiumTimeoutSeconds) + " " + shell_quoted(chromium_path()) +
      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --virtual-time-budget=10000 --user-data-dir=" +
      shell_quoted(profile.string()) + " --window-size=" + std::to_string(width) + "," +
      std::to_string(height) + " " + mode + " " + shell_quoted(url) + " >" +
      shell_quoted(out.string()) + " 2>" + shell_quoted(err.string());
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// An 8-bit RGB or RGBA PNG (what Chromium writes), decoded: the share of pixels that are not
// white (any colour channel below 240, alpha not zero). Throws on anything else.
double ink_share(const std::string& png) {
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned>(static_cast<unsigned char>(png.at(at))) << 24) |
           (static_cast<unsigned>(static_cast<unsigned char>(png.at(at + 1))) << 16) |
           (static_cast<unsigned>(static_cast<unsigned char>(png.at(at + 2))) << 8) |
           static_cast<unsigned>(static_cast<unsigned char>(png.at(at + 3)));
  };
  if (png.size() < 33 || png.compare(1, 3, "PNG") != 0) throw std::runtime_error("not a PNG");
  const unsigned width = be32(16), height = be32(20);
  const int depth = png[24], colour = png[25];
  if (depth != 8 || (colour != 2 && colour != 6) || png[28] != 0)
    throw std::runtime_error("not an 8-bit, non-interlaced RGB(A) PNG");
  const std::size_t channels = colour == 6 ? 4 : 3;
  std::string compressed;
  for (std::size_t at = 8; at + 8 <= png.size();) {
    const std::size_t length = be32(at);
    if (png.compare(at + 4, 4, "IDAT") == 0) compressed += png.substr(at + 8, length);
    at += 12 + length;
  }
  const std::size_t stride = width * channels;
  std::vector<unsigned char> raw(height * (stride + 1));
  uLongf raw_size = raw.size();
  if (uncompress(raw.data(), &raw_size, reinterpret_cast<const Bytef*>(compressed.data()),
                 compressed.size()) != Z_OK ||
      raw_size != raw.size())
    throw std::runtime_error("corrupt PNG image data");
  // undo the per-row filters (PNG spec §9) in place, then count
  std::vector<unsigned char> previous(stride, 0);
  std::size_t ink = 0;
  for (unsigned y = 0; y < height; ++y) {
    unsigned char* row = raw.data() + y * (stride + 1);
    const int filter = row[0];
    unsigned char* px = row + 1;
    for (std::size_t x = 0; x < stride; ++x) {
      const int a = x >= channels ? px[x - channels] : 0, b = previous[x],
                c = x >= channels ? previous[x - channels] : 0;
      int add = 0;
      if (filter == 1) add = a;
      if (filter == 2) add = b;
      if (filter == 3) add = (a + b) / 2;
      if (filter == 4) {
        const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
        add = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      px[x] = static_cast<unsigned char>(px[x] + add);
    }
    std::copy(px, px + stride, previous.begin());
    for (std::size_t x = 0; x < stride; x += channels) {
      const bool visible = channels == 3 || px[x + 3] > 0;
      if (visible && std::min({px[x], px[x + 1], px[x + 2]}) < 240) ++ink;
    }
  }
  return static_cast<double>(ink) / (static_cast<double>(width) * height);
}

// The self-check injected at the top of <head> of a copy of the page.
constexpr const char* kSelfCheck = R"js(<script>
(function () {
  var problems = [];
  window.addEventListener('error', function (e) {
    var where = e.filename || (e.target && (e.target.src || e.target.href)) || '';
    problems.push('error event: ' + (e.message || 'resource failed to load') + ' ' + where);
  }, true);
  window.addEventListener('load', function () {
    document.querySelectorAll('details').forEach(function (d) { d.open = true; });
    var pageWidth = document.documentElement.clientWidth;
    var report = { problems: problems, svgs: 0, plots: [] };
    // the body is the page's scroll container (html.cc): it overflows, not the document
    var body = document.body;
    if (document.documentElement.scrollWidth > pageWidth + 1 ||
        body.scrollWidth > body.clientWidth + 1)
      problems.push('page wider than the window: ' +
                    Math.max(document.documentElement.scrollWidth, body.scrollWidth) +
                    ' > ' + Math.min(pageWidth, body.clientWidth));
    document.querySelectorAll('.plot-error').forEach(function (e) {
      problems.push('error marker: ' + e.textContent.slice(0, 200));
    });
    document.querySelectorAll('table').forEach(function (t) {
      var box = t.parentElement.getBoundingClientRect();
      var r = t.getBoundingClientRect();
      if (r.right > box.right + 1 && r.right > pageWidth)
        problems.push('table overflows its box: ' + (t.className || '(table)'));
    });
    var svgs = document.querySelectorAll('svg');
    report.svgs = svgs.length;
    svgs.forEach(function (svg) {
      var id = svg.getAttribute('data-plot-id') || '(no id)';
      var r = svg.getBoundingClientRect();
      var fig = svg.closest('figure');
      var groups = svg.querySelectorAll('g[id*="gnuplot_plot_"]');
      var drawn = 0;
      groups.forEach(function (g) {
        var length = 0;
        g.querySelectorAll('path').forEach(function (p) { length += p.getTotalLength(); });
        var markers = g.querySelectorAll('use').length;
        var b = g.getBBox();
        if ((length > 0 || markers > 0) && b.width * b.height > 0) drawn++;
      });
      report.plots.push({ id: id, width: r.width, height: r.height, series: groups.length,
                          drawn: drawn });
      if (!fig) problems.push('plot outside a figure: ' + id);
      if (r.width < 250 || r.height < 150)
        problems.push('plot too small: ' + id + ' ' + r.width + 'x' + r.height);
      if (groups.length === 0 || drawn !== groups.length)
        problems.push('plot with undrawn series: ' + id + ' ' + drawn + '/' + groups.length);
      if (fig) {
        var f = fig.getBoundingClientRect();
        if (r.right > f.right + 1 || r.left < f.left - 1)
          problems.push('plot wider than its figure: ' + id);
      }
    });
    var pre = document.createElement('pre');
    pre.id = 'ivv-selfcheck';
    pre.textContent = JSON.stringify(report);
    document.body.appendChild(pre);
  });
})();
</script>)js";

// Injected like the self-check: opens every <details> and reports, per plot, its displayed
// width and the smallest displayed size of its text (the <text> element's font size times the
// scale of its screen transform, which includes the viewBox's).
constexpr const char* kFontCheck = R"js(<script>
window.addEventListener('load', function () {
  document.querySelectorAll('details').forEach(function (d) { d.open = true; });
  var plots = [];
  document.querySelectorAll('svg.plot').forEach(function (svg) {
    var smallest = Infinity, texts = 0;
    svg.querySelectorAll('text').forEach(function (t) {
      if (!t.textContent.trim()) return;
      var m = t.getScreenCTM();
      if (!m) return;
      var px = parseFloat(getComputedStyle(t).fontSize) * Math.sqrt(m.a * m.a + m.b * m.b);
      smallest = Math.min(smallest, px);
      texts++;
    });
    plots.push({ id: svg.getAttribute('data-plot-id') || '(no id)',
                 width: svg.getBoundingClientRect().width,
                 viewbox: svg.viewBox.baseVal.width, texts: texts,
                 smallest: texts ? smallest : 0 });
  });
  var pre = document.createElement('pre');
  pre.id = 'ivv-fontcheck';
  pre.textContent = JSON.stringify(plots);
  document.body.appendChild(pre);
});
</script>)js";

std::string unescape_text(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (auto pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + 1))
      s.replace(pos, std::string(from).size(), to);
  return s;
}

// The data-plot-id of every <svg> of the page (counted in `svgs`); each one's series must be
// drawn.
std::set<std::string> checked_plot_ids(const std::string& html, std::size_t& svgs) {
  std::set<std::string> page_ids;
  svgs = 0;
  for (auto pos = html.find("<svg"); pos != std::string::npos; pos = html.find("<svg", pos + 1)) {
    const auto end = html.find("</svg>", pos);
    if (end == std::string::npos) {
      ADD_FAILURE() << "an <svg> without its </svg>";
      break;
    }
    const std::string svg = html.substr(pos, end + 6 - pos);
    const SvgCheck check = check_svg(svg);
    // the plot id is an attribute of the <svg> element itself, in its first few hundred bytes
    std::string plot_id = "(none)";
    const std::string key = "data-plot-id=\"";
    const std::string head = svg.substr(0, 600);
    if (const auto k = head.find(key); k != std::string::npos) {
      const auto e = head.find('"', k + key.size());
      if (e != std::string::npos) plot_id = head.substr(k + key.size(), e - k - key.size());
    }
    page_ids.insert(plot_id);
    EXPECT_TRUE(check.ok()) << plot_id << ": " << check.drawn_series << "/" << check.series;
    ++svgs;
  }
  return page_ids;
}

// The report every test of this program looks at, written once.
class ReportInBrowser : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (chromium_path().empty()) return;
    dir_ = fs::temp_directory_path() / ("ivv-browser-test-" + std::to_string(getpid()));
    fs::remove_all(dir_);
    ReportOptions options;
    options.out_dir = dir_ / "report";
    options.filter = kFilter;
    options.quick = true;
    options.threads = 2;
    options.allow_failures = true;  // the verdict is verification's business, not this test's
    options.command_line = "report_browser_test";
    summary_ = write_report(options);
    html_ = read_file(summary_.index_html);
    fs::create_directories(dir_ / "profile");
  }
  static void TearDownTestSuite() {
    if (dir_.empty()) return;
    if (kept_)
      std::cerr << "report, DOM and screenshots kept in " << dir_ << "\n";
    else
      fs::remove_all(dir_);
  }
  void SetUp() override {
    if (chromium_path().empty())
      GTEST_FAIL() << "no Chromium found at configure time (IVV_CHROMIUM=\"" << IVV_CHROMIUM
                   << "\"): scripts/install-deps.sh installs it (make deps), and without it the "
                      "report's rendering would go unchecked";
  }
  void TearDown() override { kept_ = kept_ || HasFailure(); }

  // `html` with `script` injected at the top of <head>, rendered; the JSON the script left in
  // <pre id="pre_id">.
  static nlohmann::json run_script(const std::string& html, const std::string& script,
                                   const std::string& pre_id, const std::string& name, int width) {
    std::string checked = html;
    checked.insert(checked.find("<head>") + 6, script);
    const fs::path page = dir_ / (name + ".html");
    std::ofstream(page) << checked;
    const fs::path dom = dir_ / (name + ".dom"), err = dir_ / (name + ".err");
    const int rc = chromium("--dump-dom", "file://" + page.string(), dir_ / "profile", dom, err,
                            width, kWindowHeight);
    if (rc != 0)
      throw std::runtime_error("chromium exited with " + std::to_string(rc) + ": " +
                               read_file(err));
    const std::string text = read_file(dom);
    const std::string open = "<pre id=\"" + pre_id + "\">";
    const auto start = text.find(open);
    if (start == std::string::npos)
      throw std::runtime_error("the injected script did not run; chromium said:\n" +
                               read_file(err));
    const auto body = start + open.size();
    return nlohmann::json::parse(
        unescape_text(text.substr(body, text.find("</pre>", body) - body)));
  }

  static inline fs::path dir_;
  static inline ReportSummary summary_;
  static inline std::string html_;
  static inline bool kept_ = false;
};

TEST_F(ReportInBrowser, RendersEveryPlotWithoutErrors) {
  const ReportSummary& summary = summary_;
  const fs::path& dir = dir_;
  ASSERT_TRUE(fs::exists(summary.index_html));
  EXPECT_GT(summary.cases, 0u);
  EXPECT_EQ(summary.plot_errors, 0u);
  EXPECT_EQ(summary.section_errors, 0u);

  // The page as written: self-contained, every plot an SVG with drawn series.
  const std::string& html = html_;
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_EQ(html.find("class=\"plot-error\""), std::string::npos);
  std::size_t svgs = 0;
  const std::set<std::string> page_ids = checked_plot_ids(html, svgs);
  EXPECT_EQ(svgs, summary.plots);
  EXPECT_GE(svgs, 20u) << "the paper and the restitution sections alone draw more than 20 plots";

  // The companions agree with the page.
  const auto results = nlohmann::json::parse(read_file(dir / "report" / "results.json"));
  EXPECT_EQ(results.at("cases").size(), summary.cases);
  const std::string junit = read_file(dir / "report" / "junit.xml");
  std::size_t testcases = 0;
  for (auto p = junit.find("<testcase "); p != std::string::npos;
       p = junit.find("<testcase ", p + 1))
    ++testcases;
  EXPECT_EQ(testcases, summary.cases);
  std::set<std::string> csv_ids;
  {
    std::ifstream csv(dir / "report" / "series.csv");
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "plot_id,series,x,y");
    while (std::getline(csv, line)) csv_ids.insert(line.substr(0, line.find(',')));
  }
  EXPECT_EQ(csv_ids, page_ids) << "series.csv must hold the data of every plot in the page";

  // Rendered in Chromium with the self-check injected.
  const auto report = run_script(html, kSelfCheck, "ivv-selfcheck", "selfcheck", kDesktopWidth);
  EXPECT_EQ(report.at("svgs").get<std::size_t>(), summary.plots);
  for (const auto& problem : report.at("problems")) ADD_FAILURE() << problem.get<std::string>();

  // A screenshot of the report itself (kept on failure for a person to look at).
  const fs::path png = dir / "report.png";
  EXPECT_EQ(chromium("--screenshot=" + png.string(), "file://" + summary.index_html.string(),
                     dir / "profile", dir / "shot.out", dir / "shot.err"),
            0)
      << read_file(dir / "shot.err");
  ASSERT_TRUE(fs::exists(png));
  const std::string bytes = read_file(png);
  ASSERT_GT(bytes.size(), 24u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
  const auto be32 = [&](std::size_t at) {
    return (static_cast<unsigned>(static_cast<unsigned char>(bytes[at])) << 24) |
           (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 1])) << 16) |
           (static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 2])) << 8) |
           static_cast<unsigned>(static_cast<unsigned char>(bytes[at + 3]));
  };
  EXPECT_EQ(be32(16), 1280u);  // IHDR width
  EXPECT_GT(bytes.size(), 100'000u) << "a 1280x4000 screenshot of plots is not that small";
}

TEST_F(ReportInBrowser, EverySectionRendersAtItsAnchor) {
  std::vector<std::string> anchors;
  const std::string key = "<h2 id=\"";
  for (auto pos = html_.find(key); pos != std::string::npos; pos = html_.find(key, pos + 1)) {
    const auto begin = pos + key.size();
    anchors.push_back(html_.substr(begin, html_.find('"', begin) - begin));
  }
  ASSERT_GE(anchors.size(), 10u) << "the report has ten numbered sections";
  // and a case's row, inside its collapsed tier: where the links under the figures lead
  const std::string row = "<tr id=\"";
  const auto first_case = html_.find(row);
  ASSERT_NE(first_case, std::string::npos) << "no case row";
  const auto case_id = first_case + row.size();
  anchors.push_back(html_.substr(case_id, html_.find('"', case_id) - case_id));
  for (const auto& anchor : anchors) {
    const fs::path png = dir_ / ("section-" + anchor + ".png");
    const fs::path err = dir_ / ("section-" + anchor + ".err");
    ASSERT_EQ(chromium("--screenshot=" + png.string(),
                       "file://" + summary_.index_html.string() + "#" + anchor, dir_ / "profile",
                       dir_ / "section.out", err, kDesktopWidth, kWindowHeight),
              0)
        << anchor << ": " << read_file(err);
    const double ink = ink_share(read_file(png));
    EXPECT_GE(ink, kMinInkShare) << "#" << anchor << " screenshots blank (" << ink * 100
                                 << " % of the pixels not white): " << png;
  }
}

TEST_F(ReportInBrowser, PlotTextIsLegibleAtThePageWidth) {
  for (const int width : {kDesktopWidth, kNarrowestTwoColumnWidth}) {
    const auto plots =
        run_script(html_, kFontCheck, "ivv-fontcheck", "fontcheck-" + std::to_string(width), width);
    EXPECT_EQ(plots.size(), summary_.plots) << "window " << width << " px";
    double smallest = std::numeric_limits<double>::infinity();
    for (const auto& p : plots) {
      const double px = p.at("smallest").get<double>();
      smallest = std::min(smallest, px);
      EXPECT_GT(p.at("texts").get<int>(), 0) << p.at("id").get<std::string>() << ": no text";
      EXPECT_GE(px, kMinDisplayedFontPx)
          << p.at("id").get<std::string>() << " in a " << width << " px window: text shown at "
          << px << " px (plot " << p.at("width").get<double>() << " px wide for a viewBox of "
          << p.at("viewbox").get<double>() << ")";
    }
    std::cout << "smallest plot text in a " << width << " px window: " << smallest << " px\n";
  }
}

}  // namespace
}  // namespace ivv::reports
