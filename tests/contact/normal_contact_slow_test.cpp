// Fine-grid references (label `slow`): Hertz at 512², the acceptance grid.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "contact/halfspace.h"
#include "contact/normal_contact.h"
#include "contact/reference/hertz.h"

namespace tribo::contact {
namespace {

// Hertz (Johnson §4.2) on a non-periodic 512² grid with a ≈ 128 cells: boundary quantisation of
// the counted area is ~0.4 % in radius and the collocation error of the peak ~Δx/a; 1 % bounds both.
TEST(NormalContactSlow, HertzSphereNonPeriodic512) {
  const double e_star = 1.137e11, radius = 0.01;
  const Grid grid = Grid::patch(512, 512, 1e-3, 1e-3);
  const double a_target = 0.25e-3;
  const double load = 4.0 * e_star * std::pow(a_target, 3) / (3.0 * radius);
  ElasticHalfSpace hs(grid, e_star, false);
  const NormalContactResult r = solve_normal_load(hs, sphere_gap(grid, radius), load);
  ASSERT_TRUE(r.summary.converged) << r.summary.message;
  const double a = std::sqrt(r.real_area_m2 / std::numbers::pi);
  EXPECT_NEAR(a / reference::hertz_contact_radius_m(load, radius, e_star), 1.0, 0.01);
  EXPECT_NEAR(r.max_pressure_Pa / reference::hertz_peak_pressure_Pa(load, radius, e_star), 1.0, 0.01);
  EXPECT_NEAR(r.approach_m / reference::hertz_approach_m(load, radius, e_star), 1.0, 0.01);
}

}  // namespace
}  // namespace tribo::contact
