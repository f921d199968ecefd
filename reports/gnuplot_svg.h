// Plots drawn by gnuplot as SVG, for inlining into the HTML report.
//
// render_svg() writes a gnuplot script (data inline as datablocks, `set terminal svg dynamic`)
// to a private temporary directory, runs the gnuplot executable found at configure time on it
// and reads the SVG back; the temporary directory is removed whatever happens. The SVG is
// prepared for inlining: the XML prologue is dropped and every id it defines (point markers,
// filters) is prefixed so that several plots can share one HTML document.
//
// Data rules: non-finite points, and non-positive ones on a logarithmic axis, are not drawn
// (they break the line there); a series with nothing drawable is left out of the plot. A plot
// with no drawable series at all is an error (EmptyPlot): the report shows that, never an
// empty frame.
#pragma once

#include <stdexcept>
#include <string>

#include "verification/plot_data.h"

namespace ivv::reports {

class EmptyPlot : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The drawing's size in viewBox units and the font size in the same units. The page scales
// the drawing to its box, and the text with it: displayed text = font * displayed width /
// width. The two layouts of the report are chosen so that this stays at or above 11 px
// (browser_test measures it): alone, a plot is shown 640-760 px wide; side by side, 460-530 px
// (two columns of at least 480 px, see html.cc), hence its smaller viewBox.
struct SvgSize {
  int width = 640;   // [px] of the viewBox; the page scales it to the column width
  int height = 420;  // [px]
  int font = 13;     // [px] of the viewBox: axis, tick and key text
};
constexpr SvgSize kAloneSize{640, 420, 13};
constexpr SvgSize kSideBySideSize{480, 380, 12};

// A plot label written in plain text, as the verification cases write them ("K_h^{2/5}",
// "v0/v_y", "r^(1/4)", "zeta = 0.1", "omega0 dt"), as gnuplot enhanced text: _x and _{..}
// subscripts, ^x, ^{..} and ^(..) superscripts, a one-letter symbol followed by 0 (v0, ω0)
// with a subscript 0, Greek names as whole words (lambda, zeta, omega, ...) as letters, "+-"
// as ±; every other enhanced-text control character (@ & ~ { } \) escaped so that it prints.
std::string enhanced_text(const std::string& plain);

// The gnuplot script for `plot` (exposed for tests). Throws EmptyPlot if nothing is drawable.
std::string gnuplot_script(const verification::Plot& plot, SvgSize size = {});

// Runs gnuplot and returns the inline-ready <svg> element. `id_prefix` (made id-safe) is put
// in front of every id of the SVG. Throws EmptyPlot, or std::runtime_error if gnuplot cannot
// be run or fails (message with gnuplot's stderr).
std::string render_svg(const verification::Plot& plot, const std::string& id_prefix,
                       SvgSize size = {});

// What an SVG from render_svg() draws: a series counts as drawn when its group holds more
// than its key sample (at least two line segments, or two point markers).
struct SvgCheck {
  bool has_svg = false;  // a complete <svg>...</svg> element
  int series = 0;        // plotted series (gnuplot_plot_N groups)
  int drawn_series = 0;  // of which with data drawn
  bool ok() const { return has_svg && series > 0 && drawn_series == series; }
};
SvgCheck check_svg(const std::string& svg);

// "gnuplot 5.4 patchlevel 4", or "unavailable".
std::string gnuplot_version();

}  // namespace ivv::reports
