// The mixed line contacts the tests share (ehl_line_mixed_test.cpp, ehl_line_mixed_slow_test.cpp):
// the steel rollers of steel_roller_pair.h at 3e5 N/m (p_H ≈ 1.04 GPa, b ≈ 0.18 mm), the stationary
// surface flat or wavy.
#pragma once

#include "lubrication/ehl_line.h"
#include "lubrication/reference/ehl_film.h"
#include "steel_roller_pair.h"

namespace tribo::lubrication::steel_rollers {

constexpr double kCrawlLoad_N_per_m = 3e5;

// A profile over [−6 b, 2 b] (the solver's domain and more) of heights a cos(2π x/wavelength).
inline EhlRoughness wavy_profile(double w, double amplitude_m, double wavelength_m) {
  const double b = reference::hertz_line_half_width_m(w, kRadius_m, kModulus_Pa);
  return cosine_ridges(-6.0 * b, 2.0 * b, amplitude_m, wavelength_m, 4001);
}

inline EhlRoughness flat_profile(double w) { return wavy_profile(w, 0.0, 1.0); }

}  // namespace tribo::lubrication::steel_rollers
