// Lubricant under EHL pressures: viscosity and density as functions of the gauge pressure p (Pa).
//
// Viscosity (isothermal):
//   Barus      η(p) = η0 exp(α p)
//   Roelands   η(p) = η0 exp{(ln η0 + 9.67) [−1 + (1 + p/p_r)^z]},  p_r = 1.96e8 Pa,
//              with the pressure index z = α / (5.1e-9 (ln η0 + 9.67)), which gives the same
//              initial slope d ln η/dp = α at p = 0 (Roelands 1966; the form and constants as in
//              Hamrock, Schmid & Jacobson, "Fundamentals of Machine Elements", and Venner &
//              Lubrecht, "Multilevel Methods in Lubrication", 2000, ch. 8). η0 in Pa·s.
//   Barus overstates η by orders of magnitude above ~0.5 GPa; Roelands is the usual choice there.
// Density: Dowson & Higginson (1966), ρ/ρ0 = 1 + 0.6e-9 p / (1 + 1.7e-9 p), p in Pa — at most
// +35 % as p → ∞.
#pragma once

#include "lubrication/viscosity.h"

namespace tribo::lubrication {

enum class PressureViscosityLaw { barus, roelands };

struct PiezoviscousLubricant {
  // η0 at ambient pressure and α (Barus) or the initial slope of Roelands: the thesis white oil's
  // (viscosity.h), where their sources are given.
  double viscosity_Pa_s = Lubricant{}.viscosity_Pa_s;
  double pressure_viscosity_per_Pa = Lubricant{}.pressure_viscosity_per_Pa;
  PressureViscosityLaw law = PressureViscosityLaw::roelands;
  bool compressible = true;                 // Dowson–Higginson density; false: ρ = ρ0
};

// Throws std::invalid_argument naming the field (η0 ≤ 0, α < 0, non-finite).
void validate(const PiezoviscousLubricant& lubricant);

// η(p)/η0 and d ln η/dp (1/Pa) at gauge pressure p ≥ 0 (negative p is read as 0: a cavitated film).
struct ViscosityAtPressure {
  double ratio = 1.0;
  double log_slope_per_Pa = 0.0;
};
ViscosityAtPressure viscosity_ratio(const PiezoviscousLubricant& lubricant, double pressure_Pa);

// ρ(p)/ρ0 and d(ρ/ρ0)/dp (1/Pa); 1 and 0 for an incompressible lubricant.
struct DensityAtPressure {
  double ratio = 1.0;
  double slope_per_Pa = 0.0;
};
DensityAtPressure density_ratio(const PiezoviscousLubricant& lubricant, double pressure_Pa);

}  // namespace tribo::lubrication
