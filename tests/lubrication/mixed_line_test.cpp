// Mixed lubrication of a rough line contact by load sharing (lubrication/mixed_line.h), on the steel
// roller pair of the EHL tests: its limits (smooth surfaces: the EHL film alone; slow and rough: the
// boundary friction), the load balance it solves, checked against the film solver and
// Greenwood–Williamson called directly, and bad input. The Stribeck curve across the regimes is in
// mixed_line_slow_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "lubrication/mixed_line.h"
#include "lubrication/reference/ehl_film.h"
#include "tests/lubrication/heated_solids.h"
#include "tests/lubrication/steel_roller_pair.h"

namespace tribo::lubrication {
namespace {

using steel_rollers::rough_rollers;

MixedLineOptions coarse() {
  MixedLineOptions o;
  o.film.nodes = 151;
  return o;
}

// Summits far below the film (σ_s = 1 nm, h_c ≈ 0.3 µm) carry nothing: the film takes the whole
// load, and the point is the smooth EHL contact's, film and traction alike (one film solve).
TEST(MixedLine, SmoothSurfacesLeaveTheWholeLoadToTheFilm) {
  MixedLineContact c = rough_rollers(1.0);
  c.asperities.summit_std_m = 1e-9;
  c.summit_height_m = 0.0;
  const MixedLineResult r = solve_mixed_line(c, steel_rollers::mineral_oil(), coarse());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_EQ(r.film_share, 1.0);
  EXPECT_EQ(r.film_solves, 1);
  EXPECT_EQ(r.asperity_load_per_length_N_per_m, 0.0);
  const EhlLineResult smooth = solve_ehl_line(c.film, steel_rollers::mineral_oil(), coarse().film);
  const EhlTraction t = ehl_line_traction(smooth, steel_rollers::mineral_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa, 1e5);
  EXPECT_DOUBLE_EQ(r.central_film_m, smooth.central_film_m);
  EXPECT_NEAR(r.friction_coefficient, t.friction_coefficient, 1e-12 * t.friction_coefficient);
}

// Slow and rough (3 mm/s, Λ ≈ 0.55): the summits carry all but about 1 % of the load, and μ is the
// boundary friction f_c = 0.1 within 2 % — the left end of the Stribeck curve.
TEST(MixedLine, SlowRoughContactRunsAtTheBoundaryFriction) {
  const MixedLineResult r = solve_mixed_line(rough_rollers(3e-3), steel_rollers::mineral_oil(), coarse());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_LT(r.film_share, 0.02);
  EXPECT_LT(r.film_parameter, 1.0);
  EXPECT_NEAR(r.friction_coefficient, 0.1, 0.002);
}

// With the surfaces' flash temperature on, the summits' boundary friction heats them too: the
// film's traction is ehl_line_traction's with the interface heat f_c p_GW Δu over the Hertz width,
// p_GW the summits' load over that width (1e-12); f_c = 0 leaves the same share and a cooler film.
TEST(MixedLine, TheSummitsFrictionHeatsTheSurfacesBesideTheFilm) {
  MixedLineContact c = rough_rollers(0.3);
  c.heating = test_solids::oil_between_steel(c.film.mean_speed_m_per_s);
  const MixedLineResult r = solve_mixed_line(c, steel_rollers::mineral_oil(), coarse());
  ASSERT_TRUE(r.converged) << r.message;
  const double b = reference::hertz_line_half_width_m(c.film.load_per_length_N_per_m, c.film.reduced_radius_m, c.film.reduced_modulus_Pa);
  FilmHeating heat = c.heating;
  heat.interface_heat_W_per_m2 = 0.1 * r.asperity_load_per_length_N_per_m / (2.0 * b) * c.sliding_speed_m_per_s;
  heat.interface_heat_half_width_m = b;
  const EhlTraction t = ehl_line_traction(r.film, steel_rollers::mineral_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa,
                                          r.film_load_per_length_N_per_m, heat);
  EXPECT_NEAR(r.traction.force_per_length_N_per_m, t.force_per_length_N_per_m, 1e-12 * t.force_per_length_N_per_m);
  EXPECT_NEAR(r.traction.max_surface_temperature_rise_K, t.max_surface_temperature_rise_K, 1e-12 * t.max_surface_temperature_rise_K);
  c.boundary_friction_coefficient = 0.0;
  const MixedLineResult cold = solve_mixed_line(c, steel_rollers::mineral_oil(), coarse());
  EXPECT_EQ(cold.film_share, r.film_share);
  EXPECT_LT(cold.traction.max_surface_temperature_rise_K, r.traction.max_surface_temperature_rise_K);
  EXPECT_GT(cold.film_friction_N_per_m, r.film_friction_N_per_m);
}

// The film's traction takes the contact's limiting shear stress (LimitingShear): the same film
// sheared under the same limit apart gives the same force (1e-12), and a limit of a tenth of the
// unlimited peak stress per peak pressure lowers the film's friction without moving the share.
TEST(MixedLine, TheFilmsTractionIsCappedAtTheLimitingShearStress) {
  MixedLineContact c = rough_rollers(0.3);
  const MixedLineResult free = solve_mixed_line(c, steel_rollers::mineral_oil(), coarse());
  ASSERT_TRUE(free.converged) << free.message;
  c.limiting_shear.pressure_coefficient = 0.1 * free.traction.max_shear_stress_Pa / free.film.max_pressure_Pa;
  const MixedLineResult r = solve_mixed_line(c, steel_rollers::mineral_oil(), coarse());
  ASSERT_TRUE(r.converged) << r.message;
  const EhlTraction t = ehl_line_traction(r.film, steel_rollers::mineral_oil(), c.sliding_speed_m_per_s, c.eyring_stress_Pa,
                                          r.film_load_per_length_N_per_m, c.heating, c.limiting_shear);
  EXPECT_NEAR(r.traction.force_per_length_N_per_m, t.force_per_length_N_per_m, 1e-12 * t.force_per_length_N_per_m);
  EXPECT_GT(r.traction.limited_node_share, 0.0);
  EXPECT_EQ(r.film_share, free.film_share);
  EXPECT_LT(r.film_friction_N_per_m, free.film_friction_N_per_m);
}

// In the mixed regime (0.3 m/s) the share found balances the load: the film solver called at
// s w and s E' gives the reported central film, and Greenwood–Williamson at d = h_c − y_s over
// the whole load's Hertz width carries the rest, to the stated tolerance.
TEST(MixedLine, TheShareFoundBalancesTheLoadWithGreenwoodWilliamson) {
  const MixedLineContact c = rough_rollers(0.3);
  const MixedLineOptions o = coarse();
  const MixedLineResult r = solve_mixed_line(c, steel_rollers::mineral_oil(), o);
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.film_share, 0.2);
  EXPECT_LT(r.film_share, 0.95);
  EhlLineContact scaled = c.film;
  scaled.load_per_length_N_per_m *= r.film_share;
  scaled.reduced_modulus_Pa *= r.film_share;
  const EhlLineResult film = solve_ehl_line(scaled, steel_rollers::mineral_oil(), o.film);
  EXPECT_DOUBLE_EQ(film.central_film_m, r.central_film_m);
  const double b = reference::hertz_line_half_width_m(1e5, steel_rollers::kRadius_m, steel_rollers::kModulus_Pa);
  const double asperities = 2.0 * b * contact::gw_at_separation(c.asperities, film.central_film_m - c.summit_height_m).pressure_Pa;
  EXPECT_NEAR(r.film_share * 1e5 + asperities, 1e5, o.tolerance * 1e5);
  EXPECT_NEAR(r.friction_coefficient, (0.1 * asperities + r.traction.force_per_length_N_per_m) / 1e5, 1e-12);
}

TEST(MixedLine, BadInputIsRejected) {
  const PiezoviscousLubricant oil = steel_rollers::mineral_oil();
  MixedLineContact c = rough_rollers(1.0);
  c.asperities.e_star_Pa *= 1.1;  // not the bodies' E'/2
  EXPECT_THROW(solve_mixed_line(c, oil), std::invalid_argument);
  c = rough_rollers(1.0);
  c.summit_height_m = -1e-8;
  EXPECT_THROW(solve_mixed_line(c, oil), std::invalid_argument);
  c = rough_rollers(1.0);
  c.boundary_friction_coefficient = std::nan("");
  EXPECT_THROW(solve_mixed_line(c, oil), std::invalid_argument);
  c = rough_rollers(1.0);
  c.asperities.summit_radius_m = 0.0;
  EXPECT_THROW(solve_mixed_line(c, oil), std::invalid_argument);
  MixedLineOptions o;
  o.min_share = 1.0;
  EXPECT_THROW(solve_mixed_line(rough_rollers(1.0), oil, o), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
