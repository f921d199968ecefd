#include "solver/plate/plate_modes.h"

#include <algorithm>
#include <boost/math/constants/constants.hpp>
#include <boost/math/special_functions/bernoulli.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/input_error.h"

namespace ivv {
namespace {

using cplx = std::complex<double>;
constexpr double pi = std::numbers::pi;

// Exponentials below this are dropped against 1 (the m-term is then exactly its asymptote).
constexpr double kNegligibleExponent = 40.0;  // e^-40 = 4e-18
// The most m-terms summed exactly: an impact point within ~1e-6 of an edge (relative) would need
// more; its tail_bound then says what the asymptote leaves out.
constexpr double kMaxExactTerms = 2.0e7;

// E(c, theta) of the header, with its derivative in c: decaying exponentials only.
struct EValue {
  cplx value, derivative;
};
EValue e_function(cplx c, double theta) {
  const cplx q = std::exp(-2.0 * pi * c);
  const cplx e1 = std::exp(-c * theta), e2 = std::exp(-c * (2.0 * pi - theta));
  const cplx num = e1 + e2, dnum = -theta * e1 - (2.0 * pi - theta) * e2;
  const cplx den = 1.0 - q, dden = 2.0 * pi * q;
  return {num / den, dnum / den - num * dden / (den * den)};
}

// f(r) = sum_n sin^2(n pi eta)/(n^2 + r) and df/dr (header), c = sqrt(r).
struct FValue {
  cplx value, derivative;
};
FValue f_function(cplx r, double theta) {
  const cplx c = std::sqrt(r);
  const EValue e0 = e_function(c, 0.0), et = e_function(c, theta);
  const cplx dE = e0.value - et.value, dEp = e0.derivative - et.derivative;
  const cplx value = pi / (4.0 * c) * dE;
  const cplx dfdc = -pi / (4.0 * c * c) * dE + pi / (4.0 * c) * dEp;
  return {value, dfdc / (2.0 * c)};
}

// The roots r1, r2 of s^2 + 2 (H/D22) mu^2 s + (D11/D22) mu^4 for mu = 1 (they scale as mu^2).
struct Roots {
  cplx r1, r2;
};
Roots unit_roots(const OrthotropicBending& d) {
  const double h = (d.D12 + 2.0 * d.D66) / d.D22, q = d.D11 / d.D22;
  const cplx s = std::sqrt(cplx(h * h - q));
  return {h + s, h - s};
}

// S_m = sum_n sin^2(n pi eta)/((n^2 + r1)(n^2 + r2)), exact (header).
double inner_sum(const Roots& unit, double mu, double theta) {
  const cplx r1 = unit.r1 * (mu * mu), r2 = unit.r2 * (mu * mu);
  if (std::abs(r1 - r2) <= kDoubleRoot * std::abs(r1))
    return -f_function(0.5 * (r1 + r2), theta).derivative.real();
  return ((f_function(r1, theta).value - f_function(r2, theta).value) / (r2 - r1)).real();
}

// The bound on what the asymptote leaves out beyond M (header): f(r) = pi/(4c) + delta(r) with
//   |d delta/dr| <= (pi eps/(2 (1 - eps)^2)) (1/|c|^3 + 2 pi/|c|^2),   eps = e^{-Re(c) theta_min}
// (for eps <= 1/7; from delta = (pi/(4c)) (2q - e^{-c theta} - e^{-c(2 pi - theta)})/(1 - q), q =
// e^{-2 pi c}), and S_m's deviation from its asymptote is a divided difference of delta over the
// segment [r1, r2] (or -delta' at a double root), so at most that bound there, where Re c >=
// sqrt(min Re r) = m c_lo. Each m-term carries prefactor sin^2 <= prefactor, eps <= e^{-m x}
// with x = c_lo theta_min, and the terms beyond M fall at least by e^{-x} each: the sum is at
// most the first term over (1 - e^{-x}). Infinite (no bound) where eps > 1/7.
double tail_error_bound(double prefactor, int M, double x, double c_lo) {
  const double eps = std::exp(-(M + 1.0) * x), c = (M + 1.0) * c_lo;
  if (!(eps <= 1.0 / 7.0)) return std::numeric_limits<double>::infinity();
  const double first = prefactor * pi * eps / (2.0 * (1.0 - eps) * (1.0 - eps)) *
                       (1.0 / (c * c * c) + 2.0 * pi / (c * c));
  return first / (1.0 - std::exp(-x));
}

// C3(theta) = sum_{m >= 1} cos(m theta)/m^3 (the Clausen-type function of the header), any
// theta: reduced to [0, pi] (period 2 pi, even), then
//   C3 = zeta(3) - 3 theta^2/4 + (theta^2/2) ln theta
//        - sum_{k >= 1} |B_2k|/(2 (2k)!) theta^{2k+2}/(k (2k+1)(2k+2))
// (integrated term by term from Cl_2(theta) = theta - theta ln theta + sum_k zeta(2k)
// theta^{2k+1}/(k (2k+1) (2 pi)^{2k}), Abramowitz & Stegun 27.8.2; zeta(2k)/(2 pi)^{2k} =
// |B_2k|/(2 (2k)!)). At theta <= pi the k-th term is below pi^2 4^-k/(4 k^3): kClausenTerms
// leave less than 1e-17; the result carries ~6e-16 of rounding (the three leading terms
// cancel from ~7 to ~1 at theta = pi).
constexpr int kClausenTerms = 24;
double cos_sum_cubed(double theta) {
  theta = std::fmod(std::abs(theta), 2.0 * pi);
  if (theta > pi) theta = 2.0 * pi - theta;
  const double zeta3 = boost::math::constants::zeta_three<double>();
  if (theta == 0.0) return zeta3;
  const double t2 = theta * theta;
  double terms[kClausenTerms + 1];
  double factorial = 1.0, power = t2;
  for (int k = 1; k <= kClausenTerms; ++k) {
    factorial *= (2.0 * k - 1.0) * (2.0 * k);
    power *= t2;
    terms[k] = std::abs(boost::math::unchecked_bernoulli_b2n<double>(k)) / (2.0 * factorial) *
               power / (k * (2.0 * k + 1.0) * (2.0 * k + 2.0));
  }
  double series = 0.0;
  for (int k = kClausenTerms; k >= 1; --k) series += terms[k];  // small terms first
  return zeta3 - 0.75 * t2 + 0.5 * t2 * std::log(theta) - series;
}

}  // namespace

double plate_mode_frequency(const FinitePlate& p, int m, int n) {
  const OrthotropicBending& d = p.bending;
  const double x = m / p.length_x, y = n / p.length_y;
  const double x2 = x * x, y2 = y * y;
  const double k = d.D11 * x2 * x2 + 2.0 * (d.D12 + 2.0 * d.D66) * x2 * y2 + d.D22 * y2 * y2;
  return pi * pi * std::sqrt(k / (p.density * p.thickness));
}

SeparableFrequency separable_frequency(const FinitePlate& p) {
  const OrthotropicBending& d = p.bending;
  const double H = d.D12 + 2.0 * d.D66, D = d.D11 * d.D22;
  if (!(D > 0.0) || !(std::abs(H * H - D) <= 1e-12 * D)) return {};
  const double rho_h = p.density * p.thickness;
  return {pi * pi * std::sqrt(d.D11 / rho_h) / (p.length_x * p.length_x),
          pi * pi * std::sqrt(d.D22 / rho_h) / (p.length_y * p.length_y)};
}

StaticCompliance plate_static_compliance(const FinitePlate& p,
                                         const StaticComplianceOptions& options) {
  const double a = p.length_x, b = p.length_y;
  const double xi = p.impact_x / a, eta = p.impact_y / b;
  const double theta = 2.0 * pi * eta;
  const Roots unit = unit_roots(p.bending);
  const double prefactor = 4.0 / (a * b) * std::pow(b, 4) / (std::pow(pi, 4) * p.bending.D22);
  // Re c >= m c_lo on the segment [r1, r2] (tail_error_bound): the exponentials, at most
  // e^{-m x}, are negligible from M on
  const double c_lo = std::sqrt(std::min(unit.r1.real(), unit.r2.real())) * (b / a);
  const double theta_min = std::min(theta, 2.0 * pi - theta);
  const double x = c_lo * theta_min;
  const double M_exp = std::ceil(kNegligibleExponent / x);
  const int M = static_cast<int>(
      std::clamp(std::max(M_exp, static_cast<double>(options.min_terms)), 1.0, kMaxExactTerms));
  double sum = 0.0, head = 0.0;   // the exact m-terms; sum sin^2(m pi xi)/m^3 over the same m
  for (int m = M; m >= 1; --m) {  // small terms first
    const double s = std::sin(m * pi * xi), s2 = s * s;
    sum += s2 * inner_sum(unit, m * b / a, theta);
    head += s2 / (static_cast<double>(m) * m * m);
  }
  // the asymptote K sin^2(m pi xi)/m^3: S_m -> (pi/4)/(c1 c2 (c1 + c2)), c_i = m (b/a) c_hat_i
  const cplx c1 = std::sqrt(unit.r1) * (b / a), c2 = std::sqrt(unit.r2) * (b / a);
  const double K = prefactor * (pi / 4.0 / (c1 * c2 * (c1 + c2))).real();
  // sum_{m > M} sin^2(m pi xi)/m^3 = (zeta(3) - C3(2 pi xi))/2 - head
  const double zeta3 = boost::math::constants::zeta_three<double>();
  const double tail = std::max(0.5 * (zeta3 - cos_sum_cubed(2.0 * pi * xi)) - head, 0.0);
  StaticCompliance out;
  out.terms = M;
  out.value = prefactor * sum + K * tail;
  out.tail_bound = tail_error_bound(prefactor, M, x, c_lo);
  return out;
}

double flexural_return_time(const FinitePlate& p, double t_contact) {
  const double d =
      std::min({p.impact_x, p.length_x - p.impact_x, p.impact_y, p.length_y - p.impact_y});
  const double omega = pi / t_contact;
  const double c_g =
      2.0 * std::pow(olsson_bending_stiffness(p.bending) / (p.density * p.thickness), 0.25) *
      std::sqrt(omega);
  return 2.0 * d / c_g;
}

namespace {

// Calls visit(m, n, W) for every excited mode (W(x0, y0)^2 >= kNodalShape) with omega <=
// omega_cut, m rising and n rising within each m, until visit returns false. The factors
// sin(n pi y0/b) are tabulated once per n (a sine per mode pair was most of the table's cost).
template <class Visit>
void for_each_excited_mode(const FinitePlate& p, double omega_cut, Visit visit) {
  std::vector<double> sy;
  for (int m = 1; plate_mode_frequency(p, m, 1) <= omega_cut; ++m) {
    const double sx = std::sin(m * pi * p.impact_x / p.length_x);
    for (int n = 1; plate_mode_frequency(p, m, n) <= omega_cut; ++n) {
      if (static_cast<std::size_t>(n) > sy.size())
        sy.push_back(std::sin(n * pi * p.impact_y / p.length_y));
      const double W = sx * sy[static_cast<std::size_t>(n - 1)];
      if (W * W < kNodalShape) continue;
      if (!visit(m, n, W)) return;
    }
  }
}

}  // namespace

std::size_t count_plate_modes(const FinitePlate& p, double omega_cut) {
  std::size_t count = 0;
  for_each_excited_mode(p, omega_cut, [&](int, int, double) { return ++count, true; });
  return count;
}

PlateModes plate_modes(const FinitePlate& p, const PlateModeOptions& options) {
  if (!(options.omega_cut > 0.0 && std::isfinite(options.omega_cut)))
    throw std::invalid_argument("plate_modes: omega_cut must be finite and > 0");
  PlateModes out;
  out.omega_cut = options.omega_cut;
  out.modal_mass = p.density * p.thickness * p.length_x * p.length_y / 4.0;
  out.separable = separable_frequency(p);
  for_each_excited_mode(p, options.omega_cut, [&](int m, int n, double W) {
    if (out.modes.size() == options.max_modes) return false;  // one too many: counted below
    out.modes.push_back({m, n, plate_mode_frequency(p, m, n), W, W * W / out.modal_mass});
    return true;
  });
  if (const std::size_t count = out.modes.size() < options.max_modes
                                    ? out.modes.size()
                                    : count_plate_modes(p, options.omega_cut);
      count > options.max_modes)
    throw InputError("structure",
                     "the plate needs " + std::to_string(count) + " modes below " +
                         std::to_string(options.omega_cut) + " rad/s, more than the limit of " +
                         std::to_string(options.max_modes) +
                         ": the plate is large against the contact (no wave returns during it), "
                         "so the infinite plate (remove length_x, length_y) may be the model "
                         "wanted");
  std::sort(out.modes.begin(), out.modes.end(),
            [](const PlateMode& x, const PlateMode& y) { return x.omega < y.omega; });
  out.static_compliance =
      options.static_compliance ? *options.static_compliance : plate_static_compliance(p);
  double kept = 0.0;
  for (auto it = out.modes.rbegin(); it != out.modes.rend(); ++it)  // small terms first
    kept += it->gain / (it->omega * it->omega);
  out.kept_compliance = kept;
  out.residual_compliance = out.static_compliance.value - kept;
  if (options.residual_moment)
    out.residual_moment = dropped_compliance_moment(p, options.omega_cut);
  return out;
}

double plate_gain_density(const FinitePlate& p) {
  const OrthotropicBending& d = p.bending;
  const double H = d.D12 + 2.0 * d.D66;
  // Q(phi)^(-1/2) is even about 0 and pi/2 (a smooth periodic function of 2 phi), so the
  // trapezoidal rule over [0, pi/2] converges geometrically; 64 panels are exact to rounding for
  // any D11/D22 up to ~1e3
  constexpr int kPanels = 64;
  double I = 0.0;
  for (int j = 0; j <= kPanels; ++j) {
    const double phi = 0.5 * pi * j / kPanels, c2 = std::cos(phi) * std::cos(phi),
                 s2 = std::sin(phi) * std::sin(phi);
    const double Q = d.D11 * c2 * c2 + 2.0 * H * c2 * s2 + d.D22 * s2 * s2;
    I += (j == 0 || j == kPanels ? 0.5 : 1.0) / std::sqrt(Q);
  }
  I *= 0.5 * pi / kPanels;
  return I / (2.0 * pi * pi * std::sqrt(p.density * p.thickness));
}

// The modes are visited as for_each_excited_mode does, but the bounds compare omega^2 (pi^4/(rho h)
// times the quartic form k(m, n) of plate_mode_frequency) instead of omega, so a mode costs no
// square root, and a row m whose sin(m pi x0/a)^2 is below kNodalShape (every W of it is) is
// skipped whole: callgrind, the 5 mm ball at cut-off 20 (~3500 excited modes to 8 omega_cut),
// 0.74M -> 0.34M instructions a call, D_res the same to rounding. Where omega^2 lies within 1e-12
// of omega_cut^2 the mode is decided by plate_mode_frequency itself, as plate_modes() decides what
// it keeps.
double dropped_compliance_moment(const FinitePlate& p, double omega_cut, double reach) {
  const double modal_mass = p.density * p.thickness * p.length_x * p.length_y / 4.0;
  const double Omega = reach * omega_cut;
  const OrthotropicBending& d = p.bending;
  const double H2 = 2.0 * (d.D12 + 2.0 * d.D66),
               to_omega2 = pi * pi * pi * pi / (p.density * p.thickness);
  const double cut2 = omega_cut * omega_cut, reach2 = Omega * Omega;
  const double inv_a = 1.0 / p.length_x, inv_b = 1.0 / p.length_y;
  std::vector<double> sy;
  double sum = 0.0;  // positive terms: rounding ~ 1e-16 of the sum per term, in any order
  for (int m = 1;; ++m) {
    const double x = m * inv_a, x2 = x * x, row = d.D11 * x2 * x2, mixed = H2 * x2;
    auto omega2 = [&](int n) {
      const double y = n * inv_b, y2 = y * y;
      return to_omega2 * (row + mixed * y2 + d.D22 * y2 * y2);
    };
    if (!(omega2(1) <= reach2)) break;
    const double sx = std::sin(m * pi * p.impact_x / p.length_x);
    if (sx * sx < kNodalShape) continue;  // a nodal line: every W of the row is below it
    for (int n = 1;; ++n) {
      const double w2 = omega2(n);
      if (!(w2 <= reach2)) break;
      if (static_cast<std::size_t>(n) > sy.size())
        sy.push_back(std::sin(n * pi * p.impact_y / p.length_y));
      const double W = sx * sy[static_cast<std::size_t>(n - 1)];
      if (W * W < kNodalShape) continue;
      const bool dropped = std::abs(w2 - cut2) <= 1e-12 * cut2
                               ? plate_mode_frequency(p, m, n) > omega_cut
                               : w2 > cut2;
      if (dropped) sum += W * W / (w2 * w2);
    }
  }
  return sum / modal_mass + plate_gain_density(p) / (3.0 * Omega * Omega * Omega);
}

ResidualOscillator residual_oscillator(const PlateModes& modes) {
  const double C = modes.residual_compliance, D = modes.residual_moment;
  if (!(C > 0.0 && D > 0.0 && std::isfinite(C) && std::isfinite(D)))
    throw std::invalid_argument(
        "residual_oscillator: needs C_res > 0 and D_res > 0 (plate_modes() with "
        "residual_moment); got C_res " +
        std::to_string(C) + ", D_res " + std::to_string(D));
  const double omega2 = C / D;
  return {std::sqrt(omega2), C * omega2};
}

PlateModes static_plate_modes(const FinitePlate& p) {
  PlateModes out;
  out.omega_cut = 0.0;
  out.modal_mass = p.density * p.thickness * p.length_x * p.length_y / 4.0;
  out.static_compliance = plate_static_compliance(p);
  out.residual_compliance = out.static_compliance.value;
  return out;
}

}  // namespace ivv
