#include "rig/effects/rate_and_state.h"

#include <algorithm>
#include <cmath>

namespace tribo::rig::effects {

RateAndState::RateAndState(double a, double b, double decay_distance_m, double reference_speed_m_per_s)
    : a_(a), b_(b), dc_m_(decay_distance_m), v0_m_per_s_(reference_speed_m_per_s) {}

double RateAndState::increment(double u, double age_s) const {
  const double v_eps = kRegularisingSpeedFraction * v0_m_per_s_;
  // ln √(u² + V_ε²) written as ½ ln(u² + V_ε²).
  return 0.5 * a_ * std::log((u * u + v_eps * v_eps) / (v0_m_per_s_ * v0_m_per_s_)) +
         b_ * std::log(v0_m_per_s_ * age_s / dc_m_);
}

void RateAndState::state_rates(const EffectContext& c, std::span<double> rates) const {
  rates[0] = 1.0 - c.rig->relative_speed_m_per_s * c.state[0] / dc_m_;
}

double RateAndState::kinetic_increment(const EffectContext& c) const {
  return std::max(increment(c.rig->relative_speed_m_per_s, c.state[0]), -c.mu_k_baseline);
}

double RateAndState::static_increment(const EffectContext& c) const {
  return std::max(increment(std::abs(c.rig->drive_speed_m_per_s), c.state[0]), -c.mu_s);
}

}  // namespace tribo::rig::effects
