#include "verification/support.h"

#include <future>
#include <iomanip>
#include <map>
#include <mutex>
#include <stdexcept>

namespace ivv::verification {

Scene with(Scene s, double v0, double zeta) {
  s.velocity = v0;
  s.damping = zeta > 0 ? Damping::ratio(zeta) : Damping::none();
  return s;
}

std::vector<GridScene> paper_grid() {
  std::vector<GridScene> g;
  for (double v0 : {0.1, 1.0, 5.0})
    for (double zeta : {0.0, 0.05, 0.1, 0.3})
      g.push_back(
          {"paper v0=" + fmt(v0, 3) + " zeta=" + fmt(zeta, 3), with(paper_scene(), v0, zeta)});
  return g;
}

// Steel sphere, 5 mm radius, on 6061 aluminium: E2 = 69 GPa, nu2 = 0.33, S_y = 276 MPa.
Scene steel_on_aluminium() {
  Scene s = paper_scene();
  s.name = "steel-on-aluminium";
  s.radius = 0.005;
  s.mass = 4.0 / 3.0 * 3.141592653589793 * 0.005 * 0.005 * 0.005 * 7960;  // ~4.2 g
  s.target_youngs_modulus = 69e9;
  s.target_poisson_ratio = 0.33;
  s.yield_strength = 276e6;
  return s;
}

// Steel on mild steel: E2 = 207 GPa, S_y = 250 MPa (a stiff, low-yield-deformation pair).
Scene steel_on_steel() {
  Scene s = paper_scene();
  s.name = "steel-on-steel";
  s.target_youngs_modulus = 207e9;
  s.target_poisson_ratio = 0.3;
  s.yield_strength = 250e6;
  return s;
}

std::vector<GridScene> extended_grid() {
  std::vector<GridScene> g;
  for (const Scene& base : {steel_on_aluminium(), steel_on_steel()}) {
    const double vy = derive(base).v_yield;
    for (double ratio : {0.5, 10.0, 300.0})
      for (double zeta : {0.0, 0.1})
        g.push_back({base.name + " v0=" + fmt(ratio, 3) + "v_y zeta=" + fmt(zeta, 2),
                     with(base, ratio * vy, zeta)});
  }
  for (double mass : {1e-3, 10.0}) {
    Scene s = paper_scene();
    s.mass = mass;
    for (double v0 : {0.1, 5.0})
      g.push_back(
          {"paper m=" + fmt(mass, 3) + "kg v0=" + fmt(v0, 3) + " zeta=0.1", with(s, v0, 0.1)});
  }
  return g;
}

SimulationRequest request(const Scene& s, LawKind law, IntegratorKind integrator, double hc_mu) {
  SimulationRequest r;
  r.scene = s;
  r.law = law;
  r.integrator = integrator;
  if (law == LawKind::hunt_crossley) {
    r.scene.damping = Damping::none();
    r.parameters["mu"] = hc_mu;
  }
  return r;
}

namespace {
std::string parameters_key(const LawParameters& params) {
  std::ostringstream os;
  os << std::setprecision(17);
  for (const auto& [name, value] : params) os << name << '=' << value << ';';
  return os.str();
}

std::string key(const SimulationRequest& r) {
  std::ostringstream os;
  os << std::setprecision(17) << r.scene.mass << ' ' << r.scene.radius << ' '
     << r.scene.impactor_youngs_modulus << ' ' << r.scene.impactor_poisson_ratio << ' '
     << r.scene.target_youngs_modulus << ' ' << r.scene.target_poisson_ratio << ' '
     << r.scene.yield_strength.value_or(-1) << ' ' << r.scene.target_radius.value_or(-1) << ' '
     << r.scene.target_mass.value_or(-1) << ' ' << static_cast<int>(r.scene.damping.kind) << ' '
     << r.scene.damping.value << ' ' << r.scene.velocity << ' ' << static_cast<int>(r.law) << ' '
     << parameters_key(r.parameters) << ' ' << r.expression.force << ' ' << r.expression.unload
     << ' ' << r.expression.allow_tension;
  if (r.scene.damping.kind == Damping::Kind::structure) {  // the structure's inputs, all of them
    const Structure& st = r.scene.damping.structure;
    os << ' ' << static_cast<int>(st.kind) << ' ' << st.density << ' ' << st.thickness << ' '
       << st.area << ' ' << st.bending_stiffness.value_or(-1) << ' '
       << st.youngs_modulus.value_or(-1) << ' ' << st.poisson_ratio.value_or(-1);
  }
  return os.str();
}
}  // namespace

const ImpactResult& reference(const SimulationRequest& req) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_future<ImpactResult>> cache;
  std::shared_future<ImpactResult> f;
  std::promise<ImpactResult> promise;
  bool compute = false;
  {
    std::lock_guard lock(mutex);
    auto it = cache.find(key(req));
    if (it == cache.end()) {
      f = promise.get_future().share();
      cache.emplace(key(req), f);
      compute = true;
    } else {
      f = it->second;
    }
  }
  if (compute) {
    SimulationRequest r = req;
    r.integrator = IntegratorKind::mp50;
    try {
      promise.set_value(simulate(r));
    } catch (...) {
      promise.set_exception(std::current_exception());
    }
  }
  const ImpactResult& ref = f.get();
  if (!ref.ok()) throw std::runtime_error("the 50-digit reference failed: " + ref.reason);
  return ref;
}

double relative_error(double value, double ref) {
  if (value == ref) return 0.0;
  return std::abs(value - ref) / std::abs(ref);
}

void WorstError::add(double value, double ref, const std::string& where) {
  ++count_;
  const double err = relative_error(value, ref);
  if (!(err <= worst_)) {  // also catches NaN
    worst_ = std::isnan(err) ? std::numeric_limits<double>::infinity() : err;
    where_ = where + " (" + fmt(value, 12) + " vs " + fmt(ref, 12) + ")";
  }
}

void WorstError::add_cor(double value, double ref, const std::string& where) {
  ++count_;
  const double err = std::abs(value - ref);
  if (!(err <= worst_)) {
    worst_ = std::isnan(err) ? std::numeric_limits<double>::infinity() : err;
    where_ = where + " (" + fmt(value, 12) + " vs " + fmt(ref, 12) + ", |difference|)";
  }
}

void WorstError::fail(const std::string& why) {
  if (!failed_) failure_ = why;
  failed_ = true;
}

Outcome worst_case(const WorstError& w, double tolerance, const std::string& what) {
  Outcome o = at_most(w.value(), tolerance,
                      "largest error (relative; e: absolute, in units of v0) of " + what +
                          " over " + std::to_string(w.count()) +
                          " comparisons: " + fmt(w.value(), 3) + " at " + w.where());
  return o;
}

}  // namespace ivv::verification
