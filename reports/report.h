// The HTML verification report (docs/design.md §4, "ivv report"): one self-contained DIR/index.html
// (no script, no network, no external file; plots are inline SVG drawn by gnuplot; a print
// style sheet) with, in order:
//   1. Summary: overall verdict, counts per tier, failing cases first, provenance.
//   2. The paper reproduced: Figs 2-14 (reports/paper_figures.h).
//   3. Restitution trends (reports/restitution.h).
//   4. Every verification case of verification::all_cases() matching the filter, run on all
//      cores, in tables per tier with an expandable detail and the case's plots.
//   5. Speed against error (reports/speed_error.h).
//   6. The DEM benchmark of Chung & Ooi (2011) (reports/dem_benchmark.h).
//   7. Machine-readable companions beside index.html (reports/companions.h): results.json,
//      series.csv (every plotted series: plot_id,series,x,y) and junit.xml.
// Every file is written atomically (solver/atomic_file.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include "verification/registry.h"

namespace ivv::reports {

struct ReportOptions {
  std::filesystem::path out_dir;  // created if missing
  std::string filter;             // glob over case ids ("" or "*": all)
  int threads = 0;                // for cases and sweeps; 0 = all hardware threads
  bool allow_failures = false;    // recorded in the summary; the caller decides the exit code
  std::string command_line;       // for provenance
  std::function<void(const std::string&)> progress;  // one line per stage and per case
  bool quick = false;  // fewer benchmark points (tests); same sections and studies
};

struct ReportSummary {
  std::size_t cases = 0, passed = 0, failed = 0;
  std::size_t plots = 0;           // plots in the page
  std::size_t plot_errors = 0;     // plots that could not be drawn (shown as such in the page)
  std::size_t section_errors = 0;  // sections 2, 3, 5 whose computation threw (shown in the
                                   // page, and the overall verdict is then FAIL)
  double seconds = 0.0;            // wall clock of write_report
  std::filesystem::path index_html;
};

// Draws a battery that ran (verification::run_battery) into options.out_dir: the page and its
// companions. Computes nothing that a case judges: the sections draw the studies the cases
// read (verification/study_*.h). Throws InputError (scene/input_error.h) for an out_dir that is
// empty, is not a directory or cannot be created; std::runtime_error if a file cannot be
// written. A section whose drawing throws is reported in the page, not thrown.
ReportSummary render(const verification::BatteryResult& battery, const ReportOptions& options);

// run_battery(options.filter, options.threads) and render() of it. Throws as both do (and
// InputError for a filter that matches no case).
ReportSummary write_report(const ReportOptions& options);

}  // namespace ivv::reports
