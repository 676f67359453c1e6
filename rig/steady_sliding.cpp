#include "rig/steady_sliding.h"

#include <cmath>
#include <stdexcept>

namespace tribo::rig {

const char* to_string(LubricationRegime r) {
  switch (r) {
    case LubricationRegime::boundary: return "boundary";
    case LubricationRegime::mixed: return "mixed";
    case LubricationRegime::full_film: return "full_film";
  }
  return "?";
}

SteadySliding steady_sliding(const HomogenisedBase& b, double u) {
  if (!(u > 0.0 && std::isfinite(u))) throw std::invalid_argument("steady sliding: speed must be finite and > 0");
  SteadySliding s;
  s.speed_m_per_s = u;
  const double w = b.normal_load_N();
  double dT = 0.0;
  for (int it = 0; it < 500; ++it) {
    const double eta = b.viscosity_Pa_s(dT);
    s.separation_m = b.balanced_separation_m(eta * u);
    s.solid_load_N = b.solid_load_N(s.separation_m);
    s.lift_N = b.fluid_load_N(s.separation_m, eta * u);
    s.solid_shear_Pa = b.solid_shear_Pa(s.separation_m, eta * u);
    s.film_share_of_contact = b.film_share(s.separation_m, eta * u);
    s.solid_friction_N = s.solid_shear_Pa * b.real_area_m2(s.separation_m);
    s.fluid_shear_N = b.fluid_shear_N(s.separation_m, eta * u);
    const double target = b.jaeger_temperature_rise_K((s.solid_friction_N + s.fluid_shear_N) * u, s.separation_m, u);
    s.temperature_rise_K = dT;
    if (std::abs(target - dT) <= 1e-9 * (1.0 + target)) {
      s.converged = true;
      break;
    }
    dT = 0.5 * (dT + target);  // damped: the film's heat lowers η, which lowers the heat
  }
  if (!s.converged) s.message = "temperature fixed point did not settle in 500 iterations";
  s.film_relaxation_time_s = b.film_relaxation_time_s(s.separation_m, s.temperature_rise_K, u);
  s.mu = (s.solid_friction_N + s.fluid_shear_N) / w;
  s.fluid_share = s.lift_N / w;
  const double solid_share = s.solid_load_N / w;
  s.regime = solid_share >= 0.95 ? LubricationRegime::boundary
                                 : (solid_share <= 0.05 ? LubricationRegime::full_film : LubricationRegime::mixed);
  return s;
}

}  // namespace tribo::rig
