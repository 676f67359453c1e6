#include "lubrication/moving_heat_source.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::lubrication {

void validate(const HeatedSolid& solid) {
  const auto check = [](double v, const char* name) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw std::invalid_argument(std::string("heated solid: ") + name + " must be finite and positive, got " + numerics::shortest(v));
  };
  check(solid.thermal_conductivity_W_per_m_K, "thermal_conductivity_W_per_m_K");
  check(solid.density_kg_per_m3, "density_kg_per_m3");
  check(solid.specific_heat_J_per_kg_K, "specific_heat_J_per_kg_K");
}

double thermal_effusivity(const HeatedSolid& s) {
  return std::sqrt(s.thermal_conductivity_W_per_m_K * s.density_kg_per_m3 * s.specific_heat_J_per_kg_K);
}

double thermal_diffusivity_m2_per_s(const HeatedSolid& s) {
  return s.thermal_conductivity_W_per_m_K / (s.density_kg_per_m3 * s.specific_heat_J_per_kg_K);
}

double peclet_number(const HeatedSolid& solid, double speed_m_per_s, double half_length_m) {
  return speed_m_per_s * half_length_m / (2.0 * thermal_diffusivity_m2_per_s(solid));
}

MovingSurface::MovingSurface(const std::vector<double>& x, double speed_m_per_s, const HeatedSolid& solid) {
  const std::size_t n = x.size();
  validate(solid);
  if (!(speed_m_per_s > 0.0) || !std::isfinite(speed_m_per_s))
    throw std::invalid_argument("moving surface: the speed must be finite and positive (the surface moves towards increasing x), got " +
                                numerics::shortest(speed_m_per_s) + " m/s");
  if (n < 2) throw std::invalid_argument("moving surface: at least two nodes are needed, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(x[i]) || (i > 0 && !(x[i] > x[i - 1])))
      throw std::invalid_argument("moving surface: the nodes must be finite and strictly increasing; node " + std::to_string(i) + " is " +
                                  numerics::shortest(x[i]) + " m");
  // Cell edges: c_0 = x_0, c_j = (x_{j−1} + x_j)/2, c_n = x_{n−1}.
  std::vector<double> edge(n + 1);
  edge[0] = x[0], edge[n] = x[n - 1];
  for (std::size_t j = 1; j < n; ++j) edge[j] = 0.5 * (x[j - 1] + x[j]);
  const double scale = 2.0 / (thermal_effusivity(solid) * std::sqrt(M_PI * speed_m_per_s));
  w_.resize(n * (n + 1) / 2);
  for (std::size_t i = 0; i < n; ++i) {
    double* row = &w_[i * (i + 1) / 2];
    for (std::size_t j = 0; j < i; ++j) row[j] = scale * (std::sqrt(x[i] - edge[j]) - std::sqrt(x[i] - edge[j + 1]));
    row[i] = scale * std::sqrt(x[i] - edge[i]);
  }
}

double MovingSurface::upstream_rise_K(std::size_t i, const double* flux) const {
  const double* row = &w_[i * (i + 1) / 2];
  double sum = 0.0;
  for (std::size_t j = 0; j < i; ++j) sum += row[j] * flux[j];
  return sum;
}

std::vector<double> moving_surface_temperature_rise_K(const std::vector<double>& x_m, const std::vector<double>& flux_W_per_m2,
                                                      double speed_m_per_s, const HeatedSolid& solid) {
  if (flux_W_per_m2.size() != x_m.size())
    throw std::invalid_argument("moving surface: " + std::to_string(x_m.size()) + " nodes but " + std::to_string(flux_W_per_m2.size()) +
                                " flux values");
  const MovingSurface surface(x_m, speed_m_per_s, solid);
  std::vector<double> rise(x_m.size());
  for (std::size_t i = 0; i < rise.size(); ++i)
    rise[i] = surface.upstream_rise_K(i, flux_W_per_m2.data()) + surface.own_weight(i) * flux_W_per_m2[i];
  return rise;
}

}  // namespace tribo::lubrication
