// EHL traction (lubrication/ehl_traction.h) on films whose integrals are known in closed form: the
// Newtonian Couette shear of a parabolic gap, the Eyring stress's logarithmic growth with the
// sliding speed, and a heated film's Lambert-W stress and traction peak. The traction of a solved roller pair is in ehl_line_slow_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "lubrication/ehl_line.h"
#include "lubrication/ehl_traction.h"
#include "tests/lubrication/heated_solids.h"

namespace tribo::lubrication {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A parabolic gap h = h0 + x²/(2R) on [−a, a] under a uniform pressure p.
EhlLineResult parabolic_film(double h0, double R, double a, double p, int nodes) {
  EhlLineResult f;
  for (int i = 0; i < nodes; ++i) {
    const double x = -a + 2.0 * a * i / (nodes - 1);
    f.x_m.push_back(x);
    f.film_m.push_back(h0 + x * x / (2.0 * R));
    f.pressure_Pa.push_back(p);
  }
  return f;
}

// The film's own heating (conductivity k, temperature coefficient γ), the walls at the bulk temperature.
FilmHeating film_heating(double k, double gamma) {
  FilmHeating h;
  h.thermal_conductivity_W_per_m_K = k;
  h.temperature_viscosity_per_K = gamma;
  return h;
}

// The same, with both walls of `solid` warming as they pass the contact at u_m ± Δu/2.
FilmHeating film_and_surface_heating(double k, double gamma, const HeatedSolid& solid, double mean_speed_m_per_s) {
  FilmHeating h = film_heating(k, gamma);
  h.surfaces = solid;
  h.mean_speed_m_per_s = mean_speed_m_per_s;
  return h;
}

PiezoviscousLubricant isoviscous(double eta) {
  PiezoviscousLubricant l;
  l.viscosity_Pa_s = eta;
  l.pressure_viscosity_per_Pa = 0.0;
  l.law = PressureViscosityLaw::barus;
  return l;
}

// Newtonian Couette shear over the parabolic gap: F = η Δu ∫ dx/h = η Δu √(2R/h0) · 2 atan(a/√(2R h0)).
// The trapezoidal rule is second order: 2001 nodes over a = 20 √(2R h0) leave under 1e-5.
TEST(EhlTraction, NewtonianShearOfAParabolicGapIsTheArctanIntegral) {
  const double h0 = 2e-7, R = 0.01, eta = 0.04, du = 0.1, a = 20.0 * std::sqrt(2.0 * R * h0), w = 1e5;
  const EhlTraction t = ehl_line_traction(parabolic_film(h0, R, a, 1e6, 2001), isoviscous(eta), du, kInf, w);
  const double exact = eta * du * std::sqrt(2.0 * R / h0) * 2.0 * std::atan(a / std::sqrt(2.0 * R * h0));
  EXPECT_NEAR(t.force_per_length_N_per_m, exact, 1e-5 * exact);
  EXPECT_NEAR(t.friction_coefficient, exact / w, 1e-5 * exact / w);
  EXPECT_NEAR(t.max_shear_stress_Pa, eta * du / h0, 1e-12 * eta * du / h0);
}

// Eyring: where η Δu/(τ0 h) ≫ 1, τ = τ0 asinh(z) = τ0 [ln 2z + O(1/z²)], so a tenfold sliding
// speed adds τ0 ln 10 over the whole sheared length 2a — whatever the film's shape. With z ≥ 4e3
// everywhere (η = 1e4 Pa·s, as near a GPa), the O(1/z²) remainder is below 1e-7 of that.
TEST(EhlTraction, EyringStressGrowsWithTheLogarithmOfTheSlidingSpeed) {
  const double h0 = 2e-7, R = 0.01, a = 1e-4, tau0 = 5e6, w = 1e5;
  const EhlLineResult film = parabolic_film(h0, R, a, 1e6, 801);
  const PiezoviscousLubricant l = isoviscous(1e4);
  const double f1 = ehl_line_traction(film, l, 0.1, tau0, w).force_per_length_N_per_m;
  const double f10 = ehl_line_traction(film, l, 1.0, tau0, w).force_per_length_N_per_m;
  EXPECT_NEAR(f10 - f1, tau0 * std::log(10.0) * 2.0 * a, 1e-6 * tau0 * 2.0 * a);
  // Opposite sliding, opposite traction.
  EXPECT_DOUBLE_EQ(ehl_line_traction(film, l, -0.1, tau0, w).force_per_length_N_per_m, -f1);
}

// Heating, Newtonian, on a uniform film h at uniform viscosity η: the film's mean temperature rise
// ΔT = τΔu h/(12k) lowers η by e^{−γΔT}, so τ e^{γτΔu h/(12k)} = ηΔu/h, whose root is Lambert's W:
// τ = 12k W(s)/(γΔu h), s = γηΔu²/(12k), ΔT = W(s)/γ. At s = 1, W is the omega constant
// Ω = 0.5671432904097838. The bisection stops at 1e-15 of τ.
TEST(EhlTraction, HeatedNewtonianFilmFollowsLambertW) {
  const double h = 1e-6, eta = 0.04, gamma = 0.03, k = 0.13, omega = 0.5671432904097838;
  const double du = std::sqrt(12.0 * k / (gamma * eta));  // s = 1
  const EhlTraction t = ehl_line_traction(parabolic_film(h, 1e30, 1e-4, 1e6, 11), isoviscous(eta), du, kInf, 1e5, film_heating(k, gamma));
  EXPECT_NEAR(t.max_shear_stress_Pa, 12.0 * k * omega / (gamma * du * h), 1e-12 * t.max_shear_stress_Pa);
  EXPECT_NEAR(t.max_film_temperature_rise_K, omega / gamma, 1e-12 * omega / gamma);
  // A viscosity that does not follow the temperature (γ = 0): the isothermal stress, and the film
  // still as warm as that stress makes it, ΔT = τΔu h/(12k).
  const EhlTraction flat = ehl_line_traction(parabolic_film(h, 1e30, 1e-4, 1e6, 11), isoviscous(eta), du, kInf, 1e5, film_heating(k, 0.0));
  EXPECT_DOUBLE_EQ(flat.max_shear_stress_Pa, eta * du / h);
  EXPECT_NEAR(flat.max_film_temperature_rise_K, eta * du * du / (12.0 * k), 1e-12 * eta * du * du / (12.0 * k));
  // Without heating, the isothermal stress η Δu / h.
  EXPECT_DOUBLE_EQ(ehl_line_traction(parabolic_film(h, 1e30, 1e-4, 1e6, 11), isoviscous(eta), du, kInf, 1e5).max_shear_stress_Pa, eta * du / h);
}

// The same film's traction rises with Δu, peaks and falls: τ ∝ W(s)/√s is largest where W = 1,
// s = e, i.e. at Δu* = √(12 k e/(γη)), with τ* = √(12 k η/(γ e)) / h — the shape of a measured
// traction curve, which an isothermal film (rising without bound) cannot have.
TEST(EhlTraction, HeatedFilmTractionPeaksWhereLambertWIsOne) {
  const double h = 1e-6, eta = 0.04, gamma = 0.03, k = 0.13;
  const EhlLineResult film = parabolic_film(h, 1e30, 1e-4, 1e6, 11);
  const auto tau = [&](double du) { return ehl_line_traction(film, isoviscous(eta), du, kInf, 1e5, film_heating(k, gamma)).max_shear_stress_Pa; };
  const double du_peak = std::sqrt(12.0 * k * std::exp(1.0) / (gamma * eta));
  EXPECT_NEAR(tau(du_peak), std::sqrt(12.0 * k * eta / (gamma * std::exp(1.0))) / h, 1e-12 * tau(du_peak));
  EXPECT_GT(tau(du_peak), tau(0.98 * du_peak));
  EXPECT_GT(tau(du_peak), tau(1.02 * du_peak));
  EXPECT_LT(tau(10.0 * du_peak), 0.5 * tau(du_peak));
}

// The surfaces' flash temperature (FilmHeating::surfaces), on the solids of heated_solids.h.
using test_solids::bearing_steel;
using test_solids::soda_lime_glass;

// Rolling fast, sliding slowly (Δu/u_m = 1e-3), a uniform Newtonian film at fixed viscosity (γ = 0)
// makes a uniform heat Q = ηΔu²/h; each surface takes Q/2 and, at the outlet after L/u_m under the
// film, is as warm as a half-space under Q/2 for that time: Q√(L/(π u_m))/e. The film's mean is the
// walls' plus its own Qh/(12k). Tolerance 1e-3: the surfaces' speeds differ by 1e-3 of u_m, their
// rises by half that, and the film passes the difference between them.
TEST(EhlTraction, RollingFastEachSurfaceTakesHalfTheHeatAndWarmsAsAHalfSpace) {
  const double h = 1e-6, eta = 0.04, k = 0.13, um = 10.0, du = 1e-3 * um, half = 1e-4;
  const EhlTraction t = ehl_line_traction(parabolic_film(h, 1e30, half, 1e6, 201), isoviscous(eta), du, kInf, 1e5,
                                          film_and_surface_heating(k, 0.0, bearing_steel(), um));
  const double q = eta * du * du / h, walls = q * std::sqrt(2.0 * half / (M_PI * um)) / thermal_effusivity(bearing_steel());
  EXPECT_NEAR(t.max_surface_temperature_rise_K, walls, 1e-3 * walls);
  EXPECT_NEAR(t.max_film_temperature_rise_K, walls + q * h / (12.0 * k), 1e-3 * walls);
  EXPECT_DOUBLE_EQ(t.max_shear_stress_Pa, eta * du / h);  // γ = 0: the heat does not touch the stress
  EXPECT_NEAR(t.surface_peclet_number, peclet_number(bearing_steel(), um - 0.5 * du, half), 1e-12 * t.surface_peclet_number);
}

// A solid that conducts without limit stays at the bulk temperature: the film's own heating, to
// the bisection's 1e-15, on a heated Eyring film.
TEST(EhlTraction, ASolidThatConductsWithoutLimitLeavesTheFilmsOwnHeating) {
  const EhlLineResult film = parabolic_film(2e-7, 0.01, 1e-4, 1e8, 401);
  const PiezoviscousLubricant l = isoviscous(10.0);
  const double film_only = ehl_line_traction(film, l, 1.0, 5e6, 1e5, film_heating(0.13, 0.03)).force_per_length_N_per_m;
  const EhlTraction both = ehl_line_traction(film, l, 1.0, 5e6, 1e5, film_and_surface_heating(0.13, 0.03, {1e30, 7800.0, 460.0}, 4.0));
  EXPECT_NEAR(both.force_per_length_N_per_m, film_only, 1e-12 * film_only);
  EXPECT_LT(both.max_surface_temperature_rise_K, 1e-9);
}

// The speed of the largest of f(Δu) over [lo, hi] by golden-section search (f unimodal there).
template <class F>
double argmax(F&& f, double lo, double hi) {
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int i = 0; i < 60; ++i) {
    const double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    (f(c) > f(d) ? hi : lo) = (f(c) > f(d) ? d : c);
  }
  return 0.5 * (lo + hi);
}

// Thesis §5.2b: heat from beyond the film's own shear moves the traction maximum to a lower speed.
// A uniform Newtonian film alone peaks at Δu* = √(12 k e/(γη)) (the test above). With the walls
// warming too, a node whose walls add R_s per unit heat peaks at √(e h/(γη (h/(12k) + R_s))): the
// inlet node at Δu* (R_s = 0), the outlet node below it, with R_s = √(L/(π u_m))/e. The whole
// film's maximum lies between the two (within 5 %: the surfaces' speeds differ by up to Δu from
// u_m, so the outlet's R_s by up to 15 % on either side of its value at u_m).
TEST(EhlTraction, WarmSurfacesMoveTheTractionMaximumToALowerSpeed) {
  const double h = 1e-6, eta = 4.0, gamma = 0.03, k = 0.13, um = 20.0, half = 1e-4;
  const EhlLineResult film = parabolic_film(h, 1e30, half, 1e6, 201);
  const FilmHeating heat = film_and_surface_heating(k, gamma, soda_lime_glass(), um);
  const auto force = [&](double du) { return ehl_line_traction(film, isoviscous(eta), du, kInf, 1e5, heat).force_per_length_N_per_m; };
  const double peak = argmax(force, 0.5, 8.0);
  const double film_alone = std::sqrt(12.0 * k * std::exp(1.0) / (gamma * eta));
  const double r_s = std::sqrt(2.0 * half / (M_PI * um)) / thermal_effusivity(soda_lime_glass());
  const double outlet = std::sqrt(std::exp(1.0) * h / (gamma * eta * (h / (12.0 * k) + r_s)));
  std::printf("traction maximum: film alone %.3f m/s, outlet node %.3f m/s, whole film %.3f m/s\n", film_alone, outlet, peak);
  EXPECT_LT(peak, film_alone);
  EXPECT_GT(peak, 0.95 * outlet);
}

// A point contact's surfaces warm line by line along x, each line of nodes as a line contact of
// the same nodes would: on a film whose lines are pressurised over different lengths, the point's
// largest surface and film temperature rises are the largest of the lines' own (to round-off).
TEST(EhlTraction, EachLineOfAPointFilmWarmsItsSurfacesAsALineFilmWould) {
  const int nx = 41, ny = 5;
  const double dx = 5e-6, h = 5e-7, um = 5.0, du = 1.0, tau0 = 5e6;
  const PiezoviscousLubricant l = isoviscous(5.0);
  const FilmHeating heat = film_and_surface_heating(0.13, 0.03, bearing_steel(), um);
  EhlPointResult point;
  for (int i = 0; i < nx; ++i) point.x_m.push_back(i * dx);
  for (int j = 0; j < ny; ++j) point.y_m.push_back(j * 2e-5);
  double surface = 0.0, film_rise = 0.0;
  for (int j = 0; j < ny; ++j) {
    EhlLineResult line;
    const int last = 10 + 7 * j;  // pressurised from node 2 to node `last`
    for (int i = 0; i < nx; ++i) {
      const double p = i >= 2 && i <= last ? 1e8 : 0.0;
      line.x_m.push_back(point.x_m[i]), line.pressure_Pa.push_back(p), line.film_m.push_back(h);
      point.pressure_Pa.push_back(p), point.film_m.push_back(h);
    }
    const EhlTraction t = ehl_line_traction(line, l, du, tau0, 1e5, heat);
    surface = std::max(surface, t.max_surface_temperature_rise_K), film_rise = std::max(film_rise, t.max_film_temperature_rise_K);
  }
  const EhlPointTraction t = ehl_point_traction(point, l, du, tau0, 1.0, heat);
  EXPECT_GT(surface, 0.1);
  EXPECT_NEAR(t.max_surface_temperature_rise_K, surface, 1e-12 * surface);
  EXPECT_NEAR(t.max_film_temperature_rise_K, film_rise, 1e-12 * film_rise);
}

// Heat made at the interface outside the film (the asperity contacts' friction in the mixed regime)
// enters the surfaces beside the film's. Rolling fast and sliding slowly over a uniform Newtonian
// film at fixed viscosity, with H over the middle half of the film, each surface takes half of
// each heat, and at the outlet x = a it is T = [Q √(2a) + H (√(a + r) − √(a − r))]/(e√(π u_m)),
// r the band's half-width (on a cell edge, so the cells tile it exactly). H = Q/4 leaves the outlet
// the warmest point. Tolerance 1e-3 as for the film's heat alone.
TEST(EhlTraction, InterfaceHeatEntersTheSurfacesBesideTheFilms) {
  const double h = 1e-6, eta = 0.04, k = 0.13, um = 10.0, du = 1e-3 * um, a = 1e-4, spacing = a / 100.0;
  const double q = eta * du * du / h;
  FilmHeating heat = film_and_surface_heating(k, 0.0, bearing_steel(), um);
  heat.interface_heat_W_per_m2 = 0.25 * q;
  heat.interface_heat_half_width_m = 0.5 * a + 0.5 * spacing;
  const EhlTraction t = ehl_line_traction(parabolic_film(h, 1e30, a, 1e6, 201), isoviscous(eta), du, kInf, 1e5, heat);
  const double r = heat.interface_heat_half_width_m;
  const double outlet = (q * std::sqrt(2.0 * a) + 0.25 * q * (std::sqrt(a + r) - std::sqrt(a - r))) /
                        (thermal_effusivity(bearing_steel()) * std::sqrt(M_PI * um));
  EXPECT_NEAR(t.max_surface_temperature_rise_K, outlet, 1e-3 * outlet);
  EXPECT_NEAR(t.max_film_temperature_rise_K, outlet + q * h / (12.0 * k), 1e-3 * outlet);
  // The traction is the film's alone: the interface heat adds no shear, only warmth.
  EXPECT_DOUBLE_EQ(t.max_shear_stress_Pa, eta * du / h);
}

// Thesis §5.2b: "friction forces resulting from simultaneous viscous and metallic sources are much
// higher, with proportionately greater heat generation", so the film's traction maximum comes at a
// lower speed. The glass-walled film of the test above, now sharing the contact with metal that
// slides at f_c = 0.1 under a nominal 100 MPa (heat β Δu over the whole film, β = f_c p): its
// maximum moves from 3.85 m/s to 2.48. A node whose walls add R per unit heat solves
// τ = (ηΔu/h) exp(−γ[R(τ + β)Δu + τΔu h/(12k)]); the outlet's R = √(L/(π u_m))/e is the largest,
// so its maximum is the lowest, and the film's lies above it (5 %, as above).
TEST(EhlTraction, MetallicFrictionHeatMovesTheFilmsTractionMaximumLower) {
  const double h = 1e-6, eta = 4.0, gamma = 0.03, k = 0.13, um = 20.0, half = 1e-4, beta = 0.1 * 1e8;
  const EhlLineResult film = parabolic_film(h, 1e30, half, 1e6, 201);
  const auto film_peak = [&](double b) {
    return argmax(
        [&](double du) {
          FilmHeating heat = film_and_surface_heating(k, gamma, soda_lime_glass(), um);
          heat.interface_heat_W_per_m2 = b * du;
          heat.interface_heat_half_width_m = half;
          return ehl_line_traction(film, isoviscous(eta), du, kInf, 1e5, heat).force_per_length_N_per_m;
        },
        0.05, 8.0);
  };
  const double r = std::sqrt(2.0 * half / (M_PI * um)) / thermal_effusivity(soda_lime_glass());
  const auto outlet_stress = [&](double du) {  // the node's τ by bisection on its equation
    double lo = 0.0, hi = eta * du / h;
    for (int i = 0; i < 200; ++i) {
      const double tau = 0.5 * (lo + hi);
      const double rise = r * (tau + beta) * du + tau * du * h / (12.0 * k);
      (tau < eta * du / h * std::exp(-gamma * rise) ? lo : hi) = tau;
    }
    return 0.5 * (lo + hi);
  };
  const double film_alone = film_peak(0.0), with_metal = film_peak(beta), outlet = argmax(outlet_stress, 0.05, 8.0);
  std::printf("traction maximum: film's heat alone %.3f m/s, with the metal's %.3f m/s (outlet node %.3f m/s)\n", film_alone, with_metal,
              outlet);
  EXPECT_NEAR(film_alone, 3.853, 0.01);  // WarmSurfacesMoveTheTractionMaximumToALowerSpeed
  EXPECT_LT(with_metal, 0.8 * film_alone);
  EXPECT_GT(with_metal, 0.95 * outlet);
}

// Two solids (a steel surface against a glass one), the film conducting so well (k = 1e6 W/(m K))
// that both walls are at one temperature: the heat divides in proportion to the effusivities
// (Blok's partition), and at the outlet both surfaces are at 2Q√(L/(π u_m))/(e1 + e2). Rolling fast,
// sliding at 1e-3 of it, a uniform Newtonian film at fixed viscosity; tolerance 1e-3 as above.
TEST(EhlTraction, TwoSolidsShareTheHeatByTheirEffusivities) {
  const double h = 1e-6, eta = 0.04, um = 10.0, du = 1e-3 * um, half = 1e-4;
  FilmHeating heat = film_and_surface_heating(1e6, 0.0, bearing_steel(), um);
  heat.second_surface = soda_lime_glass();
  const EhlTraction t = ehl_line_traction(parabolic_film(h, 1e30, half, 1e6, 201), isoviscous(eta), du, kInf, 1e5, heat);
  const double q = eta * du * du / h;
  const double walls = 2.0 * q * std::sqrt(2.0 * half / (M_PI * um)) / (thermal_effusivity(bearing_steel()) + thermal_effusivity(soda_lime_glass()));
  EXPECT_NEAR(t.max_surface_temperature_rise_K, walls, 1e-3 * walls);
  // The smaller Péclet number is steel's (its diffusivity is 27 times glass's), on the faster surface.
  EXPECT_NEAR(t.surface_peclet_number, peclet_number(bearing_steel(), um + 0.5 * du, half), 1e-12 * t.surface_peclet_number);
  // Glass alone on both sides runs (e1 + e2)/(2 e_glass) times warmer.
  heat.surfaces = soda_lime_glass();
  const double glass = ehl_line_traction(parabolic_film(h, 1e30, half, 1e6, 201), isoviscous(eta), du, kInf, 1e5, heat).max_surface_temperature_rise_K;
  EXPECT_NEAR(glass / t.max_surface_temperature_rise_K,
              (thermal_effusivity(bearing_steel()) + thermal_effusivity(soda_lime_glass())) / (2.0 * thermal_effusivity(soda_lime_glass())), 2e-3);
}

// The limiting shear stress τ_L = τ_L0 + Λ p (LimitingShear), on closed forms.
//
// A Newtonian film over the parabolic gap at a uniform pressure, its limit half the stress at the
// centre: the middle |x| < x_c, where ηΔu/h > τ_L, shears at τ_L, the rest as before. With
// h(x_c) = ηΔu/τ_L = 2 h0, x_c = √(2R h0), and
//   F = τ_L 2x_c + ηΔu √(2R/h0) · 2 (atan(a/√(2R h0)) − π/4).
// The trapezoidal rule's O(Δx²) at the two kinks and over the arctan part leaves under 1e-5 with
// 20001 nodes; the share of nodes at the limit is x_c/a = 1/20 to a node at each kink.
TEST(EhlTraction, ANewtonianFilmAboveItsLimitShearsAtTheLimitInTheMiddleOnly) {
  const double h0 = 2e-7, R = 0.01, eta = 0.04, du = 1.0, w = 1e5, p = 1e6;
  const double l = std::sqrt(2.0 * R * h0), a = 20.0 * l;
  const double tau_limit = 0.5 * eta * du / h0;  // τ_L0 + Λ p with Λ = 0.05 and τ_L0 the rest
  const LimitingShear limit{tau_limit - 0.05 * p, 0.05};
  const int nodes = 20001;
  const EhlTraction t = ehl_line_traction(parabolic_film(h0, R, a, p, nodes), isoviscous(eta), du, kInf, w, {}, limit);
  const double x_c = l;
  const double exact = tau_limit * 2.0 * x_c + eta * du * std::sqrt(2.0 * R / h0) * 2.0 * (std::atan(a / l) - std::atan(1.0));
  EXPECT_NEAR(t.force_per_length_N_per_m, exact, 1e-5 * exact);
  EXPECT_EQ(t.max_shear_stress_Pa, tau_limit);
  EXPECT_NEAR(t.limited_node_share, x_c / a, 2.0 / nodes);
  // Without the limit the centre shears at ηΔu/h0, twice the limit; nothing is limited.
  const EhlTraction free = ehl_line_traction(parabolic_film(h0, R, a, p, nodes), isoviscous(eta), du, kInf, w);
  EXPECT_DOUBLE_EQ(free.max_shear_stress_Pa, 2.0 * tau_limit);
  EXPECT_EQ(free.limited_node_share, 0.0);
}

// A Hertzian pressure p_H √(1 − x²/b²) under a film stiff enough that the Eyring stress exceeds the
// limit everywhere: every node shears at τ_L0 + Λ p, so F = Λ (π/2) p_H b + τ_L0 2b and, over the
// Hertz load w = (π/2) p_H b, μ = Λ + 4 τ_L0/(π p_H) — the plateau of a traction curve at its
// limit. Tolerance 1e-5 of Λ: the trapezoidal rule's O(Δx^{3/2}) at the semi-ellipse's ends and the
// half cells at its edges (unsheared, p = 0), with Δx = b/10⁴.
TEST(EhlTraction, AContactShearedAtItsLimitEverywhereHasTheLimitsFrictionCoefficient) {
  const double p_h = 1e9, b = 1e-4, h = 1e-7, lambda = 0.05, tau_l0 = 2e6, tau0 = 5e6;
  const int nodes = 20001;
  EhlLineResult film;
  for (int i = 0; i < nodes; ++i) {
    const double x = -b + 2.0 * b * i / (nodes - 1);
    film.x_m.push_back(x);
    film.film_m.push_back(h);
    film.pressure_Pa.push_back(p_h * std::sqrt(std::max(1.0 - x * x / (b * b), 0.0)));
  }
  // η = 1e6 Pa s: the Eyring stress τ0 asinh(ηΔu/(τ0 h)) = 76 MPa, above τ_L ≤ 52 MPa.
  const double w = 0.5 * M_PI * p_h * b;
  const EhlTraction t = ehl_line_traction(film, isoviscous(1e6), 1.0, tau0, w, {}, LimitingShear{tau_l0, lambda});
  EXPECT_NEAR(t.friction_coefficient, lambda + 4.0 * tau_l0 / (M_PI * p_h), 1e-5 * lambda);
  EXPECT_DOUBLE_EQ(t.limited_node_share, 1.0);
  EXPECT_EQ(t.max_shear_stress_Pa, tau_l0 + lambda * p_h);
}

// Heat and the limit. A film held at its limit makes the heat τ_L Δu, so its mean temperature rise
// is τ_L Δu h/(12k) whatever its viscosity (1e-12). The limit caps the heated stress, not the
// isothermal one: the Lambert-W film of HeatedNewtonianFilmFollowsLambertW (s = 1) under a limit
// between its heated stress 12kΩ/(γΔu h) and its isothermal ηΔu/h shears as without the limit.
TEST(EhlTraction, AFilmAtItsLimitHeatsByTheLimitsStressAndTheLimitCapsTheHeatedStress) {
  const double h = 1e-6, k = 0.13, gamma = 0.03, du = 1.0, p = 1e8, lambda = 0.05;
  const EhlLineResult film = parabolic_film(h, 1e30, 1e-4, p, 11);
  const EhlTraction held = ehl_line_traction(film, isoviscous(100.0), du, kInf, 1e5, film_heating(k, gamma), LimitingShear{0.0, lambda});
  const double tau_limit = lambda * p;
  EXPECT_EQ(held.max_shear_stress_Pa, tau_limit);  // exactly: the limit binds at its own heat
  EXPECT_NEAR(held.max_film_temperature_rise_K, tau_limit * du * h / (12.0 * k), 1e-12 * tau_limit * du * h / (12.0 * k));
  EXPECT_DOUBLE_EQ(held.limited_node_share, 1.0);

  const double eta = 0.04, omega = 0.5671432904097838, du_s1 = std::sqrt(12.0 * k / (gamma * eta));
  const double heated = 12.0 * k * omega / (gamma * du_s1 * h), isothermal = eta * du_s1 / h;
  const LimitingShear between{0.0, 0.5 * (heated + isothermal) / p};
  const EhlTraction capped = ehl_line_traction(film, isoviscous(eta), du_s1, kInf, 1e5, film_heating(k, gamma), between);
  EXPECT_NEAR(capped.max_shear_stress_Pa, heated, 1e-12 * heated);
  EXPECT_EQ(capped.limited_node_share, 0.0);
}

// A limit that falls as the film warms, τ_L e^{−βΔT}, on a film held at it (γ = 0, a viscosity
// far above): τ e^{βτΔu h/(12k)} = τ_L, so τ = 12k W(x)/(βΔu h) with x = βτ_L Δu h/(12k) — Lambert's
// W again. At x = 1, τ = Ω τ_L and ΔT = Ω/β; at twice the speed x = 2, W(2) = 0.8526055020137255,
// and the traction has fallen: a traction curve at its limit turns over as the film warms (1e-12).
TEST(EhlTraction, ALimitThatFallsWithTemperatureFollowsLambertW) {
  const double h = 1e-6, k = 0.13, p = 1e8, lambda = 0.05, beta = 0.01, omega = 0.5671432904097838, w2 = 0.8526055020137255;
  const double tau_limit = lambda * p, du = 12.0 * k / (beta * tau_limit * h);  // x = 1
  const EhlLineResult film = parabolic_film(h, 1e30, 1e-4, p, 11);
  LimitingShear limit{0.0, lambda};
  limit.temperature_coefficient_per_K = beta;
  const EhlTraction t1 = ehl_line_traction(film, isoviscous(100.0), du, kInf, 1e5, film_heating(k, 0.0), limit);
  EXPECT_NEAR(t1.max_shear_stress_Pa, omega * tau_limit, 1e-12 * tau_limit);
  EXPECT_NEAR(t1.max_film_temperature_rise_K, omega / beta, 1e-12 * omega / beta);
  EXPECT_EQ(t1.limited_node_share, 1.0);
  const EhlTraction t2 = ehl_line_traction(film, isoviscous(100.0), 2.0 * du, kInf, 1e5, film_heating(k, 0.0), limit);
  EXPECT_NEAR(t2.max_shear_stress_Pa, w2 / 2.0 * tau_limit, 1e-12 * tau_limit);
  EXPECT_LT(t2.force_per_length_N_per_m, t1.force_per_length_N_per_m);
}

TEST(EhlTraction, BadInputIsRejected) {
  const EhlLineResult film = parabolic_film(2e-7, 0.01, 1e-4, 1e6, 11);
  const PiezoviscousLubricant l = isoviscous(0.04);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 0.0, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, std::nan(""), 5e6, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, -1.0), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, film_heating(-0.13, 0.03)), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, film_heating(0.13, std::nan(""))), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, film_and_surface_heating(0.0, 0.03, bearing_steel(), 4.0)), std::invalid_argument);  // no film conductivity
  EXPECT_THROW(ehl_line_traction(film, l, 8.0, 5e6, 1e5, film_and_surface_heating(0.13, 0.03, bearing_steel(), 4.0)), std::invalid_argument);  // a surface at rest
  EXPECT_THROW(ehl_line_traction(film, l, -9.0, 5e6, 1e5, film_and_surface_heating(0.13, 0.03, bearing_steel(), 4.0)), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, film_and_surface_heating(0.13, 0.03, {46.0, -1.0, 460.0}, 4.0)), std::invalid_argument);
  FilmHeating negative = film_and_surface_heating(0.13, 0.03, bearing_steel(), 4.0);
  negative.interface_heat_W_per_m2 = -1.0;
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, negative), std::invalid_argument);
  FilmHeating second_alone = film_heating(0.13, 0.03);
  second_alone.second_surface = bearing_steel();
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, second_alone), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {}, LimitingShear{0.0, -0.05}), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {}, LimitingShear{std::nan(""), 0.05}), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {}, LimitingShear{kInf, 0.0}), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {}, LimitingShear{0.0, 0.05, -0.01}), std::invalid_argument);
  EhlLineResult collapsed = film;
  collapsed.film_m[5] = 0.0;
  EXPECT_THROW(ehl_line_traction(collapsed, l, 0.1, 5e6, 1e5), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
