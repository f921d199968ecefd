// Plot data: what a verification case or a report figure wants drawn. Data only; rendering
// (gnuplot to inline SVG) lives in reports/.
#pragma once

#include <string>
#include <vector>

namespace ivv::verification {

struct Series {
  enum class Style { lines, points, linespoints, dashed, error_bars };
  std::string label;
  std::vector<double> x, y;
  Style style = Style::lines;
  std::vector<double> y_error = {};  // error_bars: half-length of each bar (y units)
};

struct Plot {
  std::string id;  // file-name-safe identifier, unique within a report
  std::string title;
  std::string x_label;  // with units, e.g. "time t [ms]"
  std::string y_label;
  bool log_x = false;
  bool log_y = false;
  std::vector<Series> series;
  bool margins = false;  // leave 5 % of the data range free at each side (a constant curve, or a
                         // curve at a bound such as e = 1, stays off the frame)
};

}  // namespace ivv::verification
