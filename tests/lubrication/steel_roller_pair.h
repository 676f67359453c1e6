// The line contact the EHL tests share: a steel roller pair (E' = 2.26e11 Pa, R = 10 mm) in a mineral
// oil of 0.04 Pa·s with α = 2.2e-8 1/Pa (G = αE' ≈ 4970, the usual steel/mineral-oil value),
// entrained at 1 m/s; and the pair ground rough.
#pragma once

#include "lubrication/mixed_line.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication::steel_rollers {

constexpr double kRadius_m = 0.01, kModulus_Pa = 2.26e11, kSpeed_m_per_s = 1.0;

inline PiezoviscousLubricant mineral_oil() {
  PiezoviscousLubricant l;
  l.viscosity_Pa_s = 0.04;
  l.pressure_viscosity_per_Pa = 2.2e-8;
  return l;
}

// The same pair ground rough, for the mixed regime (mixed_line.h) at 1e5 N/m: summits with
// η β σ_s = 0.04 (the usual range of Greenwood & Williamson's surfaces) — 4e10 per m², radius
// 10 µm, σ_s = 0.1 µm, their mean plane σ_s above the surface's; boundary friction 0.1; sliding at
// 5 % of the entrainment speed; Eyring stress 5 MPa.
inline MixedLineContact rough_rollers(double speed_m_per_s) {
  MixedLineContact c;
  c.film = {1e5, kRadius_m, kModulus_Pa, speed_m_per_s};
  c.asperities = {4e10, 1e-5, 1e-7, 0.5 * kModulus_Pa};
  c.summit_height_m = 1e-7;
  c.boundary_friction_coefficient = 0.1;
  c.sliding_speed_m_per_s = 0.05 * speed_m_per_s;
  c.eyring_stress_Pa = 5e6;
  return c;
}

}  // namespace tribo::lubrication::steel_rollers
