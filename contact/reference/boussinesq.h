// Boussinesq (1885): a point force F normal to the surface of an elastic half-space displaces the
// surface, at distance r from it, by
//   u_z = F / (π E* r)
// with E* the composite modulus of contact/halfspace.h (Johnson, Contact Mechanics (1985) §3.2,
// eq. 3.21a, with (1 − ν²)/E of both bodies).
#pragma once

#include <numbers>

namespace tribo::contact::reference {

inline double boussinesq_displacement_m(double force_N, double r_m, double e_star_Pa) {
  return force_N / (std::numbers::pi * e_star_Pa * r_m);
}

}  // namespace tribo::contact::reference
