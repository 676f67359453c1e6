// viscous_friction — thesis (3.2.1): a Newtonian film of constant thickness h between parallel
// plane surfaces shears at τ = η U / h, adding a force linear in the relative speed,
//
//     F_v = c U,   c = η A / h   (N s/m),
//
// so steady sliding carries μk W + c U. Default c = 5 N s/m: thesis oil η = 0.021 Pa s over the
// slider face π R² = 7.1e-5 m² at an effective film of 0.3 µm.
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class ViscousFriction final : public FrictionEffect {
 public:
  explicit ViscousFriction(double coefficient_N_s_per_m) : c_(coefficient_N_s_per_m) {}
  std::string name() const override { return "viscous_friction"; }
  double fluid_force_N(const EffectContext& c) const override { return c_ * c.rig->relative_speed_m_per_s; }

 private:
  double c_;
};

}  // namespace tribo::rig::effects
