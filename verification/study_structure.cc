#include "verification/study_structure.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "oracles/zener.h"
#include "solver/sweep/sweep.h"
#include "verification/study.h"
#include "verification/study_restitution.h"
#include "verification/support.h"

namespace ivv::verification {

Scene steel_ball_on_plate() {
  Scene s;
  s.name = "steel-ball-on-steel-plate";
  s.radius = 0.005;
  s.mass = 7960.0 * 4.0 / 3.0 * std::numbers::pi * s.radius * s.radius * s.radius;
  s.impactor_youngs_modulus = 207e9;
  s.impactor_poisson_ratio = 0.3;
  s.target_youngs_modulus = 207e9;
  s.target_poisson_ratio = 0.3;
  s.velocity = 1.0;
  return s;
}

Ply paper_ply() {
  return {120e9, 7.9e9, 5.5e9, 0.3};
}
std::vector<int> paper_stacking() {
  return {0, 90, 0, 90, 0, 0, 90, 0, 90, 0};
}

Scene paper_on_laminate_plate(double h, double v0) {
  Scene s = paper_scene();
  s.velocity = v0;
  Structure plate;
  plate.kind = Structure::Kind::plate;
  plate.density = kPaperLaminateDensity;
  plate.thickness = h;
  plate.bending_stiffness = laminate_bending_stiffness(paper_ply(), paper_stacking(), h).D_star;
  s.damping = Damping::from_structure(plate);
  return s;
}

ZenerPoint zener_units(const Scene& s, const ImpactResult& r) {
  const DerivedParameters p = derive(s);
  const double z = zener_length(p.effective_mass, p.K_h, s.velocity);
  ZenerPoint out;
  out.lambda = p.zener_lambda;
  out.e = r.e;
  out.e_bound = r.e_bound;
  out.separated = r.separated();
  out.contact_time = r.t_contact * s.velocity / z;
  out.peak_force = r.F_max / (p.K_h * z * std::sqrt(z));
  out.steps = r.steps;
  return out;
}

namespace {

ImpactResult run(const SimulationRequest& req, const std::string& what) {
  const ImpactResult r = simulate(req);
  if (!r.ok()) throw std::runtime_error(what + ": " + r.reason);
  return r;
}

ZenerPoint trend_zener_point(double lambda) {
  Scene s = steel_ball_on_plate();
  s.damping = Damping::zener(lambda);
  return zener_units(
      s, run(trend_request(s, LawKind::hertz), "Zener impact at lambda = " + fmt(lambda)));
}

// Four unlike scenes (synthetic: chosen to span m, R, E*, plate h and rho, v0 by decades; not
// measured data), each on a plate whose thickness gives `lambda`.
std::vector<SimilarityPoint> similarity_set(double lambda) {
  struct Spec {
    const char* label;
    double mass, radius, E1, nu1, E2, nu2, rho, v0;
  };
  const double ball3 = 2700.0 * 4.0 / 3.0 * std::numbers::pi * 27e-9;  // R = 3 mm aluminium
  const Spec specs[] = {
      {"steel ball R 5 mm on a steel plate, 1 m/s", steel_ball_on_plate().mass, 0.005, 207e9, 0.3,
       207e9, 0.3, 7960.0, 1.0},
      {"0.5 kg steel R 10 mm on a 7.9 GPa plate (rho 1580), 2 m/s", 0.5, 0.010, 207e9, 0.3, 7.9e9,
       0.3, 1580.0, 2.0},
      {"aluminium ball R 3 mm on an aluminium plate, 0.3 m/s", ball3, 0.003, 70e9, 0.33, 70e9, 0.33,
       2700.0, 0.3},
      {"5 kg steel R 50 mm on a 70 GPa plate (nu 0.22, rho 2500), 10 m/s", 5.0, 0.050, 207e9, 0.3,
       70e9, 0.22, 2500.0, 10.0},
  };
  std::vector<SimilarityPoint> out;
  for (const Spec& sp : specs) {
    SimilarityPoint pt;
    pt.label = sp.label;
    Scene s;
    s.name = sp.label;
    s.mass = sp.mass;
    s.radius = sp.radius;
    s.impactor_youngs_modulus = sp.E1;
    s.impactor_poisson_ratio = sp.nu1;
    s.target_youngs_modulus = sp.E2;
    s.target_poisson_ratio = sp.nu2;
    s.velocity = sp.v0;
    const DerivedParameters p = derive(s);
    pt.E_star = p.E_star;
    pt.K_h = p.K_h;
    const double c = dashpot_for_zener_lambda(s.mass, p.K_h, s.velocity, lambda);
    Structure plate;
    plate.density = sp.rho;
    plate.thickness =
        plate_thickness_for_dashpot(c, sp.rho, sp.E2 / (12.0 * (1.0 - sp.nu2 * sp.nu2)));
    pt.thickness = plate.thickness;
    s.damping = Damping::from_structure(plate);
    validate(s);
    pt.scene = s;
    pt.point = zener_units(s, run(trend_request(s, LawKind::hertz), sp.label));
    out.push_back(pt);
  }
  return out;
}

void compute_zener(StructureStudy& st) {
  for (double lambda : log_grid(1e-3, 10.0, 41)) st.curve.push_back(trend_zener_point(lambda));
  st.slope_quadrature = oracles::zener_small_lambda_slope();
  for (double lambda : {1e-3, 2e-3, 4e-3}) st.small.push_back(trend_zener_point(lambda));
  auto g = [&](int i) { return (1.0 - st.small[i].e) / st.small[i].lambda; };
  st.slope_richardson = 2.0 * g(0) - g(1);
  st.slope_richardson_next = 2.0 * g(1) - g(2);
  for (double lambda : {0.1, 0.5, 1.0}) {
    st.checked.push_back(trend_zener_point(lambda));
    st.series_solution.push_back(oracles::zener_impact(lambda));
  }
  st.similarity = similarity_set(0.5);
}

double laminate_cor(double h, double v0) {
  SimulationRequest req;
  req.scene = paper_on_laminate_plate(h, v0);
  req.law = LawKind::elastoplastic;
  req.auto_integrator = true;
  req.options.rtol = 1e-10;
  const ImpactResult r =
      run(req, "paper impactor on a " + fmt(h * 1e3, 3) + " mm plate at " + fmt(v0) + " m/s");
  return r.separated() ? r.e : 0.0;
}

void compute_laminate(StructureStudy& st) {
  st.ply = paper_ply();
  st.stacking = paper_stacking();
  st.density = kPaperLaminateDensity;
  st.d_star_per_h3 = laminate_bending_stiffness(st.ply, st.stacking, 1.0).D_star;
  const DerivedParameters paper = derive(paper_scene());
  const double c_paper = std::sqrt(paper_scene().mass * paper.K_y) / (2.0 * 0.1);  // zeta = 0.1
  st.thickness_for_paper_zeta = plate_thickness_for_dashpot(c_paper, st.density, st.d_star_per_h3);
  st.zeta_at_that_thickness =
      derive(paper_on_laminate_plate(st.thickness_for_paper_zeta, 1.0)).zeta;
  std::vector<double> hs = log_grid(1e-3, 5e-2, 25);
  hs.push_back(st.thickness_for_paper_zeta);
  std::sort(hs.begin(), hs.end());
  for (double h : hs) {
    ThicknessRow row;
    row.thickness = h;
    const DerivedParameters p = derive(paper_on_laminate_plate(h, 1.0));
    row.D_star = st.d_star_per_h3 * h * h * h;
    row.c = p.c;
    row.zeta = p.zeta;
    row.e_1 = laminate_cor(h, 1.0);
    row.e_5 = laminate_cor(h, 5.0);
    st.thickness_rows.push_back(row);
  }
}

StructureStudy compute_structure_study() {
  StructureStudy st;
  compute_zener(st);
  compute_laminate(st);
  return st;
}

}  // namespace

ZenerPoint zener_point(double lambda, IntegratorKind integrator) {
  Scene s = steel_ball_on_plate();
  s.damping = Damping::zener(lambda);
  return zener_units(
      s, run(request(s, LawKind::hertz, integrator), "Zener impact at lambda = " + fmt(lambda)));
}

const StructureStudy& structure_study() {
  static const Study<StructureStudy> study("damping from the structure", compute_structure_study);
  return study.get();
}

}  // namespace ivv::verification
