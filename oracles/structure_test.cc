// Tests of the structure oracles: modal-count impedances.
#include <gtest/gtest.h>

#include <cmath>

#include "oracles/structure_impedance.h"

namespace ivv::oracles {
namespace {

// Mode counting approaches 8 sqrt(rho h D) as the band moves up, with the excess Weyl's
// boundary term predicts (within half of it: the lattice-count fluctuation is smaller).
TEST(StructureImpedance, PlateModeCountApproachesTheInfinitePlate) {
  const double rho = 7850, h = 0.002, D = 151.648;
  const double infinite = 8.0 * std::sqrt(rho * h * D);
  for (double k1 : {1000.0, 3000.0}) {
    const ModalImpedance m = plate_impedance_from_modes(rho, h, D, 1.0, 1.6180339887, k1, 1.1 * k1);
    const double excess = m.c / infinite - 1.0;
    EXPECT_GT(m.modes, 10000);
    EXPECT_NEAR(excess, m.boundary_term, 0.5 * m.boundary_term) << "k1 = " << k1;
  }
}

// The evenly spaced modes of a bar are counted exactly: rho A c_L to rounding.
TEST(StructureImpedance, BarModeCountIsTheWaveImpedance) {
  const ModalImpedance m = bar_impedance_from_modes(1e-4, 207e9, 7850, 2.0, 10, 109);
  EXPECT_EQ(m.modes, 100);
  EXPECT_NEAR(m.c / (7850 * 1e-4 * std::sqrt(207e9 / 7850)), 1.0, 1e-13);
}

TEST(StructureImpedance, BadInputThrows) {
  EXPECT_THROW(plate_impedance_from_modes(0, 1, 1, 1, 1, 1, 2), std::invalid_argument);
  EXPECT_THROW(plate_impedance_from_modes(1, 1, 1, 1, 1, 2, 2), std::invalid_argument);
  EXPECT_THROW(bar_impedance_from_modes(1, 1, 1, 1, 5, 4), std::invalid_argument);
}

}  // namespace
}  // namespace ivv::oracles
