#include "rig/parameters.h"
#include "numerics/format.h"

#include <stdexcept>
#include <string>

namespace tribo::rig {
namespace {
void require_positive(double v, const char* name) {
  if (!std::isfinite(v) || !(v > 0.0)) {
    throw std::invalid_argument(std::string("rig: ") + name + " must be positive and finite (got " + numerics::shortest(v) + ")");
  }
}
}  // namespace

void validate(const RigParameters& rig) {
  require_positive(rig.mass_kg, "mass_kg");
  require_positive(rig.stiffness_N_per_m, "stiffness_N_per_m");
  require_positive(rig.normal_load_N, "normal_load_N");
  require_positive(rig.slider_radius_m, "slider_radius_m");
  if (!std::isfinite(rig.damping_N_s_per_m) || rig.damping_N_s_per_m < 0.0) {
    throw std::invalid_argument("rig: damping_N_s_per_m must be finite and non-negative (got " +
                                numerics::shortest(rig.damping_N_s_per_m) + ")");
  }
  if (rig.decay_rate_per_s() >= rig.natural_frequency_rad_per_s()) {
    throw std::invalid_argument("rig: damping_N_s_per_m makes the rig critically or over-damped (r >= 2 sqrt(k M))");
  }
}

}  // namespace tribo::rig
