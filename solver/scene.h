// Scene: the physical inputs of one impact, and the parameters derived from them.
//
// A sphere (mass m, radius R, E1, nu1) strikes a target half-space (E2, nu2, yield strength S_y)
// at velocity v0, optionally through a series dashpot c (paper eqs 1-4). SI units throughout.
//
// Derived parameters (paper eqs 6, 7, 11, 12, 23; SPEC §1):
//   1/E*  = (1 - nu1^2)/E1 + (1 - nu2^2)/E2            [Pa]
//   K_h   = (4/3) sqrt(R) E*                             [N/m^1.5]  Hertz stiffness
//   z_y   = 0.68 S_y^2 pi^2 R / E*^2                     [m]        yield deformation
//   K_y   = 1.5 K_h sqrt(z_y)                            [N/m]      slope of Hertz at z_y
//   omega0 = sqrt(K_y/m)                                 [rad/s]
//   zeta  = sqrt(m K_y) / (2 c)                          [-]        (c = inf <=> zeta = 0)
//   v_y   = sqrt(4 K_h z_y^{5/2} / (5 m))                [m/s]      undamped yield velocity
//
// The normalisation of paper eq. 26 (tau = omega0 t, alpha_bar = alpha omega0/v0,
// F_bar = F/(m v0 omega0)) is described by `Scales`.
#pragma once

#include <cstddef>
#include <filesystem>
#include <limits>
#include <string>

namespace ivv {

// The dashpot of the scene: absent (c = inf), given as a damping ratio, or as a coefficient.
struct Damping {
  enum class Kind { none, ratio, coefficient };
  Kind kind = Kind::none;
  double value = 0.0;  // zeta [-] for ratio, c [N s/m] for coefficient

  static Damping none() { return {}; }
  static Damping ratio(double zeta) { return {Kind::ratio, zeta}; }
  static Damping coefficient(double c) { return {Kind::coefficient, c}; }
};

struct Scene {
  std::string name = "custom";
  // impactor
  double mass = 0.0;                     // m [kg]
  double radius = 0.0;                   // R [m]
  double impactor_youngs_modulus = 0.0;  // E1 [Pa]
  double impactor_poisson_ratio = 0.0;   // nu1 [-]
  // target
  double target_youngs_modulus = 0.0;  // E2 [Pa] (E22 for a laminate)
  double target_poisson_ratio = 0.0;   // nu2 [-]
  double yield_strength = 0.0;         // S_y [Pa] (laminate: 2 x shear strength)
  // dashpot and impact
  Damping damping;
  double velocity = 0.0;  // v0 [m/s], towards the target
};

struct DerivedParameters {
  double E_star = 0.0;                                 // effective modulus E* [Pa]
  double K_h = 0.0;                                    // Hertz stiffness [N/m^1.5]
  double z_y = 0.0;                                    // yield deformation [m]
  double K_y = 0.0;                                    // elastic-plastic loading stiffness [N/m]
  double omega0 = 0.0;                                 // sqrt(K_y/m) [rad/s]
  double zeta = 0.0;                                   // damping ratio [-]; 0 without a dashpot
  double c = std::numeric_limits<double>::infinity();  // dashpot [N s/m]; inf without one
  double v_yield = 0.0;                                // undamped yield velocity [m/s]
  bool has_dashpot() const { return c < std::numeric_limits<double>::infinity(); }
};

// Scales of paper eq. 26 for one impact velocity.
struct Scales {
  double time = 0.0;      // 1/omega0 [s]
  double length = 0.0;    // v0/omega0 [m]
  double velocity = 0.0;  // v0 [m/s]
  double force = 0.0;     // m v0 omega0 [N]
  double energy = 0.0;    // m v0^2 [J]
};

// Throws InputError naming the first invalid field and its accepted range.
void validate(const Scene& scene);

// Throws InputError unless every derived parameter (E*, K_h, z_y, K_y, omega0, v_y, and zeta
// and c with a dashpot), every scale of paper eq. 26 and the energy scale of the contact
// spring, K_h (v0/omega0)^{5/2} [J], are finite and > 0, i.e. representable in double. The
// field named is the input the failing quantity depends on that lies farthest (in decades)
// from the paper's Table 1 value: the likeliest culprit of an overflow or underflow. Called
// by validate().
void validate_derived(const Scene& scene);

// Scene files are read up to this size [bytes]: a scene is a few hundred bytes, so 1 MiB leaves
// room for comments and refuses an endless input such as /dev/zero.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{1} << 20;

// Derived parameters of a valid scene (validate() first; this assumes validity).
DerivedParameters derive(const Scene& scene);

Scales scales(const Scene& scene, const DerivedParameters& p);

// The paper's Table 1: 0.5 kg steel hemisphere (R = 10 mm, E = 207 GPa, nu = 0.3) on a
// T300/934 laminate (E22 = 7.9 GPa, nu = 0.3, S_u = 101 MPa so S_y = 202 MPa), no dashpot,
// v0 = 1 m/s. With c = 11440 N s/m the damping ratio is 0.1.
Scene paper_scene();

// Reads a TOML scene (schema in SPEC §5). Throws InputError for a missing or unreadable
// file, a TOML syntax error (with line), an unknown key, a missing or out-of-range field.
Scene load_scene_file(const std::filesystem::path& path);
// The text of a scene file, at most kMaxSceneFileBytes; InputError("--scene") for a directory,
// an unreadable file or a larger one (e.g. /dev/zero).
std::string read_scene_text(const std::filesystem::path& path);
Scene parse_scene_toml(const std::string& text, const std::string& source_name);

// "paper" names the built-in scene; anything else is a file path.
Scene load_scene(const std::string& name_or_path);

}  // namespace ivv
