// Mixed lubrication of a rough ball on a disc by load sharing (lubrication/mixed_point.h): the
// smooth limit (the EHL film alone) and bad input. The boundary limit and the load balance take
// tens of film solves each: mixed_point_slow_test.cpp. Coarse film grids (25²).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "lubrication/mixed_point.h"
#include "tests/lubrication/ball_on_disc.h"

namespace tribo::lubrication {
namespace {

using namespace ball_on_disc;

// The rough ball at 0.5 m/s with summits far below the film (σ_s = 1 nm against h_c ≈ 0.13 µm).
MixedPointContact ball_with_negligible_summits() {
  MixedPointContact c = rough_ball(0.5);
  c.asperities.summit_std_m = 1e-9;
  c.summit_height_m = 0.0;
  return c;
}

// Such summits carry nothing: the film takes the whole load, and the point is the smooth EHL
// contact's, film and traction alike (one film solve).
TEST(MixedPoint, SmoothSurfacesLeaveTheWholeLoadToTheFilm) {
  const MixedPointContact c = ball_with_negligible_summits();
  const MixedPointResult r = solve_mixed_point(c, ball_oil(), coarse_mixed());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.film_share, 1.0);
  EXPECT_EQ(r.film_solves, 1);
  EXPECT_EQ(r.asperity_load_N, 0.0);
  const EhlPointResult smooth = solve_ehl_point(c.film, ball_oil(), coarse_mixed().film);
  const EhlPointTraction t = ehl_point_traction(smooth, ball_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa, c.film.load_N);
  EXPECT_DOUBLE_EQ(r.central_film_m, smooth.central_film_m);
  EXPECT_NEAR(r.friction_coefficient, t.friction_coefficient, 1e-12 * t.friction_coefficient);
}

// The film's traction takes the contact's limiting shear stress: on the same smooth ball, a limit of
// half the unlimited peak stress per peak pressure gives the smooth film's traction under that
// limit (1e-12), some nodes at it, and a lower friction.
TEST(MixedPoint, TheFilmsTractionIsCappedAtTheLimitingShearStress) {
  MixedPointContact c = ball_with_negligible_summits();
  const MixedPointResult free = solve_mixed_point(c, ball_oil(), coarse_mixed());
  ASSERT_TRUE(free.converged) << free.message;
  c.limiting_shear.pressure_coefficient = 0.5 * free.traction.max_shear_stress_Pa / free.film.max_pressure_Pa;
  const MixedPointResult r = solve_mixed_point(c, ball_oil(), coarse_mixed());
  ASSERT_TRUE(r.converged) << r.message;
  const EhlPointResult smooth = solve_ehl_point(c.film, ball_oil(), coarse_mixed().film);
  const EhlPointTraction t =
      ehl_point_traction(smooth, ball_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa, c.film.load_N, {}, c.limiting_shear);
  EXPECT_NEAR(r.friction_coefficient, t.friction_coefficient, 1e-12 * t.friction_coefficient);
  EXPECT_GT(r.traction.limited_node_share, 0.0);
  EXPECT_LT(r.friction_coefficient, free.friction_coefficient);
}

TEST(MixedPoint, BadInputIsRejected) {
  MixedPointContact c = rough_ball(1.0);
  c.asperities.e_star_Pa *= 1.1;  // not the bodies' E'/2
  EXPECT_THROW(solve_mixed_point(c, ball_oil(), coarse_mixed()), std::invalid_argument);
  c = rough_ball(1.0);
  c.summit_height_m = -1e-8;
  EXPECT_THROW(solve_mixed_point(c, ball_oil(), coarse_mixed()), std::invalid_argument);
  c = rough_ball(1.0);
  c.film.load_N = 0.0;
  EXPECT_THROW(solve_mixed_point(c, ball_oil(), coarse_mixed()), std::invalid_argument);
  MixedPointOptions o = coarse_mixed();
  o.max_film_solves = 1;
  EXPECT_THROW(solve_mixed_point(rough_ball(1.0), ball_oil(), o), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
