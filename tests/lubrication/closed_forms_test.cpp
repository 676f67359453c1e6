// Closed forms of lubrication/reference/squeeze_film.h and lubrication/viscosity.h checked
// against independent derivations: numerical quadrature of the Appendix III pressure, numerical
// integration of the constant-load squeeze ODE, and the stationary point of Crook's (3.2.5).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "lubrication/reference/squeeze_film.h"
#include "lubrication/viscosity.h"

namespace tribo::lubrication {
namespace {

constexpr double kEta = 0.021, kRadius = 4.7625e-3, kGap = 1e-6, kRate = -1e-6;

// (3.2.2) is the integral of the Appendix III pressure; Simpson's rule on 2000 intervals of a
// cubic integrand (p·2πρ) is exact to rounding, so 1e-12 relative.
TEST(SqueezeFilmClosedForm, LoadIsIntegralOfAppendixIIIPressure) {
  const int n = 2000;
  const double d = kRadius / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double rho = i * d;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * squeeze_film_pressure_Pa(kEta, kRadius, kGap, kRate, rho) * 2.0 * std::numbers::pi * rho;
  }
  EXPECT_NEAR(sum * d / 3.0, squeeze_film_load_N(kEta, kRadius, kGap, kRate),
              1e-12 * squeeze_film_load_N(kEta, kRadius, kGap, kRate));
  EXPECT_GT(squeeze_film_load_N(kEta, kRadius, kGap, kRate), 0.0);  // approaching discs carry load
}

// Integrating ḣ(h) from (3.2.2) with RK4 (time steps 1e-4 of the total) reproduces the closed
// squeeze-out time; RK4's global error at this step is < 1e-8 relative.
TEST(SqueezeFilmClosedForm, SqueezeOutTimeMatchesIntegratedOde) {
  const double load = 93.86, h0 = 2e-6, h1 = 1e-6;
  const double t_ref = squeeze_out_time_s(kEta, kRadius, load, h0, h1);
  const int steps = 10000;
  const double dt = t_ref / steps;
  double h = h0;
  auto f = [&](double g) { return squeeze_film_gap_rate_m_per_s(kEta, kRadius, g, load); };
  for (int i = 0; i < steps; ++i) {
    const double k1 = f(h), k2 = f(h + 0.5 * dt * k1), k3 = f(h + 0.5 * dt * k2), k4 = f(h + dt * k3);
    h += dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  EXPECT_NEAR(h, h1, 1e-8 * h1);
}

TEST(SqueezeFilmClosedForm, RejectsBadInput) {
  EXPECT_THROW(squeeze_film_load_N(0.0, kRadius, kGap, kRate), std::invalid_argument);
  EXPECT_THROW(squeeze_film_load_N(kEta, kRadius, -kGap, kRate), std::invalid_argument);
  EXPECT_THROW(squeeze_film_load_N(kEta, kRadius, kGap, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  EXPECT_THROW(squeeze_out_time_s(kEta, kRadius, 10.0, 1e-6, 2e-6), std::invalid_argument);
}

// Barus × exponential: the definitions of ψ and γ under (3.2.4) must come back out exactly.
TEST(Viscosity, RecoversDefiningCoefficients) {
  const Lubricant oil = thesis_white_mineral_oil();
  const double t0 = oil.reference_temperature_K;
  EXPECT_DOUBLE_EQ(viscosity_Pa_s(oil, 0.0, t0), 0.021);
  const double p = 1e8;
  EXPECT_NEAR(std::log(viscosity_Pa_s(oil, p, t0) / oil.viscosity_Pa_s) / p, oil.pressure_viscosity_per_Pa, 1e-20);
  const double dT = 20.0;
  EXPECT_NEAR(std::log(oil.viscosity_Pa_s / viscosity_Pa_s(oil, 0.0, t0 + dT)) / dT, oil.temperature_viscosity_per_K,
              1e-14);
  Lubricant bad = oil;
  bad.viscosity_Pa_s = -1.0;
  EXPECT_THROW(viscosity_Pa_s(bad, 0.0, t0), std::invalid_argument);
}

// (3.2.5) has its maximum at ln U = 1 − b: central differences of F vanish there (to the
// O(δ²) truncation, 1e-6 relative with δ = 1e-4 U*) and F(U*) = a e^{b−1}.
TEST(CrookTraction, MaximumAtLnUEqualsOneMinusB) {
  const double a = 0.5, b = 3.2;
  const double u_star = crook_peak_speed_m_per_s(b);
  EXPECT_NEAR(std::log(u_star), 1.0 - b, 1e-15);
  EXPECT_NEAR(crook_traction_N(a, b, u_star), a * std::exp(b - 1.0), 1e-12);
  const double d = 1e-4 * u_star;
  EXPECT_LT(crook_traction_N(a, b, u_star + d), crook_traction_N(a, b, u_star));
  EXPECT_LT(crook_traction_N(a, b, u_star - d), crook_traction_N(a, b, u_star));
}

// (5.2.2) limits: a = 0 gives ΔT = K μ v^{1/2} N^{1/4}; large a gives K μ v N^{1/2} / a.
TEST(JaegerFlashTemperature, LimitsOfReducedForm) {
  const double K = 30.0, mu = 0.15, v = 0.1, n = 90.0;
  EXPECT_NEAR(jaeger_temperature_rise_K(K, 0.0, mu, v, n), K * mu * std::sqrt(v) * std::pow(n, 0.25), 1e-12);
  const double a = 1e6;
  EXPECT_NEAR(jaeger_temperature_rise_K(K, a, mu, v, n), K * mu * v * std::sqrt(n) / a, 1e-6 * K * mu * v * std::sqrt(n) / a);
  EXPECT_EQ(jaeger_temperature_rise_K(K, 0.0, mu, 0.0, n), 0.0);
}

}  // namespace
}  // namespace tribo::lubrication
