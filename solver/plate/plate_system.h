// The right-hand side of the plate impact in normalised variables (plate_impact.h), a system
// in the odeint sense, sys(x, dxdt, t), over the state
//   x = [alpha, alpha', u_1, u_1', ..., u_N, u_N']   (alpha/L, alpha'/v0, u/L, u'/v0; t/T)
// with the contact force from the law on its current branch through F = f(z_kin - C_res F).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/laws/law.h"
#include "solver/plate/plate_modes.h"

namespace ivv {

template <class Law>
class PlateSystem {
 public:
  using state_type = std::vector<double>;
  using value_type = double;
  using History = history_t<Law, double>;

  // Modes from plate_modes(); m [kg] the impactor's mass; `dropped` what the modes above the
  // cut-off are (plate_modes.h): nothing, C_res in series with the spring, or the equivalent
  // oscillator, then the last mode of this system (its omega_e is above every kept mode's, so
  // the order by omega holds) and no C_res.
  PlateSystem(const Law& law, const Scales& k, const PlateModes& modes, double m,
              DroppedModes dropped)
      : law_(law), length_(k.length), force_scale_(k.force) {
    const double T = k.time;
    auto add = [&](double omega, double gain, std::array<int, 2> mn) {
      omega_.push_back(omega * T);
      omega2_.push_back(omega * T * omega * T);
      gain_.push_back(gain * m);
      lattice_.push_back(mn);
    };
    for (const PlateMode& md : modes.modes) add(md.omega, md.gain, {md.m, md.n});
    if (dropped == DroppedModes::oscillator) {
      const ResidualOscillator e = residual_oscillator(modes);
      add(e.omega, e.gain, {0, 0});  // off the lattice
    }
    separable_ = {modes.separable.along_x * T, modes.separable.along_y * T};
    compliance_ =
        dropped == DroppedModes::static_compliance ? modes.residual_compliance * m / (T * T) : 0.0;
  }

  std::size_t modes() const { return omega_.size(); }
  std::size_t size() const { return 2 + 2 * omega_.size(); }
  double omega(std::size_t k) const { return omega_[k]; }
  double gain(std::size_t k) const { return gain_[k]; }
  double compliance() const { return compliance_; }  // C_res, normalised
  // {m, n} of mode k ({0, 0}: the equivalent oscillator) and the split of omega_mn, normalised
  // (mode_phases.h)
  std::array<int, 2> lattice(std::size_t k) const { return lattice_[k]; }
  SeparableFrequency separable() const { return separable_; }
  double length() const { return length_; }            // L [m]
  double force_scale() const { return force_scale_; }  // [N]

  History history;  // the law's branch, changed by the driver at events only

  // z_kin = alpha - sum u_k and its rate alpha' - sum u_k'
  static double z_kin(const state_type& x) {
    double w = 0.0;
    for (std::size_t i = x.size() - 2; i >= 2; i -= 2) w += x[i];
    return x[0] - w;
  }
  static double z_kin_rate(const state_type& x) {
    double w = 0.0;
    for (std::size_t i = x.size() - 1; i >= 3; i -= 2) w += x[i];
    return x[1] - w;
  }

  // {z_kin, its rate} in one pass over the state (the event locator's functionals).
  static std::array<double, 2> kinematic_gap(const state_type& x) {
    double w = 0.0, w_rate = 0.0;
    for (std::size_t i = 2; i + 1 < x.size(); i += 2) {
      w += x[i];
      w_rate += x[i + 1];
    }
    return {x[0] - w, x[1] - w_rate};
  }

  // The law's force and stiffness at normalised z on the current branch.
  double law_force(double z) const { return law_.force(history, z * length_, 0.0) / force_scale_; }
  double law_stiffness(double z) const {
    return law_.stiffness(history, z * length_, 0.0) * length_ / force_scale_;
  }

  // F solving F = f(z_kin - C F) (plate_impact.h); NaN, and failure() says why, when the
  // safeguarded Newton iteration does not converge in 200 steps.
  double force(double zk) const {
    const double f0 = law_force(zk);
    if (compliance_ == 0.0 || f0 == 0.0 || !std::isfinite(f0)) return f0;
    double lo = std::min(0.0, f0), hi = std::max(0.0, f0);
    double F = f0 / (1.0 + compliance_ * law_stiffness(zk));
    for (int it = 0; it < 200; ++it) {
      const double z = zk - compliance_ * F;
      const double G = F - law_force(z);
      if (G == 0.0) return F;
      (G > 0.0 ? hi : lo) = F;
      double next = F - G / (1.0 + compliance_ * law_stiffness(z));
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      if (std::abs(next - F) <= 4e-16 * std::abs(next) + 1e-300 ||
          hi - lo <= 4e-16 * std::max(std::abs(lo), std::abs(hi)))
        return next;
      F = next;
    }
    failure_ = "the contact force F = f(z_kin - C_res F) did not converge at z_kin = " +
               std::to_string(zk);
    return std::numeric_limits<double>::quiet_NaN();
  }
  // The spring deformation z = z_kin - C F of a state.
  double spring(const state_type& x) const {
    const double zk = z_kin(x);
    return zk - compliance_ * force(zk);
  }

  void operator()(const state_type& x, state_type& dxdt, double) const {
    ++evaluations_;
    const double F = force(z_kin(x));
    dxdt[0] = x[1];
    dxdt[1] = -F;
    for (std::size_t k = 0, i = 2; k < omega_.size(); ++k, i += 2) {
      dxdt[i] = x[i + 1];
      dxdt[i + 1] = -omega2_[k] * x[i] + gain_[k] * F;
    }
  }

  // E_plate = sum (u'^2 + omega^2 u^2)/(2 g), normalised by m v0^2.
  double plate_energy(const state_type& x) const {
    double e = 0.0;
    for (std::size_t k = 0, i = 2; k < omega_.size(); ++k, i += 2)
      e += (x[i + 1] * x[i + 1] + omega2_[k] * x[i] * x[i]) / (2.0 * gain_[k]);
    return e;
  }

  const std::string& failure() const { return failure_; }
  long evaluations() const { return evaluations_; }

 private:
  Law law_;
  double length_, force_scale_;
  std::vector<double> omega_, omega2_, gain_;
  std::vector<std::array<int, 2>> lattice_;
  SeparableFrequency separable_;
  double compliance_ = 0.0;
  mutable std::string failure_;
  mutable long evaluations_ = 0;
};

}  // namespace ivv
