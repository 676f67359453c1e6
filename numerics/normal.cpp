#include "numerics/normal.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>

namespace tribo::numerics {

double standard_normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }

double standard_normal_quantile(double u) {
  assert(u >= 0.0 && u <= 1.0);
  if (u <= 0.0) return -std::numeric_limits<double>::infinity();
  if (u >= 1.0) return std::numeric_limits<double>::infinity();
  // Φ(±40) is 1 to round-off and below the smallest double in the lower tail: the root is inside.
  double lo = -40.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (standard_normal_cdf(mid) < u ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace tribo::numerics
