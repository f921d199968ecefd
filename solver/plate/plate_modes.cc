#include "solver/plate/plate_modes.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <string>

#include "scene/input_error.h"

namespace ivv {
namespace {

using cplx = std::complex<double>;
constexpr double pi = std::numbers::pi;

// Exponentials below this are dropped against 1 (the m-term is then exactly its asymptote).
constexpr double kNegligibleExponent = 40.0;  // e^-40 = 4e-18

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

// sum_{m > M} m^-3 by Euler-Maclaurin: 1/(2M^2) - 1/(2M^3) + 1/(4M^4) - 1/(12M^6) + O(M^-8).
double zeta3_tail(double M) {
  const double M2 = M * M;
  return 1.0 / (2.0 * M2) - 1.0 / (2.0 * M2 * M) + 1.0 / (4.0 * M2 * M2) -
         1.0 / (12.0 * M2 * M2 * M2);
}

}  // namespace

double plate_mode_frequency(const FinitePlate& p, int m, int n) {
  const OrthotropicBending& d = p.bending;
  const double x = m / p.length_x, y = n / p.length_y;
  const double x2 = x * x, y2 = y * y;
  const double k = d.D11 * x2 * x2 + 2.0 * (d.D12 + 2.0 * d.D66) * x2 * y2 + d.D22 * y2 * y2;
  return pi * pi * std::sqrt(k / (p.density * p.thickness));
}

StaticCompliance plate_static_compliance(const FinitePlate& p) {
  const double a = p.length_x, b = p.length_y;
  const double xi = p.impact_x / a, eta = p.impact_y / b;
  const double theta = 2.0 * pi * eta;
  const Roots unit = unit_roots(p.bending);
  const double prefactor = 4.0 / (a * b) * std::pow(b, 4) / (std::pow(pi, 4) * p.bending.D22);
  // c = mu c_hat; the exponentials e^{-c min(theta, 2 pi - theta)} negligible from M on
  const double c_hat_min = std::min(std::sqrt(unit.r1).real(), std::sqrt(unit.r2).real());
  const double theta_min = std::min(theta, 2.0 * pi - theta);
  const double M_exp = kNegligibleExponent / (c_hat_min * (b / a) * theta_min);
  const int M = static_cast<int>(std::clamp(std::ceil(M_exp), 2000.0, 2.0e7));
  double sum = 0.0;
  for (int m = M; m >= 1; --m) {  // small terms first
    const double s = std::sin(m * pi * xi);
    sum += s * s * inner_sum(unit, m * b / a, theta);
  }
  // the asymptote K sin^2(m pi xi)/m^3: S_m -> (pi/4)/(c1 c2 (c1 + c2)), c_i = m (b/a) c_hat_i
  const cplx c1 = std::sqrt(unit.r1) * (b / a), c2 = std::sqrt(unit.r2) * (b / a);
  const double K = prefactor * (pi / 4.0 / (c1 * c2 * (c1 + c2))).real();
  StaticCompliance out;
  out.terms = M;
  out.value = prefactor * sum + 0.5 * K * zeta3_tail(M);
  out.tail_bound = 0.5 * K / (std::pow(M + 1.0, 3) * std::sin(pi * xi));
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

std::size_t count_plate_modes(const FinitePlate& p, double omega_cut) {
  std::size_t count = 0;
  for (int m = 1; plate_mode_frequency(p, m, 1) <= omega_cut; ++m) {
    const double sx = std::sin(m * pi * p.impact_x / p.length_x);
    for (int n = 1; plate_mode_frequency(p, m, n) <= omega_cut; ++n) {
      const double sy = std::sin(n * pi * p.impact_y / p.length_y);
      if (sx * sx * sy * sy >= kNodalShape) ++count;
    }
  }
  return count;
}

PlateModes plate_modes(const FinitePlate& p, const PlateModeOptions& options) {
  if (!(options.omega_cut > 0.0 && std::isfinite(options.omega_cut)))
    throw std::invalid_argument("plate_modes: omega_cut must be finite and > 0");
  const std::size_t count = count_plate_modes(p, options.omega_cut);
  if (count > options.max_modes)
    throw InputError("structure",
                     "the plate needs " + std::to_string(count) + " modes below " +
                         std::to_string(options.omega_cut) + " rad/s, more than the limit of " +
                         std::to_string(options.max_modes) +
                         ": the plate is large against the contact (no wave returns during it), "
                         "so the infinite plate (remove length_x, length_y) may be the model "
                         "wanted");
  PlateModes out;
  out.omega_cut = options.omega_cut;
  out.modal_mass = p.density * p.thickness * p.length_x * p.length_y / 4.0;
  out.modes.reserve(count);
  for (int m = 1; plate_mode_frequency(p, m, 1) <= options.omega_cut; ++m) {
    const double sx = std::sin(m * pi * p.impact_x / p.length_x);
    for (int n = 1; plate_mode_frequency(p, m, n) <= options.omega_cut; ++n) {
      const double W = sx * std::sin(n * pi * p.impact_y / p.length_y);
      if (W * W < kNodalShape) continue;
      out.modes.push_back({m, n, plate_mode_frequency(p, m, n), W, W * W / out.modal_mass});
    }
  }
  std::sort(out.modes.begin(), out.modes.end(),
            [](const PlateMode& x, const PlateMode& y) { return x.omega < y.omega; });
  out.static_compliance =
      options.static_compliance ? *options.static_compliance : plate_static_compliance(p);
  double kept = 0.0;
  for (auto it = out.modes.rbegin(); it != out.modes.rend(); ++it)  // small terms first
    kept += it->gain / (it->omega * it->omega);
  out.kept_compliance = kept;
  out.residual_compliance = out.static_compliance.value - kept;
  return out;
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
