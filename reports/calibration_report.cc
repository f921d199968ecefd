#include "reports/calibration_report.h"

#include <cmath>

#include "reports/gnuplot_svg.h"
#include "solver/atomic_file.h"
#include "validation/calibration_file.h"

namespace ivv::reports {
namespace {

namespace fs = std::filesystem;
using verification::Plot;
using verification::Series;

std::string cell(double v, int digits = 5) {
  return std::isfinite(v) ? number_html(v, digits) : std::string("—");
}

Plot fit_plot(const CalibrationView& v, const std::string& anchor) {
  Plot p{slug(anchor + "-fit"),
         "Measured e with the fitted model and its 95 % band",
         "impact velocity v0 [m/s]",
         "coefficient of restitution e [-]",
         true,
         false,
         {}};
  Series data{"data (+-1 u)", {}, {}, Series::Style::error_bars, {}};
  for (const auto& r : v.fit->residuals)
    if (r.quantity == validation::Quantity::e) {
      data.x.push_back(r.v0);
      data.y.push_back(r.measured);
      data.y_error.push_back(r.uncertainty);
    }
  p.series.push_back(data);
  if (v.band) {
    Series fit{"fit (" + v.fit->law + ")", {}, {}, Series::Style::lines, {}};
    Series lo{"95 % band", {}, {}, Series::Style::dashed, {}},
        hi{"", {}, {}, Series::Style::dashed, {}};
    for (const auto& b : v.band->points) {
      fit.x.push_back(b.v0), fit.y.push_back(b.e_nominal);
      lo.x.push_back(b.v0), lo.y.push_back(b.e_lo);
      hi.x.push_back(b.v0), hi.y.push_back(b.e_hi);
    }
    p.series.insert(p.series.end(), {fit, lo, hi});
  }
  if (v.validation) {
    Series held{"held back (+-1 u)", {}, {}, Series::Style::error_bars, {}};
    for (const auto& q : v.validation->points)
      held.x.push_back(q.v0), held.y.push_back(q.D), held.y_error.push_back(q.u_D);
    p.series.push_back(held);
  }
  return p;
}

Plot residual_plot(const CalibrationView& v, const std::string& anchor) {
  Plot p{slug(anchor + "-residuals"),
         "Normalised residuals (model - data)/u",
         "impact velocity v0 [m/s]",
         "normalised residual [-]",
         true,
         false,
         {}};
  Series r{"residuals", {}, {}, Series::Style::points, {}};
  for (const auto& x : v.fit->residuals) r.x.push_back(x.v0), r.y.push_back(x.normalised);
  const double lo = r.x.empty() ? 0.1 : *std::min_element(r.x.begin(), r.x.end());
  const double hi = r.x.empty() ? 10 : *std::max_element(r.x.begin(), r.x.end());
  p.series.push_back(r);
  // the band |r| <= 2 as one closed outline (two flat lines alone have an empty bounding box,
  // which the browser test takes for an undrawn series)
  p.series.push_back(
      {"|r| = 2", {lo, hi, hi, lo, lo}, {2, 2, -2, -2, 2}, Series::Style::dashed, {}});
  return p;
}

Plot ranking_plot(const CalibrationView& v, const std::string& anchor) {
  Plot p = fit_plot(CalibrationView{v.problem, v.fit, nullptr, nullptr, nullptr, nullptr}, anchor);
  p.id = slug(anchor + "-ranking");
  p.title = "Every compared law fitted to the same data";
  for (std::size_t i = 0; i < v.ranking->models.size(); ++i) {
    if (i >= v.ranking_curves->size() || (*v.ranking_curves)[i].empty()) continue;
    Series s{v.ranking->models[i].name, {}, (*v.ranking_curves)[i], Series::Style::lines, {}};
    for (const auto& b : v.band->points) s.x.push_back(b.v0);
    p.series.push_back(s);
  }
  return p;
}

std::string parameter_table(const validation::CalibrationResult& f, const Source& source) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : f.parameters) {
    std::string profile = "—";
    if (p.profile95)
      profile = cell(p.profile95->first) + " .. " + cell(p.profile95->second) +
                (p.profile_differs ? " <b>(differs by &gt; 10 %)</b>" : "");
    rows.push_back({escape(p.name), escape(p.unit), cell(p.start),
                    p.identifiable ? cell(p.value) : "<b class=\"fail\">unidentifiable</b>",
                    cell(p.standard_error),
                    p.identifiable ? cell(p.lower95) + " .. " + cell(p.upper95) : "—", profile,
                    p.at_bound ? "at bound" : ""});
  }
  return table({"parameter", "unit", "start", "estimate", "standard error", "95 % (linearised)",
                "95 % (profile likelihood)", "note"},
               rows, source);
}

std::string correlation_table(const validation::CalibrationResult& f, const Source& source) {
  std::vector<std::string> header{""};
  for (const auto& p : f.parameters) header.push_back(escape(p.name));
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < f.correlation.size(); ++i) {
    std::vector<std::string> row{escape(f.parameters[i].name)};
    for (double c : f.correlation[i]) row.push_back(cell(c, 4));
    rows.push_back(row);
  }
  return table(header, rows, source);
}

std::string validation_table(const validation::ValidationComparison& c, const Source& source) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : c.points)
    rows.push_back({cell(p.v0, 4), cell(p.S), cell(p.D), cell(p.E, 3), cell(p.u_num, 2),
                    cell(p.u_input, 3), cell(p.u_D, 3), cell(p.u_val, 3),
                    p.exceeds ? "<span class=\"fail\">|E| &gt; 2 u<sub>val</sub></span>"
                              : "<span class=\"pass\">within</span>"});
  return table({"v0 [m/s]", "S (model)", "D (measured)", "E = S - D", "u_num", "u_input", "u_D",
                "u_val", "verdict"},
               rows, source);
}

std::string ranking_table(const validation::ModelRanking& r, const Source& source) {
  std::vector<std::vector<std::string>> rows;
  for (const auto& m : r.models) {
    if (!m.fit.ok) {
      rows.push_back(
          {"—", escape(m.name), "", "", "", "", "", escape("fit failed: " + m.fit.failure)});
      continue;
    }
    rows.push_back({std::to_string(m.rank), escape(m.name), std::to_string(m.k),
                    cell(m.fit.chi2_per_dof(), 4), m.fit.p_value ? cell(*m.fit.p_value, 3) : "—",
                    cell(m.aic, 5), cell(m.delta_aic, 4), cell(m.bic, 5)});
  }
  return table({"rank", "law", "k", "chi<sup>2</sup>/dof", "p", "AIC", "ΔAIC", "BIC"}, rows,
               source);
}

std::string draw(const Plot& plot, const std::string& caption, const PlacePlot& place) {
  if (place) return place(plot, caption);
  try {
    return "<figure>" + render_svg(plot, plot.id) + "<figcaption>" + caption +
           "</figcaption></figure>\n";
  } catch (const std::exception& e) {
    return "<p class=\"fail\">plot " + escape(plot.id) +
           " could not be drawn: " + escape(e.what()) + "</p>\n";
  }
}

}  // namespace

std::string calibration_section_html(const CalibrationView& v, const std::string& anchor,
                                     const PlacePlot& place, const Source& source) {
  const validation::CalibrationResult& f = *v.fit;
  std::string html = "<section id=\"" + slug(anchor) + "\">\n";
  html += "<p>Data: <code>" + escape(v.problem->data.source) + "</code>, " +
          std::to_string(v.problem->data.points.size()) + " impacts.</p>\n";
  if (!v.problem->data.provenance.empty()) {
    html += "<blockquote>";
    for (const auto& line : v.problem->data.provenance) html += escape(line) + "<br>";
    html += "</blockquote>\n";
  }
  if (!f.ok)
    return html + "<p class=\"fail\">Calibration failed: " + escape(f.failure) + "</p></section>\n";
  html += "<p>" + escape(f.law) + ": χ<sup>2</sup> = " + cell(f.chi2) + " on " +
          std::to_string(f.dof) + " degrees of freedom" +
          (f.p_value ? ", p = " + cell(*f.p_value, 3)
                     : " (noise estimated from the residuals: no χ<sup>2</sup> test)") +
          ". Model runs: --model auto at rtol " + cell(f.rtol, 2) + " (stated error of e ≤ " +
          cell(f.stated_error, 2) + "). " + escape(f.solver_report) + "</p>\n";
  for (const auto& s : f.estimated_noise) html += "<p>" + escape(s) + "</p>\n";
  html += draw(fit_plot(v, anchor),
               v.band ? "Dashed: the 2.5 % and 97.5 % quantiles of " +
                            std::to_string(v.band->samples) + " Monte Carlo draws (seed " +
                            std::to_string(v.band->seed) + ") over the fitted covariance."
                      : "",
               place);
  html += draw(residual_plot(v, anchor), "Dashed: ±2.", place);
  html += "<h4>Parameters</h4>\n" + parameter_table(f, source);
  for (const auto& u : f.unidentifiable)
    html += "<p><b>Unidentifiable:</b> " + escape(u) + "</p>\n";
  html += "<h4>Correlation matrix</h4>\n" + correlation_table(f, source);
  if (v.validation && v.validation->prediction.ok())
    html += "<h4>Validation (ASME V&amp;V 20) against held-back points</h4>\n<p>" +
            escape(v.validation->summary()) +
            ". E = S − D, u<sub>val</sub> = √(u<sub>num</sub>² + u<sub>input</sub>² + "
            "u<sub>D</sub>²).</p>\n" +
            validation_table(*v.validation, source);
  if (v.ranking) {
    html += "<h4>Model comparison</h4>\n" + ranking_table(*v.ranking, source);
    if (v.band && v.ranking_curves) html += draw(ranking_plot(v, anchor), "", place);
  }
  return html + "</section>\n";
}

fs::path write_calibration_report(const CalibrationView& v, const fs::path& dir,
                                  const std::string& command_line) {
  create_output_directory(dir, "--report");
  const std::string body =
      "<h1>Calibration: " + escape(v.fit->law) + "</h1>\n<p><small>command: <code>" +
      escape(command_line) + "</code></small></p>\n" +
      calibration_section_html(v, "calibration", {}, Source::illustration()) +
      "<p>Machine-readable: <a href=\"calibration.json\">calibration.json</a>.</p>";
  write_file_atomically(dir / "calibration.json", [&](std::ostream& out) {
    out << validation::calibration_json(*v.problem, *v.fit).dump(2) << "\n";
  });
  const fs::path index = dir / "index.html";
  write_file_atomically(
      index, [&](std::ostream& out) { out << page("ivv calibrate: " + v.fit->law, body); });
  return index;
}

}  // namespace ivv::reports
