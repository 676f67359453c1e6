#include "lubrication/mixed_line.h"

#include <cmath>
#include <stdexcept>

#include "lubrication/load_sharing.h"
#include "lubrication/reference/ehl_film.h"

namespace tribo::lubrication {
namespace {

[[noreturn]] void bad_mixed_input(const std::string& what) { throw std::invalid_argument("mixed line contact: " + what); }

// The film solved at share s = e^{ln_share}, the summits at its separation, and the load balance
// g(s)/w they leave.
struct LineTrial {
  double ln_share = 0.0, balance = 0.0, asperity_load_N_per_m = 0.0;
  EhlLineResult film;
  contact::GwState summits;
};

}  // namespace

MixedLineResult solve_mixed_line(const MixedLineContact& c, const PiezoviscousLubricant& lubricant, const MixedLineOptions& o) {
  const EhlLineContact& f = c.film;
  for (double v : {f.load_per_length_N_per_m, f.reduced_radius_m, f.reduced_modulus_Pa})
    if (!(std::isfinite(v) && v > 0.0)) bad_mixed_input("load, radius and modulus must be finite and > 0");
  const load_sharing::Options sharing{o.tolerance, o.min_share, o.max_film_solves};
  load_sharing::check_inputs("mixed line contact", c.asperities, f.reduced_modulus_Pa, c.summit_height_m, c.boundary_friction_coefficient,
                             sharing);

  const double w = f.load_per_length_N_per_m;
  const double half_width_m = reference::hertz_line_half_width_m(w, f.reduced_radius_m, f.reduced_modulus_Pa);
  const auto at = [&](double ln_share) {
    const double s = std::exp(ln_share);
    EhlLineContact scaled = f;
    scaled.load_per_length_N_per_m = s * w;
    scaled.reduced_modulus_Pa = s * f.reduced_modulus_Pa;
    LineTrial t{ln_share, 0.0, 0.0, solve_ehl_line(scaled, lubricant, o.film), {}};
    if (t.film.converged) {
      t.summits = contact::gw_at_separation(c.asperities, t.film.central_film_m - c.summit_height_m);
      t.asperity_load_N_per_m = 2.0 * half_width_m * t.summits.pressure_Pa;
      t.balance = (s * w + t.asperity_load_N_per_m - w) / w;
    }
    return t;
  };
  load_sharing::Outcome<LineTrial> searched = load_sharing::find_film_share<LineTrial>(at, sharing);
  MixedLineResult out;
  if (!load_sharing::take_outcome(out, searched, c.asperities.summit_std_m, o.tolerance)) return out;
  out.film_load_per_length_N_per_m = out.film_share * w;
  out.asperity_load_per_length_N_per_m = searched.found.asperity_load_N_per_m;  // take_outcome moved only the film
  // The summits' friction heats the surfaces too, at their mean pressure, as the load balance takes it.
  const FilmHeating heating = load_sharing::with_summits_heat(c.heating, c.boundary_friction_coefficient, searched.found.summits.pressure_Pa,
                                                              c.sliding_speed_m_per_s, half_width_m);
  out.traction = ehl_line_traction(out.film, lubricant, c.sliding_speed_m_per_s, c.eyring_stress_Pa, out.film_share * w, heating,
                                   c.limiting_shear);
  out.boundary_friction_N_per_m = c.boundary_friction_coefficient * out.asperity_load_per_length_N_per_m;
  out.film_friction_N_per_m = out.traction.force_per_length_N_per_m;
  out.friction_coefficient = (out.boundary_friction_N_per_m + out.film_friction_N_per_m) / w;
  return out;
}

}  // namespace tribo::lubrication
