#include "lubrication/reference/ehl_film.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tribo::lubrication::reference {

LineContactGroups line_contact_groups(double w, double radius_m, double modulus_Pa, double speed_m_per_s,
                                      double viscosity_Pa_s, double alpha_per_Pa) {
  return {viscosity_Pa_s * speed_m_per_s / (modulus_Pa * radius_m), w / (modulus_Pa * radius_m), alpha_per_Pa * modulus_Pa};
}

double hertz_line_half_width_m(double w, double radius_m, double modulus_Pa) {
  return std::sqrt(8.0 * w * radius_m / (std::numbers::pi * modulus_Pa));
}

double hertz_line_peak_pressure_Pa(double w, double radius_m, double modulus_Pa) {
  return std::sqrt(w * modulus_Pa / (2.0 * std::numbers::pi * radius_m));
}

namespace {
double j2(double x) { return x / (2.0 * (1.0 + x * x)) + 0.5 * std::atan(x); }
double j3(double x) { return x / (4.0 * (1.0 + x * x) * (1.0 + x * x)) + 0.75 * j2(x); }
double k2(double x) { return 0.5 * x * std::atan(x); }                                 // ∫J2
double k3(double x) { return -1.0 / (8.0 * (1.0 + x * x)) + 0.375 * x * std::atan(x); }  // ∫J3
}  // namespace

double martin_load_constant(double inlet_xi) {
  if (!(inlet_xi < 0.0)) throw std::invalid_argument("martin_load_constant: the inlet must lie at ξ < 0");
  const bool flooded = std::isinf(inlet_xi);
  // The antiderivatives' limits at −∞: J2 → −π/4, J3 → −3π/16.
  const double j2_in = flooded ? -std::numbers::pi / 4.0 : j2(inlet_xi);
  const double j3_in = flooded ? -3.0 * std::numbers::pi / 16.0 : j3(inlet_xi);
  auto exit_pressure = [&](double e) { return (j2(e) - j2_in) - (1.0 + e * e) * (j3(e) - j3_in); };
  double lo = 0.0, hi = 2.0;  // Π(ξe) = 0: positive below the root, negative above
  for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) (exit_pressure(0.5 * (lo + hi)) > 0.0 ? lo : hi) = 0.5 * (lo + hi);
  const double e = 0.5 * (lo + hi), c = j2_in - (1.0 + e * e) * j3_in;
  // As ξ_in → −∞: K2 − (1+e²) K3 → ξ_in c − ½ + 3(1+e²)/8 and ξ_in c(ξ_in) → ξ_in c + O(ξ_in⁻²), so
  // the terms that grow with ξ_in cancel.
  if (flooded) return 24.0 * (k2(e) - (1.0 + e * e) * k3(e) + 0.5 - 0.375 * (1.0 + e * e) - e * c);
  return 24.0 * ((k2(e) - k2(inlet_xi)) - (1.0 + e * e) * (k3(e) - k3(inlet_xi)) - (e - inlet_xi) * c);
}

double martin_minimum_film_m(double w, double radius_m, double speed_m_per_s, double viscosity_Pa_s) {
  return martin_load_constant() * viscosity_Pa_s * speed_m_per_s * radius_m / w;
}

double pan_hamrock_minimum_film(const LineContactGroups& g) {
  return 1.714 * std::pow(g.load, -0.128) * std::pow(g.speed, 0.694) * std::pow(g.material, 0.568);
}

double pan_hamrock_central_film(const LineContactGroups& g) {
  return 2.922 * std::pow(g.load, -0.166) * std::pow(g.speed, 0.692) * std::pow(g.material, 0.470);
}

double dowson_higginson_minimum_film(const LineContactGroups& g) {
  return 2.65 * std::pow(g.speed, 0.70) * std::pow(g.material, 0.54) * std::pow(g.load, -0.13);
}

double dowson_toyoda_central_film(const LineContactGroups& g) {
  return 3.06 * std::pow(g.speed, 0.69) * std::pow(g.material, 0.56) * std::pow(g.load, -0.10);
}

}  // namespace tribo::lubrication::reference
