// Mixed lubrication of a rough ball on a disc by load sharing (lubrication/mixed_point.h): the
// boundary limit, the load balance it solves (checked against the film solver and
// Greenwood–Williamson called directly), and the ball-on-disc Stribeck curve across the regimes.
// Coarse film grids (25²): each film solve is a dense Newton iteration, and a point takes tens.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "lubrication/mixed_point.h"
#include "lubrication/reference/ehl_point_film.h"
#include "tests/lubrication/ball_on_disc.h"
#include "tests/lubrication/heated_solids.h"

namespace tribo::lubrication {
namespace {

using namespace ball_on_disc;

// Slow and rough (3 mm/s, Λ < 1): the summits carry nearly all the load, and μ is the boundary
// friction f_c = 0.1 within 3 % — the left end of the ball-on-disc Stribeck curve.
TEST(MixedPoint, SlowRoughContactRunsAtTheBoundaryFriction) {
  const MixedPointResult r = solve_mixed_point(rough_ball(3e-3), ball_oil(), coarse_mixed());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_LT(r.film_share, 0.03);
  EXPECT_LT(r.film_parameter, 1.0);
  EXPECT_NEAR(r.friction_coefficient, 0.1, 0.003);
}

// In the mixed regime the share found balances the load: the film solver called at s W and s E'
// gives the reported central film, and Greenwood–Williamson at d = h_c − y_s over the whole load's
// Hertz circle carries the rest, to the stated tolerance.
TEST(MixedPoint, TheShareFoundBalancesTheLoadWithGreenwoodWilliamson) {
  const MixedPointContact c = rough_ball(0.1);
  const MixedPointOptions o = coarse_mixed();
  const MixedPointResult r = solve_mixed_point(c, ball_oil(), o);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.film_share, 0.05);
  EXPECT_LT(r.film_share, 0.95);
  EhlPointContact scaled = c.film;
  scaled.load_N *= r.film_share;
  scaled.reduced_modulus_Pa *= r.film_share;
  const EhlPointResult film = solve_ehl_point(scaled, ball_oil(), o.film);
  EXPECT_DOUBLE_EQ(film.central_film_m, r.central_film_m);
  const double a = reference::hertz_point_radius_m(c.film.load_N, kBallRadius_m, kBallModulus_Pa);
  const double asperities =
      std::numbers::pi * a * a * contact::gw_at_separation(c.asperities, film.central_film_m - c.summit_height_m).pressure_Pa;
  EXPECT_NEAR(r.film_share * c.film.load_N + asperities, c.film.load_N, o.tolerance * c.film.load_N);
  EXPECT_NEAR(r.friction_coefficient, (0.1 * asperities + r.traction.force_N) / c.film.load_N, 1e-12);
}

// With the surfaces' flash temperature on, the summits' boundary friction heats them over the Hertz
// circle: the film's traction is ehl_point_traction's with the interface heat f_c p_GW Δu over
// r ≤ a, p_GW the summits' load over π a² (1e-12), and the film is warmer than with f_c = 0.
TEST(MixedPoint, TheSummitsFrictionHeatsTheSurfacesBesideTheFilm) {
  MixedPointContact c = rough_ball(0.1);
  c.heating = test_solids::oil_between_steel(c.film.mean_speed_m_per_s);
  const MixedPointResult r = solve_mixed_point(c, ball_oil(), coarse_mixed());
  ASSERT_TRUE(r.converged) << r.message;
  const double a = reference::hertz_point_radius_m(c.film.load_N, kBallRadius_m, kBallModulus_Pa);
  FilmHeating heat = c.heating;
  heat.interface_heat_W_per_m2 = 0.1 * r.asperity_load_N / (std::numbers::pi * a * a) * std::abs(c.sliding_speed_m_per_s);
  heat.interface_heat_half_width_m = a;
  const EhlPointTraction t = ehl_point_traction(r.film, ball_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa, r.film_load_N, heat);
  EXPECT_NEAR(r.traction.force_N, t.force_N, 1e-12 * t.force_N);
  EXPECT_NEAR(r.traction.max_surface_temperature_rise_K, t.max_surface_temperature_rise_K, 1e-12 * t.max_surface_temperature_rise_K);
  FilmHeating cool = c.heating;  // the film's heat alone into the same surfaces
  EXPECT_LT(ehl_point_traction(r.film, ball_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa, r.film_load_N, cool).max_surface_temperature_rise_K,
            r.traction.max_surface_temperature_rise_K);
}

}  // namespace
}  // namespace tribo::lubrication
