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

Eigen::ArrayXXd level_map(const Eigen::ArrayXXd& z) {
  if (z.rows() < 2 || z.cols() < 2)
    throw std::invalid_argument("a map to level needs at least 2 x 2 samples, not " + std::to_string(z.rows()) + " x " + std::to_string(z.cols()));
  // z = c + a i + b j by least squares over the regular grid: i and j are orthogonal about their means.
  const Eigen::ArrayXd i = Eigen::ArrayXd::LinSpaced(z.rows(), 0.0, static_cast<double>(z.rows() - 1)) - 0.5 * static_cast<double>(z.rows() - 1);
  const Eigen::ArrayXd j = Eigen::ArrayXd::LinSpaced(z.cols(), 0.0, static_cast<double>(z.cols() - 1)) - 0.5 * static_cast<double>(z.cols() - 1);
  const double mean = z.mean();
  const double a = (z.colwise() * i).sum() / (i.square().sum() * static_cast<double>(z.cols()));
  const double b = (z.rowwise() * j.transpose()).sum() / (j.square().sum() * static_cast<double>(z.rows()));
  Eigen::ArrayXXd out = z - mean;
  out.colwise() -= a * i;
  out.rowwise() -= b * j.transpose();
  return out;
}

FilteredMap gaussian_areal_filter(const Eigen::ArrayXXd& z, double dx_m, double dy_m, double cutoff_m) {
  // Along y (each row of the map holds the samples of one x), then along x.
  FilteredMap out;
  Eigen::ArrayXXd along_y;
  for (Eigen::Index r = 0; r < z.rows(); ++r) {
    const FilteredProfile f = gaussian_profile_filter(z.row(r).transpose(), dy_m, cutoff_m);
    if (r == 0) along_y.resize(z.rows(), f.height_m.size()), out.first_y = f.first;
    along_y.row(r) = f.height_m.transpose();
  }
  for (Eigen::Index c = 0; c < along_y.cols(); ++c) {
    const FilteredProfile f = gaussian_profile_filter(along_y.col(c), dx_m, cutoff_m);
    if (c == 0) out.height_m.resize(f.height_m.size(), along_y.cols()), out.first_x = f.first;
    out.height_m.col(c) = f.height_m;
  }
  return out;
}

}  // namespace tribo::contact
