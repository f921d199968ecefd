#include "solver/plate/mode_phases.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "scene/structure.h"
#include "solver/plate/plate_modes.h"

namespace ivv {
namespace {

constexpr double kEps = 2.220446049250313e-16;

// The 200 x 200 x 2 mm steel plate of the shipped ball scene, struck off its centre (so that
// modes of every parity are kept), with bending stiffnesses D11, D22, H = D12 + 2 D66 given.
FinitePlate plate_with(double D11, double D22, double D12, double D66) {
  FinitePlate p;
  p.length_x = 0.2;
  p.length_y = 0.2;
  p.thickness = 0.002;
  p.density = 7960.0;
  p.impact_x = 0.073;
  p.impact_y = 0.118;
  p.bending = {D11, D22, D12, D66};
  return p;
}

struct Lattice {
  std::vector<double> omega;
  std::vector<std::array<int, 2>> mn;
};
Lattice lattice_of(const PlateModes& modes) {
  Lattice l;
  for (const PlateMode& md : modes.modes) l.omega.push_back(md.omega), l.mn.push_back({md.m, md.n});
  return l;
}

// The phases of ModePhases against sin and cos of omega_k t at times from a small fraction of
// the slowest period to many periods of the fastest mode. Bound: the product's phase differs
// from omega_k t by at most kSeparableRounding omega_k t (the guard), the direct call's argument
// is rounded by eps omega_k t, and the product and the table's sin and cos add a few eps.
void expect_phases_agree(const ModePhases& phases, const std::vector<double>& omega) {
  std::vector<double> c, s;
  for (double t : {1e-6, 3.7e-5, 2.9e-4, 1.3e-3}) {
    phases.at(t, c, s);
    ASSERT_EQ(c.size(), omega.size());
    for (std::size_t k = 0; k < omega.size(); ++k) {
      const double x = omega[k] * t, bound = (kSeparableRounding + kEps) * x + 8.0 * kEps;
      EXPECT_NEAR(c[k], std::cos(x), bound) << "mode " << k << " at t = " << t;
      EXPECT_NEAR(s[k], std::sin(x), bound) << "mode " << k << " at t = " << t;
    }
  }
}

TEST(ModePhases, IsotropicPlateTakesEveryModeByProductsAndAgreesWithSinCos) {
  const double D = plate_bending_stiffness(207e9, 0.3, 0.002);
  const FinitePlate p = plate_with(D, D, 0.3 * D, 0.35 * D);
  const PlateModes modes = plate_modes(p, {2.0e6});
  ASSERT_GT(modes.modes.size(), 300u);  // the ball's cut-off keeps 437
  ASSERT_TRUE(modes.separable.separates());
  const Lattice l = lattice_of(modes);
  const ModePhases phases(l.omega, l.mn, modes.separable);
  EXPECT_EQ(phases.on_lattice(), l.omega.size());
  expect_phases_agree(phases, l.omega);
}

// A specially orthotropic plate with H^2 = D11 D22 separates too (A_m, B_n with different rates).
TEST(ModePhases, OrthotropicPlateWithSquareBracketSeparates) {
  const double D11 = 20.0, D22 = 5.0, H = std::sqrt(D11 * D22);
  const FinitePlate p = plate_with(D11, D22, 0.5 * H, 0.25 * H);
  const PlateModes modes = plate_modes(p, {5.0e5});
  ASSERT_TRUE(modes.separable.separates());
  const Lattice l = lattice_of(modes);
  const ModePhases phases(l.omega, l.mn, modes.separable);
  EXPECT_EQ(phases.on_lattice(), l.omega.size());
  expect_phases_agree(phases, l.omega);
}

// H^2 != D11 D22: the frequency does not separate, every phase is sin and cos.
TEST(ModePhases, PlateWhoseFrequencyDoesNotSeparateFallsBackToSinCos) {
  const FinitePlate p = plate_with(20.0, 5.0, 2.0, 1.0);  // H = 4, sqrt(D11 D22) = 10
  const PlateModes modes = plate_modes(p, {5.0e5});
  EXPECT_FALSE(modes.separable.separates());
  const Lattice l = lattice_of(modes);
  const ModePhases phases(l.omega, l.mn, modes.separable);
  EXPECT_EQ(phases.on_lattice(), 0u);
  expect_phases_agree(phases, l.omega);
}

// A mode off the lattice (the equivalent oscillator, {0, 0}) and one whose omega is not A_m + B_n
// to the guard's rounding take sin and cos; the others still the products.
TEST(ModePhases, ModesOffTheLatticeOrOffTheSumFallBackToSinCos) {
  const double D = plate_bending_stiffness(207e9, 0.3, 0.002);
  const PlateModes modes = plate_modes(plate_with(D, D, 0.3 * D, 0.35 * D), {2.0e5});
  Lattice l = lattice_of(modes);
  ASSERT_GT(l.omega.size(), 3u);
  l.omega[1] *= 1.0 + 1e-12;  // beyond kSeparableRounding
  l.omega.push_back(1.7 * l.omega.back());
  l.mn.push_back({0, 0});
  const ModePhases phases(l.omega, l.mn, modes.separable);
  EXPECT_EQ(phases.on_lattice(), l.omega.size() - 2);
  expect_phases_agree(phases, l.omega);
}

}  // namespace
}  // namespace ivv
