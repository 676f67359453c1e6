// Least-squares slope of log(error) against log(spacing): the observed order of convergence
// (shared by the Reynolds and average-flow convergence tests).
#pragma once

#include <cmath>
#include <vector>

namespace tribo::lubrication {

inline double observed_order(const std::vector<double>& spacing, const std::vector<double>& error) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double n = static_cast<double>(spacing.size());
  for (std::size_t k = 0; k < spacing.size(); ++k) {
    const double x = std::log(spacing[k]), y = std::log(error[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace tribo::lubrication
