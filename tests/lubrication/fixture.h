// What the lubrication tests share: the thesis' oil and slider, and the textured film the
// benchmarks solve (bench/lubrication_bench.cpp).
#pragma once

#include <cmath>
#include <numbers>

#include "lubrication/reynolds.h"

namespace tribo::lubrication::fixture {

inline constexpr double kEta = 0.021;                // thesis white mineral oil, Pa s
inline constexpr double kRadius = 4.7625e-3;         // 3/16 in slider radius, m
inline constexpr double kGap = 1e-6, kRate = -1e-6;  // squeeze film: gap (m) and its rate (m/s, closing)

// h = h₀(1 + 0.4 cos(2πx/λ) cos(2πy/λ)), h₀ = 1 µm, λ = L/4, L = 1 mm, sliding in x at
// `speed_m_per_s`, ambient at x = 0 and L; (n + 1) × n nodes. Half of every dimple diverges: a
// quarter of the film cavitates with a cavitation model, and has sub-ambient pressure without.
inline ReynoldsProblem textured_film(int n, double speed_m_per_s, Cavitation cavitation, BoundaryY boundary_y = BoundaryY::periodic) {
  ReynoldsProblem pr;
  const double length = 1e-3, wavelength = length / 4;
  pr.grid = contact::Grid{n + 1, n, length / n, length / n};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < n; ++j)
    for (int i = 0; i <= n; ++i)
      pr.gap_m(i, j) = 1e-6 * (1.0 + 0.4 * std::cos(2 * std::numbers::pi * i * pr.grid.dx_m / wavelength) *
                                         std::cos(2 * std::numbers::pi * j * pr.grid.dy_m / wavelength));
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = speed_m_per_s;
  pr.boundary_y = boundary_y;
  pr.cavitation = cavitation;
  return pr;
}

}  // namespace tribo::lubrication::fixture
