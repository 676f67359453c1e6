// Mixed lubrication of a line contact by Hu & Zhu's unified treatment (lubrication/ehl_line.h with
// an EhlRoughness): bad input, and a smooth cylinder crawling on its boundary layers —
// the film closed over the whole Hertz strip, the pressure Hertz's, the load carried in contact.
// The wavy surface against Westergaard's full contact and the film's lift-off are
// ehl_line_mixed_slow_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "contact/reference/capped_cylinder.h"
#include "ehl_line_mixed.h"
#include "lubrication/reference/ehl_film.h"

namespace tribo::lubrication {
namespace {

using namespace steel_rollers;

// Crawling (1 µm/s at 3e5 N/m; Pan–Hamrock's smooth film there is ≈ 0.02 nm, against the boundary
// layers' 5 nm): every node of the Hertz strip is in contact and carries Hertz's
// semi-ellipse — the dry contact of the same cylinder — to 1 % of p_H inside |x| < 0.9 b (the grid
// rounds the square-root edge; measured 0.2 %).
TEST(EhlLineMixed, SmoothCylinderCrawlingOnItsBoundaryLayersIsHertzsDryContact) {
  const double w = kCrawlLoad_N_per_m;
  const EhlRoughness flat = flat_profile(w);
  EhlLineOptions o;
  o.nodes = 401;
  const EhlLineResult r = solve_ehl_line({w, kRadius_m, kModulus_Pa, 1e-6}, flat, mineral_oil(), o);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.contact_load_share, 0.999);
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  int inside = 0;
  for (std::size_t i = 0; i < r.x_m.size(); ++i) {
    const double x = r.x_m[i] / r.hertz_half_width_m;
    if (std::abs(x) > 0.9) continue;
    ++inside;
    EXPECT_NEAR(r.pressure_Pa[i] / r.hertz_pressure_Pa, std::sqrt(1.0 - x * x), 0.01) << "x/b = " << x;
    EXPECT_LE(r.film_m[i], flat.contact_film_m) << "x/b = " << x;
  }
  EXPECT_GT(inside, 100);
}

// A hardness below Hertz's peak, 0.8 p_H: crawling, the middle of the strip yields — its pressure
// held at the hardness, its surface flowed plastically — and the contact is the plane-strain
// elastic–perfectly-plastic cylinder of contact/reference/capped_cylinder.h (800 strips, an
// active-set solve of the dry contact: another discretisation and method than the solver's). On 401
// nodes (b/80 apart): the yielded nodes are the reference's plastic strip (half width 0.878 b) to a
// node, and the pressure follows the reference within 1 % of p_H inside 0.9 of its contact half
// width (1.058 b), as the elastic crawling contact above follows Hertz (measured 0.20 %).
TEST(EhlLineMixed, CrawlingCylinderAboveItsHardnessIsTheElasticPlasticCylinder) {
  const double w = kCrawlLoad_N_per_m;
  EhlRoughness flat = flat_profile(w);
  EhlLineOptions o;
  o.nodes = 401;
  const EhlLineContact contact{w, kRadius_m, kModulus_Pa, 1e-6};
  const double ph = reference::hertz_line_peak_pressure_Pa(w, kRadius_m, kModulus_Pa);
  flat.hardness_Pa = 0.8 * ph;
  const contact::reference::CappedCylinderContact dry =
      contact::reference::capped_cylinder_contact(w, kRadius_m, 0.5 * kModulus_Pa, flat.hardness_Pa, 800);
  const EhlLineResult r = solve_ehl_line(contact, flat, mineral_oil(), o);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  EXPECT_NEAR(r.max_pressure_Pa / flat.hardness_Pa, 1.0, 1e-12);
  const double node = r.x_m[1] - r.x_m[0];
  int yielded_inside = 0, compared = 0;
  double worst = 0.0;
  for (std::size_t i = 0; i < r.x_m.size(); ++i) {
    const double x = std::abs(r.x_m[i]), p = r.pressure_Pa[i];
    const bool yielded = p == flat.hardness_Pa;
    if (x < dry.plastic_half_width_m - node) {
      EXPECT_TRUE(yielded) << "x/b = " << x / r.hertz_half_width_m;
      yielded_inside += yielded;
    }
    if (x > dry.plastic_half_width_m + node) {
      EXPECT_FALSE(yielded) << "x/b = " << x / r.hertz_half_width_m;
    }
    if (x < 0.9 * dry.contact_half_width_m) {
      const double error = std::abs(p - contact::reference::pressure_at_Pa(dry, r.x_m[i])) / ph;
      EXPECT_LT(error, 0.01) << "x/b = " << r.x_m[i] / r.hertz_half_width_m;
      worst = std::max(worst, error), ++compared;
    }
  }
  std::printf("plastic half width %.3f b, contact half width %.3f b; %d nodes yielded (%d within), plastic load share %.3f; "
              "worst %.4f p_H over %d nodes; %d Newton iterations, %d continuation steps\n",
              dry.plastic_half_width_m / r.hertz_half_width_m, dry.contact_half_width_m / r.hertz_half_width_m, r.plastic_nodes,
              yielded_inside, r.plastic_load_share, worst, compared, r.iterations, r.continuation_steps);
  EXPECT_GE(yielded_inside, 40);
}

// A bad profile is refused by the shared check (ehl_roughness_test.cpp), named as the line contact's.
TEST(EhlLineMixed, BadRoughnessIsRejectedAsTheLineContacts) {
  try {
    solve_ehl_line({kCrawlLoad_N_per_m, kRadius_m, kModulus_Pa, 1e-3}, EhlRoughness{{0.0, 0.0}, {0.0, 1e-9}}, mineral_oil());
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("EHL line contact: the roughness positions must increase", 0), 0u) << e.what();
  }
  EhlRoughness mapped = flat_profile(kCrawlLoad_N_per_m);
  mapped.map = EhlHeightMap{0.0, 0.0, 1e-6, 1e-6, Eigen::ArrayXXd::Zero(2, 2)};
  try {
    solve_ehl_line({kCrawlLoad_N_per_m, kRadius_m, kModulus_Pa, 1e-3}, mapped, mineral_oil());
    ADD_FAILURE() << "a map accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a roughness map is a point contact's"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::lubrication
