// Mixed lubrication of a point contact by Hu & Zhu's unified treatment (lubrication/ehl_point.h
// with an EhlRoughness): bad input, and a smooth ball crawling on its boundary layers — the film
// closed over the Hertz circle, the pressure Hertz's, the load carried in contact. Ridges against
// Westergaard's full contact, the lift-off and the thick film are ehl_point_mixed_slow_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>

#include "contact/reference/capped_sphere.h"
#include "tests/lubrication/capped_routes.h"
#include "tests/lubrication/ehl_point_mixed.h"

namespace tribo::lubrication {
namespace {

using namespace ball_on_disc;

// Crawling (1 µm/s at 20 N; Hamrock–Dowson's smooth film there is ≈ 0.05 nm, against the boundary
// layers' 5 nm): the nodes of the Hertz circle are in contact and carry Hertz's semi-ellipsoid —
// the dry contact of the same ball — to 1 % of p_H within 0.5 a (measured 0.33 % on 31²) and 3 %
// within 0.9 a, where the grid's cells cut the square-root edge (measured 1.8 %). The film there is
// the layers' to within the contact margin.
TEST(EhlPointMixed, SmoothBallCrawlingOnItsBoundaryLayersIsHertzsDryContact) {
  const EhlRoughness flat = flat_surface();
  const EhlPointResult r = solve_ehl_point(ball_contact(kCrawlLoad_N, 1e-6), flat, ball_oil(), ball_grid(31));
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.contact_load_share, 0.98);
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  const std::size_t nx = r.x_m.size();
  int inner = 0;
  for (std::size_t j = 0; j < r.y_m.size(); ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double x = r.x_m[i] / r.hertz_radius_m, y = r.y_m[j] / r.hertz_radius_m, r2 = x * x + y * y;
      if (r2 > 0.81) continue;
      const double p = r.pressure_Pa[i + nx * j] / r.hertz_pressure_Pa;
      EXPECT_NEAR(p, std::sqrt(1.0 - r2), r2 < 0.25 ? 0.01 : 0.03) << "x/a = " << x << ", y/a = " << y;
      EXPECT_TRUE(r.in_contact[i + nx * j]) << "x/a = " << x << ", y/a = " << y;
      EXPECT_NEAR(r.film_m[i + nx * j], flat.contact_film_m, flat.contact_margin_m) << "x/a = " << x << ", y/a = " << y;
      inner += r2 < 0.25;
    }
  EXPECT_GE(inner, 20);
}

// A hardness below Hertz's peak, 0.8 p_H: crawling, the centre of the contact yields — its pressure
// held at the hardness, its surface flowed plastically under the boundary layers — and the contact
// is the elastic–perfectly-plastic sphere, here by the ring solution of
// contact/reference/capped_sphere.h (Johnson's disc deflections with the cap, axisymmetric, 400
// rings: independent of the EHL solver's cell kernel and grid; plastic radius 0.740 a, contact
// radius 1.010 a). On 31² (a node every a/6): the yielded nodes are the disc's to half a node (45
// within it, none beyond), and the elastic ring between the plastic edge and 0.9 of the contact
// radius follows the rings to 4 % of p_H (measured 2.6 %; 1.1 % on 41²) — one or two cells wide,
// where the fall from the cap and the square-root edge are both cut by the cells (the elastic
// contact's edge test above allows 3 %).
TEST(EhlPointMixed, CrawlingBallAboveItsHardnessIsTheElasticPlasticSphere) {
  EhlRoughness flat = flat_surface();
  const EhlPointContact contact = ball_contact(kCrawlLoad_N, 1e-6);
  const double ph = reference::hertz_point_peak_pressure_Pa(contact.load_N, contact.reduced_radius_m, contact.reduced_modulus_Pa);
  flat.hardness_Pa = 0.8 * ph;
  const contact::reference::CappedSphereContact dry = contact::reference::capped_sphere_contact(
      contact.load_N, contact.reduced_radius_m, 0.5 * contact.reduced_modulus_Pa, flat.hardness_Pa);
  const EhlPointResult r = solve_ehl_point(contact, flat, ball_oil(), ball_grid(31));
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  EXPECT_NEAR(r.max_pressure_Pa / flat.hardness_Pa, 1.0, 1e-12);
  const std::size_t nx = r.x_m.size();
  const double half_node = 0.5 * (r.x_m[1] - r.x_m[0]);
  int yielded_inside = 0, elastic_compared = 0;
  double worst = 0.0;
  for (std::size_t j = 0; j < r.y_m.size(); ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      const double radius = std::hypot(r.x_m[i], r.y_m[j]), p = r.pressure_Pa[i + nx * j];
      const bool yielded = p == flat.hardness_Pa;
      if (radius < dry.plastic_radius_m - half_node) {
        EXPECT_TRUE(yielded) << "r/a = " << radius / r.hertz_radius_m;
        yielded_inside += yielded;
      } else if (radius > dry.plastic_radius_m + half_node) {
        EXPECT_FALSE(yielded) << "r/a = " << radius / r.hertz_radius_m;
        if (radius < 0.9 * dry.contact_radius_m) {
          const double error = std::abs(p - contact::reference::pressure_at_Pa(dry, radius)) / ph;
          EXPECT_LT(error, 0.04) << "r/a = " << radius / r.hertz_radius_m;
          worst = std::max(worst, error), ++elastic_compared;
        }
      }
    }
  std::printf("plastic radius %.3f a, contact radius %.3f a; %d nodes yielded (%d within the disc), plastic load share %.3f; "
              "elastic ring: %d nodes, worst %.4f p_H; %d Newton iterations, %d continuation steps\n",
              dry.plastic_radius_m / r.hertz_radius_m, dry.contact_radius_m / r.hertz_radius_m, r.plastic_nodes, yielded_inside,
              r.plastic_load_share, elastic_compared, worst, r.iterations, r.continuation_steps);
  EXPECT_GE(yielded_inside, 40);
  EXPECT_GE(elastic_compared, 8);
}

// Two routes to the capped ball of the test above, 0.8 p_H on 31²: the cap lowered onto this grid's
// elastic answer from the Hertz start (start_from_coarser_grid off: 49 cap steps), and the nesting —
// 16² capped (the dense LU, the cap lowered onto its elastic answer), its pressures and plastic flow
// interpolated, and Newton on 31² with the cap set, no cap step there. One discrete problem, so one
// answer: every pressure to 1e-5 of p_H (Newton's tolerance 1e-7 on the residual, the pressures'
// error left below 1e-6), the yielded nodes the same, the load on them to 1e-5.
TEST(EhlPointMixed, ACappedCoarserGridStartsTheCappedSolveAtItsAnswer) {
  EhlRoughness flat = flat_surface();
  const EhlPointContact contact = ball_contact(kCrawlLoad_N, 1e-6);
  flat.hardness_Pa = 0.8 * reference::hertz_point_peak_pressure_Pa(contact.load_N, contact.reduced_radius_m, contact.reduced_modulus_Pa);
  EhlPointOptions direct = ball_grid(31);
  direct.start_from_coarser_grid = false;
  const EhlPointResult lowered = solve_ehl_point(contact, flat, ball_oil(), direct);
  const EhlPointResult nested = solve_ehl_point(contact, flat, ball_oil(), ball_grid(31));
  const double worst = expect_one_capped_answer(lowered, nested, flat.hardness_Pa, 1e-5);
  std::printf("lowered on 31²: %d Newton iterations, %d cap steps; nested: %d on 31², %d steps there; worst pressure difference %.2g p_H\n",
              lowered.iterations, lowered.continuation_steps, nested.iterations, nested.continuation_steps, worst);
}

// The same ridges given as a height map: the map's bilinear samples (a/200 apart) are the profile's
// at the nodes to 1e-9 of the ridges' depth, and the full grid the map needs (no symmetry assumed)
// solves the problem the half grid solves — the pressures equal to 1e-5 of p_H (Newton's tolerance
// 1e-7 on the residual; measured 2.3e-6), the contact share to 1e-5 — in the mixed regime, the
// crests in contact and the troughs open (a share of 0.448 at 20 µm/s).
TEST(EhlPointMixed, RidgesAsAHeightMapSolveAsTheProfileOnTheFullGrid) {
  const double a = reference::hertz_point_radius_m(kCrawlLoad_N, kBallRadius_m, kBallModulus_Pa);
  const double amplitude = 5e-9, wavelength = a;
  const EhlRoughness profile = ridges(amplitude, wavelength);
  const EhlRoughness map = height_map([&](double x, double) { return amplitude * std::cos(2.0 * std::numbers::pi * x / wavelength); });
  const EhlPointContact c = ball_contact(kCrawlLoad_N, 2e-5);
  const EhlPointResult half = solve_ehl_point(c, profile, ball_oil(), ball_grid(31)), full = solve_ehl_point(c, map, ball_oil(), ball_grid(31));
  ASSERT_TRUE(half.converged) << half.message;
  ASSERT_TRUE(full.converged) << full.message;
  ASSERT_EQ(half.pressure_Pa.size(), full.pressure_Pa.size());
  double worst = 0.0;
  for (std::size_t k = 0; k < half.pressure_Pa.size(); ++k) worst = std::max(worst, std::abs(half.pressure_Pa[k] - full.pressure_Pa[k]));
  std::printf("ridges as a map: largest pressure difference %.3g p_H, contact shares %.6f and %.6f\n", worst / half.hertz_pressure_Pa,
              half.contact_load_share, full.contact_load_share);
  EXPECT_LT(worst, 1e-5 * half.hertz_pressure_Pa);
  EXPECT_NEAR(half.contact_load_share, full.contact_load_share, 1e-5);
  EXPECT_GT(half.contact_load_share, 0.1);
  EXPECT_LT(half.contact_load_share, 0.9);
}

// A bad profile is refused by the shared check (ehl_roughness_test.cpp), named as the point contact's.
TEST(EhlPointMixed, BadRoughnessIsRejectedAsThePointContacts) {
  try {
    solve_ehl_point(ball_contact(kCrawlLoad_N, 1e-3), EhlRoughness{{0.0, 1e-3}, {0.0, 0.0}, 5e-9, -1e-9}, ball_oil());
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("EHL point contact: roughness contact_margin_m", 0), 0u) << e.what();
  }
}

}  // namespace
}  // namespace tribo::lubrication
