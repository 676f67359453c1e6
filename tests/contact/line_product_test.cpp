// contact/halfspace.h, ElasticHalfSpace::displacement_by_rows: the product u = G s taken line by
// line with the caller's passes fused into it is the product displacement_and_energy takes with
// the 2-D transform — the same displacement and the same energy s·G s — on even and odd grids
// (odd nx: every other line of s and u lacks the plans' alignment and goes through a buffer), on
// one and two threads, in double and in single precision; every line is made once, and used once
// by the thread that made it.
#include <gtest/gtest.h>
#include <omp.h>

#include <random>
#include <vector>

#include "contact/grid.h"
#include "contact/halfspace.h"

namespace tribo::contact {
namespace {

using Precision = ElasticHalfSpace::Precision;

struct LineCase {
  int nx, ny, threads;
  Precision precision = Precision::full;
};

class LineProduct : public ::testing::TestWithParam<LineCase> {};

// Tolerance: both products sum the same terms in another order, ~1e-15 of the largest value per
// transform stage; 1e-12 of max |u| (and of the energy) leaves three orders of margin and fails
// on any misplaced line, column or kernel value (those are O(1) errors). In single precision s is
// rounded to float (2⁻²⁴ = 6e-8 of each value) and each of the 2 log₂ n butterfly stages of the
// two transforms adds about as much: ~1e-6 of max |u| at 256² in the worst case (found: 3e-7 to
// 6e-7, the energy 2e-8 to 9e-8), 2e-6 here; still five orders below an O(1) error.
TEST_P(LineProduct, EqualsTheTwoDimensionalProductAndItsEnergy) {
  const LineCase c = GetParam();
  const double tolerance = c.precision == Precision::full ? 1e-12 : 2e-6;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(c.threads);
  const Grid grid = Grid::patch(c.nx, c.ny, 1e-4 * c.nx / c.ny, 1e-4);
  ElasticHalfSpace by_rows(grid, 1e11, true, c.threads);
  ElasticHalfSpace whole(grid, 1e11, true, 1);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> uniform(0.0, 1e8);
  Eigen::ArrayXXd s0(c.nx, c.ny);
  for (Eigen::Index m = 0; m < s0.size(); ++m) s0(m) = uniform(rng);

  Eigen::ArrayXXd u_ref(c.nx, c.ny);
  const double energy_ref = whole.displacement_and_energy(s0, u_ref);

  const int threads = by_rows.row_threads();
  ASSERT_EQ(threads, c.nx * c.ny >= (1 << 15) ? c.threads : 1);
  Eigen::ArrayXXd s = Eigen::ArrayXXd::Zero(c.nx, c.ny), u = Eigen::ArrayXXd::Zero(c.nx, c.ny);
  std::vector<int> made_by(c.ny, -1), used_by(c.ny, -1);
  std::vector<int> made(c.ny, 0), used(c.ny, 0);
  double decided = -1.0;
  const double energy = by_rows.displacement_by_rows(
      s.data(), u.data(),
      [&](int t, Eigen::Index j) {
        s.col(j) = s0.col(j);  // the caller writes line j of s here, as the solve's step pass does
        made_by[j] = t;
        ++made[j];
      },
      [&](double e) {
        decided = e;
        return true;
      },
      [&](int t, Eigen::Index j, const double* u_line) {
        used_by[j] = t;
        ++used[j];
        EXPECT_EQ(u_line, u.data() + j * c.nx) << "line " << j << ": the line of u itself";
      },
      c.precision);
  EXPECT_NEAR(energy, energy_ref, tolerance * energy_ref);
  EXPECT_EQ(decided, energy);
  EXPECT_LE((u - u_ref).abs().maxCoeff(), tolerance * u_ref.abs().maxCoeff());
  EXPECT_TRUE((s == s0).all()) << "s must be left as the caller made it";
  for (int j = 0; j < c.ny; ++j) {
    ASSERT_EQ(made[j], 1) << "line " << j;
    ASSERT_EQ(used[j], 1) << "line " << j;
    ASSERT_EQ(made_by[j], used_by[j]) << "line " << j;
    ASSERT_GE(made_by[j], 0);
    ASSERT_LT(made_by[j], threads);
  }

  // Without u the lines come in a buffer of the thread's and are the same values.
  Eigen::ArrayXXd lines = Eigen::ArrayXXd::Zero(c.nx, c.ny);
  const double energy_unkept = by_rows.displacement_by_rows(
      s.data(), nullptr, [&](int, Eigen::Index) {}, [&](double) { return true; },
      [&](int, Eigen::Index j, const double* u_line) { lines.col(j) = Eigen::Map<const Eigen::ArrayXd>(u_line, c.nx); },
      c.precision);
  EXPECT_EQ(energy_unkept, energy);
  EXPECT_TRUE((lines == u).all()) << "the same transforms give the same values";
  omp_set_num_threads(saved);
}

// 256² is a grid the shipped wisdom holds line plans for, 255 × 192 one it does not (odd nx);
// 64 × 48 is below the size where the lines are split between threads. The last column block
// holds one column at 256² and 64 × 48, six at 90 × 64 (46 columns in blocks of 8); in single
// precision at 64 × 48 the half spectrum's 33 values a line are padded to 34 (8-byte values: an
// even stride keeps every line on FFTW's alignment); at 99² and 201 × 171 (two threads) the last
// block holds 2 and 5 columns of odd length, every other one 8 bytes off FFTW's alignment.
INSTANTIATE_TEST_SUITE_P(EvenOddThreads, LineProduct,
                         ::testing::Values(LineCase{256, 256, 1}, LineCase{256, 256, 2}, LineCase{255, 192, 1},
                                           LineCase{255, 192, 2}, LineCase{64, 48, 2}, LineCase{90, 64, 1}));
INSTANTIATE_TEST_SUITE_P(SinglePrecision, LineProduct,
                         ::testing::Values(LineCase{256, 256, 1, Precision::single}, LineCase{256, 256, 2, Precision::single},
                                           LineCase{255, 192, 2, Precision::single}, LineCase{64, 48, 2, Precision::single},
                                           LineCase{90, 64, 1, Precision::single}, LineCase{99, 99, 1, Precision::single},
                                           LineCase{201, 171, 2, Precision::single}));

// When decide() declines, no line of u is transformed back or used.
TEST(LineProductDeclined, LeavesTheDisplacementUntouched) {
  const Grid grid = Grid::patch(32, 32, 1e-4, 1e-4);
  ElasticHalfSpace hs(grid, 1e11, true, 1);
  Eigen::ArrayXXd s = Eigen::ArrayXXd::Constant(32, 32, 1e6), u = Eigen::ArrayXXd::Constant(32, 32, 7.0);
  s(3, 5) = 2e6;
  int used = 0;
  const double energy = hs.displacement_by_rows(
      s.data(), u.data(), [](int, Eigen::Index) {}, [](double) { return false; },
      [&](int, Eigen::Index, const double*) { ++used; });
  EXPECT_GT(energy, 0.0);
  EXPECT_EQ(used, 0);
  EXPECT_TRUE((u == 7.0).all());
}

}  // namespace
}  // namespace tribo::contact
