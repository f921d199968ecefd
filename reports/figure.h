// What a report section hands to the page: plots (data, drawn later by gnuplot) with
// captions, and the options every section shares.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "reports/html.h"
#include "verification/plot_data.h"

namespace ivv::reports {

struct Figure {
  verification::Plot plot;  // plot.id is unique within the report
  std::string caption;      // HTML (escaped by the producer); says what is drawn and with what
  bool full_width = false;  // alone on its row (otherwise two figures share a row)
  Source source;  // the case(s) whose measurements are drawn, or the illustration/timing label
};

struct SectionOptions {
  bool quick = false;  // fewer benchmark points (tests); studies are the same in both modes
  int threads = 0;     // for sweeps: 0 = all hardware threads
  std::function<void(const std::string&)> progress;  // one line per stage; may be empty
  void say(const std::string& line) const {
    if (progress) progress(line);
  }
};

// An empty series to be filled point by point with add().
inline verification::Series curve(
    std::string label, verification::Series::Style style = verification::Series::Style::lines) {
  verification::Series s;
  s.label = std::move(label);
  s.style = style;
  return s;
}

inline void add(verification::Series& s, double x, double y) {
  s.x.push_back(x);
  s.y.push_back(y);
}

// At most `max_points` of a curve, evenly strided, keeping the first and last point.
template <class T>
std::vector<T> thin(const std::vector<T>& v, std::size_t max_points) {
  if (v.size() <= max_points || max_points < 2) return v;
  std::vector<T> out;
  out.reserve(max_points);
  const double stride = static_cast<double>(v.size() - 1) / static_cast<double>(max_points - 1);
  for (std::size_t i = 0; i < max_points; ++i)
    out.push_back(v[static_cast<std::size_t>(static_cast<double>(i) * stride + 0.5)]);
  return out;
}

}  // namespace ivv::reports
