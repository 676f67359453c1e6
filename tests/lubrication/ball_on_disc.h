// A steel ball on a steel disc as a ball-on-disc tribometer runs it (the EHL point-contact tests):
// a 3/4 in ball (R = 9.525 mm) on a flat, E = 210 GPa and ν = 0.3 for both (E' = E/(1 − ν²)),
// an oil of η0 = 0.04 Pa s with α = 2e-8 1/Pa (Roelands, Dowson–Higginson density).
#pragma once

#include "lubrication/ehl_point.h"

namespace tribo::lubrication::ball_on_disc {

inline constexpr double kRadius_m = 9.525e-3;
inline constexpr double kModulus_Pa = 2.1e11 / (1.0 - 0.3 * 0.3);

inline PiezoviscousLubricant oil() {
  PiezoviscousLubricant l;
  l.viscosity_Pa_s = 0.04;
  l.pressure_viscosity_per_Pa = 2e-8;
  return l;
}

inline EhlPointContact contact(double load_N, double speed_m_per_s) { return {load_N, kRadius_m, kModulus_Pa, speed_m_per_s}; }

inline EhlPointOptions grid(int nodes) {
  EhlPointOptions o;
  o.nodes_x = o.nodes_y = nodes;
  return o;
}

}  // namespace tribo::lubrication::ball_on_disc
