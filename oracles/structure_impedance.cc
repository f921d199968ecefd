#include "oracles/structure_impedance.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ivv::oracles {

ModalImpedance plate_impedance_from_modes(double rho, double h, double D, double a, double b,
                                          double k1, double k2) {
  if (!(rho > 0 && h > 0 && D > 0 && a > 0 && b > 0 && k1 > 0 && k2 > k1))
    throw std::invalid_argument("plate_impedance_from_modes: inputs must be > 0 and k2 > k1");
  const double pi = std::numbers::pi;
  // count (m, n) >= 1 with k1^2 <= (m pi/a)^2 + (n pi/b)^2 < k2^2
  long long count = 0;
  const long long m_max = static_cast<long long>(k2 * a / pi) + 1;
  for (long long m = 1; m <= m_max; ++m) {
    const double km2 = (m * pi / a) * (m * pi / a);
    if (km2 >= k2 * k2) break;
    const double lo = k1 * k1 - km2, hi = k2 * k2 - km2;
    long long n_lo = lo <= 0.0 ? 1 : static_cast<long long>(std::ceil(std::sqrt(lo) * b / pi));
    if (n_lo < 1) n_lo = 1;
    long long n_hi = static_cast<long long>(std::ceil(std::sqrt(hi) * b / pi)) - 1;  // < k2
    if (n_hi >= n_lo) count += n_hi - n_lo + 1;
  }
  if (count == 0) throw std::invalid_argument("plate_impedance_from_modes: no mode in the band");
  const double M = rho * h * a * b;
  const double band = std::sqrt(D / (rho * h)) * (k2 * k2 - k1 * k1);  // omega2 - omega1
  // <Re Y> = (pi/2) N <phi^2> / (M band), <phi^2> = 1
  ModalImpedance out;
  out.modes = count;
  out.c = 2.0 * M * band / (pi * static_cast<double>(count));
  out.boundary_term = 2.0 * (a + b) / (a * b * (k1 + k2));
  return out;
}

ModalImpedance bar_impedance_from_modes(double A, double E, double rho, double L, long long n_first,
                                        long long n_last) {
  if (!(A > 0 && E > 0 && rho > 0 && L > 0 && n_first >= 1 && n_last >= n_first))
    throw std::invalid_argument("bar_impedance_from_modes: inputs must be > 0, n_last >= n_first");
  const double pi = std::numbers::pi, cL = std::sqrt(E / rho);
  auto omega = [&](double n) { return (2.0 * n - 1.0) * pi * cL / (2.0 * L); };
  // band edges half-way between modes: [omega(n_first - 1/2), omega(n_last + 1/2)]
  const double band =
      omega(static_cast<double>(n_last) + 0.5) - omega(static_cast<double>(n_first) - 0.5);
  const long long count = n_last - n_first + 1;
  const double M = rho * A * L;
  // <Re Y> = (pi/2) N phi(L)^2 / (M band), phi(L)^2 = 2
  ModalImpedance out;
  out.modes = count;
  out.c = M * band / (pi * static_cast<double>(count));
  return out;
}

}  // namespace ivv::oracles
