#include "closed_forms/linear_model.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>
#include <sstream>

#include "scene/input_error.h"

namespace ivv::closed_forms {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void validate(const LinearModelInput& in) {
  require_positive("mass", in.mass);
  require_positive("K_h", in.K_h);
  require_positive("K_y", in.K_y);
  require_positive("v0", in.v0);
  if (!(std::isfinite(in.zeta) && in.zeta >= 0.0)) {
    std::ostringstream os;
    os << "must be >= 0 and finite (0 = no dashpot), got " << in.zeta;
    throw InputError("zeta", os.str());
  }
}

// One phase of the model: w'' + 2 a w' + omega^2 w = 0, force F = K w, so the mass is
// m = K/omega^2 and the dashpot 1/c = 2a/K (loading: a = zeta omega0, K = K_y; unloading:
// a = zeta omega0/gamma^2, K = K_y/gamma^2: both give 1/c = 2 zeta omega0/K_y).
struct Phase {
  double a = 0.0;      // decay rate [1/s]
  double omega = 0.0;  // natural frequency [rad/s]
  double K = 0.0;      // stiffness [N/m]
  double ratio() const { return a / omega; }
};

struct PhaseState {
  double w = 0.0;
  double w_dot = 0.0;
};

// Exact solution at time s from (w0, w_dot0). Written with C(s) = e^{-as} cos(bs) and
// S(s) = e^{-as} sin(bs)/b (b^2 = omega^2 - a^2), and their hyperbolic and critical
// (S = s e^{-as}) counterparts, so every regime is continuous at a = omega:
//   w = w0 C + (w_dot0 + a w0) S,  w' = w_dot0 C - (a w_dot0 + omega^2 w0) S.
PhaseState evolve(const Phase& p, double w0, double w_dot0, double s) {
  const double zeta = p.ratio();
  double C = 0.0;
  double S = 0.0;
  if (zeta < 1.0) {
    const double b = p.omega * std::sqrt((1.0 - zeta) * (1.0 + zeta));
    const double decay = std::exp(-p.a * s);
    C = decay * std::cos(b * s);
    S = decay * std::sin(b * s) / b;
  } else if (zeta == 1.0) {
    const double decay = std::exp(-p.a * s);
    C = decay;
    S = s * decay;
  } else {
    // Roots r1 = -omega^2/(a + beta) (slow, written without cancellation), r2 = -(a + beta).
    const double beta = p.omega * std::sqrt((zeta - 1.0) * (zeta + 1.0));
    const double r1 = -p.omega * p.omega / (p.a + beta);
    const double r2 = -(p.a + beta);
    C = 0.5 * (std::exp(r1 * s) + std::exp(r2 * s));
    S = std::exp(r1 * s) * (-std::expm1(-2.0 * beta * s)) / (2.0 * beta);
  }
  return {w0 * C + (w_dot0 + p.a * w0) * S,
          w_dot0 * C - (p.a * w_dot0 + p.omega * p.omega * w0) * S};
}

struct PhaseIntegrals {
  double impulse = 0.0;  // integral F ds [N s]
  double W_v = 0.0;      // integral F^2/c ds [J]
};

// Damping ratio up to which the direct exponential-trigonometric integrals are used. Above it
// (towards critical damping, where the sin(bs)/b representation loses digits to cancellation)
// the phase identities below are used; they are exact in every regime.
constexpr double kDirectIntegralMaxRatio = 0.5;

// Integrals of one phase over [0, T] (T may be +inf when a > 0), given the end state.
//
// Underdamped, direct: w = A e^{-as} sin(bs + phi), p = -a + ib,
//   integral w ds   = A Im[e^{i phi} (e^{pT} - 1)/p]
//   2a integral w^2 = A^2 (1/2)[-expm1(-2aT) - 2a Re(e^{2 i phi}(e^{2pT} - 1)/(2p))]
//   W_v = K^2/c integral w^2 = K (2a integral w^2).
// With X = (w'(0) + a w(0))/b, A e^{i phi} = X + i w(0), so e^{i phi} = (X + i w0)/A and
// e^{2 i phi} its square; e^{2pT} = (e^{pT})^2 and 1/p = conj(p)/|p|^2. e^{pT} = e^{-aT}
// (cos bT + i sin bT) is the caller's, who knows it from the phase's end without a sin, cos
// or exp (the linearized closed form is timed by `ivv bench` against a target of 0.3 us).
// Any regime, identities of the phase equation (multiply it by 1, by w', by w, integrate):
//   K integral w ds   = m [(w'(0) - w'(T)) + 2a (w(0) - w(T))]
//   W_v = 2aK integral w^2 = m (E(0) - E(T)) - 2 m a [w w']_0^T - 2 m a^2 [w^2]_0^T,
//   with E = w'^2/2 + omega^2 w^2/2 and m = K/omega^2.
PhaseIntegrals phase_integrals(const Phase& p, double w0, double w_dot0, double T,
                               const PhaseState& end, std::complex<double> epT) {
  const double zeta = p.ratio();
  if (zeta <= kDirectIntegralMaxRatio) {
    const double b = p.omega * std::sqrt((1.0 - zeta) * (1.0 + zeta));
    const double X = (w_dot0 + p.a * w0) / b;
    const std::complex<double> amplitude(X, w0);  // A e^{i phi}
    const std::complex<double> inverse_p = std::complex<double>(-p.a, -b) / (p.a * p.a + b * b);
    const double int_w = std::imag(amplitude * (epT - 1.0) * inverse_p);
    // A^2 e^{2 i phi} = amplitude^2
    const double two_a_int_w2 =
        0.5 * (std::norm(amplitude) * -std::expm1(-2.0 * p.a * T) -
               p.a * std::real(amplitude * amplitude * (epT * epT - 1.0) * inverse_p));
    return {p.K * int_w, p.K * two_a_int_w2};
  }
  const double m = p.K / (p.omega * p.omega);
  const double w2 = p.omega * p.omega;
  const double impulse = m * ((w_dot0 - end.w_dot) + 2.0 * p.a * (w0 - end.w));
  const double dE =
      0.5 * (w_dot0 * w_dot0 - end.w_dot * end.w_dot) + 0.5 * w2 * (w0 * w0 - end.w * end.w);
  const double W_v = m * dE - 2.0 * m * p.a * (end.w * end.w_dot - w0 * w_dot0) -
                     2.0 * m * p.a * p.a * (end.w * end.w - w0 * w0);
  return {impulse, W_v};
}

// Time of the first zero of z' in loading (z(0) = 0, z'(0) = v0), all regimes:
//   zeta < 1: acos(zeta)/(omega0 sqrt(1 - zeta^2)), written with atan2 for accuracy near 1;
//   zeta = 1: 1/omega0;  zeta > 1: acosh(zeta)/(omega0 sqrt(zeta^2 - 1)).
double loading_peak_time(double omega0, double zeta) {
  if (zeta < 1.0) {
    const double x = std::sqrt((1.0 - zeta) * (1.0 + zeta));
    return std::atan2(x, zeta) / (omega0 * x);
  }
  if (zeta == 1.0) return 1.0 / omega0;
  const double x = std::sqrt((zeta - 1.0) * (zeta + 1.0));
  return std::log1p((zeta - 1.0) + x) / (omega0 * x);  // acosh(zeta) = log1p(zeta - 1 + x)
}

}  // namespace

double damping_ratio(double mass, double K_y, double c) {
  if (c == kInf) return 0.0;
  return std::sqrt(mass * K_y) / (2.0 * c);
}

LinearModelInput linear_model_input(const Scene& scene, const DerivedParameters& p) {
  return {p.effective_mass, p.K_h, p.K_y, p.zeta, scene.velocity};
}

LinearizedLawUndefined::LinearizedLawUndefined(double z_max, double z_min)
    : std::domain_error([&] {
        std::ostringstream os;
        os.precision(6);
        os << "linearized law undefined: z_m = " << z_max
           << " m < (K_y/K_h)^2 = 2.25 z_y = " << z_min << " m (z_y = " << z_min / 2.25
           << " m); eq 17 needs z_m >= 2.25 z_y, i.e. a faster impact";
        return os.str();
      }()),
      z_max_(z_max),
      z_min_(z_min) {}

namespace {
// Loading. With z' = 0 at t_m, z_m = (v0/omega0) e^{-zeta omega0 t_m} in every regime
// (underdamped: z = (v0/b) e^{-at} sin(bt) and sin(b t_m) = b/omega0; the over-damped and
// critical forms reduce to the same expression).
double loading_z_max(const LinearModelInput& in, double omega0, double t_max) {
  return in.v0 / omega0 * std::exp(-in.zeta * omega0 * t_max);
}
double eq20_q(double mass, double K_h, double K_y, double v0);  // below, with eq 20
}  // namespace

bool linearized_law_defined(const LinearModelInput& in) {
  validate(in);
  const double omega0 = std::sqrt(in.K_y / in.mass);
  const double z_max = loading_z_max(in, omega0, loading_peak_time(omega0, in.zeta));
  // undamped, eq 20 asks the same question in its own rounding (q <= 1): both must agree
  if (in.zeta == 0 && eq20_q(in.mass, in.K_h, in.K_y, in.v0) > 1.0) return false;
  return !(z_max < (in.K_y / in.K_h) * (in.K_y / in.K_h));
}

LinearImpact solve_linear_model(const LinearModelInput& in) {
  validate(in);
  LinearImpact r;
  const double omega0 = std::sqrt(in.K_y / in.mass);
  const double zeta = in.zeta;
  const double v0 = in.v0;

  r.t_max = loading_peak_time(omega0, zeta);
  r.z_max = loading_z_max(in, omega0, r.t_max);
  r.F_max = in.K_y * r.z_max;
  r.alpha_dot_at_t_max = 2.0 * zeta * omega0 * r.z_max;  // F_max/c

  // Unloading law, eqs 17-18, with q = K_y/(K_h sqrt(z_m)) in [0, 1].
  const double z_min = (in.K_y / in.K_h) * (in.K_y / in.K_h);
  if (r.z_max < z_min) throw LinearizedLawUndefined(r.z_max, z_min);
  const double q = std::min(1.0, in.K_y / (in.K_h * std::sqrt(r.z_max)));
  const double log_one_minus_q_23 = (2.0 / 3.0) * std::log1p(-q);
  const double gamma2 = -std::expm1(log_one_minus_q_23);
  r.z_perm = r.z_max * std::exp(log_one_minus_q_23);
  r.gamma = std::sqrt(gamma2);
  r.omega_unload = omega0 / r.gamma;
  r.zeta_unload = zeta / r.gamma;

  const Phase loading{zeta * omega0, omega0, in.K_y};
  const Phase unloading{zeta * omega0 / gamma2, r.omega_unload, in.K_y / gamma2};
  const double w0 = gamma2 * r.z_max;  // z_m - z_f

  r.energy_initial = 0.5 * in.mass * v0 * v0;
  // Closed loop integral F dz: loading triangle minus unloading triangle (see header).
  r.W_p = 0.5 * in.K_y * r.z_max * r.z_max * (1.0 - gamma2);

  // e^{p t_m} of the loading phase: b t_m = atan2(x, zeta) with x = sqrt(1 - zeta^2), so
  // cos = zeta and sin = x, and e^{-a t_m} = z_m omega0/v0 (used where zeta <= 1/2 only)
  const double x0 = std::sqrt(std::max(0.0, (1.0 - zeta) * (1.0 + zeta)));
  const PhaseIntegrals load_int =
      phase_integrals(loading, 0.0, v0, r.t_max, PhaseState{r.z_max, 0.0},
                      (r.z_max * omega0 / v0) * std::complex<double>(zeta, x0));
  const double y_scale = 2.0 * zeta / omega0;  // m/c [s]

  r.captured = r.zeta_unload >= 1.0;
  if (r.captured) {
    // w -> 0 and w' -> 0 as t -> inf; the impactor comes to rest (alpha' -> 0+, monotone
    // because alpha'' = -F/m < 0), so t_c = inf and alpha_c = z_f + y(inf), y(inf) = m v0/c.
    const PhaseIntegrals unload_int =
        phase_integrals(unloading, w0, 0.0, kInf, PhaseState{0.0, 0.0}, 0.0);
    r.t_contact = kInf;
    r.e = 0.0;
    r.t_alpha_max = kInf;
    r.y_final = y_scale * v0;
    r.alpha_max = r.z_perm + r.y_final;
    r.impulse = load_int.impulse + unload_int.impulse;
    r.W_v = load_int.W_v + unload_int.W_v;
    r.energy_final = 0.0;
    return r;
  }

  const double zeta1 = r.zeta_unload;
  const double x1 = std::sqrt((1.0 - zeta1) * (1.0 + zeta1));
  const double phi1 = std::atan2(x1, zeta1);
  const double b1 = r.omega_unload * x1;
  const double s_f = (std::numbers::pi - phi1) / b1;
  const double s_c = (std::numbers::pi - 2.0 * phi1) / b1;
  const double decay_f = std::exp(-unloading.a * s_f);
  const double rebound = w0 * r.omega_unload * decay_f;  // -w'(s_f)
  r.t_contact = r.t_max + s_f;
  r.e = rebound / v0;
  r.t_alpha_max = r.t_max + s_c;
  r.y_final = y_scale * (v0 + rebound);
  // z(t_c) = z_f + w0 e^{-a1 s_c} (sin(b1 s_c + phi1) = sin(phi1)); y(t_c) = (m/c) v0.
  r.alpha_max = r.z_perm + w0 * std::exp(-unloading.a * s_c) + y_scale * v0;
  // e^{p s_f}: b1 s_f = pi - phi1, so cos = -zeta1 and sin = x1
  const PhaseIntegrals unload_int =
      phase_integrals(unloading, w0, 0.0, s_f, PhaseState{0.0, -rebound},
                      decay_f * std::complex<double>(-zeta1, x1));
  r.impulse = load_int.impulse + unload_int.impulse;
  r.W_v = load_int.W_v + unload_int.W_v;
  r.energy_final = 0.5 * in.mass * rebound * rebound;
  return r;
}

LinearState linear_model_state(const LinearModelInput& in, double t) {
  return linear_model_state(in, solve_linear_model(in), t);
}

LinearState linear_model_state(const LinearModelInput& in, const LinearImpact& sol, double t) {
  validate(in);
  if (!(std::isfinite(t) && t >= 0.0)) {
    std::ostringstream os;
    os << "must be >= 0 and finite, got " << t;
    throw InputError("t", os.str());
  }
  const double omega0 = std::sqrt(in.K_y / in.mass);
  const double y_scale = 2.0 * in.zeta / omega0;  // m/c [s]
  LinearState st;
  if (t >= sol.t_contact) {
    // Free flight after separation: F = 0, alpha' and y constant.
    st.phase = LinearState::Phase::separated;
    st.alpha_dot = -sol.e * in.v0;
    st.y = sol.y_final;
    st.alpha = sol.z_perm + sol.y_final + st.alpha_dot * (t - sol.t_contact);
    st.z = st.alpha - st.y;
    st.z_dot = st.alpha_dot;
    st.F = 0.0;
    return st;
  }
  if (t <= sol.t_max) {
    st.phase = LinearState::Phase::loading;
    const Phase loading{in.zeta * omega0, omega0, in.K_y};
    const PhaseState ws = evolve(loading, 0.0, in.v0, t);
    st.z = ws.w;
    st.z_dot = ws.w_dot;
    st.F = in.K_y * ws.w;
    st.alpha_dot = ws.w_dot + 2.0 * loading.a * ws.w;  // z' + F/c
  } else {
    st.phase = LinearState::Phase::unloading;
    const double gamma2 = sol.gamma * sol.gamma;
    const Phase unloading{in.zeta * omega0 / gamma2, sol.omega_unload, in.K_y / gamma2};
    const PhaseState ws = evolve(unloading, sol.z_max - sol.z_perm, 0.0, t - sol.t_max);
    st.z = sol.z_perm + ws.w;
    st.z_dot = ws.w_dot;
    st.F = unloading.K * ws.w;
    st.alpha_dot = ws.w_dot + 2.0 * unloading.a * ws.w;
  }
  st.y = y_scale * (in.v0 - st.alpha_dot);
  st.alpha = st.z + st.y;
  return st;
}

double undamped_linear_z_max(double mass, double K_y, double v0) {
  require_positive("mass", mass);
  require_positive("K_y", K_y);
  require_positive("v0", v0);
  return v0 * std::sqrt(mass / K_y);
}

namespace {
double eq20_q(double mass, double K_h, double K_y, double v0) {
  require_positive("mass", mass);
  require_positive("K_h", K_h);
  require_positive("K_y", K_y);
  require_positive("v0", v0);
  return (K_y / K_h) * std::pow(K_y / (mass * v0 * v0), 0.25);
}
}  // namespace

double linear_gamma_squared_eq20(double mass, double K_h, double K_y, double v0) {
  const double q = eq20_q(mass, K_h, K_y, v0);
  if (q > 1.0) {
    throw LinearizedLawUndefined(undamped_linear_z_max(mass, K_y, v0), (K_y / K_h) * (K_y / K_h));
  }
  return -std::expm1((2.0 / 3.0) * std::log1p(-q));
}

double linear_gamma_squared_eq21(double mass, double K_h, double K_y, double v0) {
  return (2.0 / 3.0) * eq20_q(mass, K_h, K_y, v0);
}

double linear_spring_dashpot_cor(double zeta) {
  if (!(std::isfinite(zeta) && zeta >= 0.0)) {
    std::ostringstream os;
    os << "must be >= 0 and finite, got " << zeta;
    throw InputError("zeta", os.str());
  }
  if (zeta >= 1.0) return 0.0;
  return std::exp(-std::numbers::pi * zeta / std::sqrt((1.0 - zeta) * (1.0 + zeta)));
}

}  // namespace ivv::closed_forms
