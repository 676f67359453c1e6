// rate_and_state — Dieterich (1979) JGR 84:2161; Ruina (1983) JGR 88:10359; review Marone (1998)
// Annu Rev Earth Planet Sci 26:643. The Dieterich–Ruina law with the ageing (Dieterich) state law:
//
//     Δμ  = a ln(V_r(|U|)/V0) + b ln(V0 θ/D_c)      added to the solid kinetic coefficient (channel 3)
//     Δμs = a ln(V_r(|v|)/V0) + b ln(V0 θ/D_c)      added to the static coefficient        (channel 5)
//     dθ/dt = 1 − |U| θ / D_c                         in both phases; θ(0) = D_c/V0
//
// a is the direct effect (an instant step in speed shifts μ by a ln(V2/V1)), b the evolution
// effect (μ then relaxes over the slip distance D_c), θ (s) the contact's age. Steady sliding at V
// (θ = D_c/V) gives Δμ = (a − b) ln(V/V0): V0 is where the baseline μk is the steady friction.
// While stuck (U = 0) θ grows by the hold time: a hold t_h from steady sliding at V raises the
// static limit at re-loading by b ln(1 + t_h V/D_c) above the steady level (log-time healing).
// Δμs is the friction the contact reaches when the drive re-loads it at v: the peak of a
// slide-hold-slide test, which the rig's stick phase reaches as its breakaway threshold.
//
// Relation to slip_transient (thesis §5.2a): both decay over a slip distance D_c after slip
// starts; rate_and_state adds the dependence on speed (a, and a − b in steady sliding) and the
// growth of the peak with the time spent stuck (b ln θ), where slip_transient's peak is fixed.
//
// Regularisation: ln |U| → −∞ as U → 0, and a slip starts at U = 0. Both channels use
// V_r(u) = √(u² + V_ε²), V_ε = 1e-3 V0: within (a/2)(V_ε/u)² of the log law for u ≫ V_ε (5e-7 a
// at V0), smooth and even in u, and finite at u = 0. Static and kinetic share it, so in steady
// sliding Δμs = Δμ exactly. Rice's asinh form, μ = a asinh(U e^{μ/a} / 2V0), is not used: its
// regularising speed 2V0 e^{−μ/a} (6e-7 V0 at μ/a = 15) makes every slip onset stiff for the
// Adams integrator, and it needs the total μ in the exponent, not an increment.
// The log law is a small-perturbation law; where it would make a coefficient negative (a ln(V_ε/V0)
// below −μ at creep speeds with large a), the increment is floored at −μ so forces stay ≥ 0.
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class RateAndState final : public FrictionEffect {
 public:
  // V_ε / V0: far enough below V0 that the regularisation is invisible at sliding speeds, not so
  // far that the direct-effect slope W a / V_ε makes each slip onset needlessly stiff.
  static constexpr double kRegularisingSpeedFraction = 1e-3;

  RateAndState(double a, double b, double decay_distance_m, double reference_speed_m_per_s);
  std::string name() const override { return "rate_and_state"; }
  std::size_t state_size() const override { return 1; }
  void initial_state(std::span<double> state) const override { state[0] = steady_state_age_s(v0_m_per_s_); }
  // θ enters as b ln θ, so a relative error δ shifts μ by b δ. θ ≥ D_c/U; 1e-9 of θ(0) = D_c/V0 keeps
  // that below 1e-6 b at sliding speeds up to 1e3 V0 (rtol covers larger θ).
  void state_tolerances(std::span<double> atol, double /*mu_tolerance*/) const override { atol[0] = 1e-9 * steady_state_age_s(v0_m_per_s_); }
  void state_rates(const EffectContext& c, std::span<double> rates) const override;
  double kinetic_increment(const EffectContext& c) const override;
  double static_increment(const EffectContext& c) const override;
  // The direct effect is a damper a W / U: at the µm/s of a slide-hold-slide test it exceeds a
  // stiff machine's own damping by orders of magnitude, and Adams steps would have to resolve it.
  bool stiff(double /*normal_load_N*/, double /*natural_frequency_rad_per_s*/) const override { return a_ > 0.0; }

  // θ of steady sliding at speed V: D_c / V.
  double steady_state_age_s(double speed_m_per_s) const { return dc_m_ / speed_m_per_s; }
  // a ln(V_r(u)/V0) + b ln(V0 θ/D_c), unfloored.
  double increment(double speed_m_per_s, double age_s) const;

 private:
  double a_, b_, dc_m_, v0_m_per_s_;
};

}  // namespace tribo::rig::effects
