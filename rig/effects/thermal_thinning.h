// thermal_thinning — thesis §3.2 (Crook (3.2.3)–(3.2.5)) and §5.2b–c (Jaeger (5.2.1)–(5.2.2)):
// viscous traction of the film, F = η(T) U A / h, with the film temperature rising with speed.
// At the speeds of the rig Jaeger's rise (5.2.2) is close to linear in U, ΔT ≈ θ U, and the
// viscosity follows the exponential temperature law η = η0 exp(−γ ΔT)
// (lubrication/viscosity.h). With U_T = 1/(γ θ):
//
//     F_th(U) = c0 U · η(T0 + U/(γ U_T)) / η0 = c0 U exp(−U / U_T),
//
// the humped friction–velocity curve whose maximum c0 U_T / e sits at U = U_T (thesis: 1 in/s in
// quasi-harmonic oscillation, Fig 5.2.8; Crook's maximum at ln U = 1 − b). On its falling side
// the slope −W dμ/dU can exceed r, and steady sliding turns into quasi-harmonic oscillation.
#pragma once

#include "lubrication/viscosity.h"
#include "rig/effect.h"

namespace tribo::rig::effects {

class ThermalThinning final : public FrictionEffect {
 public:
  ThermalThinning(double traction_coefficient_N_s_per_m, double thermal_speed_m_per_s);
  std::string name() const override { return "thermal_thinning"; }
  double fluid_force_N(const EffectContext& c) const override;

 private:
  double c0_, u_t_;
  lubrication::Lubricant oil_;
};

}  // namespace tribo::rig::effects
