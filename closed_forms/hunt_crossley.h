// Hunt-Crossley impact, exact restitution (docs/design.md §2 "Hunt-Crossley, exact"; paper eq 27;
// Hunt & Crossley, J. Appl. Mech. 42 (1975) 440; the Lambert-W closed form as in
// Antypov & Elliott, EPL 94 (2011) 50004).
//
//   m x'' = -K x^{3/2} (1 + mu x'),  x(0) = 0, x'(0) = v0  (no dashpot; x = alpha).
// Dividing by (1 + mu x') and integrating in x with x' dx'/dx:
//   integral v dv/(1 + mu v) = v/mu - ln(1 + mu v)/mu^2 = -(K/m) x^{5/2}/(5/2) + const.
// With f(u) = u - ln(1 + u) = -log1pmx(u) and u0 = mu v0:
//   maximum indentation (v = 0):  (K/m) x_m^{5/2}/(5/2) = f(u0)/mu^2 = v0^2 f(u0)/u0^2
//   separation (x = 0, v = -e v0): f(u0) = f(-e u0)
//   =>  e = [1 + W0(-(1 + u0) e^{-(1 + u0)})]/u0   (Lambert W, principal branch),
// independent of K, of the exponent 3/2 and of m. As mu -> 0, f(u0)/u0^2 -> 1/2 and x_m is
// Hertz's (5 m v0^2/(4K))^{2/5}.
//
// Small u0: near the branch point -1/e the Lambert-W form loses about eps/u0^2 relative, so
// below kSeriesMaxU0 the series (exact rational coefficients, derived by matching powers of
// u0 in f(u0) = f(-e u0))
//   e = 1 - 2/3 u + 4/9 u^2 - 44/135 u^3 + 104/405 u^4 - 40/189 u^5 + 7648/42525 u^6
//         - 2848/18225 u^7 + 31712/229635 u^8 + O(u^9)
// is used, and for u0 < 1 one Newton step on the well-conditioned form
// log1pmx(-e u0) = log1pmx(u0) restores full precision. Large u0: e = (1 - s)/u0 with
// s = -W0(...) exponentially small, so e -> 1/u0.
//
// Damping maps mu(e, v0) [s/m] in use (docs/design.md §3), each meant to deliver a target e:
//   hunt-crossley (Hunt & Crossley 1975; Marhefka & Orin, IEEE SMC-A 29 (1999) 566):
//                             3(1 - e)/(2 v0)
//   lankarani-nikravesh (J. Mech. Des. 112 (1990) 369):  3(1 - e^2)/(4 v0)
//   lee-wang (J. Mech. Transm. Autom. Des. 105 (1983) 534):  3(1 - e)/(4 v0)
//   gonthier (Gonthier et al., Multibody Syst. Dyn. 11 (2004) 209):  (1 - e^2)/(e v0)
//   flores (Flores et al., Mech. Mach. Theory 46 (2011) 1571):  8(1 - e)/(5 e v0)
//   hu-guo (Hu & Guo 2015):   3(1 - e)/(2 e v0)
//   gharib-hurmuzlu (Gharib & Hurmuzlu 2012):  (1/e - 1)/v0
// Since mu v0 depends on e only, the e each map delivers, delivered_cor(map, e_target) =
// hunt_crossley_cor(v0 mu(e_target, v0)), does not depend on v0.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace ivv::closed_forms {

// Below this u0 the series replaces the Lambert-W form (see above).
inline constexpr double kSeriesMaxU0 = 0.01;

// Exact Newton COR for u0 = mu v0 >= 0 [-]. Throws ivv::InputError for u0 < 0 or NaN.
double hunt_crossley_cor(double u0);

// The series above (through u0^8), exposed for tests; accurate to ~0.13 u0^9.
double hunt_crossley_cor_series(double u0);

// Inverse of hunt_crossley_cor: the u0 = mu v0 delivering e_target in (0, 1), by a bracketing
// root finder (TOMS 748) on [0, 1/e_target] (e < 1/u0 always). Throws ivv::InputError outside.
double hunt_crossley_u0_for_cor(double e_target);

struct HuntCrossleyInput {
  double K = 0.0;     // stiffness [N/m^1.5], > 0
  double mu = 0.0;    // damping [s/m], >= 0
  double mass = 0.0;  // m [kg], > 0
  double v0 = 0.0;    // impact velocity [m/s], > 0
};

struct HuntCrossleyImpact {
  double u0 = 0.0;     // mu v0 [-]
  double e = 1.0;      // Newton COR [-]
  double x_max = 0.0;  // maximum indentation [m]
};

HuntCrossleyImpact solve_hunt_crossley(const HuntCrossleyInput& in);

// The seven damping maps of docs/design.md §3, mu [s/m] for a target e in (0, 1) and v0 > 0 [m/s].
double mu_hunt_crossley(double e, double v0);
double mu_lankarani_nikravesh(double e, double v0);
double mu_lee_wang(double e, double v0);
double mu_gonthier(double e, double v0);
double mu_flores(double e, double v0);
double mu_hu_guo(double e, double v0);
double mu_gharib_hurmuzlu(double e, double v0);

struct DampingMap {
  std::string_view name;     // e.g. "lankarani-nikravesh"
  std::string_view formula;  // e.g. "3(1-e^2)/(4 v0)"
  double (*mu)(double e, double v0);
};

// The table of the seven maps, in the order listed above.
const std::array<DampingMap, 7>& damping_maps();
std::optional<DampingMap> find_damping_map(std::string_view name);

// The e the exact relation gives for the mu a map picks for e_target.
double delivered_cor(const DampingMap& map, double e_target);

}  // namespace ivv::closed_forms
