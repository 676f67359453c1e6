#include "rig/effects/thermal_thinning.h"

namespace tribo::rig::effects {

ThermalThinning::ThermalThinning(double traction_coefficient_N_s_per_m, double thermal_speed_m_per_s)
    : c0_(traction_coefficient_N_s_per_m), u_t_(thermal_speed_m_per_s), oil_(lubrication::thesis_white_mineral_oil()) {}

double ThermalThinning::fluid_force_N(const EffectContext& c) const {
  const double u = c.rig->relative_speed_m_per_s;
  const double t0 = oil_.reference_temperature_K;
  const double rise_K = u / (oil_.temperature_viscosity_per_K * u_t_);  // ΔT = θ U with γ θ = 1/U_T
  const double thinning = lubrication::viscosity_Pa_s(oil_, 0.0, t0 + rise_K) / lubrication::viscosity_Pa_s(oil_, 0.0, t0);
  return c0_ * u * thinning;
}

}  // namespace tribo::rig::effects
