// The lubricant's limiting shear stress (Johnson & Tevaarwerk 1977's plastic limit; Bair & Winer
// 1979): above τ_L(p) = τ_L0 + Λ p a film shears as a plastic solid, and its stress stays at τ_L.
// Λ is the oil's (a few hundredths to about a tenth for mineral oils, falling with temperature;
// J. Tribol. 116 (1994) 612). A heated film (ehl_traction.h FilmHeating) may lower its limit with
// its mean temperature rise ΔT as its viscosity falls, τ_L e^{−β ΔT}; β is the oil's, measured,
// and 0 (the limit at the bulk temperature) unless given. Used by the EHL traction (ehl_traction.h)
// and the isothermal films at the asperity tops (micro_ehl.h, where β has no heat to act on).
#pragma once

#include <algorithm>
#include <limits>

namespace tribo::lubrication {

// τ_L(p) = τ_L0 + Λ p; off (no limit) when both are 0.
struct LimitingShear {
  double stress_Pa = 0.0;             // τ_L0, the limit at ambient pressure
  double pressure_coefficient = 0.0;  // Λ = dτ_L/dp (dimensionless)
  double temperature_coefficient_per_K = 0.0;  // β in τ_L e^{−β ΔT}, for a heated film
  bool on() const { return stress_Pa > 0.0 || pressure_coefficient > 0.0; }
  // τ_L at pressure p (+∞ when off; negative pressures count as 0).
  double at(double pressure_Pa) const {
    return on() ? stress_Pa + pressure_coefficient * std::max(pressure_Pa, 0.0) : std::numeric_limits<double>::infinity();
  }
};

// Throws std::invalid_argument, prefixed with `who`, when τ_L0, Λ or β is negative or not finite.
void validate(const LimitingShear& limit, const char* who);

}  // namespace tribo::lubrication
