#include "oracles/plate_convolution.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <optional>
#include <stdexcept>

#include "scene/input_error.h"
#include "solver/laws/law.h"

namespace ivv {
namespace {

// The vertex of the parabola through (-1, y0), (0, y1), (1, y2): offset and value, or nullopt
// when the three points are not a strict maximum.
struct Vertex {
  double offset, value;
};
std::optional<Vertex> parabola_maximum(double y0, double y1, double y2) {
  const double curvature = y0 - 2.0 * y1 + y2;
  if (!(curvature < 0.0) || y1 < y0 || y1 < y2) return std::nullopt;
  const double s = (y0 - y2) / (2.0 * curvature);
  return Vertex{s, y1 - (y2 - y0) * (y2 - y0) / (8.0 * curvature)};
}

template <class Law>
class ConvolutionMarch {
 public:
  using History = history_t<Law, double>;

  ConvolutionMarch(const Law& law, const Scene& scene, const DerivedParameters& p,
                   const PlateModes& modes, const ConvolutionOptions& opt)
      : law_(law),
        m_(p.effective_mass),
        v0_(scene.velocity),
        dt_(opt.dt),
        t_max_(opt.t_max),
        C_(opt.residual ? modes.residual_compliance : 0.0),
        record_(opt.record_force) {
    for (const PlateMode& md : modes.modes) {
      omega_.push_back(md.omega);
      gain_.push_back(md.gain);
    }
  }

  ConvolutionResult run() {
    ConvolutionResult out;
    v_ = v0_;
    force_.push_back(0.0);
    begin_contact(0.0, 0.0);
    for (;;) {
      if ((n_ + 1) * dt_ > t_max_) {
        out.reason = "no end of the impact before t_max = " + std::to_string(t_max_) + " s";
        return out;
      }
      step(out);
      if (done_) break;
    }
    out.ok = true;
    out.e = -v_ / v0_;
    out.steps = n_;
    out.F_max = 0.0;
    for (const auto& c : out.contacts) out.F_max = std::max(out.F_max, c.peak_force);
    out.t_contact = out.contacts.front().t_end - out.contacts.front().t_start;
    out.dt = dt_;
    if (record_) out.force = force_;
    return out;
  }

 private:
  // h(k dt) = sum g sin(omega k dt)/omega, tabulated as the lags are first needed
  double response(long k) {
    while (static_cast<long>(h_.size()) <= k) {
      const double t = static_cast<double>(h_.size()) * dt_;
      double h = 0.0;
      for (std::size_t i = omega_.size(); i-- > 0;)
        h += gain_[i] * std::sin(omega_[i] * t) / omega_[i];
      h_.push_back(h);
    }
    return h_[static_cast<std::size_t>(k)];
  }

  // dt sum_{j <= n} c_j h((n + 1 - j) dt) F_j: the memory part of w at t_{n+1}
  double memory() {
    double w = 0.0;
    for (const long j : active_) w += (j == 0 ? 0.5 : 1.0) * response(n_ + 1 - j) * force_[j];
    return dt_ * w;
  }

  double law_force(double z) const { return law_.force(history_, z, 0.0); }

  // F = f(zk - C F) on the current branch (monotone in F: one root in the bracket)
  double solve(double zk) const {
    const double f0 = law_force(zk);
    if (C_ == 0.0 || f0 == 0.0) return f0;
    double lo = std::min(0.0, f0), hi = std::max(0.0, f0), F = 0.5 * (lo + hi);
    for (int it = 0; it < 300 && hi - lo > 1e-15 * std::max(std::abs(lo), std::abs(hi)); ++it) {
      const double z = zk - C_ * F;
      const double G = F - law_force(z);
      (G > 0.0 ? hi : lo) = F;
      double next = F - G / (1.0 + C_ * law_.stiffness(history_, z, 0.0));
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      F = next;
    }
    return F;
  }

  void begin_contact(double t_start, double z_start) {
    in_contact_ = true;
    contact_ = ConvolutionContact{t_start, 0.0, 0.0};
    z_prev_ = {z_start, z_start};
  }

  // The force at t_{n+1} in contact, with the branch changes between t_n and t_{n+1}.
  double contact_force(double zk) {
    double F = solve(zk);
    double z = zk - C_ * F;
    if (history_.phase == Phase::loading) {
      const std::optional<double> z_end = law_segment_end(law_, history_);
      if (z_end && z > *z_end) {
        law_next_segment(law_, history_);
        F = solve(zk);
        z = zk - C_ * F;
      }
      if (z < z_prev_[1]) {  // a maximum of z was passed: unload from its parabola's vertex
        const auto v = parabola_maximum(z_prev_[0], z_prev_[1], z);
        loading_ = history_;
        law_begin_unloading(law_, history_, v ? v->value : z_prev_[1]);
        F = solve(zk);
        z = zk - C_ * F;
      }
    } else if (z > static_cast<double>(history_.z_max)) {  // reloading past z_m
      history_ = loading_;
      F = solve(zk);
      z = zk - C_ * F;
    }
    z_prev_ = {z_prev_[1], z};
    return F;
  }

  void step(ConvolutionResult& out);
  void on_separation(ConvolutionResult& out, double F_raw);
  double excursion_bound() const;

  Law law_;
  double m_, v0_, dt_, t_max_, C_;
  bool record_;
  std::vector<double> omega_, gain_, h_, force_;
  std::vector<long> active_;  // grid indices with F != 0
  History history_{}, loading_{};
  double alpha_ = 0.0, v_ = 0.0, bound_ = 0.0;
  long n_ = 0;
  bool in_contact_ = false, done_ = false;
  ConvolutionContact contact_;
  std::array<double, 2> z_prev_{};
  std::array<double, 2> f_prev_{};  // F_{n-1}, F_n for the peak's parabola
  double last_zk_ = 0.0;            // z_kin at t_n
};

template <class Law>
void ConvolutionMarch<Law>::step(ConvolutionResult& out) {
  const double Fn = force_[static_cast<std::size_t>(n_)];
  const double alpha = alpha_ + dt_ * v_ - 0.5 * dt_ * dt_ * Fn / m_;
  const double zk = alpha - memory();
  const double z0 = static_cast<double>(history_.z_perm);
  double F = 0.0;
  if (!in_contact_ && zk > z0) {  // onset between t_n and t_{n+1}
    const double zk_n = alpha_ - (n_ == 0 ? 0.0 : last_zk_);
    const double frac = zk_n < z0 ? (z0 - zk_n) / (zk - zk_n) : 0.0;
    begin_contact((static_cast<double>(n_) + frac) * dt_, z0);
  }
  if (in_contact_) F = contact_force(zk);
  last_zk_ = zk;
  alpha_ = alpha;
  ++n_;
  if (in_contact_ && !(F > 0.0)) {
    v_ -= 0.5 * dt_ * Fn / m_;
    force_.push_back(0.0);
    on_separation(out, F);
    return;
  }
  v_ -= 0.5 * dt_ * (Fn + F) / m_;
  force_.push_back(F);
  if (F != 0.0) active_.push_back(n_);
  if (in_contact_) {
    const auto peak = parabola_maximum(f_prev_[0], f_prev_[1], F);
    contact_.peak_force = std::max(contact_.peak_force, peak ? peak->value : F);
    f_prev_ = {f_prev_[1], F};
  } else if (v_ < 0.0 && alpha_ + bound_ < z0) {
    done_ = true;
  }
}

template <class Law>
void ConvolutionMarch<Law>::on_separation(ConvolutionResult& out, double F_raw) {
  const double F_n = force_[static_cast<std::size_t>(n_ - 1)];
  contact_.t_end = (static_cast<double>(n_ - 1) + F_n / (F_n - F_raw)) * dt_;
  out.contacts.push_back(contact_);
  if (out.contacts.size() == 1) out.e_first = -v_ / v0_;
  in_contact_ = false;
  f_prev_ = {0.0, 0.0};
  bound_ = excursion_bound();
  if (v_ < 0.0 && alpha_ + bound_ < static_cast<double>(history_.z_perm)) done_ = true;
}

// B = sum_k (g_k/omega_k) |dt sum_j c_j e^{-i omega_k t_j} F_j| (trapezoid; F = 0 at the ends)
template <class Law>
double ConvolutionMarch<Law>::excursion_bound() const {
  double B = 0.0;
  for (std::size_t k = 0; k < omega_.size(); ++k) {
    std::complex<double> c = 0.0;
    for (const long j : active_)
      c += std::polar(force_[static_cast<std::size_t>(j)],
                      -omega_[k] * static_cast<double>(j) * dt_);
    B += gain_[k] / omega_[k] * std::abs(c) * dt_;
  }
  return B;
}

}  // namespace

ConvolutionResult plate_impact_by_convolution(const Scene& scene, LawKind law,
                                              const LawParameters& parameters,
                                              const PlateModes& modes,
                                              const ConvolutionOptions& options) {
  if (!(options.dt > 0.0)) throw std::invalid_argument("plate convolution: dt must be > 0");
  validate(scene);
  const LawInfo& info = law_info(law);
  if (law == LawKind::expression || info.rate_dependent)
    throw InputError("--law", std::string(info.name) + ": not modelled on a finite plate");
  validate_parameters(law, parameters);
  const DerivedParameters p = derive(scene);
  return with_builtin_law(law, parameters, p, [&](const auto& l) {
    using L = std::decay_t<decltype(l)>;
    if constexpr (L::rate_dependent) {
      return ConvolutionResult{};
    } else {
      ConvolutionMarch<L> march(l, scene, p, modes, options);
      try {
        return march.run();
      } catch (const LawDomainError& e) {
        ConvolutionResult r;
        r.reason = e.what();
        return r;
      }
    }
  });
}

}  // namespace ivv
