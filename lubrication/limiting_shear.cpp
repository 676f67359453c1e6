#include "lubrication/limiting_shear.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::lubrication {

void validate(const LimitingShear& limit, const char* who) {
  const auto good = [](double x) { return x >= 0.0 && std::isfinite(x); };
  if (!good(limit.stress_Pa) || !good(limit.pressure_coefficient) || !good(limit.temperature_coefficient_per_K))
    throw std::invalid_argument(std::string(who) +
                                ": the limiting shear stress and its pressure and temperature coefficients must be finite and >= 0, got " +
                                numerics::shortest(limit.stress_Pa) + " Pa, " + numerics::shortest(limit.pressure_coefficient) + " and " +
                                numerics::shortest(limit.temperature_coefficient_per_K) + " 1/K");
}

}  // namespace tribo::lubrication
