#include "contact/profile.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::contact {

namespace {
// α of ISO 16610-21: the weighting function transmits half the amplitude at the cut-off.
const double kAlpha = std::sqrt(std::numbers::ln2 / std::numbers::pi);
}  // namespace

Eigen::ArrayXd level_profile(const Eigen::ArrayXd& z) {
  if (z.size() < 2) throw std::invalid_argument("a profile to level needs at least 2 samples, not " + std::to_string(z.size()));
  const Eigen::ArrayXd x = Eigen::ArrayXd::LinSpaced(z.size(), 0.0, static_cast<double>(z.size() - 1));
  const double xm = x.mean(), zm = z.mean();
  const double slope = ((x - xm) * (z - zm)).sum() / (x - xm).square().sum();
  return z - zm - slope * (x - xm);
}

FilteredProfile gaussian_profile_filter(const Eigen::ArrayXd& z, double spacing_m, double cutoff_m) {
  if (!(spacing_m > 0.0) || !std::isfinite(spacing_m))
    throw std::invalid_argument("the profile's sample spacing must be > 0, not " + numerics::shortest(spacing_m) + " m");
  if (!(cutoff_m > 0.0) || !std::isfinite(cutoff_m))
    throw std::invalid_argument("the filter's cut-off must be > 0, not " + numerics::shortest(cutoff_m) + " m");
  const double half_width = std::ceil(cutoff_m / spacing_m * (1.0 - 1e-12));  // the window reaches ±λc (rounding aside)
  if (!(2.0 * half_width + 1.0 <= static_cast<double>(z.size())))
    throw std::invalid_argument("a profile of " + std::to_string(z.size()) + " samples " + numerics::shortest(spacing_m) +
                                " m apart is shorter than the filter's window (2 cut-offs of " + numerics::shortest(cutoff_m) + " m)");
  const auto m = static_cast<Eigen::Index>(half_width);
  Eigen::ArrayXd w(2 * m + 1);
  for (Eigen::Index k = -m; k <= m; ++k) {
    const double u = static_cast<double>(k) * spacing_m / (kAlpha * cutoff_m);
    w(k + m) = std::exp(-std::numbers::pi * u * u);
  }
  w /= w.sum();  // the sampled, truncated window's weights sum to one: a constant passes unchanged
  FilteredProfile out;
  out.first = m;
  out.height_m.resize(z.size() - 2 * m);
  for (Eigen::Index i = 0; i < out.height_m.size(); ++i) out.height_m(i) = (w * z.segment(i, 2 * m + 1)).sum();
  return out;
}

double gaussian_filter_transmission(double wavelength_m, double cutoff_m) {
  const double r = kAlpha * cutoff_m / wavelength_m;
  return std::exp(-std::numbers::pi * r * r);
}

}  // namespace tribo::contact
