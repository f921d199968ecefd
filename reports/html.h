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

// A table: `header` cells and rows of cells, all already HTML (escape text first).
// `css_class` goes on the <table>.
std::string table(const std::vector<std::string>& header,
                  const std::vector<std::vector<std::string>>& rows,
                  std::string_view css_class = "data");

// The whole document around `body` (already HTML): doctype, charset, title, the inline style
// sheet (screen and print). No script, no external resource.
std::string page(std::string_view title, std::string_view body);

}  // namespace ivv::reports
