// hydrodynamic_lift — thesis §3.2 and §5.2a: between nominally parallel rough surfaces, rugosity
// (micro-wedges with cavitation) generates a net fluid lift that grows with relative speed and
// unloads the solid contact. Homogenised as the share of W carried by the fluid,
//
//     f_lift(U) = f_max · U / (U + U_½),      solid fraction χ = 1 − f_lift,
//
// linear in U at small speed (lift ∝ η U for a fixed gap, Reynolds) and saturating as the gap
// opens. `tribo reynolds flow-factors` computes the lift–speed curve this summarises.
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class HydrodynamicLift final : public FrictionEffect {
 public:
  HydrodynamicLift(double max_fraction, double half_speed_m_per_s) : f_max_(max_fraction), u_half_(half_speed_m_per_s) {}
  std::string name() const override { return "hydrodynamic_lift"; }
  double solid_fraction(const EffectContext& c) const override {
    const double u = c.rig->relative_speed_m_per_s;
    return 1.0 - f_max_ * u / (u + u_half_);
  }

 private:
  double f_max_, u_half_;
};

}  // namespace tribo::rig::effects
