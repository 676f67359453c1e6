#include "lubrication/reference/squeeze_film.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "numerics/format.h"

namespace tribo::lubrication {
namespace {

void require_positive(const char* name, double value) {
  if (!std::isfinite(value) || value <= 0.0)
    throw std::invalid_argument(std::string("squeeze film: ") + name + " must be finite and > 0, got " +
                                numerics::shortest(value));
}

void require_finite(const char* name, double value) {
  if (!std::isfinite(value))
    throw std::invalid_argument(std::string("squeeze film: ") + name + " must be finite");
}

}  // namespace

double squeeze_film_pressure_Pa(double viscosity_Pa_s, double radius_m, double gap_m, double gap_rate_m_per_s,
                                double rho_m) {
  require_positive("viscosity_Pa_s", viscosity_Pa_s);
  require_positive("radius_m", radius_m);
  require_positive("gap_m", gap_m);
  require_finite("gap_rate_m_per_s", gap_rate_m_per_s);
  if (!std::isfinite(rho_m) || rho_m < 0.0 || rho_m > radius_m)
    throw std::invalid_argument("squeeze film: rho_m must lie in [0, radius_m]");
  return 3.0 * viscosity_Pa_s / (gap_m * gap_m * gap_m) * (rho_m * rho_m - radius_m * radius_m) * gap_rate_m_per_s;
}

double squeeze_film_load_N(double viscosity_Pa_s, double radius_m, double gap_m, double gap_rate_m_per_s) {
  require_positive("viscosity_Pa_s", viscosity_Pa_s);
  require_positive("radius_m", radius_m);
  require_positive("gap_m", gap_m);
  require_finite("gap_rate_m_per_s", gap_rate_m_per_s);
  const double r2 = radius_m * radius_m;
  return -1.5 * std::numbers::pi * viscosity_Pa_s * r2 * r2 * gap_rate_m_per_s / (gap_m * gap_m * gap_m);  // (3.2.2)
}

double squeeze_film_gap_rate_m_per_s(double viscosity_Pa_s, double radius_m, double gap_m, double load_N) {
  require_positive("viscosity_Pa_s", viscosity_Pa_s);
  require_positive("radius_m", radius_m);
  require_positive("gap_m", gap_m);
  require_finite("load_N", load_N);
  const double r2 = radius_m * radius_m;
  return -2.0 * load_N * gap_m * gap_m * gap_m / (3.0 * std::numbers::pi * viscosity_Pa_s * r2 * r2);
}

double squeeze_out_time_s(double viscosity_Pa_s, double radius_m, double load_N, double h0_m, double h1_m) {
  require_positive("viscosity_Pa_s", viscosity_Pa_s);
  require_positive("radius_m", radius_m);
  require_positive("load_N", load_N);
  require_positive("h0_m", h0_m);
  require_positive("h1_m", h1_m);
  if (h1_m >= h0_m) throw std::invalid_argument("squeeze film: h1_m must be smaller than h0_m (the gap closes)");
  const double r2 = radius_m * radius_m;
  return 0.75 * std::numbers::pi * viscosity_Pa_s * r2 * r2 / load_N * (1.0 / (h1_m * h1_m) - 1.0 / (h0_m * h0_m));
}

}  // namespace tribo::lubrication
