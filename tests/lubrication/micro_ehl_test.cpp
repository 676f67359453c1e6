// EHL films at the contact spots (lubrication/micro_ehl.h) against their closed forms: the rest
// limit, Hamrock–Dowson with the pin's kinematics, the Greenwood–Williamson share, Eyring's shear
// and the area-weighted mean.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lubrication/micro_ehl.h"
#include "lubrication/reference/ehl_point_film.h"

namespace tribo::lubrication {
namespace {

// A spot pressed to the hardness of the thesis' disc: 10 µm², 1.18 GPa, with its Hertz radius.
contact::ContactSpot hard_spot() {
  contact::ContactSpot s;
  s.area_m2 = 1e-11;
  s.mean_pressure_Pa = 1.18e9;
  s.load_N = s.area_m2 * s.mean_pressure_Pa;
  const double a = std::sqrt(s.area_m2 / std::numbers::pi);
  s.equivalent_radius_m = 4.0 * MicroEhlOptions{}.e_star_Pa * a * a * a / (3.0 * s.load_N);
  return s;
}

// At rest there is no film: the spot shears as a boundary junction, τ = τ_i exactly.
TEST(MicroEhl, AtRestTheSpotShearsAtTheInterfaceStrength) {
  const MicroEhlOptions o;
  const SpotFilm f = spot_film(hard_spot(), 0.0, o);
  EXPECT_EQ(f.central_film_m, 0.0);
  EXPECT_EQ(f.boundary_share, 1.0);
  EXPECT_EQ(f.shear_Pa, o.interface_shear_strength_Pa);
}

// The film is Hamrock–Dowson's central film of the spot with the pin at rest and the disc at U:
// entrained at u_m = U/2, E' = 2E* (to round-off), for the thesis oil at 1 in/s.
TEST(MicroEhl, FilmIsHamrockDowsonsAtHalfTheSlidingSpeed) {
  const MicroEhlOptions o;
  const contact::ContactSpot s = hard_spot();
  const double eta = 0.021, u = 0.0254;
  const auto g = reference::point_contact_groups(s.load_N, s.equivalent_radius_m, 2.0 * o.e_star_Pa, 0.5 * u, eta, o.pressure_viscosity_per_Pa);
  const double expected = s.equivalent_radius_m * reference::hamrock_dowson_central_film(g);
  EXPECT_NEAR(spot_film(s, eta * u, o).central_film_m / expected, 1.0, 1e-12);
  EXPECT_GT(expected, 0.1e-9);  // a film of molecular size at the thesis' maximum of friction
  EXPECT_LT(expected, 10e-9);
}

// Where the film is as thick as the tips' roughness (Λ = 1) the pierced share is
// F_1(1)/F_1(0) = (φ(1) − (1 − Φ(1))) / φ(0) = 0.20884 (Gaussian summits; Greenwood & Williamson).
TEST(MicroEhl, BoundaryShareAtUnitFilmParameterIsTheGaussianRatio) {
  MicroEhlOptions o;
  const double eta_u = 0.021 * 0.3;
  o.tip_roughness_m = spot_film(hard_spot(), eta_u, o).central_film_m;
  const double phi1 = std::exp(-0.5) / std::sqrt(2.0 * std::numbers::pi), tail1 = 0.5 * std::erfc(1.0 / std::numbers::sqrt2);
  const double expected = (phi1 - tail1) / (1.0 / std::sqrt(2.0 * std::numbers::pi));
  EXPECT_NEAR(expected, 0.20884, 1e-5);
  EXPECT_NEAR(spot_film(hard_spot(), eta_u, o).boundary_share, expected, 1e-9);
}

// The fluid shear is Eyring's, τ0 asinh(η R(p̄) U / (τ0 h_c)), at a low spot pressure (1 MPa) and
// at the hardness (where the code takes asinh x = ln 2x): both to 1e-9 of the closed form, with
// Barus' R = e^{α p̄} and with Roelands' R = exp{(ln η0 + 9.67)[(1 + p̄/1.96e8)^z − 1]},
// z = α / (5.1e-9 (ln η0 + 9.67)) (Roelands 1966, as Hamrock, Schmid & Jacobson give it), written
// out here. The spot then shears τ = b τ_i + (1 − b) τ_f.
TEST(MicroEhl, FluidShearIsEyringsAtTheSpotsBarusOrRoelandsViscosity) {
  const double eta_u = 0.021 * 0.3;
  for (const PressureViscosityLaw law : {PressureViscosityLaw::barus, PressureViscosityLaw::roelands}) {
    MicroEhlOptions o;
    o.law = law;
    const double a = std::log(o.viscosity_Pa_s) + 9.67, z = o.pressure_viscosity_per_Pa / (5.1e-9 * a);
    for (double p : {1e6, 1.18e9}) {
      contact::ContactSpot s = hard_spot();
      s.mean_pressure_Pa = p;
      const SpotFilm f = spot_film(s, eta_u, o);
      const double ln_r = law == PressureViscosityLaw::barus ? o.pressure_viscosity_per_Pa * p : a * (std::pow(1.0 + p / 1.96e8, z) - 1.0);
      const double x = eta_u * std::exp(ln_r) / (o.eyring_stress_Pa * f.central_film_m);
      EXPECT_NEAR(f.fluid_shear_Pa / (o.eyring_stress_Pa * std::asinh(x)), 1.0, 1e-9) << p;
      EXPECT_NEAR(f.shear_Pa, f.boundary_share * o.interface_shear_strength_Pa + (1.0 - f.boundary_share) * f.fluid_shear_Pa, 1e-6);
    }
  }
}

// At the hardness Barus overstates the film's viscosity: for the thesis oil (η0 0.021 Pa s,
// α 2e-8) ln R is 23.6 with Barus and 15.9 with Roelands, so in the Eyring film's logarithmic
// range the Roelands shear is lower by τ0 (23.6 − 15.9) = 7.7 τ0 — the default is Roelands.
TEST(MicroEhl, RoelandsFilmShearsLessThanBarusAtTheHardnessByTheLogOfTheirRatio) {
  MicroEhlOptions barus;
  barus.law = PressureViscosityLaw::barus;
  const MicroEhlOptions roelands;
  ASSERT_EQ(roelands.law, PressureViscosityLaw::roelands);
  contact::ContactSpot s = hard_spot();
  s.mean_pressure_Pa = 1.18e9;
  const double eta_u = 0.021 * 0.3;
  const double drop = (spot_film(s, eta_u, barus).fluid_shear_Pa - spot_film(s, eta_u, roelands).fluid_shear_Pa) / roelands.eyring_stress_Pa;
  EXPECT_NEAR(drop, 23.6 - 15.9, 0.1);  // the two logs to 0.05 each
}

// With a limiting shear stress the fluid shear is min(Eyring, τ_L0 + Λ p̄): at the hardness the
// thesis oil's Roelands film shears at 73.5 MPa, above τ_L = 1 MPa + 0.05 p̄ = 60 MPa (asserted),
// which caps it exactly; at 1 MPa the Eyring stress (0.8 MPa) lies below the limit and is kept, bit
// for bit.
TEST(MicroEhl, FluidShearStopsAtTheLimitingShearStress) {
  MicroEhlOptions o;
  o.limiting_shear = {1e6, 0.05};
  const MicroEhlOptions free;
  const double eta_u = 0.021 * 0.3;
  contact::ContactSpot s = hard_spot();
  const SpotFilm capped = spot_film(s, eta_u, o);
  ASSERT_GT(spot_film(s, eta_u, free).fluid_shear_Pa, 1e6 + 0.05 * s.mean_pressure_Pa);
  EXPECT_DOUBLE_EQ(capped.fluid_shear_Pa, 1e6 + 0.05 * s.mean_pressure_Pa);
  s.mean_pressure_Pa = 1e6;
  ASSERT_LT(spot_film(s, eta_u, free).fluid_shear_Pa, 1e6);
  EXPECT_EQ(spot_film(s, eta_u, o).fluid_shear_Pa, spot_film(s, eta_u, free).fluid_shear_Pa);
}

// Thick films leave almost no junction: at ηU = 1 Pa m (a 0.05 Pa s oil at 20 m/s) the film is
// ≈ 0.2 µm, five tip roughnesses (b = F_1(5)/F_1(0) ≈ 1e-7), and the spot shears as fluid.
TEST(MicroEhl, ThickFilmsShearAsFluid) {
  const MicroEhlOptions o;
  const SpotFilm f = spot_film(hard_spot(), 1.0, o);
  EXPECT_GT(f.central_film_m, 4.0 * o.tip_roughness_m);
  EXPECT_LT(f.boundary_share, 1e-5);
  EXPECT_NEAR(f.shear_Pa, f.fluid_shear_Pa, 1e-5 * o.interface_shear_strength_Pa);
}

// Over several spots the shear and the separated share are area-weighted; with none, the
// interface strength and no film.
TEST(MicroEhl, MeanShearIsAreaWeightedAndTauIWithoutSpots) {
  const MicroEhlOptions o;
  contact::ContactSpot small = hard_spot(), large = hard_spot();
  large.area_m2 *= 3.0, large.load_N *= 3.0, large.equivalent_radius_m *= std::sqrt(3.0);
  const double eta_u = 0.021 * 0.1;
  const double expected = (small.area_m2 * spot_film(small, eta_u, o).shear_Pa + large.area_m2 * spot_film(large, eta_u, o).shear_Pa) /
                          (small.area_m2 + large.area_m2);
  const double separated = (small.area_m2 * (1.0 - spot_film(small, eta_u, o).boundary_share) +
                            large.area_m2 * (1.0 - spot_film(large, eta_u, o).boundary_share)) /
                           (small.area_m2 + large.area_m2);
  const SpotFilms both = mean_spot_films({small, large}, eta_u, o);
  EXPECT_NEAR(both.shear_Pa, expected, 1e-6);
  EXPECT_NEAR(both.film_share, separated, 1e-15);
  EXPECT_GT(both.film_share, 0.0);
  EXPECT_EQ(mean_spot_films({}, eta_u, o).shear_Pa, o.interface_shear_strength_Pa);
  EXPECT_EQ(mean_spot_films({}, eta_u, o).film_share, 0.0);
}

TEST(MicroEhl, NegativeSpeedsAndEmptySpotsAreRefused) {
  const MicroEhlOptions o;
  EXPECT_THROW(spot_film(hard_spot(), -1.0, o), std::invalid_argument);
  EXPECT_THROW(spot_film(contact::ContactSpot{}, 1e-3, o), std::invalid_argument);
  MicroEhlOptions bad;
  bad.tip_roughness_m = 0.0;
  EXPECT_THROW(validate(bad), std::invalid_argument);
  MicroEhlOptions negative_limit;
  negative_limit.limiting_shear.pressure_coefficient = -0.05;
  EXPECT_THROW(validate(negative_limit), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
