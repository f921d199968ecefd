// The peer measurement's pieces that do not time anything: the peers solve the same problem as ivv
// (their answers agree with the 50-digit reference within what their tolerance allows), and the
// ratio table picks the fastest run within each error level.
#include "verification/peers.h"

#include "solver/simulate.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ivv::verification {
namespace {

ImpactResult paper_reference() {
  SimulationRequest req;
  req.scene = paper_scene();
  req.scene.velocity = 1.0;
  req.scene.damping = Damping::ratio(0.1);
  req.integrator = IntegratorKind::mp50;
  req.options.reference_tolerance = 1e-20;  // resolves errors >= 1e-16
  return simulate(req);
}

// At rtol = atol = 1e-10 an adaptive peer's global error is at most ~N rtol with N <= 1000
// steps (the reasoning of verification/tolerances.h), and its events are placed to 1e-13 in tau
// (bisection) or by SUNDIALS' root finding on an interpolant of the step's own order (CVODE's
// Nordsieck history; ARKODE's Hermite polynomial of degree 4, whose error at this tolerance is
// ~3e-9 on e, measured): 1e-7 on e, F_max and t_f.
constexpr double kPeerTolerance = 1e-7;

TEST(Peers, SolveTheSameImpactAsIvv) {
  const ImpactResult ref = paper_reference();
  ASSERT_TRUE(ref.separated()) << ref.reason;
  Scene s = paper_scene();
  s.velocity = 1.0;
  s.damping = Damping::ratio(0.1);
  for (Peer p : kPeers) {
    const PeerResult r = run_peer(p, s, 1e-10);
    ASSERT_TRUE(r.ok) << to_string(p) << ": " << r.reason;
    EXPECT_NEAR(r.e, ref.e, kPeerTolerance * ref.e) << to_string(p);
    EXPECT_NEAR(r.F_max, ref.F_max, kPeerTolerance * ref.F_max) << to_string(p);
    EXPECT_NEAR(r.t_contact, ref.t_contact, kPeerTolerance * ref.t_contact) << to_string(p);
    EXPECT_GT(r.rhs_evaluations, 0);
  }
}

// The SUNDIALS peers keep their solver memory from one impact to the next (re-initialised, not
// re-created): a run leaves nothing behind that changes the next one.
TEST(Peers, ARunLeavesNothingBehind) {
  Scene s = paper_scene();
  s.velocity = 1.0;
  s.damping = Damping::ratio(0.1);
  Scene other = s;
  other.velocity = 5.0;
  for (Peer p : kPeers) {
    const PeerResult first = run_peer(p, s, 1e-6);
    run_peer(p, other, 1e-11);
    const PeerResult again = run_peer(p, s, 1e-6);
    ASSERT_TRUE(first.ok && again.ok) << to_string(p) << ": " << first.reason << again.reason;
    EXPECT_EQ(first.e, again.e) << to_string(p);
    EXPECT_EQ(first.F_max, again.F_max) << to_string(p);
    EXPECT_EQ(first.rhs_evaluations, again.rhs_evaluations) << to_string(p);
  }
}

TEST(Peers, NamesAreDistinct) {
  for (Peer a : kPeers)
    for (Peer b : kPeers)
      if (a != b) {
        EXPECT_NE(to_string(a), to_string(b));
      }
}

SpeedPoint point(std::string who, double err, double us) {
  SpeedPoint p;
  p.integrator = std::move(who);
  p.law = "elastoplastic";
  p.scene = scene_label(1.0, 0.1);
  p.err_e = err;
  p.us_per_impact = us;
  return p;
}

TEST(RatioTable, FastestRunWithinEachLevel) {
  const std::vector<SpeedPoint> ivv = {point("a", 1e-7, 2.0), point("b", 1e-9, 5.0),
                                       point("c", 1e-9, 4.0), point("d", 1e-13, 20.0)};
  const std::vector<SpeedPoint> peers = {point(to_string(kPeers[0]), 1e-9, 40.0),
                                         point(to_string(kPeers[1]), 1e-7, 3.0)};
  const auto rows = ratio_table(ivv, peers);
  ASSERT_EQ(rows.size(), 4u);  // 1e-6, 1e-8, 1e-10, 1e-12
  EXPECT_EQ(rows[0].ivv_us, 2.0);
  EXPECT_EQ(rows[0].ivv_integrator, "a");
  EXPECT_EQ(rows[1].ivv_us, 4.0);  // c beats b at the same error
  EXPECT_EQ(rows[1].peer_us[0], 40.0);
  EXPECT_EQ(rows[1].peer_ratio[0], 10.0);
  EXPECT_TRUE(std::isnan(rows[1].peer_us[1]));  // 1e-7 does not reach 1e-8
  EXPECT_EQ(rows[3].ivv_integrator, "d");
}

TEST(RatioTable, IgnoresFailedPointsAndOtherScenes) {
  SpeedPoint failed = point("x", 1e-14, 0.1);
  failed.ok = false;
  SpeedPoint other = point("y", 1e-14, 0.1);
  other.scene = scene_label(5.0, 0.1);
  const auto rows = ratio_table({failed, other, point("z", 1e-14, 9.0)}, {});
  EXPECT_EQ(rows[0].ivv_integrator, "z");
}

}  // namespace
}  // namespace ivv::verification
