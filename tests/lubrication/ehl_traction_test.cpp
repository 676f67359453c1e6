// EHL traction (lubrication/ehl_traction.h) on films whose integrals are known in closed form: the
// Newtonian Couette shear of a parabolic gap, and the Eyring stress's logarithmic growth with the
// sliding speed. The traction of a solved roller pair is in ehl_line_slow_test.cpp.
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

TEST(EhlTraction, BadInputIsRejected) {
  const EhlLineResult film = parabolic_film(2e-7, 0.01, 1e-4, 1e6, 11);
  const PiezoviscousLubricant l = isoviscous(0.04);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 0.0, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, std::nan(""), 5e6, 1e5), std::invalid_argument);
  EXPECT_THROW(ehl_line_traction(film, l, 0.1, 5e6, -1.0), std::invalid_argument);
  EhlLineResult collapsed = film;
  collapsed.film_m[5] = 0.0;
  EXPECT_THROW(ehl_line_traction(collapsed, l, 0.1, 5e6, 1e5), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
