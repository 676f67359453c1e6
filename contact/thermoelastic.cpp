#include "contact/thermoelastic.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tribo::contact {

void validate(const ThermoelasticSolid& s) {
  if (!(std::isfinite(s.expansion_per_K) && s.expansion_per_K >= 0.0))
    throw std::invalid_argument("thermal expansion coefficient expansion_per_K must be >= 0 and finite");
  if (!(s.poisson_ratio >= 0.0 && s.poisson_ratio < 0.5)) throw std::invalid_argument("poisson_ratio must lie in [0, 0.5)");
  if (!(std::isfinite(s.conductivity_W_per_m_K) && s.conductivity_W_per_m_K > 0.0))
    throw std::invalid_argument("thermal conductivity conductivity_W_per_m_K must be positive and finite");
}

double thermoelastic_crown_m(const ThermoelasticSolid& s, double heat_W) {
  validate(s);
  if (!(std::isfinite(heat_W) && heat_W >= 0.0)) throw std::invalid_argument("heat_W must be >= 0 and finite");
  const double distortivity_m_per_W = (1.0 + s.poisson_ratio) * s.expansion_per_K / s.conductivity_W_per_m_K;
  return distortivity_m_per_W * heat_W / (4.0 * std::numbers::pi);
}

}  // namespace tribo::contact
