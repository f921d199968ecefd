// The phases cos(omega_k t), sin(omega_k t) of every kept plate mode at one t, by products of
// per-m and per-n rotations where the plate allows it.
//
// The plate's frequency (plate_modes.h) is omega_mn = pi^2 sqrt(Q(m/a, n/b)/(rho h)), Q(x, y) =
// D11 x^4 + 2 H x^2 y^2 + D22 y^4. When D11 D22 = H^2 (every isotropic plate, D11 = D22 = H = D)
// Q is the square (sqrt(D11) x^2 + sqrt(D22) y^2)^2, so the frequency is a sum
//   omega_mn = A_m + B_n,   A_m = pi^2 sqrt(D11/(rho h)) (m/a)^2,   B_n = pi^2 sqrt(D22/(rho h))
//   (n/b)^2
// [rad/s], and exp(i omega_mn t) = exp(i A_m t) exp(i B_n t): one sin and cos per distinct m and
// per distinct n (tens) and one complex product per mode, instead of a sin and a cos per mode
// (hundreds). Guard: a mode is taken by the product only when it is on the lattice (m, n >= 1;
// the equivalent oscillator of the dropped modes is not) and its own omega_k agrees with A_m +
// B_n to kSeparableRounding relative; every other mode, and every mode of a plate whose
// frequency does not separate, calls sin and cos. The two agree to rounding: the phase differs
// by at most kSeparableRounding omega t, the product adds 2 eps (mode_phases_test.cc).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace ivv {

// |omega_k - (A_m + B_n)| <= this times omega_k for the product (header): a few roundings of
// the frequency formula's square root against the sum's.
inline constexpr double kSeparableRounding = 16.0 * 2.220446049250313e-16;

// A_m = along_x m^2, B_n = along_y n^2 (header); both 0: the frequency does not separate.
struct SeparableFrequency {
  double along_x = 0.0, along_y = 0.0;  // [rad/s] (or normalised, as the omegas are)
  bool separates() const { return along_x > 0.0 && along_y > 0.0; }
};

class ModePhases {
 public:
  ModePhases() = default;
  // omega[k]: the modes' frequencies; lattice[k] = {m, n} of mode k, {0, 0} when it has none.
  ModePhases(const std::vector<double>& omega, const std::vector<std::array<int, 2>>& lattice,
             SeparableFrequency split)
      : omega_(omega), split_(split) {
    const bool separates = split.separates() && lattice.size() == omega.size();
    pair_.assign(omega.size(), {-1, -1});
    for (std::size_t k = 0; separates && k < omega.size(); ++k) {
      const int m = lattice[k][0], n = lattice[k][1];
      if (m < 1 || n < 1) continue;
      const double sum = split.along_x * m * m + split.along_y * n * n;
      if (!(std::abs(sum - omega[k]) <= kSeparableRounding * omega[k])) continue;
      pair_[k] = {m, n};
      max_m_ = std::max(max_m_, m), max_n_ = std::max(max_n_, n);
      ++on_lattice_;
    }
  }

  std::size_t size() const { return omega_.size(); }
  // The modes whose phase is a product (the rest call sin and cos).
  std::size_t on_lattice() const { return on_lattice_; }

  // c[k] = cos(omega_k t), s[k] = sin(omega_k t), first <= k < size() (c, s resized; the
  // entries below `first` are left as they were).
  void at(double t, std::vector<double>& c, std::vector<double>& s, std::size_t first = 0) const {
    const std::size_t N = omega_.size();
    c.resize(N), s.resize(N);
    if (first >= N) return;
    rotations(split_.along_x, max_m_, t, cx_, sx_);
    rotations(split_.along_y, max_n_, t, cy_, sy_);
    for (std::size_t k = first; k < N; ++k) {
      const auto [m, n] = pair_[k];
      if (m < 0) {
        c[k] = std::cos(omega_[k] * t), s[k] = std::sin(omega_[k] * t);
        continue;
      }
      const double a = cx_[m], b = sx_[m], p = cy_[n], q = sy_[n];
      c[k] = a * p - b * q;
      s[k] = b * p + a * q;
    }
  }

 private:
  // c[j] = cos(rate j^2 t), s[j] = sin(rate j^2 t), j = 1 .. count
  static void rotations(double rate, int count, double t, std::vector<double>& c,
                        std::vector<double>& s) {
    c.resize(static_cast<std::size_t>(count) + 1), s.resize(static_cast<std::size_t>(count) + 1);
    for (int j = 1; j <= count; ++j) {
      const double x = rate * j * j * t;
      c[static_cast<std::size_t>(j)] = std::cos(x), s[static_cast<std::size_t>(j)] = std::sin(x);
    }
  }

  std::vector<double> omega_;
  SeparableFrequency split_;
  std::vector<std::array<int, 2>> pair_;  // {m, n} of a product mode, {-1, -1} otherwise
  int max_m_ = 0, max_n_ = 0;
  std::size_t on_lattice_ = 0;
  mutable std::vector<double> cx_, sx_, cy_, sy_;  // scratch of at()
};

}  // namespace ivv
