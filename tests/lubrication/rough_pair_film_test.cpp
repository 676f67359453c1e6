// The rough-pair Reynolds cell (lubrication/geometry.h rough_pair_film): rigid placement against
// rough_pair_gap_m, deformed placement against the contact solve it wraps, and input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "contact/surface.h"
#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"

namespace tribo::lubrication {
namespace {

constexpr double kSize = 1e-3;

Eigen::ArrayXXd surface(int n, double rms_m, std::uint64_t seed) {
  contact::GaussianSurfaceParams p;
  p.kind = contact::SpectrumKind::gaussian_acf;
  p.grid = n;
  p.size_m = kSize;
  p.rms_height_m = rms_m;
  p.correlation_length_m = kSize / 16;
  p.seed = seed;
  return contact::gaussian_surface(p);
}

// Rigid mode is rough_pair_gap_m on the surface nodes, wrapped to n + 1 nodes along x: equal bit
// for bit, column n equal to column 0, periodic y, nothing else set; the contact nodes agree.
// Odd and even n.
TEST(RoughPairFilm, RigidModeIsTheWrappedRoughPairGap) {
  for (int n : {32, 33}) {
    const Eigen::ArrayXXd upper = surface(n, 0.1e-6, 2), lower = surface(n, 0.4e-6, 1);
    RoughPairFilmOptions o;
    o.mean_gap_m = 0.5e-6;
    const RoughPairFilm f = rough_pair_film(upper, lower, kSize, o);
    const double sigma = std::hypot(0.1e-6, 0.4e-6);
    EXPECT_NEAR(f.composite_rms_height_m, sigma, 1e-12 * sigma);
    std::size_t touching = 0;
    const Eigen::ArrayXXd h = rough_pair_gap_m(upper, lower, 0.5e-6, f.floor_m, &touching);
    const contact::Grid& g = f.problem.grid;
    ASSERT_EQ(g.nx, n + 1);
    ASSERT_EQ(g.ny, n);
    EXPECT_DOUBLE_EQ(g.dx_m, kSize / n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i <= n; ++i) ASSERT_EQ(f.problem.gap_m(i, j), h(i % n, j));
    EXPECT_EQ(f.contact_nodes, touching);
    EXPECT_GT(touching, 0u);  // h̄ = 1.2σ: some contact
    EXPECT_EQ(f.problem.boundary_y, BoundaryY::periodic);
    EXPECT_FALSE(f.contact.has_value());
    EXPECT_EQ(f.problem.gap_rate_m_per_s.size(), 0);
    EXPECT_EQ(f.problem.sliding_speed_m_per_s, 0.0);
    EXPECT_NO_THROW(validate(f.problem));
  }
}

// Deformed mode wraps contact::solve_normal_load: the load balance holds to the contact
// solver's tolerance (Σ p ΔA = W is enforced: 1e-8), the film is the contact gap floored — its
// mean exceeds the contact's mean gap by at most the floor (0 ≤ mean film − ḡ ≤ floor) — and a
// harder press (more load) leaves a thinner mean film and more contact nodes.
TEST(RoughPairFilm, DeformedModeIsTheFlooredContactGap) {
  const int n = 64;
  const Eigen::ArrayXXd upper = surface(n, 0.1e-6, 2), lower = surface(n, 0.4e-6, 1);
  RoughPairFilmOptions o;
  o.normal_load_N = 0.5;
  o.hardness_Pa = 6e9;
  const RoughPairFilm f = rough_pair_film(upper, lower, kSize, o);
  ASSERT_TRUE(f.contact.has_value());
  const contact::NormalContactResult& c = *f.contact;
  ASSERT_TRUE(c.summary.converged) << c.summary.message;
  std::printf("  W = 0.5 N: area fraction %.4f, mean gap %.4e m, mean film %.4e m, floor %.2e m, contact nodes %zu\n",
              c.area_fraction, c.mean_gap_m, f.mean_film_m, f.floor_m, f.contact_nodes);
  EXPECT_NEAR(c.normal_load_N, 0.5, 1e-8 * 0.5);
  EXPECT_GE(f.mean_film_m, c.mean_gap_m);
  EXPECT_LE(f.mean_film_m - c.mean_gap_m, f.floor_m);
  std::size_t below = 0;
  for (Eigen::Index k = 0; k < c.gap_m.size(); ++k) below += c.gap_m(k) < f.floor_m;
  EXPECT_EQ(f.contact_nodes, below);
  EXPECT_GT(f.contact_nodes, 0u);
  for (int j = 0; j < n; ++j) {
    EXPECT_EQ(f.problem.gap_m(n, j), f.problem.gap_m(0, j));
    EXPECT_EQ(f.problem.gap_m(5, j), std::max(c.gap_m(5, j), f.floor_m));
  }
  RoughPairFilmOptions harder = o;
  harder.normal_load_N = 2.0;
  const RoughPairFilm f2 = rough_pair_film(upper, lower, kSize, harder);
  ASSERT_TRUE(f2.contact->summary.converged);
  EXPECT_LT(f2.mean_film_m, f.mean_film_m);
  EXPECT_GT(f2.contact_nodes, f.contact_nodes);
  // The film is a valid Reynolds problem: sliding over it gives a converged JFO solve.
  ReynoldsProblem pr = f.problem;
  pr.sliding_speed_m_per_s = 0.1;
  pr.cavitation = Cavitation::mass_conserving;
  EXPECT_TRUE(solve_reynolds(pr).summary.converged);
}

// Bad input names the field: neither or both placements, bad values, shapes, flat surfaces.
TEST(RoughPairFilm, RejectsBadInputNamingIt) {
  const Eigen::ArrayXXd upper = surface(16, 0.1e-6, 2), lower = surface(16, 0.4e-6, 1);
  auto expect_message = [&](const RoughPairFilmOptions& o, const std::string& needle,
                            const Eigen::ArrayXXd& up, const Eigen::ArrayXXd& lo) {
    try {
      rough_pair_film(up, lo, kSize, o);
      ADD_FAILURE() << "no exception for " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  RoughPairFilmOptions o;
  expect_message(o, "exactly one of mean_gap_m", upper, lower);
  o.mean_gap_m = 1e-6;
  o.normal_load_N = 1.0;
  expect_message(o, "exactly one of mean_gap_m", upper, lower);
  o.normal_load_N.reset();
  o.contact_gap_fraction = 0.0;
  expect_message(o, "contact_gap_fraction", upper, lower);
  o.contact_gap_fraction = 1e-3;
  o.mean_gap_m = 1e-13;
  expect_message(o, "mean_gap_m must exceed the film floor", upper, lower);
  o.mean_gap_m = 1e-6;
  expect_message(o, "same n x n grid", upper, surface(8, 0.4e-6, 1));
  expect_message(o, "both surfaces are flat", Eigen::ArrayXXd::Zero(16, 16), Eigen::ArrayXXd::Zero(16, 16));
  RoughPairFilmOptions c;
  c.normal_load_N = -1.0;
  expect_message(c, "normal_load_N must be finite and > 0", upper, lower);
  c.normal_load_N = 1.0;
  c.composite_modulus_Pa = 0.0;
  expect_message(c, "composite_modulus_Pa", upper, lower);
}

}  // namespace
}  // namespace tribo::lubrication
