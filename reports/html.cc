#include "reports/html.h"

#include <cmath>
#include <cstdio>

namespace ivv::reports {

std::string escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    switch (ch) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += ch;
    }
  }
  return out;
}

std::string number(double v, int digits) {
  if (std::isnan(v)) return "NaN";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string number_html(double v, int digits) {
  if (!std::isfinite(v) || v == 0) return number(v, digits);
  const double a = std::abs(v);
  if (a >= 1e-3 && a < 1e4) return number(v, digits);
  int exponent = static_cast<int>(std::floor(std::log10(a)));
  double mantissa = v / std::pow(10.0, exponent);
  // rounding to `digits` may carry into the next power (9.9996 -> 10.00)
  if (std::abs(std::stod(number(mantissa, digits))) >= 10.0) {
    ++exponent;
    mantissa /= 10.0;
  }
  return number(mantissa, digits) + "×10<sup>" + std::to_string(exponent) + "</sup>";
}

std::string slug(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char ch : text) {
    const bool keep = (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') ||
                      (ch >= '0' && ch <= '9') || ch == '_' || ch == '-';
    out += keep ? ch : '-';
  }
  return out;
}

namespace {
std::string_view kind_name(Source::Kind k) {
  switch (k) {
    case Source::Kind::cases:
      return "cases";
    case Source::Kind::case_rows:
      return "case-rows";
    case Source::Kind::illustration:
      return "illustration";
    case Source::Kind::timing:
      return "timing";
    case Source::Kind::unstated:
      break;
  }
  return "unstated";
}

std::string case_list(const std::vector<std::string>& ids) {
  std::string out;
  for (const auto& id : ids) {
    out += out.empty() ? "" : ", ";
    const bool glob = id.find_first_of("*?") != std::string::npos;
    out += glob ? "<code>" + escape(id) + "</code>"
                : "<a href=\"#case-" + slug(id) + "\"><code>" + escape(id) + "</code></a>";
  }
  return out;
}
}  // namespace

std::string source_attribute(const Source& source) {
  std::string value(kind_name(source.kind));
  for (std::size_t i = 0; i < source.cases.size(); ++i)
    value += (i == 0 ? ":" : " ") + source.cases[i];
  return " data-source=\"" + escape(value) + "\"";
}

std::string source_label(const Source& source) {
  const std::string ids = case_list(source.cases);
  switch (source.kind) {
    case Source::Kind::cases:
      return "<span class=\"source\">From " +
             std::string(source.cases.size() == 1 ? "case " : "cases ") + ids + ".</span>";
    case Source::Kind::case_rows:
      return "";
    case Source::Kind::illustration:
      return "<span class=\"source illustration\">Illustration</span>" +
             (ids.empty() ? std::string(".") : " (related cases: " + ids + ").");
    case Source::Kind::timing:
      return "<span class=\"source timing\">Timing, information only</span>" +
             (ids.empty() ? std::string(".") : " (related cases: " + ids + ").");
    case Source::Kind::unstated:
      break;
  }
  return "";
}

std::string table_open(const Source& source, std::string_view css_class) {
  const std::string label = source_label(source);
  return (label.empty() ? std::string() : "<p class=\"source\">" + label + "</p>\n") +
         "<table class=\"" + std::string(css_class) + "\"" + source_attribute(source) + ">\n";
}

std::string table(const std::vector<std::string>& header,
                  const std::vector<std::vector<std::string>>& rows, const Source& source,
                  std::string_view css_class) {
  std::string out = table_open(source, css_class) + "<thead><tr>";
  for (const auto& h : header) out += "<th>" + h + "</th>";
  out += "</tr></thead>\n<tbody>\n";
  for (const auto& row : rows) {
    out += "<tr>";
    for (const auto& cell : row) out += "<td>" + cell + "</td>";
    out += "</tr>\n";
  }
  out += "</tbody></table>\n";
  return out;
}

namespace {
constexpr std::string_view kStyle = R"css(
:root { --fg: #1b1f24; --muted: #57606a; --line: #d0d7de; --pass: #1a7f37; --fail: #cf222e;
        --bg-alt: #f6f8fa; }
* { box-sizing: border-box; }
/* The body, not the document, scrolls. Headless Chromium's --screenshot captures the document
   from its origin while it rasters only the part scrolled to, so a page opened at an anchor
   below the first screen (#structure) came out blank; with the root never scrolled, the capture
   is what the reader sees. Print restores the normal flow. */
html { height: 100%; overflow: hidden; }
body { height: 100%; overflow-y: auto; margin: 0;
       font-family: system-ui, -apple-system, "Segoe UI", "DejaVu Sans", sans-serif;
       color: var(--fg); line-height: 1.45; font-size: 15px; }
div.page { margin: 0 auto; padding: 1.5rem 2rem 4rem; max-width: 1180px; }
h1 { font-size: 1.8rem; margin: 0 0 .3rem; }
h2 { font-size: 1.35rem; margin-top: 2.4rem; padding-bottom: .3rem;
     border-bottom: 2px solid var(--line); }
h3 { font-size: 1.1rem; margin-top: 1.6rem; }
p.lead { color: var(--muted); margin-top: 0; }
nav.toc { background: var(--bg-alt); border: 1px solid var(--line); border-radius: 6px;
          padding: .5rem 1rem; margin: 1rem 0; }
nav.toc ol { margin: .2rem 0; }
.verdict { font-size: 1.2rem; font-weight: 600; padding: .6rem 1rem; border-radius: 6px;
           display: inline-block; margin: .5rem 0; }
.verdict.pass { background: #dafbe1; color: var(--pass); border: 1px solid var(--pass); }
.verdict.fail { background: #ffebe9; color: var(--fail); border: 1px solid var(--fail); }
span.pass { color: var(--pass); font-weight: 600; }
span.fail { color: var(--fail); font-weight: 600; }
table { border-collapse: collapse; margin: .6rem 0 1rem; font-size: .88rem; }
th, td { border: 1px solid var(--line); padding: .25rem .5rem; vertical-align: top;
         text-align: left; }
th { background: var(--bg-alt); }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
table.cases { width: 100%; table-layout: fixed; }
table.cases td { overflow-wrap: anywhere; }
table.cases { font-size: .82rem; }
table.cases col.c-id { width: 22%; } table.cases col.c-num { width: 9%; }
table.cases col.c-tol { width: 7%; } table.cases col.c-cmp { width: 7%; }
table.cases col.c-reason { width: 32%; } table.cases col.c-margin { width: 7%; }
table.cases col.c-verdict { width: 7%; }
table.cases td.num { white-space: nowrap; overflow-wrap: normal; }
table.cases td.reason { font-size: .8rem; color: var(--muted); }
tr.failed td { background: #fff5f5; }
code, .mono { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: .85em; }
figure { margin: 1rem 0 1.6rem; padding: .6rem; border: 1px solid var(--line);
         border-radius: 6px; break-inside: avoid; page-break-inside: avoid; }
figure svg { display: block; width: 100%; max-width: 760px; height: auto; margin: 0 auto; }
figure.wide { max-width: 900px; margin-left: auto; margin-right: auto; }
details.case figure svg { max-width: 640px; }
figcaption { font-size: .9rem; color: var(--fg); margin-top: .4rem; }
figcaption b.ftitle { display: block; }
.plot-error { border: 2px solid var(--fail); color: var(--fail); padding: .6rem; }
p.source { font-size: .85rem; margin: .6rem 0 .2rem; color: var(--muted); }
span.source { font-size: .85rem; color: var(--muted); }
span.source.illustration, span.source.timing { font-weight: 600; color: #8250df;
         border: 1px solid #8250df; border-radius: 4px; padding: 0 .3rem; }
.grid2 { display: grid; grid-template-columns: repeat(auto-fit, minmax(480px, 1fr));
         gap: 0 1rem; }
details.tier > summary { cursor: pointer; margin: 1.6rem 0 .4rem; }
details.tier > summary h3 { display: inline; margin: 0; }
details.case { margin: .2rem 0; }
details.case > summary { cursor: pointer; }
details.case > div { padding: .4rem .8rem; border-left: 3px solid var(--line);
                     margin: .3rem 0 .8rem; }
.note { background: #fff8c5; border: 1px solid #d4a72c; border-radius: 6px;
        padding: .4rem .8rem; }
dl.prov { display: grid; grid-template-columns: max-content 1fr; gap: .15rem 1rem;
          font-size: .9rem; }
dl.prov dt { font-weight: 600; }
dl.prov dd { margin: 0; overflow-wrap: anywhere; }
@media print {
  html, body { height: auto; overflow: visible; }
  body { font-size: 10.5pt; }
  div.page { max-width: none; padding: 0; }
  nav.toc { display: none; }
  h2 { break-before: page; }
  h2.first { break-before: auto; }
  figure, tr { break-inside: avoid; }
  figure.wide svg { max-width: 70%; }
  details.case figure svg { max-width: 55%; }
  .grid2 { grid-template-columns: 1fr 1fr; gap: 0 .5rem; }
  figure { margin: .3rem 0 .6rem; padding: .3rem; }
  figcaption { font-size: 7.5pt; }
  table.cases { font-size: 7.5pt; }
  details.case > summary, details.tier > summary { list-style: none; }
  details.case::details-content, details.tier::details-content {
    content-visibility: visible; display: block; }
  a { color: inherit; text-decoration: none; }
}
)css";
}  // namespace

std::string page(std::string_view title, std::string_view body) {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  out += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  out += "<title>" + escape(title) + "</title>\n<style>";
  out += kStyle;
  out += "</style>\n</head>\n<body>\n<div class=\"page\">\n";
  out += body;
  out += "\n</div>\n</body>\n</html>\n";
  return out;
}

}  // namespace ivv::reports
