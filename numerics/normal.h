// The standard normal distribution's tail and quantile, for the statistical rules that take a
// significance level (gap/verdict.h) and the tests that place points at Gaussian quantiles.
#pragma once

namespace tribo::numerics {

// Φ(x) = ½ erfc(−x/√2).
double standard_normal_cdf(double x);
// Φ⁻¹(u) for u in (0, 1), by bisection on Φ to round-off (−∞ / +∞ at u = 0 / 1).
double standard_normal_quantile(double u);

}  // namespace tribo::numerics
