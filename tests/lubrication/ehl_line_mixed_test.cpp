// Mixed lubrication of a line contact by Hu & Zhu's unified treatment (lubrication/ehl_line.h with
// an EhlRoughness): bad input, and a smooth cylinder crawling on its boundary layers —
// the film closed over the whole Hertz strip, the pressure Hertz's, the load carried in contact.
// The wavy surface against Westergaard's full contact and the film's lift-off are
// ehl_line_mixed_slow_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "ehl_line_mixed.h"

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
  EhlRoughness hard = flat_profile(kCrawlLoad_N_per_m);
  hard.hardness_Pa = 1e9;
  try {
    solve_ehl_line({kCrawlLoad_N_per_m, kRadius_m, kModulus_Pa, 1e-3}, hard, mineral_oil());
    ADD_FAILURE() << "a hardness accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("hardness_Pa (a pressure cap) is the point contact's"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tribo::lubrication
