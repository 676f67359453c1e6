// The contact spots of a solved pressure field: the connected regions where the pressure is
// positive (4-neighbour connectivity, periodic across the patch's edges as the BEM is), each with
// its area, load and mean pressure, and the radius of the Hertz contact of that size and load.
//
// Equivalent radius. A Hertz spot of radius a under load w has a = (3 w R / (4 E*))^{1/3}
// (Johnson, "Contact Mechanics", (4.22)), so
//     R_eq = 4 E* a³ / (3 w),    a = √(A / π):
// exact for an elastic paraboloidal asperity (to the grid's resolution of its area); for a spot
// pressed to the hardness it is the paraboloid whose elastic contact would have that size and load —
// the geometry an EHL film over the spot sees (lubrication/micro_ehl.h), without differentiating
// the heights twice on the grid.
#pragma once

#include <Eigen/Core>

#include <vector>

#include "contact/grid.h"

namespace tribo::contact {

struct ContactSpot {
  double area_m2 = 0.0;
  double load_N = 0.0;
  double mean_pressure_Pa = 0.0;       // load / area
  double equivalent_radius_m = 0.0;    // R_eq above
};

// The spots of `pressure_Pa` on `grid` (periodic), in the order of their first node in column-major
// order. Throws std::invalid_argument when the field's size differs from the grid's or e_star_Pa ≤ 0.
std::vector<ContactSpot> contact_spots(const Eigen::ArrayXXd& pressure_Pa, const Grid& grid, double e_star_Pa);

}  // namespace tribo::contact
