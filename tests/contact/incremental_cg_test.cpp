// The contact iteration carries u = G p incrementally (one half-space product per iteration) and
// re-synchronises only when the estimated error of the carried u outgrows the residual
// (NormalContactOptions::resync_drift). These tests hold it to the reference path that recomputes
// u = G p every iteration (resync_interval = 1), on odd and even grids, periodic and not, elastic
// and elastic-plastic, and check the energy product the line step takes from the spectrum.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

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

struct Case {
  Eigen::Index n;
  bool periodic;
  double cap_over_mean;  // ∞: elastic; else the hardness over the mean pressure
};

class IncrementalAgainstReference : public ::testing::TestWithParam<Case> {};

// Both paths converge to the tolerance, carry the same load, and their answers differ by no more
// than two solutions within the tolerance can: the approach and the displacement to ~ the
// tolerance of the elastic deflection, the pressure to a small multiple (the inverse of G
// amplifies short-wavelength gap errors), the contact set to a handful of boundary cells. The
// returned u is G p recomputed (the iteration ends on an exact product).
TEST_P(IncrementalAgainstReference, AgreesToTheSolveTolerance) {
  const Case c = GetParam();
  const Grid grid = Grid::patch(c.n, c.n, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, c.periodic);
    // Non-periodic: a Hertz sphere, R = 10 mm, contact radius 0.2 mm ≈ 13 cells.
  const Eigen::ArrayXXd h = c.periodic ? rough_gap(c.n, 11) : sphere_gap(grid, 0.01);
  const double load = c.periodic ? ten_percent_load(c.n, 11) : 4.0 * kEStar * std::pow(0.2e-3, 3) / (3.0 * 0.01);
  NormalContactOptions fast;
  fast.tolerance = 1e-10;
  if (std::isfinite(c.cap_over_mean)) fast.pressure_cap_Pa = c.cap_over_mean * load / grid.area_m2();
  NormalContactOptions reference = fast;
  reference.resync_interval = 1;

  const NormalContactResult a = solve_normal_load(hs, h, load, fast);
  const NormalContactResult b = solve_normal_load(hs, h, load, reference);
  ASSERT_TRUE(a.summary.converged) << a.summary.message;
  ASSERT_TRUE(b.summary.converged) << b.summary.message;
  EXPECT_LE(a.summary.residual, fast.tolerance);
  // The reference pays a product for u every iteration; the incremental path fewer.
  EXPECT_GE(b.summary.fft_pairs, 2 * b.summary.iterations);
  EXPECT_LT(a.summary.fft_pairs, b.summary.fft_pairs);

  EXPECT_NEAR(a.normal_load_N / load, 1.0, 1e-12);
  const double u_scale = std::sqrt((b.displacement_m - b.displacement_m.mean()).square().mean());
  EXPECT_LE(std::abs(a.approach_m - b.approach_m), 1e-7 * u_scale);
  EXPECT_LE(std::sqrt((a.displacement_m - b.displacement_m).square().mean()), 1e-7 * u_scale);
  const double p_rms = std::sqrt(b.pressure_Pa.square().mean());
  EXPECT_LE(std::sqrt((a.pressure_Pa - b.pressure_Pa).square().mean()), 1e-5 * p_rms);
  EXPECT_NEAR(a.real_area_m2 / b.real_area_m2, 1.0, 4.0 / (b.area_fraction * static_cast<double>(c.n * c.n)));

  Eigen::ArrayXXd u;
  hs.displacement(a.pressure_Pa, u);
  EXPECT_LE((u - a.displacement_m).abs().maxCoeff(), 1e-12 * a.displacement_m.abs().maxCoeff());
}

INSTANTIATE_TEST_SUITE_P(OddAndEvenGrids, IncrementalAgainstReference,
                         ::testing::Values(Case{127, true, INFINITY}, Case{128, true, INFINITY},
                                           Case{127, true, 1.0 / 0.6}, Case{128, true, 1.0 / 0.6},
                                           Case{63, false, INFINITY}, Case{64, false, INFINITY}));

// Approach control has no load projection: only cells changing set move p off the direction.
TEST(IncrementalAgainstReference, ApproachControlOddGrid) {
  const Grid grid = Grid::patch(95, 95, 1e-3, 1e-3);
  ElasticHalfSpace hs(grid, kEStar, true);
  const Eigen::ArrayXXd h = rough_gap(95, 5);
  NormalContactOptions fast;
  fast.tolerance = 1e-10;
  NormalContactOptions reference = fast;
  reference.resync_interval = 1;
  const double delta = 0.1 * h.maxCoeff();
  const NormalContactResult a = solve_approach(hs, h, delta, fast);
  const NormalContactResult b = solve_approach(hs, h, delta, reference);
  ASSERT_TRUE(a.summary.converged) << a.summary.message;
  ASSERT_TRUE(b.summary.converged) << b.summary.message;
  EXPECT_NEAR(a.normal_load_N / b.normal_load_N, 1.0, 1e-6);
  EXPECT_NEAR(a.real_area_m2 / b.real_area_m2, 1.0, 4.0 / (b.area_fraction * 95.0 * 95.0));
}

TEST(IncrementalAgainstReference, ResyncOptionsAreValidated) {
  NormalContactOptions o;
  std::string why;
  EXPECT_TRUE(o.is_valid(&why));
  o.resync_interval = 0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("resync_interval"), std::string::npos);
  o = {};
  o.resync_drift = -1.0;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("resync_drift"), std::string::npos);
}

}  // namespace
}  // namespace tribo::contact
