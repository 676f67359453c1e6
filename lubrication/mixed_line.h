// Mixed lubrication of a rough line contact by load sharing: one point of the Stribeck curve, from
// boundary through mixed into full-film EHL (Johnson, Greenwood & Poon 1972, Wear 19:91; the
// Stribeck curve of Gelinck & Schipper 2000, Tribol. Int. 33:175).
//
// The load w per unit length is shared by the film and the asperities, w = w_f + w_c, w_f = s w.
// Both act over the same contact and the bodies deform under their sum; each part is solved as if
// it were alone on bodies whose modulus is scaled by its share (the hypothesis of Johnson,
// Greenwood & Poon):
//   film        the smooth EHL line contact (ehl_line.h) at load s w and reduced modulus s E'. Its
//               Hertz half-width b = √(8 s w R/(π s E')) is the whole load's, and its pressures are
//               the film's own.
//   asperities  Greenwood–Williamson (contact/greenwood_williamson.h) at the separation
//               d = h_c − y_s of the mean summit plane from the counterface, h_c the film's central
//               thickness (between the surfaces' mean planes) and y_s the summits' mean height
//               above their surface's mean plane; their nominal pressure is taken uniform over the
//               width 2b: w_c = 2 b p_GW(d). As the film vanishes, d → −y_s, and the summits then
//               carry the whole load where p_GW(−y_s) ≥ w/(2b): with y_s = 0 they could not
//               (p_GW(0) is a fixed fraction of what they can carry), and the curve would never
//               reach the boundary regime.
// The share s ∈ (0, 1] solves g(s) = s w + 2 b p_GW(h_c(s) − y_s) − w = 0. At fixed W = w/(E'R) the film
// sees the speed parameter U/s and the material parameter G s, so h_c grows as s falls: the
// asperity load falls while (1 − s) w rises, and g has one root. It is bracketed in ln s between
// `min_share` and 1 and found by regula falsi with the Illinois modification (each evaluation is a
// full EHL solve).
// Friction: F = f_c w_c + F_f, with f_c the boundary friction coefficient of the asperity contacts
// (a constant, as in Gelinck & Schipper) and F_f the film's traction (ehl_traction.h) at its own
// pressures and films; μ = F / w. With the surfaces' flash temperature on (FilmHeating::surfaces),
// the summits' friction heat f_c p_GW |Δu| enters the surfaces over the width 2b beside the film's
// (ehl_traction.h), so a film sharing the contact with metal is warmer than a film alone — the
// thesis' reading (§5.2b) of why its friction maximum falls at a lower speed than Crook's.
// Left out: the asperity pressure's shape across the contact (its
// mean is used, as Gelinck & Schipper do); micro-EHL films on the asperities; and the roughness in
// the film's flow (no flow factors).
#pragma once

#include <limits>
#include <string>

#include "contact/greenwood_williamson.h"
#include "lubrication/ehl_line.h"
#include "lubrication/ehl_traction.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct MixedLineContact {
  EhlLineContact film;                     // geometry, load w, E', entrainment u_m
  contact::GreenwoodWilliamson asperities;  // summits of the combined roughness; e_star_Pa must be E'/2
  double summit_height_m = 0.0;             // y_s ≥ 0: the mean summit plane above the surface's mean plane
  double boundary_friction_coefficient = 0.1;  // f_c ≥ 0 of the asperity contacts
  double sliding_speed_m_per_s = 0.0;          // Δu, for the film's traction
  double eyring_stress_Pa = std::numeric_limits<double>::infinity();  // τ0; +∞: Newtonian film
  LimitingShear limiting_shear;                                       // τ_L0 + Λ p; off by default
  FilmHeating heating;                                                // off by default
};

struct MixedLineOptions {
  EhlLineOptions film;  // each film solve
  // Converged when the load balance |g(s)|/w = |s w + w_c − w|/w ≤ tolerance.
  double tolerance = 1e-6;
  double min_share = 1e-6;  // the smallest film share s searched
  int max_film_solves = 60;
};

struct MixedLineResult {
  double film_share = 0.0;                        // s = w_f / w
  double film_load_per_length_N_per_m = 0.0;      // w_f
  double asperity_load_per_length_N_per_m = 0.0;  // w_c = 2 b p_GW(h_c)
  double central_film_m = 0.0;                    // h_c, between the surfaces' mean planes
  double separation_m = 0.0;                      // d = h_c − y_s, the summits' (GW)
  double film_parameter = 0.0;                    // Λ = h_c / σ_s
  double asperity_area_fraction = 0.0;            // real over nominal area within the width 2b (GW)
  double boundary_friction_N_per_m = 0.0;         // f_c w_c
  double film_friction_N_per_m = 0.0;             // F_f
  double friction_coefficient = 0.0;              // (f_c w_c + F_f) / w
  EhlLineResult film;                             // the film solve at the share found
  EhlTraction traction;                           // its traction (friction coefficient per w_f)
  bool converged = false;
  int film_solves = 0;
  double residual = 0.0;  // |g(s)| / w at return
  std::string message;
};

// Throws std::invalid_argument for bad input (as solve_ehl_line and ehl_line_traction do, invalid
// summit parameters, a summit E* other than E'/2, a negative or non-finite y_s, a negative or non-finite f_c, options out of
// range); never throws for non-convergence (see `converged` and `message`).
MixedLineResult solve_mixed_line(const MixedLineContact& contact, const PiezoviscousLubricant& lubricant,
                                 const MixedLineOptions& options = {});

}  // namespace tribo::lubrication
