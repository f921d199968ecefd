#include "verification/peers.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "verification/peer_problem.h"
#include "verification/work_precision.h"

namespace ivv::verification {
namespace peer_detail {

Problem make_problem(const Scene& scene) {
  const DerivedParameters p = derive(scene);
  const Scales k = scales(scene, p, ScaleBasis::yield);  // the elastoplastic law's own
  return {k.length, k.force, p.K_h, p.z_y, p.K_y, 2.0 * p.zeta};
}

PeerResult finish(const Problem& pb, const Scene& scene, const State& x, double tau, double F_max) {
  PeerResult r;
  r.ok = true;
  r.e = -x[1];
  r.F_max = F_max * pb.Fs;
  r.t_contact = tau / derive(scene).omega0;
  r.rhs_evaluations = pb.evals;
  return r;
}

}  // namespace peer_detail

namespace {
using namespace peer_detail;

constexpr double kOutputInterval = 0.05;  // gsl peer: output grid in tau

bool converged(double lo, double hi) {
  return hi - lo <= 1e-13 * (1 + std::abs(hi));
}

int gsl_rhs(double, const double y[], double dydt[], void* params) {
  const auto* pb = static_cast<const Problem*>(params);
  State x{y[0], y[1], y[2]}, d;
  (*pb)(x, d, 0.0);
  for (int i = 0; i < 3; ++i) dydt[i] = d[i];
  return GSL_SUCCESS;
}

PeerResult gsl_peer(const Scene& scene, double tol) {
  Problem pb = make_problem(scene);
  gsl_odeiv2_system sys{gsl_rhs, nullptr, 3, &pb};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-4, tol, tol);
  PeerResult fail;
  State x{0.0, 1.0, 0.0};
  double tau = 0.0, F_max = 0.0;
  auto integrate = [&](State& y, double& t, double t1) {
    double buf[3] = {y[0], y[1], y[2]};
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, buf);
    y = {buf[0], buf[1], buf[2]};
    return status == GSL_SUCCESS;
  };
  for (int phase = 0; phase < 2; ++phase) {
    double g_prev = pb.event(x);
    for (;;) {
      State y = x;
      double t = tau;
      if (!integrate(y, t, tau + kOutputInterval) || t > kTauLimit) {
        gsl_odeiv2_driver_free(d);
        fail.reason = "gsl driver failed";
        return fail;
      }
      const double g = pb.event(y);
      if ((g_prev > 0) != (g > 0)) {
        // bisect by re-integrating from the last output (tau, x)
        double lo = tau, hi = t;
        State x_hi = y;
        while (!converged(lo, hi)) {
          const double mid = 0.5 * (lo + hi);
          State ym = x;
          double tm = tau;
          gsl_odeiv2_driver_reset(d);
          integrate(ym, tm, mid);
          if ((pb.event(ym) > 0) == (g_prev > 0)) {
            lo = mid;
          } else {
            hi = mid;
            x_hi = ym;
          }
        }
        x = x_hi;
        tau = hi;
        gsl_odeiv2_driver_reset(d);
        break;
      }
      x = y;
      tau = t;
      g_prev = g;
    }
    if (phase == 0) F_max = pb.switch_to_unloading(x);
  }
  gsl_odeiv2_driver_free(d);
  return finish(pb, scene, x, tau, F_max);
}

PeerResult odeint_peer(const Scene& scene, double tol) {
  namespace odeint = boost::numeric::odeint;
  Problem pb = make_problem(scene);
  auto stepper = odeint::make_dense_output(tol, tol, odeint::runge_kutta_dopri5<State>());
  State x{0.0, 1.0, 0.0};
  double tau = 0.0, F_max = 0.0, dt = 1e-4;
  auto rhs = [&pb](const State& s, State& d, double t) { pb(s, d, t); };
  for (int phase = 0; phase < 2; ++phase) {
    stepper.initialize(x, tau, dt);
    double g_prev = pb.event(x);
    for (;;) {
      stepper.do_step(rhs);
      if (stepper.current_time() > kTauLimit) return {false, "no event before tau = 1e3"};
      const double g = pb.event(stepper.current_state());
      if ((g_prev > 0) != (g > 0)) {
        double lo = stepper.previous_time(), hi = stepper.current_time();
        State xm = stepper.current_state();
        State x_hi = xm;
        while (!converged(lo, hi)) {
          const double mid = 0.5 * (lo + hi);
          stepper.calc_state(mid, xm);
          if ((pb.event(xm) > 0) == (g_prev > 0)) {
            lo = mid;
          } else {
            hi = mid;
            x_hi = xm;
          }
        }
        x = x_hi;
        tau = hi;
        dt = stepper.current_time_step();
        break;
      }
      g_prev = g;
    }
    if (phase == 0) F_max = pb.switch_to_unloading(x);
  }
  return finish(pb, scene, x, tau, F_max);
}

}  // namespace

std::string to_string(Peer p) {
  switch (p) {
    case Peer::gsl_rk8pd_driver:
      return "gsl-rk8pd-driver";
    case Peer::odeint_dopri5_dense:
      return "odeint-dopri5-dense";
    case Peer::cvode_adams:
      return "sundials-cvode-adams";
    case Peer::cvode_bdf:
      return "sundials-cvode-bdf";
    case Peer::arkode_erk:
      return "sundials-arkode-erk";
  }
  throw std::logic_error("to_string: not a Peer");
}

std::string setup(Peer p) {
  const std::string after_step =
      "; events noticed after a step, bisected to 1e-13 in normalised time";
  const std::string own_roots =
      "; events by its own root finding (direction -1), re-initialised at maximum compression "
      "(the law's slope jumps); memory made once per thread, re-initialised per impact";
  switch (p) {
    case Peer::gsl_rk8pd_driver:
      return "GSL odeiv2 rk8pd behind gsl_odeiv2_driver_apply, outputs every 0.05 in tau" +
             after_step + " by re-integrating from the last output";
    case Peer::odeint_dopri5_dense:
      return "Boost.Odeint dense-output dopri5 (make_dense_output, do_step)" + after_step +
             " on the dense output";
    case Peer::cvode_adams:
      return "SUNDIALS 6.4 CVODE, Adams (orders 1-12) with fixed-point iteration (the guide's "
             "non-stiff choice)" +
             own_roots;
    case Peer::cvode_bdf:
      return "SUNDIALS 6.4 CVODE, BDF (orders 1-5), Newton with a dense linear solver and the "
             "analytic Jacobian (the guide's stiff choice)" +
             own_roots;
    case Peer::arkode_erk:
      return "SUNDIALS 6.4 ARKODE ERKStep, Dormand-Prince 7-4-5 (faster here than its "
             "Fehlberg 13-7-8 and Verner 8-5-6), Hermite interpolant of degree 4 (the most "
             "for order 5)" +
             own_roots;
  }
  throw std::logic_error("setup: not a Peer");
}

PeerResult run_peer(Peer peer, const Scene& scene, double tol) {
  switch (peer) {
    case Peer::gsl_rk8pd_driver:
      gsl_set_error_handler_off();
      return gsl_peer(scene, tol);
    case Peer::odeint_dopri5_dense:
      return odeint_peer(scene, tol);
    case Peer::cvode_adams:
      return cvode_peer(scene, tol, CvodeMethod::adams);
    case Peer::cvode_bdf:
      return cvode_peer(scene, tol, CvodeMethod::bdf);
    case Peer::arkode_erk:
      return arkode_erk_peer(scene, tol);
  }
  throw std::logic_error("run_peer: not a Peer");
}

// ---- measuring the peers against ivv -------------------------------------------------------

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double rel(double x, double ref) {
  const double d = std::abs(x - ref);
  const double r = ref == 0.0 ? d : d / std::abs(ref);
  return r == 0.0 ? kErrorFloor : r;
}

}  // namespace

std::string scene_label(double v0, double zeta) {
  std::ostringstream os;
  os << (zeta >= kStiffSceneZeta ? "stiff" : "paper") << " v0=" << v0 << " zeta=" << zeta;
  return os.str();
}

std::vector<SpeedPoint> measure_peers(const std::vector<double>& tols, const ImpactResult& ref,
                                      double min_seconds, int min_repeats) {
  Scene scene = paper_scene();
  scene.velocity = 1.0;
  scene.damping = Damping::ratio(0.1);
  std::vector<SpeedPoint> out;
  for (Peer peer : kPeers) {
    for (double tol : tols) {
      SpeedPoint pt;
      pt.integrator = to_string(peer);
      pt.law = "elastoplastic";
      pt.scene = scene_label(1.0, 0.1);
      pt.reference = "mp50";
      pt.rtol = tol;
      PeerResult r = run_peer(peer, scene, tol);
      pt.rhs_evals = r.rhs_evaluations;
      pt.ok = r.ok;
      pt.reason = r.reason;
      if (r.ok) {
        pt.err_e = rel(r.e, ref.e);
        pt.err_F = rel(r.F_max, ref.F_max);
        pt.err_t = rel(r.t_contact, ref.t_contact);
        pt.us_per_impact =
            median_microseconds([&] { r = run_peer(peer, scene, tol); }, min_seconds, min_repeats);
      } else {
        pt.err_e = pt.err_F = pt.err_t = pt.us_per_impact = kNaN;
      }
      out.push_back(pt);
    }
  }
  return out;
}

namespace {

double best_us(const std::vector<SpeedPoint>& pts, const std::string& scene, double level,
               std::string* who) {
  double best = kNaN;
  for (const SpeedPoint& p : pts) {
    if (!p.ok || p.scene != scene || p.law != "elastoplastic" || !(p.err_e <= level)) continue;
    if (std::isnan(best) || p.us_per_impact < best) {
      best = p.us_per_impact;
      *who = p.integrator;
    }
  }
  return best;
}

}  // namespace

std::vector<RatioRow> ratio_table(const std::vector<SpeedPoint>& points,
                                  const std::vector<SpeedPoint>& peers) {
  const std::string scene = scene_label(1.0, 0.1);
  std::vector<RatioRow> rows;
  for (double level : {1e-6, 1e-8, 1e-10, 1e-12}) {
    RatioRow row;
    row.level = level;
    row.ivv_us = best_us(points, scene, level, &row.ivv_integrator);
    for (Peer peer : kPeers) {
      double best = kNaN;
      for (const SpeedPoint& p : peers)
        if (p.ok && p.integrator == to_string(peer) && p.err_e <= level &&
            (std::isnan(best) || p.us_per_impact < best))
          best = p.us_per_impact;
      row.peer_us.push_back(best);
      row.peer_ratio.push_back(best / row.ivv_us);
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace ivv::verification
