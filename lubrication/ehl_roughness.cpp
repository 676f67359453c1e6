#include "lubrication/ehl_roughness.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/format.h"

namespace tribo::lubrication {

double ridge_height_m(const EhlRoughness& r, double x) {
  if (r.x_m.empty() || x < r.x_m.front() || x > r.x_m.back()) return 0.0;
  const auto hi = std::upper_bound(r.x_m.begin(), r.x_m.end(), x);
  if (hi == r.x_m.end()) return r.height_m.back();
  const auto k = static_cast<std::size_t>(hi - r.x_m.begin());
  const double t = (x - r.x_m[k - 1]) / (r.x_m[k] - r.x_m[k - 1]);
  return (1.0 - t) * r.height_m[k - 1] + t * r.height_m[k];
}

double surface_height_m(const EhlRoughness& r, double x, double y) {
  double z = ridge_height_m(r, x);
  if (!r.map) return z;
  const EhlHeightMap& m = *r.map;
  const double fi = (x - m.x0_m) / m.dx_m, fj = (y - m.y0_m) / m.dy_m;
  const Eigen::Index nx = m.height_m.rows(), ny = m.height_m.cols();
  if (!(fi >= 0.0 && fj >= 0.0 && fi <= static_cast<double>(nx - 1) && fj <= static_cast<double>(ny - 1))) return z;
  const Eigen::Index i = std::min(static_cast<Eigen::Index>(fi), nx - 2), j = std::min(static_cast<Eigen::Index>(fj), ny - 2);
  const double s = fi - static_cast<double>(i), t = fj - static_cast<double>(j);
  z += (1.0 - s) * (1.0 - t) * m.height_m(i, j) + s * (1.0 - t) * m.height_m(i + 1, j) + (1.0 - s) * t * m.height_m(i, j + 1) +
       s * t * m.height_m(i + 1, j + 1);
  return z;
}

EhlRoughness cosine_ridges(double from_m, double to_m, double amplitude_m, double wavelength_m, std::size_t points) {
  if (points < 2 || !(to_m > from_m) || !(wavelength_m > 0.0))
    throw std::invalid_argument("cosine_ridges: needs at least two points over an interval and a positive wavelength");
  EhlRoughness r;
  r.x_m.reserve(points);
  r.height_m.reserve(points);
  for (std::size_t k = 0; k < points; ++k) {
    const double x = from_m + (to_m - from_m) * static_cast<double>(k) / static_cast<double>(points - 1);
    r.x_m.push_back(x);
    r.height_m.push_back(amplitude_m * std::cos(2.0 * std::numbers::pi * x / wavelength_m));
  }
  return r;
}

void validate(const EhlRoughness& r, const std::string& who) {
  using numerics::shortest;
  if (r.map) {
    const EhlHeightMap& m = *r.map;
    if (m.height_m.rows() < 2 || m.height_m.cols() < 2)
      throw std::invalid_argument(who + ": the roughness map needs at least 2 x 2 samples, got " + std::to_string(m.height_m.rows()) +
                                  " x " + std::to_string(m.height_m.cols()));
    if (!(std::isfinite(m.dx_m) && m.dx_m > 0.0 && std::isfinite(m.dy_m) && m.dy_m > 0.0 && std::isfinite(m.x0_m) && std::isfinite(m.y0_m)))
      throw std::invalid_argument(who + ": the roughness map's origin must be finite and its spacings positive, got dx " +
                                  shortest(m.dx_m) + " m, dy " + shortest(m.dy_m) + " m");
    if (!m.height_m.allFinite()) throw std::invalid_argument(who + ": the roughness map holds a height that is not finite");
  }
  const bool map_alone = r.map && r.x_m.empty() && r.height_m.empty();
  if (!map_alone && (r.x_m.size() < 2 || r.x_m.size() != r.height_m.size()))
    throw std::invalid_argument(who + ": the roughness profile needs at least two points and as many heights as positions, got " +
                                std::to_string(r.x_m.size()) + " positions and " + std::to_string(r.height_m.size()) + " heights");
  for (std::size_t k = 0; k < r.x_m.size(); ++k) {
    if (!std::isfinite(r.x_m[k]) || !std::isfinite(r.height_m[k]))
      throw std::invalid_argument(who + ": roughness point " + std::to_string(k) + " is not finite");
    if (k > 0 && !(r.x_m[k] > r.x_m[k - 1]))
      throw std::invalid_argument(who + ": the roughness positions must increase, point " + std::to_string(k) + " at " +
                                  shortest(r.x_m[k]) + " m does not");
  }
  if (!std::isfinite(r.contact_film_m) || r.contact_film_m <= 0.0)
    throw std::invalid_argument(who + ": roughness contact_film_m must be positive and finite, got " + shortest(r.contact_film_m));
  if (!(r.hardness_Pa > 0.0)) throw std::invalid_argument(who + ": roughness hardness_Pa must be positive, got " + shortest(r.hardness_Pa));
  if (!std::isfinite(r.contact_margin_m) || r.contact_margin_m < 0.0)
    throw std::invalid_argument(who + ": roughness contact_margin_m must be finite and not negative, got " + shortest(r.contact_margin_m));
}

}  // namespace tribo::lubrication
