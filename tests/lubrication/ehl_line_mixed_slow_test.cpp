// Mixed lubrication of a line contact (lubrication/ehl_line.h with an EhlRoughness), the
// cases that need 801 nodes: a wavy stationary surface crawling in full contact against
// Westergaard's solution, the contact lifting off as the speed rises, and a thick film that is the
// smooth contact's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "ehl_line_mixed.h"

namespace tribo::lubrication {
namespace {

using namespace steel_rollers;

EhlLineOptions fine() {
  EhlLineOptions o;
  o.nodes = 801;  // 33 nodes a wavelength of b/4
  return o;
}

// A sinusoid of wavelength λ pressed flat by a half-space carries p̄ + p* cos(2πx/λ) with
// p* = π E* Δ/λ wherever p̄ ≥ p* (Westergaard 1939; Johnson, Contact Mechanics, 1985, ch. 13), so
// a wavy pin crawling on its boundary layers inside the Hertz strip carries Hertz's semi-ellipse plus
// that ripple. Δ set for p* = 0.2 p_H at λ = b/4: within |x| < b/2 (where p_H√(1 − x²/b²) > p*) the
// pressure is Hertz + ripple to 0.5 % of p_H — 2.5 % of the ripple, for a grid of 33 nodes a
// wavelength and the strip's finite width (measured 0.17 %). Without the profile in the film the
// ripple is missing (0.2 p_H); with its sign turned, 0.4 p_H.
TEST(EhlLineMixedSlow, WavyPinCrawlingIsWestergaardsFullContactOnHertz) {
  const double w = kCrawlLoad_N_per_m;
  const double b = reference::hertz_line_half_width_m(w, kRadius_m, kModulus_Pa);
  const double ph = reference::hertz_line_peak_pressure_Pa(w, kRadius_m, kModulus_Pa);
  const double wavelength = b / 4.0, ripple = 0.2;
  const double amplitude = ripple * ph * wavelength / (std::numbers::pi * 0.5 * kModulus_Pa);  // E* = E'/2
  const EhlLineResult r =
      solve_ehl_line({w, kRadius_m, kModulus_Pa, 1e-4}, wavy_profile(w, amplitude, wavelength), mineral_oil(), fine());
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_GT(r.contact_load_share, 0.999);
  int inside = 0;
  for (std::size_t i = 0; i < r.x_m.size(); ++i) {
    const double x = r.x_m[i] / b;
    if (std::abs(x) > 0.5) continue;
    ++inside;
    const double westergaard = std::sqrt(1.0 - x * x) + ripple * std::cos(2.0 * std::numbers::pi * r.x_m[i] / wavelength);
    EXPECT_NEAR(r.pressure_Pa[i] / ph, westergaard, 0.005) << "x/b = " << x;
  }
  EXPECT_GT(inside, 100);
}

// The Stribeck transition of the mixed model: the load the contact carries falls as the speed
// rises — all of it at 10 µm/s, nearly all at 0.1 mm/s, part of it at 0.5 mm/s, and by 1 mm/s every
// film has opened past the contact margin above the boundary layers (measured: 1.0000 at 10 µm/s,
// 0.9999 at 0.1 mm/s, 0.917 at 0.5 mm/s with a central film of 5.75 nm over the layers' 5 and the
// margin's 1, none at 1 mm/s; with the first-order wedge before 2026-12-02 the films were thicker
// and the share 0.906 already at 0.3 mm/s).
TEST(EhlLineMixedSlow, ContactLiftsOffAsTheSpeedRises) {
  const double w = kCrawlLoad_N_per_m;
  double last = 1.0;
  for (const double u : {1e-5, 1e-4, 5e-4, 1e-3}) {
    const EhlRoughness flat = flat_profile(w);
    const EhlLineResult r = solve_ehl_line({w, kRadius_m, kModulus_Pa, u}, flat, mineral_oil(), fine());
    ASSERT_TRUE(r.converged) << "u = " << u << ": " << r.message;
    std::printf("u_m %g m/s: contact share %.4f, %d nodes, central film %.3g m\n", u, r.contact_load_share, r.contact_nodes, r.central_film_m);
    EXPECT_LE(r.contact_load_share, last + 1e-9) << "u = " << u;
    if (u == 1e-5) {
      EXPECT_GT(r.contact_load_share, 0.999);
    }
    if (u == 1e-4) {
      EXPECT_GT(r.contact_load_share, 0.99);
    }
    if (u == 5e-4) {
      EXPECT_GT(r.contact_load_share, 0.5);
      EXPECT_LT(r.contact_load_share, 0.99);
    }
    if (u == 1e-3) {
      EXPECT_EQ(r.contact_nodes, 0);
      EXPECT_GT(r.minimum_film_m, flat.contact_film_m + flat.contact_margin_m);
    }
    last = r.contact_load_share;
  }
}

// A film 60 times the boundary layers (1 m/s: 0.28 µm) is the smooth contact's (its default 401
// nodes, second-order wedge, within 0.5 % of 801's): within 5 % at the centre and the outlet
// constriction. What separates them, measured: +5.5 % on 401 nodes and +3.4 % on 801 — first order
// in the node spacing, so ≈ 2 % on 801 is the rough contact's first-order wedge and ≈ 1.3 % the
// boundary layers, whose 5 nm pass no pressure flow. The peak pressure within 0.5 %.
TEST(EhlLineMixedSlow, ThickFilmIsTheSmoothContacts) {
  const double w = kCrawlLoad_N_per_m;
  const EhlLineContact c{w, kRadius_m, kModulus_Pa, kSpeed_m_per_s};
  const EhlLineResult a = solve_ehl_line(c, mineral_oil()), r = solve_ehl_line(c, flat_profile(w), mineral_oil(), fine());
  ASSERT_TRUE(a.converged) << a.message;
  ASSERT_TRUE(r.converged) << r.message;
  std::printf("smooth hc %.5g hmin %.5g pmax %.5g | mixed hc %.5g hmin %.5g pmax %.5g\n", a.central_film_m, a.minimum_film_m, a.max_pressure_Pa,
              r.central_film_m, r.minimum_film_m, r.max_pressure_Pa);
  EXPECT_EQ(r.contact_nodes, 0);
  EXPECT_NEAR(r.central_film_m / a.central_film_m, 1.0, 0.05);
  EXPECT_NEAR(r.minimum_film_m / a.minimum_film_m, 1.0, 0.05);
  EXPECT_NEAR(r.max_pressure_Pa / a.max_pressure_Pa, 1.0, 0.005);
}

}  // namespace
}  // namespace tribo::lubrication
