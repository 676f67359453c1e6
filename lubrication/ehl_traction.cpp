#include "lubrication/ehl_traction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "numerics/format.h"

namespace tribo::lubrication {

EhlTraction ehl_line_traction(const EhlLineResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                              double eyring_stress_Pa, double load_per_length_N_per_m) {
  validate(lubricant);
  if (!std::isfinite(sliding_speed_m_per_s))
    throw std::invalid_argument("EHL traction: the sliding speed must be finite, got " + numerics::shortest(sliding_speed_m_per_s) + " m/s");
  if (!(eyring_stress_Pa > 0.0))
    throw std::invalid_argument("EHL traction: the Eyring stress must be positive (infinite for a Newtonian film), got " +
                                numerics::shortest(eyring_stress_Pa) + " Pa");
  if (!(load_per_length_N_per_m > 0.0) || !std::isfinite(load_per_length_N_per_m))
    throw std::invalid_argument("EHL traction: the load per length must be positive, got " + numerics::shortest(load_per_length_N_per_m) + " N/m");
  const std::size_t n = film.x_m.size();
  if (n < 2 || film.pressure_Pa.size() != n || film.film_m.size() != n)
    throw std::invalid_argument("EHL traction: the film needs at least two nodes with x, pressure and film thickness each");
  const bool newtonian = std::isinf(eyring_stress_Pa);
  EhlTraction out;
  std::vector<double> tau(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!(film.pressure_Pa[i] > 0.0)) continue;  // cavitated (or at the domain's ends)
    const double h = film.film_m[i];
    if (!(h > 0.0))
      throw std::invalid_argument("EHL traction: non-positive film " + numerics::shortest(h) + " m at x = " + numerics::shortest(film.x_m[i]) + " m");
    const double newtonian_stress = lubricant.viscosity_Pa_s * viscosity_ratio(lubricant, film.pressure_Pa[i]).ratio * sliding_speed_m_per_s / h;
    tau[i] = newtonian ? newtonian_stress : eyring_stress_Pa * std::asinh(newtonian_stress / eyring_stress_Pa);
    out.max_shear_stress_Pa = std::max(out.max_shear_stress_Pa, std::abs(tau[i]));
  }
  for (std::size_t i = 1; i < n; ++i) out.force_per_length_N_per_m += 0.5 * (tau[i] + tau[i - 1]) * (film.x_m[i] - film.x_m[i - 1]);
  out.friction_coefficient = out.force_per_length_N_per_m / load_per_length_N_per_m;
  return out;
}

}  // namespace tribo::lubrication
