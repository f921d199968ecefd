#include "reports/dem_benchmark.h"

#include <map>

#include "reports/html.h"
#include "solver/steppers/integrators.h"
#include "verification/cases.h"

namespace ivv::reports {

std::string dem_benchmark_html(const std::vector<verification::CaseRecord>& records) {
  std::string out =
      "<p>The elastic normal-impact tests of Y. C. Chung and J. Y. Ooi, <i>Benchmark tests for "
      "verifying discrete element modelling codes at particle impact level</i>, Granular Matter "
      "13 (2011) 643–656, as shipped scenes (<code>--scene NAME --law hertz</code>). Test 1: two "
      "identical free spheres (effective radius R* = R/2, effective mass m* = m/2; v<sub>0</sub> "
      "is the relative approach speed). Test 2: a sphere on a rigid plane (E* = "
      "E<sub>1</sub>/(1 − ν<sub>1</sub>²)). The reference is the Hertz closed form "
      "(z<sub>m</sub> = (5m*v<sub>0</sub>²/(4K<sub>h</sub>))<sup>2/5</sup>, F<sub>max</sub> = "
      "K<sub>h</sub>z<sub>m</sub><sup>3/2</sup>, t<sub>f</sub> = 2.9432752 z<sub>m</sub>/"
      "v<sub>0</sub>, e = 1), not numbers read from the paper; see "
      "<code>reference_data/chung_ooi_2011.md</code>.</p>\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& ref : verification::chung_ooi_references()) {
    const auto& t = ref.benchmark;
    const Scene& s = ref.scene;
    const DerivedParameters& p = ref.derived;
    const oracles::HertzImpact& x = ref.closed_form;
    rows.push_back({"<code>" + escape(t.scene) + "</code>", escape(t.test), escape(t.what),
                    number(p.effective_radius, 4), number(p.effective_mass, 6),
                    number(p.E_star / 1e9, 5), number(s.velocity, 4), number(x.z_max * 1e3, 6),
                    number(x.F_max / 1e3, 6), number(x.t_contact * 1e6, 6)});
  }
  out += table({"scene", "test", "what", "R* [m]", "m* [kg]", "E* [GPa]", "v<sub>0</sub> [m/s]",
                "z<sub>m</sub> [mm]", "F<sub>max</sub> [kN]", "t<sub>f</sub> [µs]"},
               rows, Source::from_cases({"dem.chung-ooi-1-*", "dem.chung-ooi-2-*"}));

  // cases dem.<scene>.<integrator> that were run, by scene then integrator
  std::map<std::string, std::map<std::string, const verification::CaseRecord*>> run;
  for (const auto& r : records) {
    for (const auto& t : verification::chung_ooi_scenes()) {
      const std::string prefix = "dem." + std::string(t.scene) + ".";
      if (r.c->id.starts_with(prefix))
        run[std::string(t.scene)][r.c->id.substr(prefix.size())] = &r;
    }
  }
  if (run.empty()) return out + "<p>No <code>dem.chung-ooi-*</code> case was run.</p>\n";
  std::vector<std::string> header = {"scene"};
  for (IntegratorKind k : all_integrators()) header.push_back(escape(to_string(k)));
  rows.clear();
  for (const auto& t : verification::chung_ooi_scenes()) {
    std::vector<std::string> row = {"<code>" + escape(t.scene) + "</code>"};
    for (IntegratorKind k : all_integrators()) {
      const auto& cases = run[std::string(t.scene)];
      const auto it = cases.find(std::string(to_string(k)));
      if (it == cases.end()) {
        row.push_back("—");
        continue;
      }
      const auto& o = it->second->outcome;
      row.push_back(
          "<a href=\"#case-" + slug(it->second->c->id) + "\">" + number(o.measured, 2) + "</a> " +
          (o.passed ? "<span class=\"pass\">pass</span>" : "<span class=\"fail\">FAIL</span>"));
    }
    rows.push_back(row);
  }
  out +=
      "<p>Largest error per case over maximum overlap, peak force, contact time (relative), e "
      "and, for Test 1, both bodies' velocities after impact (absolute, in units of "
      "v<sub>0</sub>), against each integrator's default-settings tolerance (1e-7; mp50 1e-12; "
      "reasons in section 4). The runs are normalised with the Hertz scales of each scene, so "
      "the same integrator makes the same normalised error in all four.</p>\n";
  out += table(header, rows, Source::rows_are_cases());
  return out;
}

}  // namespace ivv::reports
