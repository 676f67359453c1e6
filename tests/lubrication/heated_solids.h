// Solids for the flash-temperature tests (lubrication/moving_heat_source.h), handbook values:
// hardened bearing steel (AISI 52100: k ≈ 46 W/(m K), ρ ≈ 7800 kg/m³, c ≈ 460 J/(kg K)) and a
// soda-lime glass (k ≈ 1.0, ρ ≈ 2500, c ≈ 840), the disc of optical EHL rigs, whose effusivity
// √(kρc) is a tenth of steel's.
#pragma once

#include "lubrication/moving_heat_source.h"

namespace tribo::lubrication::test_solids {

inline HeatedSolid bearing_steel() { return {46.0, 7800.0, 460.0}; }
inline HeatedSolid soda_lime_glass() { return {1.0, 2500.0, 840.0}; }

}  // namespace tribo::lubrication::test_solids
