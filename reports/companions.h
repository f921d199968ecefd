// The machine-readable companions written beside index.html:
//
//   results.json  {"cases": [{"id", "title", "tier", "passed", "measured", "reference",
//                  "tolerance", "reason", "comparison", "margin", "detail", "slow",
//                  "seconds"}, ...]}: the shape of `ivv verify`, in registry order; a number
//                 that is NaN or infinite is null.
//   series.csv    every plotted series of the report, long format: plot_id,series,x,y
//                 (RFC 4180 quoting; one row per point, plot ids as in data-plot-id of the
//                 page's <svg> elements).
//   junit.xml     one <testsuite> per tier, one <testcase classname="ivv.<tier>" name="<id>">
//                 per case; a failed case has a <failure> with the measurement and detail.
#pragma once

#include <string>
#include <vector>

#include "verification/registry.h"

namespace ivv::reports {

std::string results_json(const std::vector<verification::CaseRecord>& records);
std::string series_csv(const std::vector<const verification::Plot*>& plots);
std::string junit_xml(const std::vector<verification::CaseRecord>& records);

// One-line summary of what a case compared, e.g. "|m - r|/|r| = 3e-9 <= 1e-8".
std::string comparison_text(const verification::Outcome& o);

}  // namespace ivv::reports
