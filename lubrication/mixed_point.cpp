#include "lubrication/mixed_point.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "lubrication/load_sharing.h"
#include "lubrication/reference/ehl_point_film.h"

namespace tribo::lubrication {
namespace {

// The film solved at share s = e^{ln_share}, the summits at its separation, and the load balance
// g(s)/W they leave.
struct PointTrial {
  double ln_share = 0.0, balance = 0.0, asperity_load_N = 0.0;
  EhlPointResult film;
  contact::GwState summits;
};

}  // namespace

MixedPointResult solve_mixed_point(const MixedPointContact& c, const PiezoviscousLubricant& lubricant, const MixedPointOptions& o) {
  const EhlPointContact& f = c.film;
  for (double v : {f.load_N, f.reduced_radius_m, f.reduced_modulus_Pa})
    if (!(std::isfinite(v) && v > 0.0)) throw std::invalid_argument("mixed point contact: load, radius and modulus must be finite and > 0");
  const load_sharing::Options sharing{o.tolerance, o.min_share, o.max_film_solves};
  load_sharing::check_inputs("mixed point contact", c.asperities, f.reduced_modulus_Pa, c.summit_height_m, c.boundary_friction_coefficient,
                             sharing);

  const double w = f.load_N;
  const double a = reference::hertz_point_radius_m(w, f.reduced_radius_m, f.reduced_modulus_Pa);
  const double area_m2 = std::numbers::pi * a * a;
  const auto at = [&](double ln_share) {
    const double s = std::exp(ln_share);
    EhlPointContact scaled = f;
    scaled.load_N = s * w;
    scaled.reduced_modulus_Pa = s * f.reduced_modulus_Pa;
    PointTrial t{ln_share, 0.0, 0.0, solve_ehl_point(scaled, lubricant, o.film), {}};
    if (t.film.converged) {
      t.summits = contact::gw_at_separation(c.asperities, t.film.central_film_m - c.summit_height_m);
      t.asperity_load_N = area_m2 * t.summits.pressure_Pa;
      t.balance = (s * w + t.asperity_load_N - w) / w;
    }
    return t;
  };
  load_sharing::Outcome<PointTrial> searched = load_sharing::find_film_share<PointTrial>(at, sharing);
  MixedPointResult out;
  if (!load_sharing::take_outcome(out, searched, c.asperities.summit_std_m, o.tolerance)) return out;
  out.film_load_N = out.film_share * w;
  out.asperity_load_N = searched.found.asperity_load_N;  // take_outcome moved only the film
  // The summits' friction heats the surfaces too, at their mean pressure, as the load balance takes it.
  const FilmHeating heating = load_sharing::with_summits_heat(c.heating, c.boundary_friction_coefficient, searched.found.summits.pressure_Pa,
                                                              c.sliding_speed_m_per_s, a);
  out.traction = ehl_point_traction(out.film, lubricant, c.sliding_speed_m_per_s, c.eyring_stress_Pa, out.film_share * w, heating,
                                   c.limiting_shear);
  out.boundary_friction_N = c.boundary_friction_coefficient * out.asperity_load_N;
  out.film_friction_N = out.traction.force_N;
  out.friction_coefficient = (out.boundary_friction_N + out.film_friction_N) / w;
  return out;
}

}  // namespace tribo::lubrication
