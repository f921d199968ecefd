// Section 6 of the report: the published DEM benchmark of Chung & Ooi (2011), Granular
// Matter 13:643-656, normal-impact Tests 1 and 2 (reference_data/chung_ooi_2011.md).
//
// One table of the shipped scenes (reference_data/scenes/chung-ooi-*.toml) with their
// effective radius and mass and the Hertz closed form they are checked against (docs/design.md §2,
// oracles/hertz.h), and one table of the verification cases dem.<scene>.<integrator> that were
// run: largest error against that closed form per scene and integrator, and the verdict. The
// cases themselves are the registry's (verification/cases_dem.cc); nothing is rerun here.
#pragma once

#include <string>
#include <vector>

#include "verification/registry.h"

namespace ivv::reports {

// HTML of the section's body (the page gives it its heading). Scenes are loaded by name; a scene
// that cannot be loaded throws InputError (the report shows the section as failed).
std::string dem_benchmark_html(const std::vector<verification::CaseRecord>& records);

}  // namespace ivv::reports
