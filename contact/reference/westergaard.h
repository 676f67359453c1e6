// Westergaard (1939) periodic contact of a sinusoidal wavy surface z = h cos(2π x/λ) (amplitude h,
// wavelength λ) on an elastic half-space of composite modulus E*, mean pressure p̄:
//   complete contact pressure   p* = π E* h / λ
//   complete contact (p̄ ≥ p*)   p(x) = p̄ + p* cos(2π x/λ)   (x measured from a crest)
//   partial contact (p̄ < p*)    contact half-width a with sin²(π a/λ) = p̄ / p*,
//                               contact fraction 2a/λ = (2/π) arcsin √(p̄/p*)
// (Johnson, Contact Mechanics (1985) §13.2, eqs. 13.5–13.8.)
#pragma once

#include <cmath>
#include <numbers>

namespace tribo::contact::reference {

inline double westergaard_complete_contact_pressure_Pa(double amplitude_m, double wavelength_m, double e_star_Pa) {
  return std::numbers::pi * e_star_Pa * amplitude_m / wavelength_m;
}

// Pressure at distance x from a crest for p̄ ≥ p* (complete contact).
inline double westergaard_full_contact_pressure_Pa(double x_m, double mean_pressure_Pa, double amplitude_m,
                                                   double wavelength_m, double e_star_Pa) {
  return mean_pressure_Pa + westergaard_complete_contact_pressure_Pa(amplitude_m, wavelength_m, e_star_Pa) *
                                std::cos(2.0 * std::numbers::pi * x_m / wavelength_m);
}

// Contact area fraction 2a/λ; 1 at and above p*.
inline double westergaard_area_fraction(double mean_pressure_Pa, double amplitude_m, double wavelength_m,
                                        double e_star_Pa) {
  const double ratio = mean_pressure_Pa / westergaard_complete_contact_pressure_Pa(amplitude_m, wavelength_m, e_star_Pa);
  return ratio >= 1.0 ? 1.0 : 2.0 / std::numbers::pi * std::asin(std::sqrt(ratio));
}

}  // namespace tribo::contact::reference
