// The report as a user sees it: a quick report (a small case filter) is generated into a
// temporary directory and rendered in headless Chromium.
//
// Fails when a plot is missing or empty (in the HTML, checked in C++, and as rendered), when
// the page has a script or resource error, a layout overflow (content wider than the page or
// than its box), an error marker (.plot-error), or when the companions disagree with the page.
// The rendering check injects a small script into a copy of the page (the report itself has
// none) that opens every <details>, measures every plot and reports in a <pre> element read
// back from --dump-dom. A full-page screenshot is taken of the report itself.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
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

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string shell_quoted(const std::string& s) {
  std::string out = "'";
  for (char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

// Runs headless Chromium on `url` with `mode` (--dump-dom or --screenshot=...); stdout to
// `out`. Returns the exit status.
int chromium(const std::string& mode, const std::string& url, const fs::path& profile,
             const fs::path& out, const fs::path& err) {
  const std::string cmd =
      "timeout " + std::to_string(kChromiumTimeoutSeconds) + " " + shell_quoted(IVV_CHROMIUM) +
      " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
      " --disable-background-networking --disable-component-update --disable-sync"
      " --virtual-time-budget=10000 --user-data-dir=" +
      shell_quoted(profile.string()) + " --window-size=1280,4000 " + mode + " " +
      shell_quoted(url) + " >" + shell_quoted(out.string()) + " 2>" + shell_quoted(err.string());
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
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
    if (document.documentElement.scrollWidth > pageWidth + 1)
      problems.push('page wider than the window: ' + document.documentElement.scrollWidth +
                    ' > ' + pageWidth);
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

std::string unescape_text(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (auto pos = s.find(from); pos != std::string::npos; pos = s.find(from, pos + 1))
      s.replace(pos, std::string(from).size(), to);
  return s;
}

TEST(ReportInBrowser, RendersEveryPlotWithoutErrors) {
  const fs::path dir = fs::temp_directory_path() / ("ivv-browser-test-" + std::to_string(getpid()));
  fs::remove_all(dir);
  ReportOptions options;
  options.out_dir = dir / "report";
  options.filter = kFilter;
  options.quick = true;
  options.threads = 2;
  options.allow_failures = true;  // the verdict is verification's business, not this test's
  options.command_line = "report_browser_test";
  const ReportSummary summary = write_report(options);
  ASSERT_TRUE(fs::exists(summary.index_html));
  EXPECT_GT(summary.cases, 0u);
  EXPECT_EQ(summary.plot_errors, 0u);
  EXPECT_EQ(summary.section_errors, 0u);

  // The page as written: self-contained, every plot an SVG with drawn series.
  const std::string html = read_file(summary.index_html);
  EXPECT_EQ(html.find("<script"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
  EXPECT_EQ(html.find("@import"), std::string::npos);
  EXPECT_EQ(html.find("href=\"http"), std::string::npos);
  EXPECT_EQ(html.find("class=\"plot-error\""), std::string::npos);
  std::set<std::string> page_ids;
  std::size_t svgs = 0;
  for (auto pos = html.find("<svg"); pos != std::string::npos; pos = html.find("<svg", pos + 1)) {
    const auto end = html.find("</svg>", pos);
    ASSERT_NE(end, std::string::npos);
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
  EXPECT_EQ(svgs, summary.plots);
  EXPECT_GE(svgs, 20u) << "sections 2, 3 and 5 alone draw more than 20 plots";

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
  std::string checked = html;
  checked.insert(checked.find("<head>") + 6, kSelfCheck);
  const fs::path check_page = dir / "selfcheck.html";
  std::ofstream(check_page) << checked;
  const fs::path profile = dir / "profile";
  fs::create_directories(profile);
  ASSERT_EQ(chromium("--dump-dom", "file://" + check_page.string(), profile, dir / "dom.html",
                     dir / "dom.err"),
            0)
      << read_file(dir / "dom.err");
  const std::string dom = read_file(dir / "dom.html");
  const auto start = dom.find("<pre id=\"ivv-selfcheck\">");
  ASSERT_NE(start, std::string::npos) << "the self-check did not run; chromium said:\n"
                                      << read_file(dir / "dom.err");
  const auto body_start = start + std::string("<pre id=\"ivv-selfcheck\">").size();
  const auto report = nlohmann::json::parse(
      unescape_text(dom.substr(body_start, dom.find("</pre>", body_start) - body_start)));
  EXPECT_EQ(report.at("svgs").get<std::size_t>(), summary.plots);
  for (const auto& problem : report.at("problems")) ADD_FAILURE() << problem.get<std::string>();

  // A screenshot of the report itself (kept on failure for a person to look at).
  const fs::path png = dir / "report.png";
  EXPECT_EQ(chromium("--screenshot=" + png.string(), "file://" + summary.index_html.string(),
                     profile, dir / "shot.out", dir / "shot.err"),
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

  if (!HasFailure())
    fs::remove_all(dir);
  else
    std::cerr << "report, DOM and screenshot kept in " << dir << "\n";
}

}  // namespace
}  // namespace ivv::reports
