#include "reports/law_report.h"

#include <algorithm>
#include <system_error>

#include "reports/gnuplot_svg.h"
#include "reports/html.h"
#include "scene/input_error.h"
#include "solver/atomic_file.h"

namespace ivv::reports {

namespace fs = std::filesystem;

std::string law_section_html(const conformance::Report& report, const std::string& anchor,
                             const std::string& intro_html, const PlacePlot& place,
                             const Source& table_source) {
  std::string html =
      "<section id=\"" + slug(anchor) + "\">\n<h3>" + escape(report.law) + " — " +
      (report.passed() ? "<span class=\"pass\">PASS</span>" : "<span class=\"fail\">FAIL</span>") +
      "</h3>\n<p>" + escape(report.description) + "</p>\n" + intro_html;
  std::vector<std::vector<std::string>> rows;
  for (const conformance::Check& c : report.checks) {
    rows.push_back(
        {escape(c.id),
         c.passed ? "<span class=\"pass\">pass</span>" : "<span class=\"fail\">FAIL</span>",
         escape(c.measured_text()), escape(c.reference_text()), escape(c.tolerance_text()),
         escape(c.detail) + "<br><small>why this tolerance: " + escape(c.why) + "</small>"});
  }
  html += table({"check", "verdict", "measured", "reference", "tolerance", "what was measured"},
                rows, table_source);
  if (!report.skipped.empty()) {
    html += "<p>Skipped (not applicable to this law, or not claimed):</p>\n<ul>\n";
    for (const auto& [id, why] : report.skipped)
      html += "<li><code>" + escape(id) + "</code>: " + escape(why) + "</li>\n";
    html += "</ul>\n";
  }
  if (!report.notes.empty()) {
    html +=
        "<p>Integrator accuracy, not the law's (a difference gone when the run was repeated "
        "tighter, a capture bound looser than the check's tolerance, or a run the integrator could "
        "not finish where the reference did):</p>\n<ul>\n";
    for (const conformance::IntegratorNote& n : report.notes)
      html += "<li>" + escape(n.line()) + "</li>\n";
    html += "</ul>\n";
  }
  for (verification::Plot plot : report.plots()) {
    plot.id = slug(anchor + "-" + plot.id);
    const bool loop = plot.id.find("conformance-loop-") != std::string::npos;
    const std::string caption =
        loop ? " Force against spring deformation in one impact per damping (dp45 at the "
               "default tolerances, the scene's v0): loading up, unloading down; the area "
               "between them is the work the spring dissipates, and a loop run anticlockwise "
               "(unloading above loading) creates energy."
             : " Coefficient of restitution of the reference runs (measured) over the velocity "
               "grid, with the line e = 1 (elastic)" +
                   std::string(report.cor.empty() || !report.cor.front().expected
                                   ? ""
                                   : " and the COR the law claims (dashed, drawn last)") +
                   ".";
    if (place) {
      html += place(plot, caption);
      continue;
    }
    try {
      html += "<figure>" + render_svg(plot, plot.id) + "<figcaption>" + caption +
              "</figcaption></figure>\n";
    } catch (const std::exception& e) {
      html += "<p class=\"fail\">plot " + escape(plot.id) +
              " could not be drawn: " + escape(e.what()) + "</p>\n";
    }
  }
  return html + "</section>\n";
}

void check_report_dir(const fs::path& dir) {
  check_output_directory(dir, "--report");
}

namespace {

// What the dynamic checks struck, and what the reloading checks ask of the law, in words.
std::string scope_html(const conformance::Report& report) {
  const bool plate = std::any_of(report.cor.begin(), report.cor.end(),
                                 [](const conformance::CorPoint& c) { return c.finite_plate; });
  std::string html =
      plate ? "<p>The dynamic checks struck the scene's <b>finite plate</b>, by its own driver "
              "(the impactor against the plate's modes, no dashpot): the energy ledger holds the "
              "plate's vibration energy, the impulse is m (v<sub>0</sub> &minus; "
              "v<sub>final</sub>), and the COR is the final one after every contact; a check "
              "that does not apply on a plate is skipped with its reason.</p>\n"
            : "";
  html +=
      "<p><b>Reloading</b> (static.reloading, static.reloading_beyond): loaded to z<sub>m</sub> "
      "and unloaded to z<sub>1</sub> &lt; z<sub>m</sub>, the law reloads on its unloading "
      "branch (as the drivers do when a plate's rebound compresses the spring again); over the "
      "cycle z<sub>m</sub> &rarr; z<sub>1</sub> &rarr; z<sub>m</sub> it must create no energy "
      "(the work put in on reloading at least the work returned on unloading), and at "
      "z<sub>m</sub> it must meet its loading curve and load on along it.</p>\n";
  return html;
}

}  // namespace

fs::path write_law_report(const conformance::Report& report, const fs::path& dir,
                          const std::string& command_line) {
  create_output_directory(dir, "--report");
  const std::string body = "<h1>Contact-law conformance: " + escape(report.law) + "</h1>\n<p>" +
                           escape(report.brief()) + "</p>\n<p><small>command: <code>" +
                           escape(command_line) + "</code></small></p>\n" + scope_html(report) +
                           law_section_html(report, "law") +
                           "<p>Machine-readable: <a href=\"results.json\">results.json</a>.</p>";
  const fs::path index = dir / "index.html";
  // both written first, then renamed into place: an error in either leaves neither
  StagedFile results(dir / "results.json", [&](std::ostream& out) {
    out << conformance::to_json(report).dump(2) << "\n";
  });
  StagedFile html(index,
                  [&](std::ostream& out) { out << page("ivv check-law: " + report.law, body); });
  results.commit();
  html.commit();
  return index;
}

}  // namespace ivv::reports
