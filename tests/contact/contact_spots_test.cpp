// The contact spots of a pressure field: labelling against hand-made fields (counts and areas
// exact), and the equivalent radius against Hertz.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "contact/contact_spots.h"
#include "tests/contact/fixture.h"

namespace tribo::contact {
namespace {

using fixture::kEStar;

// Three spots on a periodic 10 × 9 patch: one of 2 nodes, one of 4 that wraps across both edges
// (the four corner nodes), and a single node touching the first only diagonally — 4-connectivity
// keeps it apart. Areas are node counts × cell area, loads the pressures × cell area, exactly.
TEST(ContactSpots, LabelsPeriodicFourConnectedRegionsExactly) {
  const Grid grid = Grid::patch(10, 9, 1e-3, 0.9e-3);
  const double cell = grid.dx_m * grid.dy_m;
  Eigen::ArrayXXd p = Eigen::ArrayXXd::Zero(10, 9);
  p(0, 0) = p(9, 0) = p(0, 8) = p(9, 8) = 2.0;  // the corners: one spot across both edges
  p(4, 4) = 1.0, p(5, 4) = 3.0;                   // a pair
  p(6, 5) = 5.0;                                  // diagonal to (5, 4): its own spot
  const std::vector<ContactSpot> spots = contact_spots(p, grid, kEStar);
  ASSERT_EQ(spots.size(), 3u);
  EXPECT_DOUBLE_EQ(spots[0].area_m2, 4.0 * cell);  // first node in column-major order: (0, 0)
  EXPECT_DOUBLE_EQ(spots[0].load_N, 8.0 * cell);
  EXPECT_DOUBLE_EQ(spots[1].area_m2, 2.0 * cell);
  EXPECT_DOUBLE_EQ(spots[1].mean_pressure_Pa, 2.0);
  EXPECT_DOUBLE_EQ(spots[2].load_N, 5.0 * cell);
}

// A Hertz contact solved by the BEM (the 2.5 % setting of normal_contact_test.cpp: a ≈ 32 cells,
// odd and even grids): the equivalent radius 4E*a³/(3w) returns the sphere's radius. The counted
// area carries half a cell of its radius (1.5 %), which R_eq ∝ a³ triples: 5 %.
class SpotRadius : public ::testing::TestWithParam<Eigen::Index> {};

TEST_P(SpotRadius, EquivalentRadiusOfAHertzSpotIsTheSpheres) {
  const fixture::CoarseHertz h = fixture::coarse_hertz(GetParam());
  ASSERT_TRUE(h.result.summary.converged) << h.result.summary.message;
  const std::vector<ContactSpot> spots = contact_spots(h.result.pressure_Pa, h.grid, kEStar);
  ASSERT_EQ(spots.size(), 1u);
  EXPECT_NEAR(spots[0].load_N / h.load_N, 1.0, 1e-6);
  EXPECT_NEAR(spots[0].equivalent_radius_m / h.radius_m, 1.0, 0.05);
}

INSTANTIATE_TEST_SUITE_P(OddAndEvenGrids, SpotRadius, ::testing::Values(127, 128));

TEST(ContactSpots, AFieldOfAnotherSizeIsRefused) {
  EXPECT_THROW(contact_spots(Eigen::ArrayXXd::Zero(4, 4), Grid::patch(5, 4, 1.0, 1.0), kEStar), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::contact
