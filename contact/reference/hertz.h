// Hertz (1882) contact of an elastic sphere of radius R on a flat, composite modulus E*, load W:
//   contact radius   a  = (3 W R / (4 E*))^{1/3}
//   peak pressure    p0 = 3 W / (2π a²),   p(r) = p0 √(1 − r²/a²)
//   approach         δ  = a² / R
// (Johnson, Contact Mechanics (1985) §4.2, eqs. 4.22–4.23.)
#pragma once

#include <cmath>
#include <numbers>

namespace tribo::contact::reference {

inline double hertz_contact_radius_m(double load_N, double radius_m, double e_star_Pa) {
  return std::cbrt(3.0 * load_N * radius_m / (4.0 * e_star_Pa));
}

inline double hertz_peak_pressure_Pa(double load_N, double radius_m, double e_star_Pa) {
  const double a = hertz_contact_radius_m(load_N, radius_m, e_star_Pa);
  return 3.0 * load_N / (2.0 * std::numbers::pi * a * a);
}

inline double hertz_approach_m(double load_N, double radius_m, double e_star_Pa) {
  const double a = hertz_contact_radius_m(load_N, radius_m, e_star_Pa);
  return a * a / radius_m;
}

inline double hertz_pressure_Pa(double r_m, double load_N, double radius_m, double e_star_Pa) {
  const double a = hertz_contact_radius_m(load_N, radius_m, e_star_Pa);
  return r_m >= a ? 0.0 : hertz_peak_pressure_Pa(load_N, radius_m, e_star_Pa) * std::sqrt(1.0 - r_m * r_m / (a * a));
}

}  // namespace tribo::contact::reference
