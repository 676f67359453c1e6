#include "lubrication/viscosity.h"
#include "numerics/format.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tribo::lubrication {
namespace {

// A literal message: nothing is built unless the check fails (viscosity_Pa_s runs inside the
// rig's right-hand side, millions of times a diagnosis).
void require(bool ok, const char* what) {
  if (!ok) throw std::invalid_argument(what);
}

}  // namespace

Lubricant thesis_white_mineral_oil() { return Lubricant{}; }

void validate(const Lubricant& l) {
  if (!(std::isfinite(l.viscosity_Pa_s) && l.viscosity_Pa_s > 0.0))
    throw std::invalid_argument("lubricant: viscosity_Pa_s must be finite and > 0, got " + numerics::shortest(l.viscosity_Pa_s) + " Pa s");
  require(std::isfinite(l.pressure_viscosity_per_Pa) && l.pressure_viscosity_per_Pa >= 0.0,
          "lubricant: pressure_viscosity_per_Pa must be finite and >= 0");
  require(std::isfinite(l.temperature_viscosity_per_K) && l.temperature_viscosity_per_K >= 0.0,
          "lubricant: temperature_viscosity_per_K must be finite and >= 0");
  require(std::isfinite(l.reference_temperature_K) && l.reference_temperature_K > 0.0,
          "lubricant: reference_temperature_K must be finite and > 0");
}

double viscosity_Pa_s(const Lubricant& l, double pressure_Pa, double temperature_K) {
  validate(l);
  require(std::isfinite(pressure_Pa), "viscosity: pressure_Pa must be finite");
  require(std::isfinite(temperature_K) && temperature_K > 0.0, "viscosity: temperature_K must be finite and > 0");
  return l.viscosity_Pa_s *
         std::exp(l.pressure_viscosity_per_Pa * pressure_Pa -
                  l.temperature_viscosity_per_K * (temperature_K - l.reference_temperature_K));
}

double crook_traction_N(double a_N_m_per_s, double b, double speed_m_per_s) {
  require(std::isfinite(a_N_m_per_s) && std::isfinite(b), "crook traction: a and b must be finite");
  require(std::isfinite(speed_m_per_s) && speed_m_per_s > 0.0, "crook traction: speed_m_per_s must be finite and > 0");
  return a_N_m_per_s / speed_m_per_s * (b + std::log(speed_m_per_s));  // thesis (3.2.5)
}

double crook_peak_speed_m_per_s(double b) {
  require(std::isfinite(b), "crook traction: b must be finite");
  return std::exp(1.0 - b);
}

double jaeger_temperature_rise_K(double K, double a, double mu_k, double speed_m_per_s, double solid_load_N) {
  require(std::isfinite(K) && K >= 0.0, "jaeger: K must be finite and >= 0");
  require(std::isfinite(a) && a >= 0.0, "jaeger: a must be finite and >= 0");
  require(std::isfinite(mu_k) && mu_k >= 0.0, "jaeger: mu_k must be finite and >= 0");
  require(std::isfinite(speed_m_per_s) && speed_m_per_s >= 0.0, "jaeger: speed_m_per_s must be finite and >= 0");
  require(std::isfinite(solid_load_N) && solid_load_N >= 0.0, "jaeger: solid_load_N must be finite and >= 0");
  const double denominator = a + std::sqrt(speed_m_per_s) * std::pow(solid_load_N, 0.25);
  if (denominator == 0.0) return 0.0;  // v = 0 or N_s = 0 with a = 0: no frictional heat, no rise
  return K * mu_k * speed_m_per_s * std::sqrt(solid_load_N) / denominator;  // thesis (5.2.2)
}

void validate(const JaegerContact& c) {
  require(std::isfinite(c.slider_conductivity_W_per_m_K) && c.slider_conductivity_W_per_m_K > 0.0,
          "jaeger: slider_conductivity_W_per_m_K must be finite and > 0");
  require(std::isfinite(c.disc_conductivity_W_per_m_K) && c.disc_conductivity_W_per_m_K > 0.0,
          "jaeger: disc_conductivity_W_per_m_K must be finite and > 0");
  require(std::isfinite(c.slider_diffusivity_m2_per_s) && c.slider_diffusivity_m2_per_s > 0.0,
          "jaeger: slider_diffusivity_m2_per_s must be finite and > 0");
}

double jaeger_flash_temperature_rise_K(const JaegerContact& c, double power_W, double real_area_m2,
                                       double speed_m_per_s) {
  require(std::isfinite(power_W) && power_W >= 0.0, "jaeger: power_W must be finite and >= 0");
  require(std::isfinite(real_area_m2) && real_area_m2 >= 0.0, "jaeger: real_area_m2 must be finite and >= 0");
  require(std::isfinite(speed_m_per_s) && speed_m_per_s >= 0.0, "jaeger: speed_m_per_s must be finite and >= 0");
  if (power_W == 0.0 || real_area_m2 == 0.0) return 0.0;
  const double b = std::sqrt(c.slider_diffusivity_m2_per_s);
  const double bracket = 1.1 * c.disc_conductivity_W_per_m_K * b +
                         0.7 * c.slider_conductivity_W_per_m_K * std::pow(real_area_m2, 0.25) * std::sqrt(speed_m_per_s);
  return power_W * b / (1.9 * std::sqrt(real_area_m2) * bracket);  // thesis (5.2.1), SI
}

}  // namespace tribo::lubrication
