// EHL traction (lubrication/ehl_traction.h) on films whose integrals are known in closed form: the
// Newtonian Couette shear of a parabolic gap, the Eyring stress's logarithmic growth with the
// sliding speed, and a heated film's Lambert-W stress and traction peak. The traction of a solved roller pair is in ehl_line_slow_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "lubrication/ehl_line.h"
#include "lubrication/ehl_traction.h"

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
  const EhlTraction t = ehl_line_traction(parabolic_film(h, 1e30, 1e-4, 1e6, 11), isoviscous(eta), du, kInf, 1e5, {k, gamma});
  EXPECT_NEAR(t.max_shear_stress_Pa, 12.0 * k * omega / (gamma * du * h), 1e-12 * t.max_shear_stress_Pa);
  EXPECT_NEAR(t.max_film_temperature_rise_K, omega / gamma, 1e-12 * omega / gamma);
  // A viscosity that does not follow the temperature (γ = 0): the isothermal stress, and the film
  // still as warm as that stress makes it, ΔT = τΔu h/(12k).
  const EhlTraction flat = ehl_line_traction(parabolic_film(h, 1e30, 1e-4, 1e6, 11), isoviscous(eta), du, kInf, 1e5, {k, 0.0});
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
  const auto tau = [&](double du) { return ehl_line_traction(film, isoviscous(eta), du, kInf, 1e5, {k, gamma}).max_shear_stress_Pa; };
  const double du_peak = std::sqrt(12.0 * k * std::exp(1.0) / (gamma * eta));
  EXPECT_NEAR(tau(du_peak), std::sqrt(12.0 * k * eta / (gamma * std::exp(1.0))) / h, 1e-12 * tau(du_peak));
  EXPECT_GT(tau(du_peak), tau(0.98 * du_peak));
  EXPECT_GT(tau(du_peak), tau(1.02 * du_peak));
  EXPECT_LT(tau(10.0 * du_peak), 0.5 * tau(du_peak));
}

TEST(EhlTraction, BadInputIsRejected) {
  const EhlLineResult film = parabolic_film(2e-7, 0.01, 1e-4, 1e6, 11);
  const PiezoviscousLubricant l = isoviscous(0.04);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 0.0, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, std::nan(""), 5e6, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, -1.0), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {-0.13, 0.03}), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, 1e5, {0.13, std::nan("")}), std::invalid_argument);
  EhlLineResult collapsed = film;
  collapsed.film_m[5] = 0.0;
  EXPECT_THROW(ehl_line_traction(collapsed, l, 0.1, 5e6, 1e5), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
