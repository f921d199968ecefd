#include "scene/structure.h"

#include <cmath>
#include <stdexcept>

#include "scene/input_error.h"

namespace ivv {

std::string_view structure_kind_name(Structure::Kind kind) {
  switch (kind) {
    case Structure::Kind::plate:
      return "plate";
    case Structure::Kind::bar:
      return "bar";
    case Structure::Kind::plate_and_bar:
      return "plate+bar";
  }
  return "?";
}

std::optional<Structure::Kind> structure_kind_from_name(std::string_view name) {
  for (auto k : {Structure::Kind::plate, Structure::Kind::bar, Structure::Kind::plate_and_bar}) {
    if (structure_kind_name(k) == name) return k;
  }
  return std::nullopt;
}

std::optional<PlateEdges> plate_edges_from_name(std::string_view name) {
  if (name == plate_edges_name(PlateEdges::simply_supported)) return PlateEdges::simply_supported;
  return std::nullopt;
}

std::string_view plate_edges_name(PlateEdges edges) {
  switch (edges) {
    case PlateEdges::simply_supported:
      return "simply-supported";
  }
  return "?";
}

std::string_view dropped_modes_name(DroppedModes dropped) {
  switch (dropped) {
    case DroppedModes::static_compliance:
      return "static-compliance";
    case DroppedModes::oscillator:
      return "oscillator";
    case DroppedModes::truncated:
      return "truncated";
  }
  return "?";
}

std::optional<DroppedModes> dropped_modes_from_name(std::string_view name) {
  for (DroppedModes d :
       {DroppedModes::static_compliance, DroppedModes::oscillator, DroppedModes::truncated})
    if (name == dropped_modes_name(d)) return d;
  return std::nullopt;
}

double olsson_bending_stiffness(const OrthotropicBending& d) {
  const double root = std::sqrt(d.D11 * d.D22);
  const double A = (d.D12 + 2.0 * d.D66) / root;
  return std::sqrt(d.D11 * d.D22 * (A + 1.0) / 2.0);
}

FinitePlate finite_plate(const Structure& s, double target_E, double target_nu) {
  if (!s.has_plate() || !s.length_x || !s.length_y)
    throw std::logic_error("finite_plate: the structure has no finite plate");
  FinitePlate p;
  p.length_x = *s.length_x;
  p.length_y = *s.length_y;
  p.thickness = s.thickness;
  p.density = s.density;
  p.impact_x = s.impact_x.value_or(p.length_x / 2.0);
  p.impact_y = s.impact_y.value_or(p.length_y / 2.0);
  p.orthotropic_given = s.bending.has_value();
  if (s.bending) {
    p.bending = *s.bending;
  } else {
    const double nu = s.poisson_ratio.value_or(target_nu);
    const double D = s.bending_stiffness.value_or(
        plate_bending_stiffness(s.youngs_modulus.value_or(target_E), nu, s.thickness));
    p.bending = {D, D, nu * D, (1.0 - nu) * D / 2.0};
  }
  return p;
}

double plate_bending_stiffness(double E, double nu, double h) {
  return E * h * h * h / (12.0 * (1.0 - nu * nu));
}

double plate_dashpot(double rho, double h, double D) {
  return 8.0 * std::sqrt(rho * h * D);
}

double bar_dashpot(double A, double E, double rho) {
  return A * std::sqrt(E * rho);
}

double series_dashpot(double c1, double c2) {
  if (std::isinf(c1)) return c2;
  if (std::isinf(c2)) return c1;
  return c1 * c2 / (c1 + c2);
}

namespace {

void require_positive_finite(std::string_view field, double v, const char* unit) {
  require(std::isfinite(v) && v > 0.0, field, std::string("a finite number > 0 ") + unit, v);
}

// Keys that a kind does not use are bad input, not silently ignored.
void reject_unused(const Structure& s) {
  const std::string kind(structure_kind_name(s.kind));
  auto refuse = [&](const char* field, const char* why) {
    throw InputError(std::string("structure.") + field,
                     "not used by kind = \"" + kind + "\" (" + why + ")");
  };
  if (!s.has_bar() && s.area != 0.0) refuse("area", "a plate's dashpot is 8 sqrt(rho h D)");
  if (!s.has_plate()) {
    if (s.thickness != 0.0) refuse("thickness", "a bar's dashpot is A sqrt(E rho)");
    if (s.bending_stiffness) refuse("bending_stiffness", "a bar's dashpot is A sqrt(E rho)");
    if (s.poisson_ratio) refuse("poisson_ratio", "a bar's dashpot is A sqrt(E rho)");
  }
  if (s.bending_stiffness && s.poisson_ratio)
    refuse("poisson_ratio", "bending_stiffness is given: D* is used as it is");
  if (s.kind == Structure::Kind::plate && s.bending_stiffness && s.youngs_modulus)
    refuse("youngs_modulus", "bending_stiffness is given: D* is used as it is");
}

// D11..D66 positive definite for a specially orthotropic plate: D11 > 0, D22 > 0, D66 > 0 and
// D11 D22 > D12^2 (the bending strain energy is then positive for every curvature).
void validate_orthotropic(const Structure& s) {
  const OrthotropicBending& d = *s.bending;
  require_positive_finite("structure.D11", d.D11, "N m");
  require_positive_finite("structure.D22", d.D22, "N m");
  require_positive_finite("structure.D66", d.D66, "N m");
  require(std::isfinite(d.D12) && d.D12 * d.D12 < d.D11 * d.D22, "structure.D12",
          "a finite number with D12^2 < D11 D22 (positive definite bending stiffness)", d.D12);
  if (s.bending_stiffness)
    throw InputError("structure.bending_stiffness",
                     "not with D11, D22, D12, D66: the plate's stiffness is given twice (the "
                     "infinite plate's D* is Olsson's sqrt(D11 D22 (A + 1)/2) of them)");
  if (s.youngs_modulus || s.poisson_ratio)
    throw InputError(s.youngs_modulus ? "structure.youngs_modulus" : "structure.poisson_ratio",
                     "not with D11, D22, D12, D66: the plate's stiffness is given by them");
}

// An impact point strictly inside the plate: on an edge it excites no Navier mode.
void validate_impact_point(std::string_view field, const std::optional<double>& x0, double a,
                           std::string_view length_field) {
  if (!x0) return;
  std::string range = "a point strictly inside the plate, 0 < ";
  range += std::string(field.substr(field.find('.') + 1)) + " < " +
           std::string(length_field.substr(length_field.find('.') + 1)) + " = " +
           std::to_string(a) + " m (on an edge it excites no mode)";
  require(std::isfinite(*x0) && *x0 > 0.0 && *x0 < a, field, range, *x0);
}

void validate_finite_plate(const Structure& s) {
  if (!s.finite_plate()) {
    const char* needs = "needs a finite plate: give length_x and length_y (and edges)";
    if (s.edges) throw InputError("structure.edges", needs);
    if (s.impact_x) throw InputError("structure.impact_x", needs);
    if (s.impact_y) throw InputError("structure.impact_y", needs);
    if (s.dropped_modes) throw InputError("structure.dropped_modes", needs);
    return;
  }
  if (s.kind != Structure::Kind::plate)
    throw InputError(s.length_x ? "structure.length_x" : "structure.length_y",
                     "a finite plate needs kind = \"plate\" (a finite plate in series with a bar "
                     "is not modelled; without lengths the plate is infinite)");
  if (!s.length_x || !s.length_y)
    throw InputError(s.length_x ? "structure.length_y" : "structure.length_x",
                     "missing: length_x and length_y are given together (both make the plate "
                     "finite; neither leaves it infinite)");
  require_positive_finite("structure.length_x", *s.length_x, "m");
  require_positive_finite("structure.length_y", *s.length_y, "m");
  if (!s.edges)
    throw InputError("structure.edges",
                     "missing: a finite plate needs edges = \"simply-supported\" (the only kind "
                     "modelled)");
  validate_impact_point("structure.impact_x", s.impact_x, *s.length_x, "structure.length_x");
  validate_impact_point("structure.impact_y", s.impact_y, *s.length_y, "structure.length_y");
}

}  // namespace

void validate_structure(const Structure& s, double target_E, double target_nu) {
  reject_unused(s);
  validate_finite_plate(s);
  if (s.bending) validate_orthotropic(s);
  require_positive_finite("structure.density", s.density, "kg/m^3");
  if (s.youngs_modulus)
    require_positive_finite("structure.youngs_modulus", *s.youngs_modulus, "Pa");
  const double E = s.youngs_modulus.value_or(target_E);
  const char* rigid =
      "the target is rigid (target.youngs_modulus = inf), so the structure's modulus must be "
      "given: ";
  if (s.has_plate()) {
    require_positive_finite("structure.thickness", s.thickness, "m");
    if (s.bending_stiffness) {
      require_positive_finite("structure.bending_stiffness", *s.bending_stiffness, "N m");
    } else if (!s.bending) {
      if (!std::isfinite(E))
        throw InputError("structure.bending_stiffness",
                         std::string(rigid) + "bending_stiffness [N m] or youngs_modulus [Pa]");
      const double nu = s.poisson_ratio.value_or(target_nu);
      require(std::isfinite(nu) && nu > -1.0 && nu < 0.5,
              s.poisson_ratio ? "structure.poisson_ratio" : "target.poisson_ratio",
              "a Poisson's ratio in (-1, 0.5)", nu);
    }
  }
  if (s.has_bar()) {
    require_positive_finite("structure.area", s.area, "m^2");
    if (!std::isfinite(E))
      throw InputError("structure.youngs_modulus", std::string(rigid) + "youngs_modulus [Pa]");
  }
  const StructureDashpot d = structure_dashpot(s, target_E, target_nu);
  require(std::isfinite(d.c) && d.c > 0.0, "structure",
          "a structure whose dashpot c is a finite number > 0 N s/m in double precision", d.c);
}

StructureDashpot structure_dashpot(const Structure& s, double target_E, double target_nu) {
  StructureDashpot d;
  const double E = s.youngs_modulus.value_or(target_E);
  if (s.has_plate()) {
    d.bending_stiffness_given = s.bending_stiffness.has_value() || s.bending.has_value();
    d.bending_stiffness = s.bending ? olsson_bending_stiffness(*s.bending)
                                    : s.bending_stiffness.value_or(plate_bending_stiffness(
                                          E, s.poisson_ratio.value_or(target_nu), s.thickness));
    d.c_plate = plate_dashpot(s.density, s.thickness, d.bending_stiffness);
  }
  if (s.has_bar()) d.c_bar = bar_dashpot(s.area, E, s.density);
  d.c = series_dashpot(d.c_plate, d.c_bar);
  return d;
}

std::string structure_formula(const Structure& s) {
  const std::string D = s.bending             ? "D = D* = sqrt(D11 D22 (A + 1)/2) (Olsson)"
                        : s.bending_stiffness ? "D = D* (given)"
                                              : "D = E h^3/(12 (1 - nu^2))";
  switch (s.kind) {
    case Structure::Kind::plate:
      return "c = c_plate = 8 sqrt(rho h D), " + D;
    case Structure::Kind::bar:
      return "c = c_bar = A sqrt(E rho)";
    case Structure::Kind::plate_and_bar:
      return "1/c = 1/c_plate + 1/c_bar, c_plate = 8 sqrt(rho h D), " + D +
             ", c_bar = A sqrt(E rho)";
  }
  return "";
}

// m^{3/5} K_h^{2/5} as (m^3 K_h^2)^{1/5}: one power instead of two (each simulate() derives
// it), where m^3 K_h^2 is a normal number; as the two powers where it would over- or underflow
double zener_mass_stiffness_factor(double m, double K_h) {
  const double q = m * m * m * K_h * K_h;
  if (std::isnormal(q)) return std::pow(q, 0.2);
  return std::pow(m, 0.6) * std::pow(K_h, 0.4);
}

double zener_velocity_factor(double v0) {
  return std::pow(v0, 0.2);
}

double zener_lambda_of_factors(double mass_stiffness, double velocity, double c) {
  if (std::isinf(c)) return 0.0;
  return mass_stiffness * velocity / c;
}

double zener_lambda(double m, double K_h, double v0, double c) {
  if (std::isinf(c)) return 0.0;  // before the powers: a run without a dashpot pays none
  return zener_lambda_of_factors(zener_mass_stiffness_factor(m, K_h), zener_velocity_factor(v0), c);
}

double dashpot_for_zener_lambda(double m, double K_h, double v0, double lambda) {
  return zener_mass_stiffness_factor(m, K_h) * zener_velocity_factor(v0) / lambda;
}

double zener_length(double m, double K_h, double v0) {
  return std::pow(m * v0 * v0 / K_h, 0.4);
}

double plate_thickness_for_dashpot(double c, double rho, double d3) {
  return std::sqrt(c / (8.0 * std::sqrt(rho * d3)));
}

LaminateBending laminate_bending_stiffness(const Ply& ply, const std::vector<int>& angles,
                                           double h) {
  if (angles.empty()) throw std::invalid_argument("laminate: no plies");
  if (!(h > 0.0)) throw std::invalid_argument("laminate: thickness must be > 0");
  // reduced stiffnesses of the ply in its axes (plane stress)
  const double nu21 = ply.nu12 * ply.E2 / ply.E1;
  const double den = 1.0 - ply.nu12 * nu21;
  const double Q11 = ply.E1 / den, Q22 = ply.E2 / den, Q12 = ply.nu12 * ply.E2 / den;
  const double Q66 = ply.G12;
  LaminateBending b;
  const double t = h / static_cast<double>(angles.size());
  for (std::size_t k = 0; k < angles.size(); ++k) {
    if (angles[k] != 0 && angles[k] != 90)
      throw std::invalid_argument("laminate: only 0 and 90 degree plies (D16 = D26 = 0)");
    const double z0 = -h / 2 + static_cast<double>(k) * t, z1 = z0 + t;
    const double w = (z1 * z1 * z1 - z0 * z0 * z0) / 3.0;
    const bool along = angles[k] == 0;  // a 90 degree ply swaps Q11 and Q22; Q12, Q66 stay
    b.D11 += (along ? Q11 : Q22) * w;
    b.D22 += (along ? Q22 : Q11) * w;
    b.D12 += Q12 * w;
    b.D66 += Q66 * w;
  }
  const double root = std::sqrt(b.D11 * b.D22);
  const double A = (b.D12 + 2.0 * b.D66) / root;
  b.D_star = std::sqrt(b.D11 * b.D22 * (A + 1.0) / 2.0);
  return b;
}

}  // namespace ivv
