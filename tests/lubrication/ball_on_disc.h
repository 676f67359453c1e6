// A steel ball on a steel disc as a ball-on-disc tribometer runs it (the EHL point-contact tests):
// a 3/4 in ball (R = 9.525 mm) on a flat, E = 210 GPa and ν = 0.3 for both (E' = E/(1 − ν²)),
// an oil of η0 = 0.04 Pa s with α = 2e-8 1/Pa (Roelands, Dowson–Higginson density).
#pragma once

#include "lubrication/ehl_point.h"
#include "lubrication/mixed_point.h"

namespace tribo::lubrication::ball_on_disc {

inline constexpr double kBallRadius_m = 9.525e-3;
inline constexpr double kBallModulus_Pa = 2.1e11 / (1.0 - 0.3 * 0.3);

inline PiezoviscousLubricant ball_oil() {
  PiezoviscousLubricant l;
  l.viscosity_Pa_s = 0.04;
  l.pressure_viscosity_per_Pa = 2e-8;
  return l;
}

inline EhlPointContact ball_contact(double load_N, double speed_m_per_s) { return {load_N, kBallRadius_m, kBallModulus_Pa, speed_m_per_s}; }

inline EhlPointOptions ball_grid(int nodes) {
  EhlPointOptions o;
  o.nodes_x = o.nodes_y = nodes;
  return o;
}

// The mixed solves of the tests: each film on 25² nodes.
inline MixedPointOptions coarse_mixed() {
  MixedPointOptions o;
  o.film = ball_grid(25);
  return o;
}

// The same ball rough (as the rollers of steel_roller_pair.h): summits 4e10 per m² of radius 10 µm,
// σ_s = 0.1 µm, their mean plane 0.1 µm above the surface's, boundary friction 0.1; 10 N, 5 %
// slide-to-roll, Eyring τ0 = 5 MPa.
inline MixedPointContact rough_ball(double speed_m_per_s) {
  MixedPointContact c;
  c.film = ball_contact(10.0, speed_m_per_s);
  c.asperities = {4e10, 1e-5, 1e-7, 0.5 * kBallModulus_Pa};
  c.summit_height_m = 1e-7;
  c.boundary_friction_coefficient = 0.1;
  c.sliding_speed_m_per_s = 0.05 * speed_m_per_s;
  c.eyring_stress_Pa = 5e6;
  return c;
}

}  // namespace tribo::lubrication::ball_on_disc
