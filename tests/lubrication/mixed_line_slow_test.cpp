// The Stribeck curve of a rough line contact by load sharing (lubrication/mixed_line.h): from the
// boundary friction through the mixed regime into full-film EHL, on the rough steel roller pair.
// 4 s in Release (five speeds, about 40 film solves); label slow.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "lubrication/mixed_line.h"
#include "tests/lubrication/steel_roller_pair.h"

namespace tribo::lubrication {
namespace {

// Entrainment 3 mm/s … 3 m/s: the film's share of the load rises with the speed; μ starts at the
// boundary friction 0.1 (within 2 %), falls to a minimum and rises again in full film, where the
// Eyring traction grows with the shear rate — the Stribeck curve's shape. The film carries 99 % of
// the load once the film parameter Λ = h_c/σ_s passes 3, and less than that below Λ = 2: the
// textbook criterion for full-film lubrication (Λ ≳ 3, Hamrock, Schmid & Jacobson, Fundamentals
// of Fluid Film Lubrication, there with the composite rms roughness for σ_s) comes out of the
// load sharing, not put in.
TEST(MixedLine, StribeckCurveRunsFromBoundaryThroughMixedIntoFullFilm) {
  const std::vector<double> speeds{3e-3, 3e-2, 0.3, 1.0, 3.0};
  std::vector<MixedLineResult> r;
  MixedLineOptions o;
  o.film.nodes = 201;
  for (double u : speeds) {
    r.push_back(solve_mixed_line(steel_rollers::rough_rollers(u), steel_rollers::mineral_oil(), o));
    ASSERT_TRUE(r.back().converged) << u << " m/s: " << r.back().message;
  }
  for (std::size_t k = 1; k < r.size(); ++k) EXPECT_GE(r[k].film_share, r[k - 1].film_share) << speeds[k] << " m/s";
  EXPECT_NEAR(r.front().friction_coefficient, 0.1, 0.002);
  const auto lowest = std::min_element(r.begin(), r.end(), [](const auto& a, const auto& b) { return a.friction_coefficient < b.friction_coefficient; });
  EXPECT_NE(lowest, r.begin());
  EXPECT_NE(lowest, r.end() - 1) << "no rise in full film";
  EXPECT_LT(lowest->friction_coefficient, 0.5 * r.front().friction_coefficient);
  for (const MixedLineResult& p : r) {
    if (p.film_parameter >= 3.0) {
      EXPECT_GE(p.film_share, 0.99) << "Λ = " << p.film_parameter;
    }
    if (p.film_parameter < 2.0) {
      EXPECT_LT(p.film_share, 0.99) << "Λ = " << p.film_parameter;
    }
  }
}

}  // namespace
}  // namespace tribo::lubrication
