#include "lubrication/reference/ehl_point_film.h"

#include <cmath>
#include <numbers>

namespace tribo::lubrication::reference {

PointContactGroups point_contact_groups(double w, double radius_m, double modulus_Pa, double speed_m_per_s, double viscosity_Pa_s,
                                        double alpha_per_Pa) {
  return {viscosity_Pa_s * speed_m_per_s / (modulus_Pa * radius_m), w / (modulus_Pa * radius_m * radius_m), alpha_per_Pa * modulus_Pa};
}

double hertz_point_radius_m(double w, double radius_m, double modulus_Pa) { return std::cbrt(3.0 * w * radius_m / (2.0 * modulus_Pa)); }

double hertz_point_peak_pressure_Pa(double w, double radius_m, double modulus_Pa) {
  const double a = hertz_point_radius_m(w, radius_m, modulus_Pa);
  return 3.0 * w / (2.0 * std::numbers::pi * a * a);
}

double hamrock_dowson_central_film(const PointContactGroups& g) {
  return 2.69 * std::pow(g.speed, 0.67) * std::pow(g.material, 0.53) * std::pow(g.load, -0.067) * (1.0 - 0.61 * std::exp(-0.73));
}

double hamrock_dowson_minimum_film(const PointContactGroups& g) {
  return 3.63 * std::pow(g.speed, 0.68) * std::pow(g.material, 0.49) * std::pow(g.load, -0.073) * (1.0 - std::exp(-0.68));
}

double hamrock_dowson_flooded_inlet(double central_film_over_radius, double radius_over_contact_radius) {
  return 1.0 + 3.06 * std::pow(radius_over_contact_radius * radius_over_contact_radius * central_film_over_radius, 0.58);
}

}  // namespace tribo::lubrication::reference
