// The dashpot from the struck structure (paper, after eq. 4) and Zener's inelasticity parameter.
//
// A sphere striking a large structure loses energy to the waves it sends away: the force at the
// contact point is proportional to the velocity there, F = c ẏ, with c the structure's
// driving-point impedance (a real number for these two idealised structures):
//
//   infinite thin plate, transverse (bending) waves:
//     c_plate = 8 sqrt(rho h D*)                                            [N s/m]
//     D = E h^3 / (12 (1 - nu^2))  (isotropic plate; a laminate gives its effective D*) [N m]
//     (L. Cremer, M. Heckl, B. A. T. Petersson, Structure-Borne Sound, 3rd ed., Springer 2005:
//      driving-point impedance of an infinite thin plate, Z = 8 sqrt(B' m''), B' = D the
//      bending stiffness, m'' = rho h the mass per unit area; Zener 1941 used the same.)
//   semi-infinite bar, axial waves (force at its end):
//     c_bar = A sqrt(E rho) = rho A c_L,  c_L = sqrt(E/rho)                  [N s/m]
//     (e.g. K. F. Graff, Wave Motion in Elastic Solids, 1975, ch. 2: the d'Alembert wave
//      F = rho A c_L v travelling into the bar.)
//   plate and bar both excited: the two dashpots in series, 1/c = 1/c_plate + 1/c_bar.
//
// Laminates: for a specially orthotropic plate (D16 = D26 = 0) the effective bending stiffness
// used for impact is D* = sqrt(D11 D22 (A + 1)/2), A = (D12 + 2 D66)/sqrt(D11 D22)
// (R. Olsson, "Mass criterion for wave controlled impact response of composite plates",
// Composites Part A 31 (2000) 879-887). laminate_bending_stiffness() computes D11, D22, D12,
// D66 of a cross-ply stack by classical lamination theory (e.g. R. M. Jones, Mechanics of
// Composite Materials, 2nd ed. 1999, §4.2: D_ij = sum_k Qbar_ij (z_k^3 - z_{k-1}^3)/3).
//
// Zener's parameter (C. Zener, "The intrinsic inelasticity of large plates", Phys. Rev. 59
// (1941) 669-673): for the Hertz law K_h z^{3/2} in series with the dashpot c, the impact has
// one dimensionless group
//     lambda = m^{3/5} K_h^{2/5} v0^{1/5} / c                               [-]
// With z* = (m v0^2/K_h)^{2/5} [m], sigma = z/z*, tau = t v0/z*, the impactor displacement
// a = alpha/z*, the equations m alpha'' = -F, c y' = F become a'' = -sigma^{3/2},
// y' = lambda sigma^{3/2}: e depends on lambda alone (docs/design.md §1).
//
// A finite plate (docs/design.md §1 "A finite plate"): with length_x = a and length_y = b the plate
// is a Kirchhoff plate a x b, simply supported on its four edges, struck at (impact_x, impact_y)
// (default the centre), isotropic (D12 = nu D, D66 = (1 - nu) D/2) or specially orthotropic
// with D11, D22, D12, D66 given. Its dynamics are solver/plate/; here only its description and
// the checks of bad input. Given D11..D66 also define the infinite plate's D* (Olsson's).
//
// Units: SI throughout (m, kg, Pa, N m, N s/m).
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace ivv {

// The bending stiffnesses of a specially orthotropic plate (D16 = D26 = 0) [N m].
struct OrthotropicBending {
  double D11 = 0.0, D22 = 0.0, D12 = 0.0, D66 = 0.0;
};

// The edge conditions of a finite plate: only simply supported (Navier modes) is modelled.
enum class PlateEdges { simply_supported };

// What a finite plate's impact does with the modes above its cut-off (solver/plate/plate_modes.h):
// their static compliance C_res in series with the spring (mode acceleration, the default), one
// equivalent oscillator matching C_res and their second moment D_res (e converges as cut-off^-4
// on the 5 mm ball, where the static compliance converges as cut-off^-3; not the default: see
// PlateImpactOptions::dropped), or nothing (plain truncation, for convergence studies).
enum class DroppedModes {
  truncated,          // nothing
  static_compliance,  // C_res in series with the contact spring
  oscillator,         // one equivalent oscillator matching C_res and D_res
};

// The struck structure of a scene ([structure] in a scene file).
struct Structure {
  enum class Kind { plate, bar, plate_and_bar };
  Kind kind = Kind::plate;
  double density = 0.0;                     // rho [kg/m^3]
  double thickness = 0.0;                   // h [m] (plate)
  double area = 0.0;                        // A [m^2] (bar)
  std::optional<double> bending_stiffness;  // D* [N m] (plate); absent: E h^3/(12 (1 - nu^2))
  std::optional<double> youngs_modulus;     // E [Pa] of the structure; absent: the target's
  std::optional<double> poisson_ratio;      // nu [-] of the plate; absent: the target's
  // A finite plate: both lengths or neither (infinite); edges required with them.
  std::optional<double> length_x;             // a [m]
  std::optional<double> length_y;             // b [m]
  std::optional<PlateEdges> edges;            // required with the lengths
  std::optional<double> impact_x;             // x0 [m], absent: a/2
  std::optional<double> impact_y;             // y0 [m], absent: b/2
  std::optional<OrthotropicBending> bending;  // D11..D66 [N m]; absent: isotropic
  std::optional<DroppedModes> dropped_modes;  // absent: the static compliance (finite plate only)

  bool has_plate() const { return kind != Kind::bar; }
  bool finite_plate() const { return length_x.has_value() || length_y.has_value(); }
  bool has_bar() const { return kind != Kind::plate; }
};

// "plate", "bar", "plate+bar" (the scene file's spelling).
std::string_view structure_kind_name(Structure::Kind kind);
std::optional<Structure::Kind> structure_kind_from_name(std::string_view name);

// The dashpot of a structure, element by element. An element the structure does not have has
// c_i = inf (no dashpot in series).
struct StructureDashpot {
  static constexpr double inf = std::numeric_limits<double>::infinity();
  double bending_stiffness = std::numeric_limits<double>::quiet_NaN();  // D used [N m] (plate)
  bool bending_stiffness_given = false;  // D* from the scene (else E h^3/(12(1 - nu^2)))
  double c_plate = inf;                  // 8 sqrt(rho h D) [N s/m]
  double c_bar = inf;                    // A sqrt(E rho) [N s/m]
  double c = inf;                        // series: 1/c = 1/c_plate + 1/c_bar [N s/m]
};

// "simply-supported" (the scene file's spelling); nullopt for any other name.
std::optional<PlateEdges> plate_edges_from_name(std::string_view name);
std::string_view plate_edges_name(PlateEdges edges);
// "static-compliance", "oscillator", "truncated" (the scene file's spelling); nullopt for any
// other name.
std::optional<DroppedModes> dropped_modes_from_name(std::string_view name);
std::string_view dropped_modes_name(DroppedModes dropped);
// The accepted names, quoted and joined for a message.
inline constexpr const char* kDroppedModesNames =
    "\"static-compliance\" (the default), \"oscillator\", \"truncated\"";

// The facts of a valid finite plate (validate_structure first): a x b x h, rho, the impact
// point and the four bending stiffnesses (isotropic ones from E, nu when not given).
struct FinitePlate {
  double length_x = 0.0, length_y = 0.0;  // a, b [m]
  double thickness = 0.0;                 // h [m]
  double density = 0.0;                   // rho [kg/m^3]
  double impact_x = 0.0, impact_y = 0.0;  // x0, y0 [m]
  OrthotropicBending bending;             // [N m]
  bool orthotropic_given = false;         // D11..D66 from the scene (else isotropic)
  double mass() const { return density * thickness * length_x * length_y; }  // [kg]
};
// Throws std::logic_error when s has no finite plate.
FinitePlate finite_plate(const Structure& s, double target_E, double target_nu);

// Olsson's effective stiffness of a specially orthotropic plate, sqrt(D11 D22 (A + 1)/2),
// A = (D12 + 2 D66)/sqrt(D11 D22) [N m] (D for an isotropic one).
double olsson_bending_stiffness(const OrthotropicBending& d);

// Formulas of the header, each alone.
double plate_bending_stiffness(double youngs_modulus, double poisson_ratio, double thickness);
double plate_dashpot(double density, double thickness, double bending_stiffness);
double bar_dashpot(double area, double youngs_modulus, double density);
double series_dashpot(double c1, double c2);  // 1/(1/c1 + 1/c2); inf is no dashpot

// Throws InputError naming the [structure] field at fault and its accepted range: density,
// thickness, area, bending_stiffness, youngs_modulus, poisson_ratio (-1 < nu < 0.5), and a
// material the formulas need but cannot have (a rigid target gives no E for the structure);
// for a finite plate: both lengths positive and finite, edges = "simply-supported", the impact
// point strictly inside, D11..D66 all or none and positive definite (D11 > 0, D22 > 0,
// D66 > 0, D11 D22 > D12^2), not with bending_stiffness; no lengths with a bar.
// target_E, target_nu: the scene's target (E may be +inf: rigid).
void validate_structure(const Structure& s, double target_E, double target_nu);

// The dashpot of a valid structure (validate_structure first).
StructureDashpot structure_dashpot(const Structure& s, double target_E, double target_nu);

// One-line formulas for a human reader (scene show), e.g. "c_plate = 8 sqrt(rho h D)".
std::string structure_formula(const Structure& s);

// Zener's lambda = m^{3/5} K_h^{2/5} v0^{1/5} / c (0 when c = inf), and the c that gives a
// requested lambda: c = m^{3/5} K_h^{2/5} v0^{1/5} / lambda.
double zener_lambda(double mass, double K_h, double v0, double c);
double dashpot_for_zener_lambda(double mass, double K_h, double v0, double lambda);
// lambda from its factors, for a caller that keeps them (a sweep: m^{3/5} K_h^{2/5} once, v0^{1/5}
// once a velocity; the three pow calls were ~430 instructions of a 300 x 300 map's point,
// callgrind): zener_lambda(m, K_h, v0, c) is zener_lambda_of_factors(zener_mass_stiffness_factor(m,
// K_h), zener_velocity_factor(v0), c), the same operations in the same order, so the same double.
double zener_mass_stiffness_factor(double mass, double K_h);  // m^{3/5} K_h^{2/5}
double zener_velocity_factor(double v0);                      // v0^{1/5}
double zener_lambda_of_factors(double mass_stiffness, double velocity, double c);  // 0 for c = inf
// Zener's length z* = (m v0^2/K_h)^{2/5} [m] (the Hertz maximum compression is
// (5/4)^{2/5} z*); time z*/v0 and force K_h z*^{3/2} follow.
double zener_length(double mass, double K_h, double v0);

// The thickness h [m] at which a plate of bending stiffness D = d3 h^3 (d3 [N/m^2]: E/(12(1 -
// nu^2)) for an isotropic plate, D*/h^3 of a laminate of fixed stacking) and density rho has
// the dashpot c: c = 8 sqrt(rho h d3 h^3) = 8 h^2 sqrt(rho d3), so h = sqrt(c/(8 sqrt(rho d3))).
double plate_thickness_for_dashpot(double c, double density, double d3);

// A ply of a laminate: orthotropic, in its own axes (1 along the fibres).
struct Ply {
  double E1 = 0.0;    // [Pa]
  double E2 = 0.0;    // [Pa]
  double G12 = 0.0;   // [Pa]
  double nu12 = 0.0;  // [-]
};

// Bending stiffnesses of a laminate of equal-thickness plies (angles 0 or 90 degrees only, so
// that D16 = D26 = 0), listed from one face to the other; total thickness h [m].
struct LaminateBending {
  double D11 = 0.0, D22 = 0.0, D12 = 0.0, D66 = 0.0;  // [N m]
  double D_star = 0.0;                                // Olsson's sqrt(D11 D22 (A + 1)/2) [N m]
};
// Throws std::invalid_argument for an angle other than 0 or 90, an empty stack, h <= 0.
LaminateBending laminate_bending_stiffness(const Ply& ply, const std::vector<int>& angles_deg,
                                           double thickness);

}  // namespace ivv
