// The pin-on-disc rig as a spring-mass-damper driven through friction, thesis (4.2.1):
//
//     M ẍ + r ẋ + k x = F,
//
// x the slider (beam) displacement, F the friction force the driven disc exerts on the slider.
// Defaults are the thesis rig, steel on steel (Appendix I; DESIGN §5), converted to SI.
#pragma once

#include <cmath>

namespace tribo::rig {

struct RigParameters {
  double mass_kg = 0.99822;               // M = 5.70e-3 lb s²/in
  double stiffness_N_per_m = 10367.5;     // k = 59.2 lb/in (measured)
  double damping_N_s_per_m = 1.7338;      // r = 0.99e-2 lb s/in (decay r/2M = 0.87 1/s)
  double normal_load_N = 93.857;          // W = 21.1 lb
  double slider_radius_m = 4.7625e-3;     // 3/8 in diameter slider

  double natural_frequency_rad_per_s() const { return std::sqrt(stiffness_N_per_m / mass_kg); }
  double decay_rate_per_s() const { return damping_N_s_per_m / (2.0 * mass_kg); }
  double damped_frequency_rad_per_s() const {
    const double wn = natural_frequency_rad_per_s(), s = decay_rate_per_s();
    return std::sqrt(wn * wn - s * s);
  }
};

// Throws std::invalid_argument naming the first non-physical parameter (non-positive mass,
// stiffness, load or radius; negative damping; NaN; overdamped rig).
void validate(const RigParameters& rig);

}  // namespace tribo::rig
