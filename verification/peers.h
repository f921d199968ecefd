// Peer baselines: the same impact written as a competent user would with stock libraries,
// measured in the same run as ivv (`ivv bench`, the report's speed section).
//
// The problem (every peer; verification/peer_problem.h): the elastoplastic law of paper eqs
// 8-10 with a dashpot, in the normalised variables of solver/driver/impact_system.h (a' = w, w' =
// -F, z' = w - 2 zeta F, state (a, w, z), no quadratures), the kink at z = z_y left to the
// integrator's error control. Two events, as a user would code them: maximum compression
// z' = 0 (switch to the unloading curve, record z_m and F_max = F(z_m)) and separation F = 0
// (e = -w, t_f). Every peer runs at rtol = atol = tol (the state is O(1)).
//
// Events found after the step, then bisected to |dt| <= 1e-13 (1 + t) in normalised time:
//   gsl-rk8pd-driver   GSL odeiv2 rk8pd behind its stock driver (gsl_odeiv2_driver_apply)
//                      called for output intervals of 0.05 in tau (about 80 per contact); an
//                      event is bisected by re-integrating from the last output before it to
//                      each midpoint with the driver (reset in between).
//   odeint-dopri5-dense  Boost.Odeint's dense-output dopri5 (make_dense_output, stepped with
//                      do_step, the state observed after each step); an event is bisected on
//                      the dense output (calc_state), then the stepper restarts there.
// Events found by the library's own root finding (SUNDIALS 6.4: CVodeRootInit /
// ERKStepRootInit with one root function per phase, direction -1, the state at the root from
// the solver's interpolant), set up as the user guides advise (peers_sundials.cc):
//   sundials-cvode-adams  CVODE, Adams-Moulton (orders 1-12) with fixed-point iteration, the
//                      guide's choice for non-stiff problems;
//   sundials-cvode-bdf CVODE, BDF (orders 1-5) with Newton iteration, a dense linear solver and
//                      the analytic Jacobian, the guide's choice for stiff problems (this one
//                      is not stiff: BDF is here because users reach for it);
//   sundials-arkode-erk  ARKODE ERKStep, Dormand-Prince 7-4-5 (faster here than its
//                      eighth-order Fehlberg 13-7-8 and Verner 8-5-6 at every tolerance from
//                      1e-6 to 1e-12), Hermite interpolant of degree 4, the most ERKStep allows
//                      an order-5 method (the interpolant places the roots and gives the state
//                      there).
//   At maximum compression the law changes branch (its slope jumps): CVodeReInit /
//   ERKStepReset there, as the guides advise at a discontinuity. Each solver's memory (context,
//   vectors, matrix, solvers) is made once per thread and re-initialised for each impact (the
//   guides' way to solve a sequence of problems of one size): it is not part of the time.
// They share nothing with ivv's drivers, laws or event locator; the scene's derived parameters
// come from ivv::derive (so all solve the same problem).
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "solver/result.h"

namespace ivv::verification {

struct PeerResult {
  bool ok = false;
  std::string reason;      // why not, when !ok
  double e = 0.0;          // Newton COR
  double F_max = 0.0;      // [N]
  double t_contact = 0.0;  // [s]
  long rhs_evaluations = 0;
};

enum class Peer { gsl_rk8pd_driver, odeint_dopri5_dense, cvode_adams, cvode_bdf, arkode_erk };
std::string to_string(Peer p);
// How the peer is set up, in a sentence for the report and `ivv bench --json` (the header
// above says the same at length).
std::string setup(Peer p);
inline constexpr Peer kPeers[] = {Peer::gsl_rk8pd_driver, Peer::odeint_dopri5_dense,
                                  Peer::cvode_adams, Peer::cvode_bdf, Peer::arkode_erk};

// One impact of `scene` (which must have a dashpot, and separate) at rtol = atol = tol.
PeerResult run_peer(Peer peer, const Scene& scene, double tol);

// ---- measuring the peers against ivv (the report's speed section and `ivv bench`) ----------

// One point of a speed measurement: an integrator of ivv or a peer at one setting, its errors
// against a reference and its median time.
struct SpeedPoint {
  std::string integrator, law, scene, reference;
  double rtol = 0.0;  // rtol = atol; rk4: dt in tau
  double err_e = 0.0, err_F = 0.0, err_t = 0.0;
  double us_per_impact = 0.0;  // median [us]
  long rhs_evals = 0;
  bool ok = true;
  std::string reason;
};

// One row per error level of the ratio table: the fastest time reaching err_e <= level on the
// paper scene (v0 = 1 m/s, zeta = 0.1, elastoplastic) for ivv (any integrator) and each peer.
struct RatioRow {
  double level = 0.0;
  double ivv_us = 0.0;  // NaN when no point reaches the level
  std::string ivv_integrator;
  std::vector<double> peer_us;     // per kPeers entry, NaN when not reached
  std::vector<double> peer_ratio;  // peer_us / ivv_us
};
std::vector<RatioRow> ratio_table(const std::vector<SpeedPoint>& points,
                                  const std::vector<SpeedPoint>& peers);

// The label of the paper scene at (v0, zeta) in SpeedPoint::scene ("paper v0=1 zeta=0.1";
// "stiff v0=1 zeta=100" from zeta = kStiffSceneZeta on: `ivv bench`'s stiff scene).
inline constexpr double kStiffSceneZeta = 100.0;
std::string scene_label(double v0, double zeta);

// Peers on the paper scene (v0 = 1 m/s, zeta = 0.1) over `tols`, against `reference` (the mp50
// run of the elastoplastic law on that scene); each point timed by median_microseconds
// (work_precision.h) with min_seconds and min_repeats.
std::vector<SpeedPoint> measure_peers(const std::vector<double>& tols,
                                      const ImpactResult& reference, double min_seconds,
                                      int min_repeats);

}  // namespace ivv::verification
