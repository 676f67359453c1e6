// Traction of a solved EHL line contact (ehl_line.h): the shear the film passes from one surface to
// the other when they slide at Δu = u1 − u2 while rolling at u_m.
//
// Shear stress (Couette), with the Eyring model of a lubricant's non-Newtonian response (Eyring
// 1936; applied to EHL traction by Johnson & Tevaarwerk 1977, Proc. R. Soc. A 356:215):
//   τ(x) = τ0 asinh(η(p) Δu / (τ0 h)),     Newtonian τ = η(p) Δu / h as τ0 → ∞,
// τ0 the Eyring stress (a few MPa for mineral oils; Johnson & Tevaarwerk, Evans & Johnson 1986).
// Above a few τ0 the stress grows only with ln Δu: the flat, slowly falling traction curves of
// EHL rigs, where the Newtonian film would give a friction coefficient far above one.
// Left out: the Poiseuille shear (h/2) dp/dx, equal and opposite on the two surfaces, so it adds
// no net traction to their sum and is small on each beside the Couette term in the loaded zone;
// the cavitated outlet (p = 0 at the nodes past the film's rupture, where the gap holds striations
// of unknown extent); and heat — the film is isothermal, as in the solve.
// Traction force per unit length F = ∫ τ dx (trapezoidal rule over the solve's nodes), friction
// coefficient μ = F / w.
#pragma once

#include "lubrication/ehl_line.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct EhlTraction {
  double force_per_length_N_per_m = 0.0;
  double friction_coefficient = 0.0;
  double max_shear_stress_Pa = 0.0;
};

// Throws std::invalid_argument for a sliding speed that is not finite, an Eyring stress that is
// not positive (+∞ is the Newtonian film), a non-positive load, or a film with fewer than two
// nodes or a non-positive film thickness where the pressure is positive.
EhlTraction ehl_line_traction(const EhlLineResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                              double eyring_stress_Pa, double load_per_length_N_per_m);

}  // namespace tribo::lubrication
