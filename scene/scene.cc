// A scene's derived parameters (docs/design.md §1: E*, K_h, z_y, K_y, omega0, zeta, v_y, the
// normalisation of paper eq. 26) and the paper's Table 1 scene. Validation: scene_validation.cc;
// the TOML form: scene_toml.cc.
#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/input_error.h"

namespace ivv {

namespace {

// derive()'s parameters of the two bodies, which depend on neither the velocity nor the dashpot:
// R*, m*, E*, K_h and, with a yield strength, z_y, K_y, omega0, v_y. No dashpot (zeta 0, c inf).
DerivedParameters derive_bodies(const Scene& s) {
  DerivedParameters p;
  p.effective_radius =
      s.target_radius ? s.radius * *s.target_radius / (s.radius + *s.target_radius) : s.radius;
  p.effective_mass = s.target_mass ? s.mass * *s.target_mass / (s.mass + *s.target_mass) : s.mass;
  const double R = p.effective_radius, m = p.effective_mass;
  // a rigid target (E2 = inf) adds no compliance: (1 - nu2^2)/inf = 0
  const double compliance =
      (1.0 - s.impactor_poisson_ratio * s.impactor_poisson_ratio) / s.impactor_youngs_modulus +
      (1.0 - s.target_poisson_ratio * s.target_poisson_ratio) / s.target_youngs_modulus;
  p.E_star = 1.0 / compliance;                  // eq. 7
  p.K_h = 4.0 / 3.0 * std::sqrt(R) * p.E_star;  // eq. 6
  if (s.yield_strength) {
    const double Sy = *s.yield_strength;
    const double pi2 = std::numbers::pi * std::numbers::pi;
    p.z_y = 0.68 * Sy * Sy * pi2 * R / (p.E_star * p.E_star);  // eq. 11
    p.K_y = 1.5 * p.K_h * std::sqrt(p.z_y);                    // eq. 12
    p.omega0 = std::sqrt(p.K_y / m);                           // eq. 23
    p.v_yield = std::sqrt(4.0 * p.K_h * p.z_y * p.z_y * std::sqrt(p.z_y) / (5.0 * m));
  }
  return p;
}

// 2 c zeta = sqrt(m* K_y) [N s/m] (NaN without a yield strength).
double critical_damping(const DerivedParameters& p) {
  return std::sqrt(p.effective_mass * p.K_y);
}

// The dashpot of a damping ratio zeta > 0: c = sqrt(m* K_y)/(2 zeta).
void set_damping_ratio(DerivedParameters& p, double critical, double zeta) {
  p.zeta = zeta;
  p.c = critical / (2.0 * p.zeta);
}

}  // namespace

DerivedParameters derive(const Scene& s) {
  DerivedParameters p = derive_bodies(s);
  const double m = p.effective_mass;
  const double critical = critical_damping(p);
  switch (s.damping.kind) {
    case Damping::Kind::none:
      break;
    case Damping::Kind::ratio:  // validate() requires a yield strength for it
      set_damping_ratio(p, critical, s.damping.value);
      break;
    case Damping::Kind::coefficient:
      p.c = s.damping.value;
      p.zeta = critical / (2.0 * p.c);
      break;
    case Damping::Kind::zener_lambda:
      p.c = dashpot_for_zener_lambda(m, p.K_h, s.velocity, s.damping.value);
      p.zeta = critical / (2.0 * p.c);
      break;
    case Damping::Kind::structure:
      p.c =
          structure_dashpot(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio).c;
      p.zeta = critical / (2.0 * p.c);
      break;
  }
  p.zener_lambda = zener_lambda(m, p.K_h, s.velocity, p.c);
  return p;
}

VelocityDampingDerivation::VelocityDampingDerivation(const Scene& base)
    : bodies_(derive_bodies(base)),
      critical_(critical_damping(bodies_)),
      mass_stiffness_factor_(zener_mass_stiffness_factor(bodies_.effective_mass, bodies_.K_h)) {}

DerivedParameters VelocityDampingDerivation::at(double velocity_factor, double zeta) const {
  DerivedParameters p = bodies_;
  if (zeta > 0) set_damping_ratio(p, critical_, zeta);
  p.zener_lambda = zener_lambda_of_factors(mass_stiffness_factor_, velocity_factor, p.c);
  return p;
}

Scales scales(const Scene& s, const DerivedParameters& p, ScaleBasis basis) {
  const double m = p.effective_mass, v0 = s.velocity;
  double omega = 0.0;
  switch (basis) {
    case ScaleBasis::yield:
      if (!p.has_yield()) {
        throw InputError("target.yield_strength",
                         "missing: the yield-based scales (omega0 = sqrt(K_y/m)) need it");
      }
      omega = p.omega0;
      break;
    case ScaleBasis::hertz:
      omega = v0 / std::pow(5.0 * m * v0 * v0 / (4.0 * p.K_h), 0.4);  // v0/z_mH
      break;
  }
  Scales k;
  k.time = 1.0 / omega;
  k.length = v0 / omega;
  k.velocity = v0;
  k.force = m * v0 * omega;
  k.energy = m * v0 * v0;
  return k;
}

BodyVelocities body_velocities_after(const Scene& s, double w) {
  if (!s.target_mass) return {w, 0.0};
  const double m1 = s.mass, m2 = *s.target_mass;
  const double centre = m1 * s.velocity / (m1 + m2);  // unchanged by the contact
  return {centre + m2 / (m1 + m2) * w, centre - m1 / (m1 + m2) * w};
}

Scene paper_scene() {
  Scene s;
  s.name = "paper";
  s.mass = 0.5;
  s.radius = 0.010;
  s.impactor_youngs_modulus = 207e9;
  s.impactor_poisson_ratio = 0.3;
  s.target_youngs_modulus = 7.9e9;
  s.target_poisson_ratio = 0.3;
  s.yield_strength = 2.0 * 101e6;  // laminate: S_y = 2 S_u
  s.velocity = 1.0;
  return s;
}

}  // namespace ivv
