// Validation of a scene (docs/design.md §5, §6): the ranges of the inputs (validate) and of the
// derived parameters the integrators need (validate_derived). Each failure is one InputError
// naming the field and the accepted range.
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "scene/input_error.h"
#include "scene/scene.h"

namespace ivv {
namespace {

// Accepted ranges. They are wide on purpose (docs/design.md §6 asks for masses from 1e-6 to 1e3 kg
// and velocities from 1e-6 to beyond 100 m/s); they exclude only the physically meaningless.
void require_positive_finite(std::string_view field, double v, const char* unit) {
  if (std::isfinite(v) && v > 0.0) return;  // no string built on the hot path
  require(false, field, std::string("a finite number > 0 ") + unit, v);
}

void require_poisson(std::string_view field, double nu) {
  require(std::isfinite(nu) && nu > -1.0 && nu < 0.5, field, "a Poisson's ratio in (-1, 0.5)", nu);
}

// The target: a half-space or a free sphere, elastic or rigid, with or without a yield strength.
void validate_target(const Scene& s) {
  const double E2 = s.target_youngs_modulus;
  require(E2 > 0.0 && !std::isnan(E2), "target.youngs_modulus",
          "a number > 0 Pa (inf: a rigid target)", E2);
  require_poisson("target.poisson_ratio", s.target_poisson_ratio);
  if (s.yield_strength) {
    require_positive_finite("target.yield_strength", *s.yield_strength, "Pa");
  }
  if (s.target_radius.has_value() != s.target_mass.has_value()) {
    throw InputError(s.target_radius ? "target.mass" : "target.radius",
                     "a free target sphere needs both radius and mass (neither: a half-space)");
  }
  if (s.target_radius) require_positive_finite("target.radius", *s.target_radius, "m");
  if (s.target_mass) require_positive_finite("target.mass", *s.target_mass, "kg");
  if (s.damping.kind == Damping::Kind::ratio && !s.yield_strength) {
    throw InputError("damping.zeta",
                     "a damping ratio is defined with K_y = 1.5 K_h sqrt(z_y) and needs "
                     "target.yield_strength; give damping.c [N s/m] (--c) instead");
  }
}

}  // namespace

const char* damping_field(Damping::Kind kind) {
  switch (kind) {
    case Damping::Kind::none:
      return "";
    case Damping::Kind::ratio:
      return "damping.zeta";
    case Damping::Kind::coefficient:
      return "damping.c";
    case Damping::Kind::zener_lambda:
      return "damping.lambda";
    case Damping::Kind::structure:
      return "structure";
  }
  return "";
}

DerivedParameters validate_and_derive(const Scene& s) {
  require_positive_finite("impactor.mass", s.mass, "kg");
  require_positive_finite("impactor.radius", s.radius, "m");
  require_positive_finite("impactor.youngs_modulus", s.impactor_youngs_modulus, "Pa");
  require_poisson("impactor.poisson_ratio", s.impactor_poisson_ratio);
  validate_target(s);
  require_positive_finite("impact.velocity", s.velocity, "m/s");
  switch (s.damping.kind) {
    case Damping::Kind::none:
      break;
    case Damping::Kind::ratio:
      require_positive_finite("damping.zeta", s.damping.value, "(dimensionless)");
      break;
    case Damping::Kind::coefficient:
      require_positive_finite("damping.c", s.damping.value, "N s/m");
      break;
    case Damping::Kind::zener_lambda:
      require_positive_finite("damping.lambda", s.damping.value, "(dimensionless)");
      break;
    case Damping::Kind::structure:
      validate_structure(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio);
      break;
  }
  DerivedParameters p = derive(s);
  validate_derived(s, p);
  return p;
}

void validate(const Scene& s) {
  (void)validate_and_derive(s);
}

namespace {
// The damping input of a scene and its Table 1 value (the paper's c = 11440 N s/m; zeta 0.1;
// lambda 0.2398, that c at 1 m/s; a structure by its c).
std::pair<double, double> damping_input(const Scene& s) {
  switch (s.damping.kind) {
    case Damping::Kind::ratio:
      return {s.damping.value, 0.1};
    case Damping::Kind::zener_lambda:
      return {s.damping.value, 0.2398};
    case Damping::Kind::structure:
      return {
          structure_dashpot(s.damping.structure, s.target_youngs_modulus, s.target_poisson_ratio).c,
          11440.0};
    default:
      return {s.damping.value, 11440.0};
  }
}

// The InputError of a derived quantity `name` = `value` that is not a positive finite number:
// the field named is the input it depends on (bit i of `depends`: input i below) that lies
// farthest in decades from Table 1. Built only on failure: the reference scene and the
// message cost more than all the checks of a valid scene (the paper impact's validation was
// 1,200 instructions of its 22,000, callgrind).
[[noreturn]] void throw_unrepresentable(const Scene& s, const char* name, double value,
                                        unsigned depends) {
  const Scene ref = paper_scene();
  struct Input {
    const char* field;
    double value, reference;
  };
  const auto [damping_value, damping_ref] = damping_input(s);
  const std::array<Input, 7> inputs = {{
      {"impactor.mass", s.mass, ref.mass},
      {"impactor.radius", s.radius, ref.radius},
      {"impactor.youngs_modulus", s.impactor_youngs_modulus, ref.impactor_youngs_modulus},
      // a rigid target (inf) and an absent yield strength are never the culprit
      {"target.youngs_modulus",
       std::isfinite(s.target_youngs_modulus) ? s.target_youngs_modulus : ref.target_youngs_modulus,
       ref.target_youngs_modulus},
      {"target.yield_strength", s.yield_strength.value_or(*ref.yield_strength),
       *ref.yield_strength},
      {"impact.velocity", s.velocity, ref.velocity},
      {damping_field(s.damping.kind), damping_value, damping_ref},
  }};
  const Input* culprit = nullptr;
  double worst = -1.0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (!(depends & (1u << i)) || !(inputs[i].value > 0)) continue;
    const double decades = std::abs(std::log10(inputs[i].value / inputs[i].reference));
    if (decades > worst) {
      worst = decades;
      culprit = &inputs[i];
    }
  }
  std::ostringstream os;
  os.precision(6);
  os << "gives " << name << " = " << value
     << ", not a representable positive number (double covers about 1e-308 to 1e308); "
        "bring the scene's values nearer physical scales";
  throw InputError(culprit ? culprit->field : "scene", os.str());
}
}  // namespace

void validate_derived(const Scene& s, const DerivedParameters& p) {
  // bit i of `depends` set: input i of throw_unrepresentable enters the quantity
  auto check = [&](const char* name, double value, unsigned depends) {
    if (std::isfinite(value) && value > 0.0) return;
    throw_unrepresentable(s, name, value, depends);
  };
  constexpr unsigned moduli = 0b1100, stiffness = moduli | 0b0010, yield = stiffness | 0b10000;
  constexpr unsigned dynamic = yield | 0b0001;
  check("E*", p.E_star, moduli);
  check("K_h", p.K_h, stiffness);
  // a dashpot derived from lambda (m, K_h, v0) or from the structure (its own c) is checked
  // whether or not a yield strength exists
  if (s.damping.kind == Damping::Kind::zener_lambda)
    check("c", p.c, stiffness | 0b0001 | 0b100000 | 0b1000000);
  if (s.damping.kind == Damping::Kind::structure) check("c", p.c, 0b1000000);
  const bool yield_given = s.yield_strength.has_value();  // p.has_yield() is false for z_y = inf
  if (yield_given) {
    check("z_y", p.z_y, yield);
    check("K_y", p.K_y, yield);
    check("omega0", p.omega0, dynamic);
    check("v_y", p.v_yield, dynamic);
    if (p.has_dashpot()) {
      check("zeta", p.zeta, dynamic | 0b1000000);
      check("c", p.c, dynamic | 0b1000000);
    }
  }
  // the scales of every basis a law may use on this scene (scene/scene.h ScaleBasis)
  for (ScaleBasis basis : {ScaleBasis::hertz, ScaleBasis::yield}) {
    if (basis == ScaleBasis::yield && !yield_given) continue;
    const unsigned d = basis == ScaleBasis::yield ? dynamic : stiffness | 0b0001 | 0b100000;
    const unsigned sc = d | 0b100000;
    const Scales k = scales(s, p, basis);
    check("the time scale", k.time, d);
    check("the length scale", k.length, sc);
    check("the force scale", k.force, sc);
    check("the energy scale m v0^2", k.energy, sc);
    const double L15 = k.length * std::sqrt(k.length);  // L^1.5 without pow
    check("the spring energy scale K_h L^2.5", p.K_h * L15 * k.length, sc);
    check("the spring force scale K_h L^1.5 / F_scale", p.K_h * L15 / k.force, sc);
  }
}

}  // namespace ivv
