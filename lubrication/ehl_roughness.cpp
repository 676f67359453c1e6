#include "lubrication/ehl_roughness.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "numerics/format.h"

namespace tribo::lubrication {

double ridge_height_m(const EhlRoughness& r, double x) {
  if (x < r.x_m.front() || x > r.x_m.back()) return 0.0;
  const auto hi = std::upper_bound(r.x_m.begin(), r.x_m.end(), x);
  if (hi == r.x_m.end()) return r.height_m.back();
  const auto k = static_cast<std::size_t>(hi - r.x_m.begin());
  const double t = (x - r.x_m[k - 1]) / (r.x_m[k] - r.x_m[k - 1]);
  return (1.0 - t) * r.height_m[k - 1] + t * r.height_m[k];
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
  if (r.x_m.size() < 2 || r.x_m.size() != r.height_m.size())
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
  if (!std::isfinite(r.contact_margin_m) || r.contact_margin_m < 0.0)
    throw std::invalid_argument(who + ": roughness contact_margin_m must be finite and not negative, got " + shortest(r.contact_margin_m));
}

}  // namespace tribo::lubrication
