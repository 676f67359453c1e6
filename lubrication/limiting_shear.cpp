#include "lubrication/limiting_shear.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::lubrication {

void validate(const LimitingShear& limit, const char* who) {
  if (!(limit.stress_Pa >= 0.0) || !std::isfinite(limit.stress_Pa) || !(limit.pressure_coefficient >= 0.0) ||
      !std::isfinite(limit.pressure_coefficient))
    throw std::invalid_argument(std::string(who) + ": the limiting shear stress and its pressure coefficient must be finite and >= 0, got " +
                                numerics::shortest(limit.stress_Pa) + " Pa and " + numerics::shortest(limit.pressure_coefficient));
}

}  // namespace tribo::lubrication
