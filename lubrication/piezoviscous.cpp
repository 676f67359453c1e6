#include "lubrication/piezoviscous.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::lubrication {
namespace {

constexpr double kRoelandsPressure_Pa = 1.96e8;
constexpr double kRoelandsLogViscosityOffset = 9.67;  // ln(6.315e-5 Pa·s), Roelands' asymptote
constexpr double kRoelandsSlopeScale_per_Pa = 5.1e-9;  // 1/p_r of the index definition

}  // namespace

void validate(const PiezoviscousLubricant& l) {
  if (!std::isfinite(l.viscosity_Pa_s) || l.viscosity_Pa_s <= 0.0)
    throw std::invalid_argument("lubricant viscosity_Pa_s must be positive and finite, got " + numerics::shortest(l.viscosity_Pa_s));
  if (!std::isfinite(l.pressure_viscosity_per_Pa) || l.pressure_viscosity_per_Pa < 0.0)
    throw std::invalid_argument("lubricant pressure_viscosity_per_Pa must be ≥ 0 and finite, got " +
                                numerics::shortest(l.pressure_viscosity_per_Pa));
  if (l.law == PressureViscosityLaw::roelands && std::log(l.viscosity_Pa_s) + kRoelandsLogViscosityOffset <= 0.0)
    throw std::invalid_argument("Roelands' law needs η0 above its asymptote 6.3e-5 Pa·s, got " +
                                numerics::shortest(l.viscosity_Pa_s) + " Pa·s");
}

ViscosityAtPressure viscosity_ratio(const PiezoviscousLubricant& l, double pressure_Pa) {
  const double p = std::max(pressure_Pa, 0.0);
  const double alpha = l.pressure_viscosity_per_Pa;
  if (l.law == PressureViscosityLaw::barus) return {std::exp(alpha * p), pressure_Pa > 0.0 ? alpha : 0.0};
  const double a = std::log(l.viscosity_Pa_s) + kRoelandsLogViscosityOffset;
  const double z = alpha / (kRoelandsSlopeScale_per_Pa * a);
  const double s = std::pow(1.0 + p / kRoelandsPressure_Pa, z);
  // d/dp of a (s − 1) = a z s / (p_r + p).
  return {std::exp(a * (s - 1.0)), pressure_Pa > 0.0 ? a * z * s / (kRoelandsPressure_Pa + p) : 0.0};
}

DensityAtPressure density_ratio(const PiezoviscousLubricant& l, double pressure_Pa) {
  if (!l.compressible || pressure_Pa <= 0.0) return {};
  const double p = pressure_Pa, d = 1.0 + 1.7e-9 * p;  // Dowson–Higginson
  return {1.0 + 0.6e-9 * p / d, 0.6e-9 / (d * d)};
}

}  // namespace tribo::lubrication
