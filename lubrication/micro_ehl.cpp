#include "lubrication/micro_ehl.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "contact/greenwood_williamson.h"
#include "lubrication/reference/ehl_point_film.h"

namespace tribo::lubrication {

void validate(const MicroEhlOptions& o) {
  const auto positive = [](double x, const char* name) {
    if (!(std::isfinite(x) && x > 0.0)) throw std::invalid_argument(std::string("micro-EHL: ") + name + " must be positive and finite");
  };
  positive(o.e_star_Pa, "e_star_Pa");
  positive(o.pressure_viscosity_per_Pa, "pressure_viscosity_per_Pa");
  positive(o.eyring_stress_Pa, "eyring_stress_Pa");
  positive(o.tip_roughness_m, "tip_roughness_m");
  positive(o.interface_shear_strength_Pa, "interface_shear_strength_Pa");
  positive(o.viscosity_Pa_s, "viscosity_Pa_s");
  validate(o.limiting_shear, "micro-EHL");
}

namespace {

// ln(η(p)/η0): Barus α p, or Roelands' (ln η0 + 9.67)[(1 + p/p_r)^z − 1] (piezoviscous.h) — in
// logarithms, since Barus' ratio overflows a double above α p ≈ 709.
double log_viscosity_ratio(const MicroEhlOptions& o, double p) {
  if (o.law == PressureViscosityLaw::barus) return o.pressure_viscosity_per_Pa * p;
  PiezoviscousLubricant oil;
  oil.viscosity_Pa_s = o.viscosity_Pa_s;
  oil.pressure_viscosity_per_Pa = o.pressure_viscosity_per_Pa;
  oil.law = PressureViscosityLaw::roelands;
  return std::log(viscosity_ratio(oil, p).ratio);
}

}  // namespace

SpotFilm spot_film(const contact::ContactSpot& spot, double eta_u, const MicroEhlOptions& o) {
  if (!(std::isfinite(eta_u) && eta_u >= 0.0)) throw std::invalid_argument("micro-EHL: ηU must be finite and not negative");
  if (!(spot.load_N > 0.0 && spot.area_m2 > 0.0 && spot.equivalent_radius_m > 0.0))
    throw std::invalid_argument("micro-EHL: a spot needs a positive load, area and radius");
  SpotFilm f;
  f.shear_Pa = o.interface_shear_strength_Pa;
  if (eta_u == 0.0) return f;
  const double r = spot.equivalent_radius_m;
  // η u_m = ηU/2: passed as the viscosity with a mean speed of ½ (the groups hold their product).
  const auto g = reference::point_contact_groups(spot.load_N, r, 2.0 * o.e_star_Pa, 0.5, eta_u, o.pressure_viscosity_per_Pa);
  f.central_film_m = r * reference::hamrock_dowson_central_film(g);
  using contact::SummitDistribution;
  f.boundary_share = contact::gw_integral(SummitDistribution::gaussian, 1.0, f.central_film_m / o.tip_roughness_m) /
                     contact::gw_integral(SummitDistribution::gaussian, 1.0, 0.0);
  // asinh(x) with ln x = ln ηU + ln R(p̄) − ln(τ0 h_c): R alone reaches 1e7–1e10 at the hardness.
  const double ln_x = std::log(eta_u) + log_viscosity_ratio(o, spot.mean_pressure_Pa) - std::log(o.eyring_stress_Pa * f.central_film_m);
  f.fluid_shear_Pa = std::min(o.eyring_stress_Pa * (ln_x > 20.0 ? std::log(2.0) + ln_x : std::asinh(std::exp(ln_x))),
                              o.limiting_shear.at(spot.mean_pressure_Pa));
  f.shear_Pa = f.boundary_share * o.interface_shear_strength_Pa + (1.0 - f.boundary_share) * f.fluid_shear_Pa;
  return f;
}

SpotFilms mean_spot_films(const std::vector<contact::ContactSpot>& spots, double eta_u, const MicroEhlOptions& o) {
  double area = 0.0, force = 0.0, separated = 0.0;
  for (const contact::ContactSpot& s : spots) {
    const SpotFilm f = spot_film(s, eta_u, o);
    area += s.area_m2;
    force += s.area_m2 * f.shear_Pa;
    separated += s.area_m2 * (1.0 - f.boundary_share);
  }
  return area > 0.0 ? SpotFilms{force / area, separated / area} : SpotFilms{o.interface_shear_strength_Pa, 0.0};
}

}  // namespace tribo::lubrication
