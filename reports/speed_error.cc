#include "reports/speed_error.h"

#include <cmath>
#include <limits>

#include "reports/html.h"

namespace ivv::reports {
namespace {

using verification::Plot;
using verification::Series;

std::string machine_text(const verification::MachineInfo& m) {
  return escape(m.cpu_model) + ", " + std::to_string(m.logical_cores) + " logical cores, " +
         escape(m.compiler) + ", " + escape(m.build_type) + " build, machine code " +
         escape(m.machine_code);
}

void work_precision_figures(const verification::WorkPrecisionStudy& study, const std::string& id,
                            const std::vector<verification::SpeedPoint>& peers,
                            std::vector<Figure>& out) {
  struct Metric {
    const char* key;
    const char* name;
    const char* key_label;
    double verification::WorkPrecisionPoint::*error;
  };
  for (const Metric m : {Metric{"e", "COR e", "e", &verification::WorkPrecisionPoint::error_e},
                         Metric{"fmax", "peak force F_max", "F_max",
                                &verification::WorkPrecisionPoint::error_F_max}}) {
    Plot p;
    p.id = "speed-" + id + "-" + m.key;
    p.title = "Work-precision, " + study.label + ": relative error of " + m.name +
              " against time per impact";
    p.x_label = "wall-clock time per impact [s]";
    p.y_label = std::string("relative error of ") + m.key_label + " [-]";
    p.log_x = p.log_y = true;
    int failed = 0;
    for (const auto& s : study.series) {
      Series c;
      c.label = std::string(to_string(s.integrator));
      c.style = Series::Style::linespoints;
      for (const auto& pt : s.points) {
        if (!pt.ok) {
          ++failed;
          continue;
        }
        c.x.push_back(pt.seconds_per_impact);
        c.y.push_back(pt.*(m.error));
      }
      p.series.push_back(c);
    }
    for (verification::Peer peer : verification::kPeers) {
      Series c;
      c.label = "peer: " + verification::to_string(peer);
      c.style = Series::Style::points;
      for (const auto& pt : peers) {
        if (pt.integrator != verification::to_string(peer) || !pt.ok) continue;
        c.x.push_back(pt.us_per_impact * 1e-6);
        c.y.push_back(std::string(m.key) == "e" ? pt.err_e : pt.err_F);
      }
      if (!c.x.empty()) p.series.push_back(c);
    }
    std::string caption =
        "Scene: " + escape(study.label) + ". One point per tolerance (" + "rtol = atol from " +
        number(study.series.empty() || study.series.front().points.empty()
                   ? 0.0
                   : study.series.front().points.front().tolerance) +
        " down, the adaptive integrators; the fixed step dt in τ for rk4). Errors relative to the "
        "mp50 reference (e = " +
        number(study.reference.e, 12) + ", F<sub>max</sub> = " + number(study.reference.F_max, 12) +
        " N, tolerance " + number(study.base.options.reference_tolerance) +
        "); an error of exactly 0 is drawn at 1e-17. Time: median of repeated single-threaded "
        "runs on " +
        machine_text(study.machine) + ".";
    if (std::abs(study.reference.e) < 1e-3)
      caption +=
          " With e this small (nearly no rebound) its relative error measures an "
          "absolute error of order e times the plotted value.";
    if (failed > 0)
      caption += " " + std::to_string(failed) +
                 " points failed or ended in another status than the reference and are not drawn "
                 "(see the table).";
    out.push_back(
        {.plot = p, .caption = caption, .source = Source::timing({"convergence.work-precision"})});
  }
}

}  // namespace

SpeedSection speed_section(const SectionOptions& options) {
  SpeedSection out;

  options.say(std::string("speed: work-precision studies (mp50 reference, then every integrator ") +
              "and tolerance, single-threaded; the peers) - the study the cases read");
  const verification::WorkPrecisionStudies& wp = verification::work_precision_study(options.quick);
  out.machine = wp.machine;
  out.studies = wp.studies;
  out.peers = wp.peers;
  out.ratios = wp.ratios;
  for (std::size_t i = 0; i < wp.studies.size(); ++i)
    work_precision_figures(
        wp.studies[i], wp.ids[i],
        wp.ids[i] == "paper" ? wp.peers : std::vector<verification::SpeedPoint>{}, out.figures);

  options.say("speed: convergence of rk4 and dp45 (fixed step), from the study the cases read");
  {
    const verification::FixedStepConvergenceStudy& st =
        verification::fixed_step_convergence_study();
    Plot p;
    p.id = "speed-convergence";
    p.title = "Convergence of the fixed-step integrators: error of e against the step";
    p.x_label = "fixed step dt in normalised time τ [-]";
    p.y_label = "relative error of e vs closed form [-]";
    p.log_x = p.log_y = true;
    for (const verification::ConvergenceStudy& c : st.runs) {
      out.convergence.push_back(c);
      Series s;
      s.label = std::string(to_string(c.integrator)) +
                (c.events_located ? ", events located" : ", events at step ends") + ": order " +
                number(c.fitted_order, 3);
      s.style = c.events_located ? Series::Style::linespoints : Series::Style::points;
      s.x = c.steps;
      s.y = c.errors_e;
      p.series.push_back(s);
    }
    out.figures.push_back(
        {p,
         "Linearized law, paper scene at v<sub>0</sub> = 1 m/s with ζ = 0.1, where the exact "
         "COR is known in closed form (eqs 22-25). rk4, and dp45 with its error control off; "
         "the fitted order (legend and table) is the least-squares slope of log(error) on "
         "log(dt). With event location it measures the method's convergence (formal orders: "
         "rk4 4, dp45 5; the generic cases <code>convergence.order.*</code> check every "
         "fixed-step integrator's declared order). Detected only at step ends, the switch to "
         "unloading and the separation are found to within one step, and the error stops "
         "falling as dt<sup>p</sup>: the open markers.",
         true,
         Source::from_cases({"convergence.rk4.events-at-step-ends",
                             "convergence.dp45.events-at-step-ends", "convergence.order.rk4",
                             "convergence.order.dp45"})});
  }

  options.say("speed: hard cases, every double-precision integrator (study)");
  out.hard_cases = verification::hard_case_study();
  return out;
}

namespace {
// How each peer is set up, so that a reader can judge the comparison fair
// (verification/peers.h says it at length).
std::string peer_setups_html() {
  std::string out =
      "<p>How each peer is set up (the same problem, tolerance rtol = atol):</p>\n<ul>\n";
  for (verification::Peer p : verification::kPeers)
    out += "<li><b>" + escape(verification::to_string(p)) +
           "</b>: " + escape(verification::setup(p)) + "</li>\n";
  return out + "</ul>\n";
}
}  // namespace

std::string ratio_table_html(const SpeedSection& s) {
  std::vector<std::string> head = {"error of e at most", "ivv best [µs]", "ivv integrator"};
  for (verification::Peer p : verification::kPeers) {
    head.push_back(verification::to_string(p) + " [µs]");
    head.push_back("ratio");
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : s.ratios) {
    std::vector<std::string> row = {number(r.level), number(r.ivv_us, 3), escape(r.ivv_integrator)};
    for (std::size_t i = 0; i < r.peer_us.size(); ++i) {
      row.push_back(number(r.peer_us[i], 3));
      row.push_back(number(r.peer_ratio[i], 3));
    }
    rows.push_back(row);
  }
  return "<p>Paper scene, v<sub>0</sub> = 1 m/s, ζ = 0.1, elastoplastic: for each error level the "
         "fastest run of any ivv integrator whose relative error of e is within it, and the "
         "fastest run of each peer (same scene, same mp50 reference, same machine and run); "
         "ratio = peer time / ivv time (above 1: ivv is faster). NaN: no run reached the "
         "level.</p>\n" +
         table(head, rows, Source::timing()) + peer_setups_html();
}

}  // namespace ivv::reports
