#include "rig/effects/slip_transient.h"

#include <algorithm>
#include <cmath>

namespace tribo::rig::effects {

SlipTransient::SlipTransient(double amplitude, double decay_distance_m, double rate_weakening, double reference_speed_m_per_s,
                             double ageing_share)
    : amplitude_(amplitude), decay_distance_m_(decay_distance_m), rate_weakening_(rate_weakening),
      reference_speed_m_per_s_(reference_speed_m_per_s), ageing_share_(ageing_share) {}

double SlipTransient::steady_increment(double speed_m_per_s) const {
  return -rate_weakening_ * std::log(speed_m_per_s / reference_speed_m_per_s_);
}

void SlipTransient::state_rates(const EffectContext& c, std::span<double> rates) const {
  const double u = std::abs(c.rig->relative_speed_m_per_s);
  if (ageing()) {
    const double b = std::max(rate_weakening_ / ageing_share_, kMinimumB);
    rates[0] = u > 0.0 ? (u / decay_distance_m_) * b * std::expm1(-(c.state[0] - steady_increment(u)) / b) : 0.0;
    return;
  }
  rates[0] = 0.0;
  if (rates.size() < 2) return;
  // |U| (R − Δμ_ss) → 0 as U → 0 (|U| ln|U| → 0); at rest exactly 0.
  rates[1] = u > 0.0 ? -(u / decay_distance_m_) * (c.state[1] - steady_increment(u)) : 0.0;
}

void SlipTransient::on_slip_onset(const EffectContext& c, std::span<double> state) const {
  state[0] = amplitude_ * std::max(0.0, c.mu_s - c.mu_k_baseline);
  if (state.size() > 1) state[1] = 0.0;
}

double SlipTransient::kinetic_increment(const EffectContext& c) const {
  if (ageing()) return std::max(c.state[0], -c.mu_k_baseline);
  const double transient = c.state[0] * std::exp(-c.rig->slip_distance_m / decay_distance_m_);
  if (c.state.size() < 2) return transient;
  // Floored at −μk as rate_and_state's log law, so the force stays ≥ 0 far above U_ref.
  return std::max(transient + c.state[1], -c.mu_k_baseline);
}

}  // namespace tribo::rig::effects
