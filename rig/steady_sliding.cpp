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

namespace {

// h̄ with N_s(h̄) + η U L(h̄) = W for a given viscosity.
double film_separation_m(const HomogenisedBase& b, double eta, double u) {
  const auto& h = b.table().separation_m;
  const double w = b.normal_load_N();
  const auto excess = [&](double x) { return b.solid_load_N(x) + eta * u * b.lift_per_eta_u_m(x) - w; };
  double lo = h.front(), hi = h.back();
  if (excess(hi) > 0.0)
    throw std::out_of_range("steady sliding at U = " + std::to_string(u) + " m/s: the lift carries the load above the "
                            "table's largest separation " + std::to_string(hi) + " m; extend separation_ratios");
  for (int it = 0; it < 200 && hi - lo > 1e-14 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (excess(mid) > 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

SteadySliding steady_sliding(const HomogenisedBase& b, double u) {
  if (!(u > 0.0 && std::isfinite(u))) throw std::invalid_argument("steady sliding: speed must be finite and > 0");
  SteadySliding s;
  s.speed_m_per_s = u;
  const double w = b.normal_load_N(), tau = b.table().junction.interface_shear_strength_Pa;
  double dT = 0.0;
  for (int it = 0; it < 500; ++it) {
    const double eta = b.viscosity_Pa_s(dT);
    s.separation_m = film_separation_m(b, eta, u);
    s.solid_load_N = b.solid_load_N(s.separation_m);
    s.lift_N = eta * u * b.lift_per_eta_u_m(s.separation_m);
    s.solid_friction_N = tau * b.real_area_m2(s.separation_m);
    s.fluid_shear_N = eta * u * b.shear_per_eta_u_m(s.separation_m);
    const double target = b.jaeger_temperature_rise_K((s.solid_friction_N + s.fluid_shear_N) * u, s.separation_m, u);
    s.temperature_rise_K = dT;
    if (std::abs(target - dT) <= 1e-9 * (1.0 + target)) {
      s.converged = true;
      break;
    }
    dT = 0.5 * (dT + target);  // damped: the film's heat lowers η, which lowers the heat
  }
  if (!s.converged) s.message = "temperature fixed point did not settle in 500 iterations";
  s.mu = (s.solid_friction_N + s.fluid_shear_N) / w;
  s.fluid_share = s.lift_N / w;
  const double solid_share = s.solid_load_N / w;
  s.regime = solid_share >= 0.95 ? LubricationRegime::boundary
                                 : (solid_share <= 0.05 ? LubricationRegime::full_film : LubricationRegime::mixed);
  return s;
}

}  // namespace tribo::rig
