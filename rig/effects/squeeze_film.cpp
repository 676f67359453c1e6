#include "rig/effects/squeeze_film.h"

#include "lubrication/reference/squeeze_film.h"

namespace tribo::rig::effects {

SqueezeFilm::SqueezeFilm(double film_fraction, double build_up_distance_m, double film_thickness_m,
                         double patch_radius_m, double viscosity_Pa_s)
    : phi_max_(film_fraction), build_up_m_(build_up_distance_m), h_m_(film_thickness_m),
      radius_m_(patch_radius_m), eta_Pa_s_(viscosity_Pa_s) {}

double SqueezeFilm::squeeze_time_s(double normal_load_N) const {
  return lubrication::squeeze_out_time_s(eta_Pa_s_, radius_m_, normal_load_N, h_m_, 0.5 * h_m_);
}

void SqueezeFilm::state_rates(const EffectContext& c, std::span<double> rates) const {
  const double phi = c.state[0];
  rates[0] = (phi_max_ - phi) * c.rig->relative_speed_m_per_s / build_up_m_ - phi / squeeze_time_s(c.rig->normal_load_N);
}

}  // namespace tribo::rig::effects
