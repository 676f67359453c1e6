#include "rig/steady_sliding.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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
  // The state at ΔT, and Jaeger's ΔT_J for its friction power.
  const auto at = [&](double dT) {
    const double eta = b.viscosity_Pa_s(dT);
    s.separation_m = b.balanced_separation_m(eta * u);
    s.solid_load_N = b.solid_load_N(s.separation_m);
    s.lift_N = b.fluid_load_N(s.separation_m, eta * u);
    s.solid_shear_Pa = b.solid_shear_Pa(s.separation_m, eta * u);
    s.film_share_of_contact = b.film_share(s.separation_m, eta * u);
    s.solid_friction_N = s.solid_shear_Pa * b.real_area_m2(s.separation_m);
    s.fluid_shear_N = b.fluid_shear_N(s.separation_m, eta * u);
    s.temperature_rise_K = dT;
    return b.jaeger_temperature_rise_K((s.solid_friction_N + s.fluid_shear_N) * u, s.separation_m, u);
  };
  const auto settled = [](double dT, double target) { return std::abs(target - dT) <= 1e-9 * (1.0 + target); };
  double dT = 0.0, hottest = 0.0;
  for (int it = 0; it < 500 && !s.converged; ++it) {
    const double target = at(dT);
    hottest = std::max(hottest, target);
    s.converged = settled(dT, target);
    dT = s.converged ? dT : 0.5 * (dT + target);  // damped: the film's heat lowers η, which lowers the heat
  }
  if (!s.converged) {
    // The damped iteration cycles where the heat falls steeply with ΔT (a film that lifts the load
    // as it cools): bisect ΔT_J(ΔT) − ΔT, ≥ 0 at ΔT = 0 and < 0 above the hottest ΔT_J seen.
    double lo = 0.0, hi = 2.0 * hottest + 1.0, miss = 0.0;
    for (int it = 0; it < 200 && !s.converged && hi - lo > 1e-13 * hi; ++it) {
      const double mid = 0.5 * (lo + hi), target = at(mid);
      s.converged = settled(mid, target);
      miss = target - mid;
      (target > mid ? lo : hi) = mid;
    }
    if (!s.converged)
      s.message = "temperature fixed point did not settle: 500 damped iterations, then bisection to ΔT = " + std::to_string(s.temperature_rise_K) +
                  " K, where ΔT_J − ΔT = " + std::to_string(miss) + " K";
  }
  s.film_relaxation_time_s = b.film_relaxation_time_s(s.separation_m, s.temperature_rise_K, u);
  s.mu = (s.solid_friction_N + s.fluid_shear_N) / w;
  s.fluid_share = s.lift_N / w;
  const double solid_share = s.solid_load_N / w;
  s.regime = solid_share >= 0.95 ? LubricationRegime::boundary
                                 : (solid_share <= 0.05 ? LubricationRegime::full_film : LubricationRegime::mixed);
  return s;
}

}  // namespace tribo::rig
