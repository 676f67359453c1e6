// Steady sliding of the homogenised law (rig/homogenised_law.h) at a constant relative speed U:
// the state at which the law's own rates vanish — the Stribeck curve the rig integrates.
//
//   film         N_s(h̄) + η(ΔT) U L(h̄) = W                  (dh̄/dt = 0, no squeeze; a ball's
//                EHL film W_f(h̄, ηU) and traction F_f join the lift and the fluid shear)
//   temperature  ΔT = ΔT_J(F U, h̄, U)                          (dΔT/dt = 0, thesis (5.2.1))
//   friction     μ = F/W,  F = τ̄(h̄, η(ΔT) U) A_r(h̄) + η(ΔT) U S(h̄);  fluid share = η U L(h̄) / W
//                (τ̄ = τ_i without the asperity tops' EHL films, "tribo-law-1")
// h̄ by HomogenisedBase::balanced_separation_m, ΔT by damped fixed-point iteration. A film that settles
// over a slip distance U t_h independent of U decays with slip distance, as the thesis' transient
// (§5.2a, Figs 5.2.3–5.2.6); one with t_h independent of U decays with time.
// Regime by the share of W the solids carry: boundary ≥ 95 %, full film ≤ 5 %, mixed between.
#pragma once

#include <string>

#include "rig/homogenised_law.h"

namespace tribo::rig {

enum class LubricationRegime { boundary, mixed, full_film };
const char* to_string(LubricationRegime regime);

struct SteadySliding {
  double speed_m_per_s = 0;
  double separation_m = 0;
  double temperature_rise_K = 0;
  double solid_load_N = 0, lift_N = 0, solid_friction_N = 0, fluid_shear_N = 0;
  double solid_shear_Pa = 0;          // τ̄ of the real contact area (τ_i without micro-EHL films)
  double film_share_of_contact = 0;   // the share of the real area the films separate (0 without)
  double film_relaxation_time_s = 0;  // t_h of the film about this state (homogenised_law.h); it
                                      // settles over the slip distance U t_h
  double mu = 0;             // (solid + fluid shear) / W
  double fluid_share = 0;    // lift / W
  LubricationRegime regime = LubricationRegime::boundary;
  bool converged = false;
  std::string message;       // why not, when not converged
};

// Throws std::out_of_range when the film would leave the table (lift carries W above its largest
// separation: extend the table towards full film), std::invalid_argument for U ≤ 0.
SteadySliding steady_sliding(const HomogenisedBase& base, double speed_m_per_s);

}  // namespace tribo::rig
