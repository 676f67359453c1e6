// slip_transient — thesis §5.2a, Figs 5.2.3–5.2.6: after slip onset the friction decays from the
// breakaway level towards the stable kinetic curve, and the decay is governed by the slip
// distance s (the same curve at ω = 102 and 152 rad/s), not by time or velocity:
//
//     Δμ(s) = a · (μs,eff − μk(0)) · exp(−s / D_c),    added to the solid kinetic coefficient.
//
// The stable curve it decays to may itself fall with slip speed (the thesis normalises each
// transient by "the value of friction at which they met the stable kinetic friction curve"). With
// a rate weakening β > 0 the increment relaxes over the same slip distance towards
//
//     Δμ_ss(U) = −β ln(|U| / U_ref),    dΔμ/dt = −(|U| / D_c) (Δμ − Δμ_ss(|U|)),
//
// which is Ruina's slip law written for μ (Ruina 1983, JGR 88:10359, eq. 8; with Ψ = b ln(V0θ/D_c),
// dθ/dt = −(Vθ/D_c) ln(Vθ/D_c) gives dΨ/dt = −(V/D_c)(Ψ + b ln(V/V0))): its steady state
// μss = μ0 − (b − a) ln(V/V0) with β = b − a when the direct effect a is small. β = 0 is the
// thesis form above exactly. U_ref only moves the level that μk absorbs (diagnosis: the data's
// median driven speed).
//
// Dieterich's ageing law instead of Ruina's slip law, with the ageing share f = β/b = 1 − a/b in
// (0, 1] (f = 0 is the slip law above): the whole increment X = Δμ follows
//
//     dX/dt = (|U| / D_c) (e^{−(X − Δμ_ss)/b} − 1) b,     b = β / f,    X = Δμ(onset) at slip onset,
//
// which is Dieterich's dθ/dt = 1 − |U|θ/D_c for the state's part b ln(U_ref θ/D_c) of μ (Dieterich
// 1979; Ruina 1983), with the direct effect a ln|U| folded into the stable level. Far above that
// level X falls linearly, by b per D_c of slip (ln θ drops linearly), not exponentially; and as the
// slip slows the level rises and the state heals with time, at the rate (U_ref/D_c) b e^{−X/b} (|U|/U_ref)^{1−f}
// — the slip law's state does not move without slip. At f → 0 (b ≫ the deviations) both are the
// linear relaxation above. b is floored at kMinimumB.
//
// State: Δμ at onset (set at each breakaway) and, when β > 0, the rate part R (reset to 0 at each breakaway),
// dR/dt = −(|U|/D_c)(R − Δμ_ss(|U|)); the increment is Δμ(onset) e^{−s/D_c} + R, which satisfies
// the relaxation above (it is linear) and keeps the closed form for β = 0. At |U| → 0 the target
// diverges but its rate |U| ln|U| → 0: R freezes while stuck and re-attaching.
// The picture is a fluid film built up by lift as the slider travels, like the rate-and-state D_c.
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class SlipTransient final : public FrictionEffect {
 public:
  // b's floor in the ageing law: below the b of any measured surface (rock and paper 0.005–0.02,
  // Marone 1998), and it bounds the law's stiffness, e^{|X − Δμ_ss|/b}, where a fit wanders.
  static constexpr double kMinimumB = 2e-3;

  SlipTransient(double amplitude, double decay_distance_m, double rate_weakening = 0.0, double reference_speed_m_per_s = 1e-2,
                double ageing_share = 0.0);
  std::string name() const override { return "slip_transient"; }
  // R only with a rate weakening: β = 0 integrates the thesis form with its one state exactly as
  // before (an idle second state would change CVODE's error norm, hence its steps).
  // Dieterich's law integrates the whole increment, one state.
  std::size_t state_size() const override { return rate_weakening_ > 0.0 && !ageing() ? 2 : 1; }
  void initial_state(std::span<double> state) const override {
    for (double& x : state) x = 0.0;
  }
  // R is a friction coefficient: 1e-9 is far below any measured μ. At the displacement's μ
  // tolerance instead (1e-6 in a gap prediction) a fit's predictions with rate weakening took
  // half the steps, but the fits moved: the velocity-step diagnosis test's re-calibrated baseline
  // stick-slipped on held-out data for 5 of 6 noise seeds against 2 of 6 (bench/README.md, "A
  // stiff squeeze film with BDF"). Not taken.
  void state_tolerances(std::span<double> atol, double /*mu_tolerance*/) const override {
    atol[0] = 1e-10;
    if (atol.size() > 1) atol[1] = 1e-9;
  }
  void state_rates(const EffectContext& c, std::span<double> rates) const override;
  void on_slip_onset(const EffectContext& c, std::span<double> state) const override;
  double kinetic_increment(const EffectContext& c) const override;
  // Δμ_ss at slip speed |U| (> 0).
  double steady_increment(double speed_m_per_s) const;
  // Dieterich's ageing law shapes the increment (f > 0 with a rate weakening).
  bool ageing() const { return ageing_share_ > 0.0 && rate_weakening_ > 0.0; }

 private:
  double amplitude_, decay_distance_m_, rate_weakening_, reference_speed_m_per_s_, ageing_share_;
};

}  // namespace tribo::rig::effects
