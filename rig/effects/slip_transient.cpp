#include "rig/effects/slip_transient.h"

#include <algorithm>
#include <cmath>

namespace tribo::rig::effects {

SlipTransient::SlipTransient(double amplitude, double decay_distance_m)
    : amplitude_(amplitude), decay_distance_m_(decay_distance_m) {}

void SlipTransient::on_slip_onset(const EffectContext& c, std::span<double> state) const {
  state[0] = amplitude_ * std::max(0.0, c.mu_s - c.mu_k_baseline);
}

double SlipTransient::kinetic_increment(const EffectContext& c) const {
  return c.state[0] * std::exp(-c.rig->slip_distance_m / decay_distance_m_);
}

}  // namespace tribo::rig::effects
