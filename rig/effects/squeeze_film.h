// squeeze_film — thesis (3.2.2), Appendix III, §5.2a and Fig 5.2.2: slip builds a load-bearing
// film (lift over slip distance D_b); near zero relative speed the film cannot vanish at once,
// because squeezing it out takes time. Its load share φ (state) follows
//
//     dφ/dt = (φ_max − φ) |U| / D_b − φ / τ_sq,
//
// with τ_sq the time to squeeze a film of thickness h down to h/2 between parallel discs of the
// patch radius R under the load W (Appendix III; lubrication/reference/squeeze_film.h):
//
//     τ_sq = (3π η R⁴ / 4W) (1/(h/2)² − 1/h²).
//
// The solid contact carries (1 − φ) W, so friction near U = 0 is lower, and the force at which
// the surfaces re-attach is lower: slip runs on for several cycles (multi-cycle slip).
#pragma once

#include "rig/effect.h"

namespace tribo::rig::effects {

class SqueezeFilm final : public FrictionEffect {
 public:
  SqueezeFilm(double film_fraction, double build_up_distance_m, double film_thickness_m, double patch_radius_m,
              double viscosity_Pa_s);
  std::string name() const override { return "squeeze_film"; }
  std::size_t state_size() const override { return 1; }
  void initial_state(std::span<double> state) const override { state[0] = 0.0; }
  // φ takes μ φ W off the friction, μ ≤ 1: an error of the displacement's μ tolerance in φ moves
  // the friction by no more than that of x.
  void state_tolerances(std::span<double> atol, double mu_tolerance) const override { atol[0] = mu_tolerance; }
  void state_rates(const EffectContext& c, std::span<double> rates) const override;
  double solid_fraction(const EffectContext& c) const override { return 1.0 - c.state[0]; }
  // Squeeze-out time τ_sq at normal load W.
  double squeeze_time_s(double normal_load_N) const;
  // A film squeezed out within a radian of the rig's oscillation, τ_sq ω_n < 1: Adams' steps,
  // about 1/(8 ω_n) where the rig alone sets them, would be bound by their stability to ≈ τ_sq
  // through every stick (validation case 14818's film, τ_sq ω_n = 0.055: its prediction of the
  // foreign control 2.8× faster with BDF and φ at the μ tolerance, the case's items 2.2e-5 rms from
  // the reference against 9.0e-6 before; bench/README.md, "A stiff squeeze film with BDF").
  bool stiff(double normal_load_N, double natural_frequency_rad_per_s) const override {
    return squeeze_time_s(normal_load_N) * natural_frequency_rad_per_s < 1.0;
  }

 private:
  double phi_max_, build_up_m_, h_m_, radius_m_, eta_Pa_s_;
};

}  // namespace tribo::rig::effects
