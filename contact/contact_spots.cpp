#include "contact/contact_spots.h"

#include <cmath>
#include <stdexcept>

namespace tribo::contact {

std::vector<ContactSpot> contact_spots(const Eigen::ArrayXXd& p, const Grid& grid, double e_star_Pa) {
  if (p.rows() != grid.nx || p.cols() != grid.ny) throw std::invalid_argument("contact_spots: the pressure field does not match the grid");
  if (!(e_star_Pa > 0.0)) throw std::invalid_argument("contact_spots: e_star_Pa must be positive");
  const Eigen::Index nx = p.rows(), ny = p.cols();
  const double cell = grid.dx_m * grid.dy_m;
  Eigen::ArrayXX<char> seen = Eigen::ArrayXX<char>::Zero(nx, ny);
  std::vector<ContactSpot> spots;
  std::vector<std::pair<Eigen::Index, Eigen::Index>> stack;
  for (Eigen::Index j = 0; j < ny; ++j)
    for (Eigen::Index i = 0; i < nx; ++i) {
      if (seen(i, j) || !(p(i, j) > 0.0)) continue;
      ContactSpot s;
      stack.assign(1, {i, j});
      seen(i, j) = 1;
      while (!stack.empty()) {  // flood fill: every node reached once
        const auto [a, b] = stack.back();
        stack.pop_back();
        s.area_m2 += cell;
        s.load_N += p(a, b) * cell;
        const std::pair<Eigen::Index, Eigen::Index> next[] = {
            {(a + 1) % nx, b}, {(a + nx - 1) % nx, b}, {a, (b + 1) % ny}, {a, (b + ny - 1) % ny}};
        for (const auto& [c, d] : next)
          if (!seen(c, d) && p(c, d) > 0.0) seen(c, d) = 1, stack.emplace_back(c, d);
      }
      s.mean_pressure_Pa = s.load_N / s.area_m2;
      const double a = std::sqrt(s.area_m2 / M_PI);
      s.equivalent_radius_m = 4.0 * e_star_Pa * a * a * a / (3.0 * s.load_N);
      spots.push_back(s);
    }
  return spots;
}

}  // namespace tribo::contact
