#include "reports/impact_text.h"

#include <iomanip>
#include <sstream>

#include "solver/infinite_plate_check.h"
#include "solver/plate/plate_modes.h"

namespace ivv {

namespace {

// The outcome of a run that separated or was captured.
void outcome_lines(std::ostream& out, const SimulationRequest& req, const ImpactResult& r,
                   const DerivedParameters& p) {
  out << std::setprecision(8);
  out << "  COR          e = " << r.e;
  if (r.status == ImpactStatus::captured) out << " (captured: e <= " << r.e_bound << ")";
  out << "  (Poisson " << r.e_poisson << ", energetic " << r.e_energetic << ")\n";
  out << std::setprecision(6);
  out << "  peak force   F_max = " << r.F_max << " N at t = " << r.t_F_max * 1e3 << " ms\n";
  if (r.status == ImpactStatus::captured)
    out << "  contact      never ends (captured: the impactor comes to rest on the target; "
           "capture established at t = "
        << r.t_capture * 1e3 << " ms)\n";
  else
    out << "  contact      t_contact = " << r.t_contact * 1e3 << " ms\n";
  out << "  deformation  z_max = " << r.z_max * 1e3 << " mm, alpha_max = " << r.alpha_max * 1e3
      << " mm, z_perm = " << r.z_perm * 1e3 << " mm\n";
  out << "  energy [J]   initial " << r.energy.initial << " = final " << r.energy.final
      << " + plastic " << r.energy.plastic << " + viscous " << r.energy.viscous;
  if (r.energy.stored > 0) out << " + stored " << r.energy.stored;
  out << " + residual " << r.energy.residual << "\n";
  out << "  impulse      " << r.impulse
      << " N s (m* v0 (1 + e) = " << p.effective_mass * req.scene.velocity * (1 + r.e) << ")\n";
  if (req.scene.free_target()) {
    out << "  after impact impactor " << r.impactor_velocity_after << " m/s, target "
        << r.target_velocity_after << " m/s (frame: target at rest before; + towards it)\n";
  }
  out << "  work         " << r.steps << " steps, " << r.rhs_evaluations << " RHS evaluations\n";
}

}  // namespace

std::string impact_summary(const SimulationRun& run) {
  const SimulationRequest& req = run.request;
  const ImpactResult& r = run.result;
  std::ostringstream out;
  const DerivedParameters p = derive(req.scene);
  out << std::setprecision(6);
  out << "scene " << req.scene.name << ", law " << to_string(req.law) << ", integrator "
      << to_string(req.integrator) << "\n";
  out << "  v0 = " << req.scene.velocity << " m/s";
  if (p.has_yield()) out << " (v_y = " << p.v_yield << " m/s)";
  out << ", ";
  if (p.has_dashpot() && p.has_yield())
    out << "zeta = " << p.zeta << " (c = " << p.c << " N s/m)\n";
  else if (p.has_dashpot())
    out << "c = " << p.c << " N s/m\n";
  else
    out << "no dashpot\n";
  if (p.has_dashpot() && req.law == LawKind::hertz)
    out << "  Zener's lambda = m*^(3/5) K_h^(2/5) v0^(1/5) / c = " << p.zener_lambda << "\n";
  out << "  status       " << to_string(r.status);
  if (r.failure != FailureKind::none) out << " (" << to_string(r.failure) << ")";
  if (!r.reason.empty()) out << ": " << r.reason;
  out << "\n";
  if (r.ok()) outcome_lines(out, req, r, p);
  for (const std::string& w : infinite_plate_warnings(req.scene, r))
    out << "  warning      " << w << "\n";
  if (run.choice && req.model == ModelKind::automatic)
    out << "  model        " << run.choice->brief() << "; --model full to integrate always\n";
  return out.str();
}

std::string dashpot_text(const Scene& s, const DerivedParameters& p) {
  std::ostringstream os;
  os.precision(6);
  if (s.damping.kind == Damping::Kind::structure) {
    const Structure& st = s.damping.structure;
    const StructureDashpot d =
        structure_dashpot(st, s.target_youngs_modulus, s.target_poisson_ratio);
    os << "structure " << structure_kind_name(st.kind) << ", rho = " << st.density << " kg/m^3";
    if (st.has_plate()) os << ", h = " << st.thickness << " m";
    if (st.has_bar()) os << ", A = " << st.area << " m^2";
    os << "\n";
    if (st.has_plate()) {
      os << "  D       = " << d.bending_stiffness << " N m"
         << (d.bending_stiffness_given ? "  (bending_stiffness, given)"
                                       : "  = E h^3/(12 (1 - nu^2))")
         << "\n"
         << "  c_plate = " << d.c_plate << " N s/m  = 8 sqrt(rho h D)\n";
    }
    if (st.has_bar()) os << "  c_bar   = " << d.c_bar << " N s/m  = A sqrt(E rho)\n";
    if (st.has_plate() && st.has_bar())
      os << "  c       = " << d.c << " N s/m  (series: 1/c = 1/c_plate + 1/c_bar)\n";
  }
  if (!p.has_dashpot()) {
    os << "  no dashpot (c = inf, zeta = 0)\n";
    return os.str();
  }
  os << "  c      = " << p.c << " N s/m";
  switch (s.damping.kind) {
    case Damping::Kind::ratio:
      os << "  = sqrt(m K_y)/(2 zeta)";
      break;
    case Damping::Kind::zener_lambda:
      os << "  = m^{3/5} K_h^{2/5} v0^{1/5}/lambda";
      break;
    case Damping::Kind::structure:
      os << "  (from the structure)";
      break;
    default:
      break;
  }
  os << "\n";
  if (p.has_yield()) os << "  zeta   = " << p.zeta << "  = sqrt(m K_y)/(2 c)\n";
  os << "  lambda = " << p.zener_lambda << "  = m^{3/5} K_h^{2/5} v0^{1/5}/c (Zener 1941)\n";
  return os.str();
}

std::string scene_summary(const Scene& s) {
  const DerivedParameters p = derive(s);
  std::ostringstream out;
  out << std::setprecision(6) << "scene " << s.name << "\n"
      << "  impactor  m = " << s.mass << " kg, R = " << s.radius
      << " m, E1 = " << s.impactor_youngs_modulus << " Pa, nu1 = " << s.impactor_poisson_ratio
      << "\n";
  out << "  target    ";
  if (s.free_target())
    out << "free sphere m2 = " << *s.target_mass << " kg, R2 = " << *s.target_radius << " m, ";
  else
    out << "half-space, ";
  if (s.rigid_target())
    out << "rigid target (E2 = inf)";
  else
    out << "E2 = " << s.target_youngs_modulus << " Pa, nu2 = " << s.target_poisson_ratio;
  if (s.yield_strength)
    out << ", S_y = " << *s.yield_strength << " Pa\n";
  else
    out << ", no yield strength (laws without yield only: hertz, hunt-crossley)\n";
  out << "  impact    v0 = " << s.velocity << " m/s"
      << (s.free_target() ? " (relative approach speed)" : "") << "\n"
      << "derived\n"
      << "  R*     = " << p.effective_radius << " m\n"
      << "  m*     = " << p.effective_mass << " kg\n"
      << "  E*     = " << p.E_star << " Pa" << (s.rigid_target() ? " (rigid target)" : "") << "\n"
      << "  K_h    = " << p.K_h << " N/m^1.5\n";
  if (p.has_yield()) {
    out << "  z_y    = " << p.z_y << " m\n"
        << "  K_y    = " << p.K_y << " N/m\n"
        << "  omega0 = " << p.omega0 << " rad/s\n"
        << "  v_y    = " << p.v_yield << " m/s\n";
  }
  out << dashpot_text(s, p) << finite_plate_text(s);
  return out.str();
}

// The model the impact needs (solver/plate/plate_regime.h), and the answer it gives.
std::string plate_regime_text(const PlateRun& run) {
  const PlateRegime& g = *run.regime;
  const PlateModelOutcome& a = *run.answer();
  std::ostringstream out;
  out.precision(6);
  out << "  regime       " << g.regime << " (the cheapest model within " << g.tolerance
      << " of the full plate in e and F_max); mass ratio " << g.mass_ratio << ", wave return "
      << g.wave_return_time << " s against contact " << g.contact_time << " s, relative stiffness "
      << g.relative_stiffness << "\n               infinite plate: zeta " << g.zeta_plate
      << ", Zener lambda " << g.zener_lambda << ", c = " << g.c_plate << " N s/m\n";
  for (const PlateModelOutcome& m : g.models) {
    out << "    " << std::left << std::setw(16) << to_string(m.model);
    if (!m.ok) {
      out << "failed: " << m.reason << "\n";
      continue;
    }
    out << "e = " << std::setw(12) << m.e << " F_max = " << std::setw(12) << m.F_max
        << " N  t_contact = " << std::setw(12) << m.t_contact << " s";
    if (m.model != PlateModel::full) out << "  error " << m.error;
    out << "\n";
  }
  out << "  published    Olsson's mass criterion: " << g.olsson << "\n"
      << "  answer       " << to_string(a.model) << (run.forced ? " (as asked by --model)" : "")
      << ": e = " << a.e << ", F_max = " << a.F_max << " N, t_contact = " << a.t_contact
      << " s, estimated error " << run.estimated_error() << "\n";
  return out.str();
}

std::string plate_impact_summary(const PlateRun& run) {
  const PlateImpactResult& r = run.result;
  std::ostringstream out;
  out.precision(8);
  out << "finite plate  " << run.scene.name << ", law " << to_string(run.law)
      << (run.law == LawKind::expression ? " F = " + run.expression.force : std::string())
      << (run.expression.unload.empty() ? std::string()
                                        : ", unloading F = " + run.expression.unload)
      << ", v0 = " << run.scene.velocity << " m/s, " << r.mode_count << " modes below "
      << r.omega_cut << " rad/s, C_res = " << r.residual_compliance
      << " of C_static = " << r.static_compliance << " m/N\n";
  if (!r.ok) {
    out << "  status       failed: " << r.reason << "\n";
    return out.str();
  }
  out << "  COR          e = " << r.e
      << " (once no further contact is possible), e_first = " << r.e_first
      << " (at the first separation)\n"
      << "  truncation   cut-off " << r.cutoff << ", e at cut-off " << r.cutoff_coarser << " "
      << run.e_half_cutoff << ": the modes left out cost about " << run.truncation_error
      << " in e (tolerance " << run.options.truncation_tol << ")\n"
      << "  stepper      " << plate_stepper_name(run.options.stepper) << " at rtol "
      << run.options.rtol << ", " << r.steps << " steps\n"
      << "  contacts     " << r.contacts.size() << ", F_max = " << r.F_max
      << " N, t_contact = " << r.t_contact << " s (the first contact)\n";
  for (std::size_t i = 0; i < r.contacts.size() && i < 20; ++i) {
    const PlateContact& c = r.contacts[i];
    out << "    " << i + 1 << ": t = " << c.t_start << " ... " << c.t_end << " s, impulse "
        << c.impulse << " N s, peak " << c.peak_force << " N\n";
  }
  if (r.contacts.size() > 20) out << "    ... (" << r.contacts.size() - 20 << " more)\n";
  out << "  energy       (1/2) m v0^2 = " << r.energy.initial << " J = kinetic " << r.energy.kinetic
      << " + plate " << r.energy.plate << " + plastic " << r.energy.plastic << " J (ledger within "
      << r.energy.max_error << " over " << r.energy.checks << " checks)\n"
      << "  impulse      " << r.impulse << " N s = m (v0 - v_final); plate excursion bound "
      << r.excursion_bound << " m at t = " << r.t_end << " s\n";
  if (run.regime) out << plate_regime_text(run);
  return out.str();
}

std::string finite_plate_text(const Scene& s) {
  if (s.damping.kind != Damping::Kind::structure || !s.damping.structure.finite_plate()) return "";
  const FinitePlate p =
      finite_plate(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio);
  std::ostringstream os;
  os.precision(6);
  os << "finite plate " << p.length_x << " x " << p.length_y << " x " << p.thickness
     << " m, simply supported, struck at (" << p.impact_x << ", " << p.impact_y << ") m\n"
     << "  D11, D22, D12, D66 = " << p.bending.D11 << ", " << p.bending.D22 << ", " << p.bending.D12
     << ", " << p.bending.D66 << " N m"
     << (p.orthotropic_given ? " (given)" : " (isotropic from E, nu)") << "\n"
     << "  plate mass = " << p.mass() << " kg, impactor/plate = " << s.mass / p.mass() << "\n"
     << "  omega_11 = " << plate_mode_frequency(p, 1, 1)
     << " rad/s, C_static = " << plate_static_compliance(p).value << " m/N under the impactor\n"
     << "  (a finite plate has no dashpot: c above is the infinite plate's, for comparison)\n";
  return os.str();
}

}  // namespace ivv
