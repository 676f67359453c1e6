// The line contact the EHL tests share: a steel roller pair (E' = 2.26e11 Pa, R = 10 mm) in a mineral
// oil of 0.04 Pa·s with α = 2.2e-8 1/Pa (G = αE' ≈ 4970, the usual steel/mineral-oil value),
// entrained at 1 m/s.
#pragma once

#include "lubrication/piezoviscous.h"

namespace tribo::lubrication::steel_rollers {

constexpr double kRadius_m = 0.01, kModulus_Pa = 2.26e11, kSpeed_m_per_s = 1.0;

inline PiezoviscousLubricant mineral_oil() {
  PiezoviscousLubricant l;
  l.viscosity_Pa_s = 0.04;
  l.pressure_viscosity_per_Pa = 2.2e-8;
  return l;
}

}  // namespace tribo::lubrication::steel_rollers
