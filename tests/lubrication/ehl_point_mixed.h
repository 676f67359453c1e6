// The mixed point contacts the tests share (ehl_point_mixed_test.cpp, ehl_point_mixed_slow_test.cpp):
// the ball of ball_on_disc.h at 20 N (p_H ≈ 0.83 GPa, a ≈ 0.11 mm) on a stationary surface flat or
// carrying transverse ridges.
#pragma once

#include <utility>

#include "lubrication/reference/ehl_point_film.h"
#include "tests/lubrication/ball_on_disc.h"

namespace tribo::lubrication::ball_on_disc {

constexpr double kCrawlLoad_N = 20.0;

// Ridges a cos(2π x/wavelength) over [−5 a, 3 a] (the solver's domain and more).
inline EhlRoughness ridges(double amplitude_m, double wavelength_m) {
  const double a = reference::hertz_point_radius_m(kCrawlLoad_N, kBallRadius_m, kBallModulus_Pa);
  return cosine_ridges(-5.0 * a, 3.0 * a, amplitude_m, wavelength_m, 4001);
}

inline EhlRoughness flat_surface() { return ridges(0.0, 1.0); }

// The domain of a crawling or mixed contact, [−1.5 a, 1.5 a] along and across the flow, `nodes` each
// way: films of 5–10 nm need no more inlet — Hamrock & Dowson's fully flooded inlet boundary
// m* = 1 + 3.06 [(R/a)² h_c/R]^0.58 (1977) is 1.15 a at 1 mm/s (measured: the same central film as
// the default domain's at the same spacing, 6.74 and 6.77 nm) — so the nodes go to the spacing its
// films need. The default's −3.5 a is for full films.
inline EhlPointOptions tight_grid(int nodes) {
  EhlPointOptions o = ball_grid(nodes);
  o.inlet_over_radius = -1.5, o.outlet_over_radius = 1.5, o.side_over_radius = 1.5;
  return o;
}

// A map of heights f(x, y) over [−5 a, 3 a] × [−4 a, 4 a], sampled every a/200 (no profile).
template <class Height>
EhlRoughness height_map(Height&& f) {
  const double a = reference::hertz_point_radius_m(kCrawlLoad_N, kBallRadius_m, kBallModulus_Pa);
  EhlHeightMap m;
  m.x0_m = -5.0 * a, m.y0_m = -4.0 * a, m.dx_m = m.dy_m = a / 200.0;
  m.height_m.resize(1601, 1601);
  for (Eigen::Index j = 0; j < m.height_m.cols(); ++j)
    for (Eigen::Index i = 0; i < m.height_m.rows(); ++i)
      m.height_m(i, j) = f(m.x0_m + static_cast<double>(i) * m.dx_m, m.y0_m + static_cast<double>(j) * m.dy_m);
  EhlRoughness r;
  r.map = std::move(m);
  return r;
}

}  // namespace tribo::lubrication::ball_on_disc
