// Scene: the physical inputs of one impact, and the parameters derived from them.
//
// A sphere (mass m1, radius R1, E1, nu1) strikes a target at relative approach velocity v0,
// optionally through a series dashpot c (paper eqs 1-4). SI units throughout. The target is
//   - a half-space (the paper's case; no target radius or mass), or
//   - a free sphere (target radius R2 and mass m2, both given): a two-body central impact,
//     reduced to one body of effective radius R* and effective mass m* (Johnson, Contact
//     Mechanics, 1985, §4.2 and §11.1) with v0 the relative approach speed;
// and it is rigid when its Young's modulus is +inf (then E* = E1/(1 - nu1^2)). The target's
// yield strength S_y is optional: only laws that model yield need it (elastoplastic,
// linearized); Hertz and Hunt-Crossley do not.
//
// Derived parameters (paper eqs 6, 7, 11, 12, 23; docs/design.md §1):
//   R*    = R1 R2/(R1 + R2)  (R1 for a half-space)      [m]        effective radius
//   m*    = m1 m2/(m1 + m2)  (m1 for a fixed target)    [kg]       effective mass
//   1/E*  = (1 - nu1^2)/E1 + (1 - nu2^2)/E2            [Pa]       (second term 0 if E2 = inf)
//   K_h   = (4/3) sqrt(R*) E*                            [N/m^1.5]  Hertz stiffness
//   z_y   = 0.68 S_y^2 pi^2 R* / E*^2                    [m]        yield deformation
//   K_y   = 1.5 K_h sqrt(z_y)                            [N/m]      slope of Hertz at z_y
//   omega0 = sqrt(K_y/m*)                                [rad/s]
//   zeta  = sqrt(m* K_y) / (2 c)                         [-]        (c = inf <=> zeta = 0)
//   v_y   = sqrt(4 K_h z_y^{5/2} / (5 m*))               [m/s]      undamped yield velocity
//   lambda = m*^{3/5} K_h^{2/5} v0^{1/5} / c              [-]        Zener 1941 (structure.h)
// z_y, K_y, omega0, v_y and zeta exist only when S_y is given (NaN otherwise; has_yield()).
//
// Normalisation (`Scales`), chosen by the contact law (ScaleBasis):
//   yield: paper eq. 26, tau = omega0 t, alpha_bar = alpha omega0/v0, F_bar = F/(m* v0 omega0);
//   hertz: the law's own scales for a law without yield, z_mH = (5 m* v0^2/(4 K_h))^{2/5} (the
//          Hertz maximum compression) as length and omega = v0/z_mH: tau = omega t,
//          alpha_bar = alpha/z_mH, F_bar = F/(m* v0 omega). A Hertz contact lasts tau = 2.943.
#pragma once

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "scene/data_dir.h"
#include "scene/structure.h"

namespace ivv {

// The dashpot of the scene: absent (c = inf), given as a damping ratio, as a coefficient, as
// Zener's parameter lambda (scene/structure.h: c = m^{3/5} K_h^{2/5} v0^{1/5}/lambda, so c
// follows v0), or derived from the struck structure (a [structure] section: plate, bar, or
// both in series; scene/structure.h).
struct Damping {
  enum class Kind { none, ratio, coefficient, zener_lambda, structure };
  Kind kind = Kind::none;
  double value = 0.0;   // zeta [-] for ratio, c [N s/m] for coefficient, lambda [-] for
                        // zener_lambda; unused for structure
  Structure structure;  // for Kind::structure

  static Damping none() { return {}; }
  static Damping ratio(double zeta) { return {Kind::ratio, zeta, {}}; }
  static Damping coefficient(double c) { return {Kind::coefficient, c, {}}; }
  static Damping zener(double lambda) { return {Kind::zener_lambda, lambda, {}}; }
  static Damping from_structure(const Structure& s) { return {Kind::structure, 0.0, s}; }
};

// Where a dashpot came from, as the user typed it: "damping.zeta", "damping.c",
// "damping.lambda", "structure" ("" for none). Names the field in messages.
const char* damping_field(Damping::Kind kind);

struct Scene {
  std::string name = "custom";
  // impactor
  double mass = 0.0;                     // m1 [kg]
  double radius = 0.0;                   // R1 [m]
  double impactor_youngs_modulus = 0.0;  // E1 [Pa]
  double impactor_poisson_ratio = 0.0;   // nu1 [-]
  // target
  double target_youngs_modulus = 0.0;    // E2 [Pa] (E22 for a laminate); +inf: rigid target
  double target_poisson_ratio = 0.0;     // nu2 [-] (unused for a rigid target)
  std::optional<double> yield_strength;  // S_y [Pa] (laminate: 2 x shear strength); absent:
                                         // only laws without yield can run
  std::optional<double> target_radius;   // R2 [m]: the target is a free sphere (with mass)
  std::optional<double> target_mass;     // m2 [kg]: absent = half-space of infinite mass
  // dashpot and impact
  Damping damping;
  double velocity = 0.0;  // v0 [m/s], relative approach speed (towards the target)

  bool rigid_target() const {
    return target_youngs_modulus == std::numeric_limits<double>::infinity();
  }
  bool free_target() const { return target_mass.has_value(); }
};

// The yield-related members (z_y, K_y, omega0, v_yield, and zeta when the dashpot is given as
// a coefficient) exist only when the scene gives a yield strength; otherwise they are NaN and
// has_yield() is false. Every dynamical use of R and m goes through effective_radius and
// effective_mass.
struct DerivedParameters {
  static constexpr double absent = std::numeric_limits<double>::quiet_NaN();
  double effective_radius = 0.0;                       // R* [m]
  double effective_mass = 0.0;                         // m* [kg]
  double E_star = 0.0;                                 // effective modulus E* [Pa]
  double K_h = 0.0;                                    // Hertz stiffness [N/m^1.5]
  double z_y = absent;                                 // yield deformation [m]
  double K_y = absent;                                 // elastic-plastic loading stiffness [N/m]
  double omega0 = absent;                              // sqrt(K_y/m*) [rad/s]
  double zeta = 0.0;                                   // damping ratio [-]; 0 without a dashpot
  double c = std::numeric_limits<double>::infinity();  // dashpot [N s/m]; inf without one
  double v_yield = absent;                             // undamped yield velocity [m/s]
  double zener_lambda = 0.0;  // m*^{3/5} K_h^{2/5} v0^{1/5}/c [-] (Zener 1941); 0 without a dashpot
  bool has_dashpot() const { return c < std::numeric_limits<double>::infinity(); }
  bool has_yield() const { return std::isfinite(z_y); }
};

// Which scales normalise a run (see the header comment): a law states its own.
enum class ScaleBasis {
  yield,  // omega0 = sqrt(K_y/m*), length v0/omega0 (paper eq. 26); needs a yield strength
  hertz   // omega = v0/z_mH, length z_mH, the Hertz maximum compression
};

// Scales for one impact velocity: tau = t/time, alpha_bar = alpha/length, F_bar = F/force.
struct Scales {
  double time = 0.0;      // 1/omega [s]
  double length = 0.0;    // v0/omega [m]
  double velocity = 0.0;  // v0 [m/s]
  double force = 0.0;     // m* v0 omega [N]
  double energy = 0.0;    // m* v0^2 [J]
};

// Throws InputError naming the first invalid field and its accepted range.
void validate(const Scene& scene);
// validate(scene), and derive(scene) of the valid scene (computed once for both).
DerivedParameters validate_and_derive(const Scene& scene);

// Throws InputError unless every derived parameter (E*, K_h, z_y, K_y, omega0, v_y, and zeta
// and c with a dashpot), every scale of paper eq. 26 and the energy scale of the contact
// spring, K_h (v0/omega0)^{5/2} [J], are finite and > 0, i.e. representable in double. The
// field named is the input the failing quantity depends on that lies farthest (in decades)
// from the paper's Table 1 value: the likeliest culprit of an overflow or underflow. Called
// by validate() and validate_and_derive() with `derived` = derive(scene), computed once.
void validate_derived(const Scene& scene, const DerivedParameters& derived);

// Scene files are read up to this size [bytes]: a scene is a few hundred bytes, so 1 MiB leaves
// room for comments and refuses an endless input such as /dev/zero.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 20;

// Derived parameters of a valid scene (validate() first; this assumes validity).
DerivedParameters derive(const Scene& scene);

// derive() of many scenes that differ from one base scene only in the impact velocity and a
// damping ratio (the points of a v0 x zeta sweep): what depends on neither (R*, m*, E*, K_h,
// z_y, K_y, omega0, v_y, the critical 2 c zeta = sqrt(m* K_y) and Zener's m*^{3/5} K_h^{2/5}) is
// derived once, so a point costs a division and two products instead of derive()'s square roots
// and powers (~570 instructions a point of the 300 x 300 map, callgrind). Its parameters are
// derive()'s to the bit: derive() is made of the same steps (scene_test.cc holds the two equal).
class VelocityDampingDerivation {
 public:
  // `base`: a valid scene (validate()); its velocity and its damping are not used.
  explicit VelocityDampingDerivation(const Scene& base);
  // derive(s) for s = the base scene with velocity v0 and damping Damping::ratio(zeta) for
  // zeta > 0, Damping::none() for zeta = 0 (a sweep's points: solver/sweep/sweep_grid.h).
  // `velocity_factor` is zener_velocity_factor(v0) (scene/structure.h), which a caller with few
  // velocities computes once each.
  DerivedParameters at(double velocity_factor, double zeta) const;

 private:
  DerivedParameters bodies_;            // no dashpot, zener_lambda 0
  double critical_ = 0.0;               // sqrt(m* K_y) = 2 c zeta [N s/m] (NaN without S_y)
  double mass_stiffness_factor_ = 0.0;  // m*^{3/5} K_h^{2/5}
};

// Throws InputError("target.yield_strength", ...) for ScaleBasis::yield without a yield strength.
Scales scales(const Scene& scene, const DerivedParameters& p, ScaleBasis basis);

// Velocities of the two bodies after an impact whose relative velocity ends at
// `relative_velocity_after` [m/s] (alpha_dot at the end; < 0: separating), in the frame where
// the target was at rest before; positive towards the target. Centre-of-mass velocity
// V = m* v0/m2 is unchanged by the contact: v1 = V + (m*/m1) w, v2 = V - (m*/m2) w, so
// m1 v1 + m2 v2 = m1 v0. A fixed target (no mass) stays at rest and v1 = w.
struct BodyVelocities {
  double impactor = 0.0;  // [m/s]
  double target = 0.0;    // [m/s]
};
BodyVelocities body_velocities_after(const Scene& scene, double relative_velocity_after);

// The paper's Table 1: 0.5 kg steel hemisphere (R = 10 mm, E = 207 GPa, nu = 0.3) on a
// T300/934 laminate (E22 = 7.9 GPa, nu = 0.3, S_u = 101 MPa so S_y = 202 MPa), no dashpot,
// v0 = 1 m/s. With c = 11440 N s/m the damping ratio is 0.1.
Scene paper_scene();

// Reads a TOML scene (schema in docs/design.md §5). Throws InputError for a missing or unreadable
// file, a TOML syntax error (with line), an unknown key, a missing or out-of-range field.
Scene load_scene_file(const std::filesystem::path& path);
// The text of a scene file, at most kMaxSceneFileBytes; InputError("--scene") for a directory,
// an unreadable file or a larger one (e.g. /dev/zero).
std::string read_scene_text(const std::filesystem::path& path);
Scene parse_scene_toml(const std::string& text, const std::string& source_name);

// "paper" names the built-in scene; an existing file path is read; otherwise a bare name
// (no '/' and no ".toml") is looked up as scenes/NAME.toml in data_directories()
// (scene/data_dir.h: $IVV_DATA_DIR, an installed package's share/ivv, <exe>/../share/ivv), e.g.
// "chung-ooi-2-aluminium".
Scene load_scene(const std::string& name_or_path);

}  // namespace ivv
