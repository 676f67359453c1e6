#include "apps/demo_model.h"

namespace tribo::cli {

rig::FrictionModel thesis_demo_model() {
  rig::FrictionModel m = rig::coulomb(0.55, 0.12);
  m.add("rate_dependent_static");
  m.add("slip_transient");
  m.add("squeeze_film");
  m.set("thermal_thinning", "thermal_speed_m_per_s", 0.05);
  m.set("viscous_friction", "coefficient_N_s_per_m", 22.0);
  return m;
}

}  // namespace tribo::cli
