// Mixed lubrication of a rough circular point contact — a rough ball on a disc — by load sharing:
// one point of its Stribeck curve, from boundary through mixed into full-film EHL (Johnson,
// Greenwood & Poon 1972; Gelinck & Schipper 2000, who treat line and circular contacts alike).
//
// As mixed_line.h, with the point contact's film and area: the load W = W_f + W_c, W_f = s W;
//   film        the smooth EHL point contact (ehl_point.h) at load s W and reduced modulus s E':
//               its Hertz radius a = (3 s W R/(2 s E'))^{1/3} is the whole load's;
//   asperities  Greenwood–Williamson at d = h_c − y_s, their nominal pressure uniform over the
//               Hertz circle: W_c = π a² p_GW(d);
// s ∈ (0, 1] solves s W + π a² p_GW(h_c(s) − y_s) = W (lubrication/load_sharing.h). Friction
// F = f_c W_c + F_f, F_f the film's Eyring traction (ehl_traction.h) at its own pressures and
// films; μ = F / W. With the surfaces' flash temperature on, the summits' friction heat enters
// them over the Hertz circle beside the film's, as on the line (mixed_line.h). Left out, as for
// the line: the asperity pressure's shape over the circle, micro-EHL films on the asperities, the
// roughness in the film's flow.
#pragma once

#include <limits>
#include <string>

#include "contact/greenwood_williamson.h"
#include "lubrication/ehl_point.h"
#include "lubrication/ehl_traction.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct MixedPointContact {
  EhlPointContact film;                     // geometry, load W, E', entrainment u_m
  contact::GreenwoodWilliamson asperities;  // summits of the combined roughness; e_star_Pa must be E'/2
  double summit_height_m = 0.0;             // y_s ≥ 0: the mean summit plane above the surface's mean plane
  double boundary_friction_coefficient = 0.1;  // f_c ≥ 0 of the asperity contacts
  double sliding_speed_m_per_s = 0.0;          // Δu, for the film's traction
  double eyring_stress_Pa = std::numeric_limits<double>::infinity();  // τ0; +∞: Newtonian film
  LimitingShear limiting_shear;                                       // τ_L0 + Λ p; off by default
  FilmHeating heating;                                                // off by default
};

struct MixedPointOptions {
  EhlPointOptions film;  // each film solve
  // Converged when the load balance |g(s)|/W = |s W + W_c − W|/W ≤ tolerance.
  double tolerance = 1e-6;
  double min_share = 1e-6;  // the smallest film share s searched
  int max_film_solves = 60;
};

struct MixedPointResult {
  double film_share = 0.0;              // s = W_f / W
  double film_load_N = 0.0;             // W_f
  double asperity_load_N = 0.0;         // W_c = π a² p_GW(h_c − y_s)
  double central_film_m = 0.0;          // h_c, between the surfaces' mean planes
  double separation_m = 0.0;            // d = h_c − y_s, the summits' (GW)
  double film_parameter = 0.0;          // Λ = h_c / σ_s
  double asperity_area_fraction = 0.0;  // real over nominal area within the Hertz circle (GW)
  double boundary_friction_N = 0.0;     // f_c W_c
  double film_friction_N = 0.0;         // F_f
  double friction_coefficient = 0.0;    // (f_c W_c + F_f) / W
  EhlPointResult film;                  // the film solve at the share found
  EhlPointTraction traction;            // its traction (friction coefficient per W_f)
  bool converged = false;
  int film_solves = 0;
  double residual = 0.0;  // |g(s)| / W at return
  std::string message;
};

// Throws std::invalid_argument for bad input (as solve_ehl_point and ehl_point_traction do, invalid
// summits, summits whose E* is not E'/2, a negative y_s or f_c, bad options); never throws for
// non-convergence (`converged`, `message`).
MixedPointResult solve_mixed_point(const MixedPointContact& contact, const PiezoviscousLubricant& lubricant,
                                   const MixedPointOptions& options = {});

}  // namespace tribo::lubrication
