// Small HTML building blocks of the report: escaping, number formatting, the page frame (with
// its screen and print style sheet) and tables. Pure string functions; no I/O.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace ivv::reports {

// Escapes &, <, >, " and ' for text and attribute values.
std::string escape(std::string_view text);

// A number for people: %.*g with `digits` significant digits; "NaN", "inf", "-inf" spelled out.
std::string number(double v, int digits = 6);

// A number for HTML text: like number(), but a power of ten outside [1e-3, 1e4) is written
// "1.23×10<sup>9</sup>".
std::string number_html(double v, int digits = 4);

// An id/anchor-safe version of `text`: [A-Za-z0-9_-] kept, everything else becomes '-'.
std::string slug(std::string_view text);

// Where the numbers of a figure or a table come from (the report once ran its own simulations,
// unchecked by any case): every number the report shows
// is a verification case's measurement, or it is labelled, visibly, as an illustration or as a
// timing (information only, never pass/fail). Rendered as the attribute data-source on the
// <figure> or <table> and as a visible label; a figure or table whose Source was never set
// renders data-source="unstated", which reports_test rejects.
struct Source {
  enum class Kind {
    unstated,      // nobody said: a defect the report's test catches
    cases,         // the numbers are the measurements of `cases`
    case_rows,     // each row is a case or a conformance check, with its own verdict
    illustration,  // not a measurement; `cases` (may be empty) are the related cases
    timing,        // wall-clock timings: information only; `cases` are the related cases
  };
  Kind kind = Kind::unstated;
  std::vector<std::string> cases;  // registry case ids, or globs over them (* and ?)

  static Source from_cases(std::vector<std::string> ids) { return {Kind::cases, std::move(ids)}; }
  static Source rows_are_cases() { return {Kind::case_rows, {}}; }
  static Source illustration(std::vector<std::string> related = {}) {
    return {Kind::illustration, std::move(related)};
  }
  static Source timing(std::vector<std::string> related = {}) {
    return {Kind::timing, std::move(related)};
  }
};

// ` data-source="KIND[:id id ...]"` with KIND cases, case-rows, illustration, timing or
// unstated (ids space-separated, escaped).
std::string source_attribute(const Source& source);
// The visible label: "From case(s) <links>", "Illustration (related cases: ...)",
// "Timing, information only (...)"; empty for case_rows. HTML, links to #case-<slug>.
std::string source_label(const Source& source);

// A table: `header` cells and rows of cells, all already HTML (escape text first), preceded by
// the visible label of `source` (a <p class="source">) and carrying its attribute.
// `css_class` goes on the <table>.
std::string table(const std::vector<std::string>& header,
                  const std::vector<std::vector<std::string>>& rows, const Source& source,
                  std::string_view css_class = "data");
// The opening tag <table class="css_class" data-source="..."> of a table built by hand,
// preceded by the label of `source`.
std::string table_open(const Source& source, std::string_view css_class = "data");

// The whole document around `body` (already HTML): doctype, charset, title, the inline style
// sheet (screen and print). No script, no external resource.
std::string page(std::string_view title, std::string_view body);

}  // namespace ivv::reports
