// Registration of the battery, one function per tier file.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "oracles/hertz.h"
#include "scene/scene.h"
#include "verification/registry.h"

namespace ivv::verification {

void register_analytic_cases(Registry& reg);
void register_cross_implementation_cases(Registry& reg);
void register_conservation_cases(Registry& reg);
void register_convergence_cases(Registry& reg);
void register_stability_cases(Registry& reg);
void register_published_trend_cases(Registry& reg);
void register_example_cases(Registry& reg);
void register_dem_cases(Registry& reg);
void register_structure_cases(Registry& reg);
void register_plate_cases(Registry& reg);         // cases_plate.cc: the finite plate
void register_plate_regime_cases(Registry& reg);  // which model a plate impact needs
void register_conformance_cases(Registry& reg);
void register_validation_cases(Registry& reg);

// A published DEM benchmark scene shipped in reference_data/scenes/ (cases_dem.cc).
struct DemBenchmarkScene {
  std::string_view scene;  // name for load_scene(), e.g. "chung-ooi-1-glass"
  std::string_view test;   // "Test 1"
  std::string_view what;   // one line for people
};
// Chung & Ooi (2011) normal-impact Tests 1 and 2; case ids are "dem.<scene>.<integrator>".
std::span<const DemBenchmarkScene> chung_ooi_scenes();

// The reference of the dem.<scene>.* cases: the shipped scene, its derived parameters and the
// Hertz closed form with the effective radius and mass (oracles/hertz.h; SI units). A study
// (verification/study.h): loaded and solved once, read by the cases and the report's DEM table.
struct DemReference {
  DemBenchmarkScene benchmark;
  Scene scene;
  DerivedParameters derived;
  oracles::HertzImpact closed_form;
};
const std::vector<DemReference>& chung_ooi_references();

}  // namespace ivv::verification
