// slip_transient — thesis §5.2a, Figs 5.2.3–5.2.6: after slip onset the friction decays from the
// breakaway level towards the stable kinetic curve, and the decay is governed by the slip
// distance s (the same curve at ω = 102 and 152 rad/s), not by time or velocity:
//
//     Δμ(s) = a · (μs,eff − μk(0)) · exp(−s / D_c),    added to the solid kinetic coefficient.
//
// State: Δμ at onset (set at each breakaway). The picture is a fluid film built up by lift as the
// slider travels, like the rate-and-state D_c.
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class SlipTransient final : public FrictionEffect {
 public:
  SlipTransient(double amplitude, double decay_distance_m);
  std::string name() const override { return "slip_transient"; }
  std::size_t state_size() const override { return 1; }
  void initial_state(std::span<double> state) const override { state[0] = 0.0; }
  void on_slip_onset(const EffectContext& c, std::span<double> state) const override;
  double kinetic_increment(const EffectContext& c) const override;

 private:
  double amplitude_, decay_distance_m_;
};

}  // namespace tribo::rig::effects
