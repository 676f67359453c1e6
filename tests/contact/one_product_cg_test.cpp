// The contact iteration takes one half-space product per iteration, of the projected step it
// takes, so u = G p is exact throughout (normal_contact.h). These tests hold its answer to the
// definition of the solution, recomputed from scratch: u = G p by a fresh product and the contact
// conditions checked on it, on odd and even grids, periodic and not, elastic and
// elastic-plastic, load and approach control; and check the energy product the line step takes
// from the spectrum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/surface.h"
#include "tests/contact/fixture.h"

namespace tribo::contact {
namespace {

using fixture::kEStar;

GaussianSurfaceParams bench_family(Eigen::Index n, std::uint64_t seed) {
  GaussianSurfaceParams p;
  p.grid = n;
  p.size_m = 1e-3;
  p.hurst = 0.8;
  p.rms_height_m = 1e-6;
  p.cutoff_wavelength_m = 4.0 * p.size_m / static_cast<double>(n);  // the bench's surface family
  p.seed = seed;
  return p;
}
Eigen::ArrayXXd rough_gap(Eigen::Index n, std::uint64_t seed) { return gap_from_heights(gaussian_surface(bench_family(n, seed))); }
// About 10 % real contact (A ≈ κ W / (E* h'), κ ≈ 2.2), as in bench/contact_bench.cpp.
double ten_percent_load(Eigen::Index n, std::uint64_t seed) {
  const double slope = surface_statistics(gaussian_surface(bench_family(n, seed)), 1e-3, 1e-3).rms_slope;
  return 0.045 * slope * kEStar * 1e-6;
}

// Σ_i p_i (G p)_i from the spectrum (Parseval) equals the grid sum, odd and even, periodic and
// zero-padded: the CG step length relies on it.
TEST(HalfSpaceEnergy, ParsevalMatchesTheGridSum) {
  for (const bool periodic : {true, false}) {
    for (const Eigen::Index n : {31, 32}) {
      const Grid grid = Grid::patch(n, n + 3, 1e-3, 1e-3 * static_cast<double>(n + 3) / static_cast<double>(n));
      ElasticHalfSpace hs(grid, kEStar, periodic);
      const Eigen::ArrayXXd p = Eigen::ArrayXXd::Random(n, n + 3).abs() * 1e8;
      Eigen::ArrayXXd u(n, n + 3);
      const double energy = hs.displacement_and_energy(p, u);
      EXPECT_NEAR(energy / (p * u).sum(), 1.0, 1e-12) << (periodic ? "periodic " : "padded ") << n;
      Eigen::ArrayXXd u2;
      hs.displacement(p, u2);  // the plain product sizes its output and gives the same field
      EXPECT_LE((u2 - u).abs().maxCoeff(), 1e-14 * u.abs().maxCoeff());
    }
  }
}

// The residual of the contact conditions (normal_contact.h) of a pressure field, on u = G p
// computed afresh, relative to ‖u − ū‖₂ as the solver measures it; δ is the solver's approach.
double fresh_residual(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h, const NormalContactResult& r, double cap) {
  Eigen::ArrayXXd u;
  hs.displacement(r.pressure_Pa, u);
  const Eigen::ArrayXXd g = h + u - r.approach_m;
  double res2 = 0.0;
  for (Eigen::Index i = 0; i < g.size(); ++i) {
    const double p = r.pressure_Pa(i), gi = g(i);
    const double ri = p <= 0.0 ? std::min(gi, 0.0) : (p >= cap ? std::max(gi, 0.0) : gi);
    res2 += ri * ri;
  }
  return std::sqrt(res2) / std::sqrt((u - u.mean()).square().sum());
}

struct Case {
  Eigen::Index n;
  bool periodic;
  double cap_over_mean;  // ∞: elastic; else the hardness over the mean pressure
};

class OneProductPerIteration : public ::testing::TestWithParam<Case> {};

// Converged, one product per iteration and one for the start (the FFT floor), the load carried
// to round-off, the pressure within [0, cap], the returned displacement equal to G p recomputed
// (to round-off: u is never approximated), and the contact conditions met on that fresh u to
// the solve's tolerance (the 1 % margin covers the round-off of the residual's sums). On a
// periodic grid the products far from the tolerance are single precision, and one more product
// takes u = G p again in double where the solve leaves them (NormalContactOptions::
// single_precision_above): without it u would carry their round-off, ~1e-7 of max |u|.
TEST_P(OneProductPerIteration, MeetsTheContactConditionsOnAFreshlyComputedDisplacement) {
  const Case c = GetParam();
  const Grid grid = Grid::patch(c.n, c.n, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, c.periodic);
  // Non-periodic: a Hertz sphere, R = 10 mm, contact radius 0.2 mm ≈ 13 cells.
  const Eigen::ArrayXXd h = c.periodic ? rough_gap(c.n, 11) : sphere_gap(grid, 0.01);
  const double load = c.periodic ? ten_percent_load(c.n, 11) : 4.0 * kEStar * std::pow(0.2e-3, 3) / (3.0 * 0.01);
  NormalContactOptions opt;
  opt.tolerance = 1e-10;
  if (std::isfinite(c.cap_over_mean)) opt.pressure_cap_Pa = c.cap_over_mean * load / grid.area_m2();

  const NormalContactResult r = solve_normal_load(hs, h, load, opt);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_EQ(r.summary.single_pairs > 0, c.periodic);
  EXPECT_LT(r.summary.single_pairs, r.summary.iterations);
  EXPECT_EQ(r.summary.fft_pairs, r.summary.iterations + 1 + (c.periodic ? 1 : 0));
  EXPECT_NEAR(r.normal_load_N / load, 1.0, 1e-12);
  EXPECT_GE(r.pressure_Pa.minCoeff(), 0.0);
  EXPECT_LE(r.pressure_Pa.maxCoeff(), opt.pressure_cap_Pa);
  if (std::isfinite(c.cap_over_mean)) {
    EXPECT_GT(r.plastic_area_m2, 0.0);
  }

  Eigen::ArrayXXd u;
  hs.displacement(r.pressure_Pa, u);
  EXPECT_LE((u - r.displacement_m).abs().maxCoeff(), 1e-12 * u.abs().maxCoeff());
  EXPECT_LE(fresh_residual(hs, h, r, opt.pressure_cap_Pa), 1.01 * opt.tolerance);
}

INSTANTIATE_TEST_SUITE_P(OddAndEvenGrids, OneProductPerIteration,
                         ::testing::Values(Case{127, true, INFINITY}, Case{128, true, INFINITY},
                                           Case{127, true, 1.0 / 0.6}, Case{128, true, 1.0 / 0.6},
                                           Case{63, false, INFINITY}, Case{64, false, INFINITY}));

// Approach control: no load projection, the steps are the box projection alone.
TEST(OneProductPerIteration, ApproachControlOddGrid) {
  const Grid grid = Grid::patch(95, 95, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, true);
  const Eigen::ArrayXXd h = rough_gap(95, 5);
  NormalContactOptions opt;
  opt.tolerance = 1e-10;
  const double delta = 0.1 * h.maxCoeff();
  const NormalContactResult r = solve_approach(hs, h, delta, opt);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  EXPECT_GT(r.summary.single_pairs, 0);
  EXPECT_EQ(r.summary.fft_pairs, r.summary.iterations + 2);  // the start's, and double again after the single ones
  EXPECT_EQ(r.approach_m, delta);
  EXPECT_GT(r.area_fraction, 0.01);
  EXPECT_LE(fresh_residual(hs, h, r, opt.pressure_cap_Pa), 1.01 * opt.tolerance);
}

// A warm start at the answer is already converged: the start's product and no iteration.
TEST(OneProductPerIteration, AWarmStartAtTheSolutionNeedsNoIteration) {
  const Grid grid = Grid::patch(64, 64, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, true);
  const Eigen::ArrayXXd h = rough_gap(64, 3);
  const double load = ten_percent_load(64, 3);
  NormalContactOptions opt;
  opt.tolerance = 1e-9;
  const NormalContactResult cold = solve_normal_load(hs, h, load, opt);
  ASSERT_TRUE(cold.summary.converged) << cold.summary.message;
  const NormalContactResult warm = solve_normal_load(hs, h, load, opt, &cold.pressure_Pa);
  ASSERT_TRUE(warm.summary.converged) << warm.summary.message;
  EXPECT_LE(warm.summary.iterations, 1);
  EXPECT_NEAR(warm.real_area_m2 / cold.real_area_m2, 1.0, 2.0 / (cold.area_fraction * 64.0 * 64.0));
}

// Mixed precision (NormalContactOptions::single_precision_above): the products in single
// precision while the residual is above 1e-6, then double to the tolerance, reach the solution
// the solve reaches in double throughout — odd and even grids, elastic and capped. Both meet
// ε ≤ 1e-10; two such pressures differ by about ε times the problem's conditioning (found:
// 2e-10 to 1.5e-9 of ‖p‖₂), and 2e-8 leaves a margin of ten while a solve stopped near 1e-6, or
// left with the single products' round-off in u (1e-7 of u), would miss it. The single phase
// keeps CG's rate: at most 10 % more iterations than double throughout (found: 8 % fewer to as
// many).
TEST(MixedPrecision, SingleProductsFarFromTheToleranceReachTheDoubleSolution) {
  for (const Eigen::Index n : {127, 128}) {
    for (const double cap_over_mean : {std::numeric_limits<double>::infinity(), 1.0 / 0.6}) {
      SCOPED_TRACE(std::to_string(n) + "², cap over mean pressure " + std::to_string(cap_over_mean));
      const Grid grid = Grid::patch(n, n, 1e-3, 1e-3);
      ElasticHalfSpace hs(grid, kEStar, true);
      const Eigen::ArrayXXd h = rough_gap(n, 7);
      const double load = ten_percent_load(n, 7);
      NormalContactOptions opt;
      opt.tolerance = 1e-10;
      if (std::isfinite(cap_over_mean)) opt.pressure_cap_Pa = cap_over_mean * load / grid.area_m2();
      const NormalContactResult mixed = solve_normal_load(hs, h, load, opt);
      opt.single_precision_above = 0.0;
      const NormalContactResult full = solve_normal_load(hs, h, load, opt);
      ASSERT_TRUE(mixed.summary.converged) << mixed.summary.message;
      ASSERT_TRUE(full.summary.converged) << full.summary.message;
      EXPECT_GT(mixed.summary.single_pairs, mixed.summary.iterations / 3);
      EXPECT_EQ(full.summary.single_pairs, 0);
      EXPECT_EQ(full.summary.fft_pairs, full.summary.iterations + 1);
      EXPECT_LE(mixed.summary.iterations, 1.1 * full.summary.iterations);
      const double dp = (mixed.pressure_Pa - full.pressure_Pa).matrix().norm() / full.pressure_Pa.matrix().norm();
      EXPECT_LE(dp, 2e-8);
      EXPECT_NEAR(mixed.approach_m, full.approach_m, 1e-7 * (h.maxCoeff() - h.minCoeff()));
    }
  }
}

// A solve stopped by its iteration limit while its products are single takes u = G p in double
// before it returns: the returned displacement is G p of the returned pressure to round-off.
TEST(MixedPrecision, AStopWhileSingleReturnsADoubleState) {
  const Grid grid = Grid::patch(128, 128, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, true);
  const Eigen::ArrayXXd h = rough_gap(128, 7);
  NormalContactOptions opt;
  opt.max_iterations = 12;
  const NormalContactResult r = solve_normal_load(hs, h, ten_percent_load(128, 7), opt);
  EXPECT_FALSE(r.summary.converged);
  EXPECT_GT(r.summary.residual, opt.single_precision_above);
  EXPECT_EQ(r.summary.iterations, 12);
  EXPECT_EQ(r.summary.single_pairs, 12);
  EXPECT_EQ(r.summary.fft_pairs, 14);
  Eigen::ArrayXXd u;
  hs.displacement(r.pressure_Pa, u);
  EXPECT_LE((u - r.displacement_m).abs().maxCoeff(), 1e-12 * u.abs().maxCoeff());
}

TEST(MixedPrecision, ANegativeThresholdIsRejected) {
  NormalContactOptions opt;
  opt.single_precision_above = -1e-6;
  std::string why;
  EXPECT_FALSE(opt.is_valid(&why));
  EXPECT_NE(why.find("single_precision_above"), std::string::npos) << why;
}

}  // namespace
}  // namespace tribo::contact
