// HTML for conformance reports: one law's checks as a section (used by the main report's
// worked-examples section) and as a whole self-contained page (`ivv check-law --report DIR`,
// which writes DIR/index.html and DIR/results.json).
#pragma once

#include <filesystem>
#include <functional>
#include <string>

#include "reports/html.h"
#include "verification/conformance.h"

namespace ivv::reports {

// Places a plot with its caption (HTML) and returns the HTML to put where it goes.
using PlacePlot = std::function<std::string(const verification::Plot&, const std::string&)>;

// A <section> (HTML) for one law: verdict, the checks table (measured, reference, tolerance,
// why, detail), what was not applicable, and the delivered COR drawn against the claim.
// `anchor` is the section's id. `place` draws the plots (default: gnuplot now, inline; a plot
// that cannot be drawn is said so in place). `table_source` labels the checks table (the main
// report names the examples.* cases that judge it; by default each row is a check with its
// verdict).
std::string law_section_html(const conformance::Report& report, const std::string& anchor,
                             const std::string& intro_html = "", const PlacePlot& place = {},
                             const Source& table_source = Source::rows_are_cases());

// Throws InputError("--report", ...) unless DIR is a directory or can be created (checked
// before any computation, so bad input costs nothing); creates nothing (solver/atomic_file.h:
// check_output_directory): the writers create DIR, so a run that fails leaves none.
void check_report_dir(const std::filesystem::path& dir);

// Writes DIR/index.html (same page frame and style as the main report) and DIR/results.json
// (conformance::to_json), each atomically. Throws InputError("--report", ...) for a DIR that
// exists and is not a directory or cannot be created. Returns the index.html path.
std::filesystem::path write_law_report(const conformance::Report& report,
                                       const std::filesystem::path& dir,
                                       const std::string& command_line);

}  // namespace ivv::reports
