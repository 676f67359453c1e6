// Elastohydrodynamic films at the load-bearing asperity tops (thesis §3.2, §5.2b, conclusion 7:
// "superimposed metallic solid-contact and elastohydrodynamic effects"): every contact spot the BEM
// gives (contact/contact_spots.h) is taken as an EHL point contact of its equivalent radius R and
// load w, the pin stationary and the disc sliding at U, so the film is entrained at u_m = U/2.
//
//   film      Hamrock–Dowson's central film (reference/ehl_point_film.h, E' = 2E*, Barus α):
//               h_c = R · 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^−0.73),  U = η u_m / (E' R);
//             ehl_point.h solves the same contact (tests/lubrication/micro_ehl_slow_test.cpp
//             compares the two at a spot's conditions);
//   share     the tips carry their own roughness σ_tip below the BEM's grid; where it pierces the
//             film the spot shears as a boundary junction (τ_i), elsewhere as fluid. The pierced
//             share of the spot is the Greenwood–Williamson real-area ratio at the film's height,
//               b = F_1(h_c/σ_tip) / F_1(0)   (Gaussian summits; 1 at h_c = 0, e^{−Λ²/2}-fast beyond);
//   fluid     Eyring shear of the Couette film at the spot's mean pressure p̄ (ehl_traction.h's
//             form, isothermal): τ_f = τ0 asinh(η(p̄) U / (τ0 h_c)), capped at the limiting shear
//             stress τ_L0 + Λ p̄ when one is given (limiting_shear.h), η(p̄) = η R(p̄) with Roelands'
//             pressure ratio R (piezoviscous.h; the default, as in the EHL solvers) or Barus' e^{α p̄}.
//             At a steel spot's pressure, the hardness 1.18 GPa, Barus gives e^{23.6} and Roelands
//             (thesis oil) e^{15.9}: Barus overstates η by 2000× there, and τ_f by 7.7 τ0;
//   spot      τ = b τ_i + (1 − b) τ_f, and over the spots the area-weighted mean τ̄ = Σ A τ / Σ A,
//             which replaces τ_i in the kinetic force τ_i A_r of the homogenised law.
//
// Everything depends on η and U through ηU alone (h_c ∝ (ηU)^0.67, τ_f's argument ∝ (ηU)^0.33), so
// a table over ηU (law.json "tribo-law-2") serves a rig whose η changes with its flash temperature
// (thesis (5.2.1)): that is how frictional heat thins these films. Roelands' ratio depends on η0
// apart from U (through ln η0), so it is taken at the oil's η0 at its reference temperature
// (MicroEhlOptions::viscosity_Pa_s): for a hotter oil the ratio is too high — the thesis oil 68 K
// hotter, with Roelands' index held, has e^{10.3} at the hardness against e^{15.9} — still closer
// than Barus' e^{23.6}. The film's own shear heating
// (ehl_traction.h FilmHeating) is left out — it depends on U apart from η and would need another
// axis. The fluid pressure of a spot's film equals the spot's contact pressure (the Hertz limit of
// heavily loaded EHL), so the films change the spots' shear, not the load balance.
#pragma once

#include <vector>

#include "contact/contact_spots.h"
#include "lubrication/limiting_shear.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct MicroEhlOptions {
  double e_star_Pa = 1.137e11;                  // composite modulus (E' = 2 E*)
  double pressure_viscosity_per_Pa = 2.0e-8;    // α (mineral oils 1–3e-8, Hamrock's tables): Barus, or Roelands' initial slope
  // The pressure–viscosity law of the film's shear (the film thickness is Hamrock–Dowson's, a fit in α).
  PressureViscosityLaw law = PressureViscosityLaw::roelands;
  double viscosity_Pa_s = Lubricant{}.viscosity_Pa_s;  // η0, for Roelands' index z (piezoviscous.h)
  // Eyring stress τ0 (a few MPa for mineral oils: Johnson & Tevaarwerk 1977; Evans & Johnson 1986).
  double eyring_stress_Pa = 5.0e6;
  // τ_L0 + Λ p̄, the film's limiting shear stress; off by default (the oil's, when measured).
  LimitingShear limiting_shear;
  // σ_tip: roughness of the tips below the contact grid. Hand-set: default the thesis slider's
  // post-test finish along the sliding direction, 1–1.5 µin CLA (Appendix V), Rq ≈ 1.25 CLA = 40 nm.
  double tip_roughness_m = 40e-9;
  double interface_shear_strength_Pa = 1.18e9 / 5.3;  // τ_i of the boundary junctions
};

// Throws std::invalid_argument naming the first field that is not positive and finite, or a limiting
// shear stress or pressure coefficient that is negative or not finite.
void validate(const MicroEhlOptions& options);

struct SpotFilm {
  double central_film_m = 0.0;   // h_c
  double boundary_share = 1.0;   // b
  double fluid_shear_Pa = 0.0;   // τ_f (0 when h_c = 0)
  double shear_Pa = 0.0;         // b τ_i + (1 − b) τ_f
};

// The film over one spot at ηU ≥ 0 (Pa·m; the disc's speed times the oil's viscosity at zero pressure).
// Throws std::invalid_argument for a negative or non-finite ηU or a spot without positive load and area.
SpotFilm spot_film(const contact::ContactSpot& spot, double eta_u_Pa_m, const MicroEhlOptions& options);

// Over the spots, area-weighted: the shear τ̄ (τ_i when there are none) and the share of the spots'
// area the films separate, Σ A (1 − b) / Σ A (0 when there are none).
struct SpotFilms {
  double shear_Pa = 0.0;
  double film_share = 0.0;
};
SpotFilms mean_spot_films(const std::vector<contact::ContactSpot>& spots, double eta_u_Pa_m, const MicroEhlOptions& options);

}  // namespace tribo::lubrication
