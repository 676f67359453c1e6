// Solids for the flash-temperature tests (lubrication/moving_heat_source.h), handbook values:
// hardened bearing steel (AISI 52100: k ≈ 46 W/(m K), ρ ≈ 7800 kg/m³, c ≈ 460 J/(kg K)) and a
// soda-lime glass (k ≈ 1.0, ρ ≈ 2500, c ≈ 840), the disc of optical EHL rigs, whose effusivity
// √(kρc) is a tenth of steel's.
#pragma once

#include "lubrication/ehl_traction.h"
#include "lubrication/moving_heat_source.h"

namespace tribo::lubrication::test_solids {

inline HeatedSolid bearing_steel() { return {46.0, 7800.0, 460.0}; }
inline HeatedSolid soda_lime_glass() { return {1.0, 2500.0, 840.0}; }

// A mineral oil's film heating (k = 0.13 W/(m K), γ = 0.03 /K) between bearing-steel surfaces passing
// the contact at u_m ± Δu/2.
inline FilmHeating oil_between_steel(double mean_speed_m_per_s) {
  FilmHeating h;
  h.thermal_conductivity_W_per_m_K = 0.13;
  h.temperature_viscosity_per_K = 0.03;
  h.surfaces = bearing_steel();
  h.mean_speed_m_per_s = mean_speed_m_per_s;
  return h;
}

}  // namespace tribo::lubrication::test_solids
