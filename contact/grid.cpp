#include "contact/grid.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace tribo::contact {

void validate(const Grid& g) {
  if (g.nx < 1 || g.ny < 1) {
    throw std::invalid_argument("grid must have at least 1 point per side, got " + std::to_string(g.nx) + " x " +
                                std::to_string(g.ny));
  }
  if (!(std::isfinite(g.dx_m) && g.dx_m > 0.0 && std::isfinite(g.dy_m) && g.dy_m > 0.0)) {
    throw std::invalid_argument("grid cell size dx_m, dy_m must be positive and finite");
  }
}

}  // namespace tribo::contact
