// The fast moving heat source (lubrication/moving_heat_source.h) against the half-space's closed
// forms (Carslaw & Jaeger 1959, §2.9): a surface moving at u under a flux q(x) from x0 warms by
// T(x) = 1/(e√(πu)) ∫ q(x')/√(x − x') dx' — for a uniform flux 2q√((x − x0)/(πu))/e, the
// half-space heated for its transit time; for q = s (x − x0), (4/3) s (x − x0)^{3/2}/(e√(πu)).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "lubrication/moving_heat_source.h"
#include "tests/lubrication/heated_solids.h"
#include "tests/lubrication/observed_order.h"

namespace tribo::lubrication {
namespace {

using test_solids::bearing_steel;

std::vector<double> uniform_nodes(double x0, double length, int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i) x[i] = x0 + length * i / (n - 1);
  return x;
}

// A uniform flux over cells that tile [x0, x]: the kernel's exact integrals add up to the closed
// form at every node, whatever the spacing — even, odd and uneven grids, to round-off.
TEST(MovingHeatSource, AUniformFluxWarmsEachPointAsAHalfSpaceHeatedForItsTransitTime) {
  const double q = 2e6, u = 4.0, x0 = -1e-4, e = thermal_effusivity(bearing_steel());
  std::vector<double> uneven = {x0, x0 + 1e-6, x0 + 5e-6, x0 + 2e-5, x0 + 2.2e-5, x0 + 9e-5, x0 + 2e-4};
  for (const std::vector<double>& x : {uniform_nodes(x0, 2e-4, 100), uniform_nodes(x0, 2e-4, 101), uneven}) {
    const std::vector<double> rise = moving_surface_temperature_rise_K(x, std::vector<double>(x.size(), q), u, bearing_steel());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double exact = 2.0 * q * std::sqrt((x[i] - x0) / (M_PI * u)) / e;
      EXPECT_NEAR(rise[i], exact, 1e-12 * (exact + 1.0)) << "node " << i << " of " << x.size();
    }
  }
  // The rise at the trailing edge of a 0.2 mm band on steel at 4 m/s under 2 MW/m²: 1.3 K.
  EXPECT_NEAR(2.0 * q * std::sqrt(2e-4 / (M_PI * u)) / e, 1.25, 0.01);
}

// A flux rising linearly from the leading edge: the error at the trailing edge falls as the
// spacing to the power 3/2 — the flux's change over the node's own cell, ∝ Δ, weighed by the
// kernel's integral over it, ∝ √Δ (the cells elsewhere are centred on their nodes) — observed over
// four refinements on even and odd node counts.
TEST(MovingHeatSource, ALinearFluxConvergesToItsClosedFormAtTheObservedOrder) {
  const double s = 1e10, u = 2.0, x0 = 0.0, length = 1e-4, e = thermal_effusivity(bearing_steel());
  const double exact = (4.0 / 3.0) * s * std::pow(length, 1.5) / (e * std::sqrt(M_PI * u));
  for (int first : {40, 41}) {
    std::vector<double> spacing, error;
    for (int n = first; n <= 8 * first; n *= 2) {
      const std::vector<double> x = uniform_nodes(x0, length, n);
      std::vector<double> q(x.size());
      for (std::size_t i = 0; i < x.size(); ++i) q[i] = s * (x[i] - x0);
      spacing.push_back(length / (n - 1));
      error.push_back(std::abs(moving_surface_temperature_rise_K(x, q, u, bearing_steel()).back() - exact));
    }
    const double order = observed_order(spacing, error);
    EXPECT_NEAR(order, 1.5, 0.1) << "grids from " << first << " nodes";
    EXPECT_LT(error.back(), 2e-3 * exact);
  }
}

TEST(MovingHeatSource, PecletNumberIsSpeedTimesHalfLengthOverTwiceTheDiffusivity) {
  const double kappa = 46.0 / (7800.0 * 460.0);
  EXPECT_NEAR(thermal_diffusivity_m2_per_s(bearing_steel()), kappa, 1e-15 * kappa);
  EXPECT_NEAR(peclet_number(bearing_steel(), 4.0, 6.5e-5), 4.0 * 6.5e-5 / (2.0 * kappa), 1e-12);
  EXPECT_NEAR(thermal_effusivity(bearing_steel()), std::sqrt(46.0 * 7800.0 * 460.0), 1e-9);
}

TEST(MovingHeatSource, BadInputIsRejected) {
  const std::vector<double> x = uniform_nodes(0.0, 1e-4, 5), q(5, 1e6);
  EXPECT_THROW(moving_surface_temperature_rise_K(x, q, 0.0, bearing_steel()), std::invalid_argument);      // at rest
  EXPECT_THROW(moving_surface_temperature_rise_K(x, q, -1.0, bearing_steel()), std::invalid_argument);     // backwards
  EXPECT_THROW(moving_surface_temperature_rise_K(x, q, 1.0, {0.0, 7800.0, 460.0}), std::invalid_argument);
  EXPECT_THROW(moving_surface_temperature_rise_K(x, q, 1.0, {46.0, 7800.0, std::nan("")}), std::invalid_argument);
  EXPECT_THROW(moving_surface_temperature_rise_K({0.0, 1e-5, 1e-5}, {1.0, 1.0, 1.0}, 1.0, bearing_steel()), std::invalid_argument);  // repeated node
  EXPECT_THROW(moving_surface_temperature_rise_K({0.0}, {1.0}, 1.0, bearing_steel()), std::invalid_argument);
  EXPECT_THROW(moving_surface_temperature_rise_K(x, std::vector<double>(4, 1e6), 1.0, bearing_steel()), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
