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

struct SvgSize {
  int width = 640;   // [px] of the viewBox; the page scales it to the column width
  int height = 420;  // [px]
};

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
