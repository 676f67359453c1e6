#include "lubrication/ehl_traction.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/format.h"

namespace tribo::lubrication {

namespace {

// The shear stress at one node: τ = τ0 asinh(η e^{−γΔT(τ)} Δu/(τ0 h)) with ΔT = |τ Δu| h/(12 k),
// for Δu ≥ 0 (the caller carries the sign). No heating when k = 0; the isothermal stress (with its
// temperature rise) when γ = 0.
double shear_stress_Pa(double viscosity_Pa_s, double du, double h, double tau0, const FilmHeating& heat, double* rise_K) {
  const bool newtonian = std::isinf(tau0);
  const auto stress_at = [&](double temperature_rise_K) {
    const double newtonian_stress = viscosity_Pa_s * std::exp(-heat.temperature_viscosity_per_K * temperature_rise_K) * du / h;
    return newtonian ? newtonian_stress : tau0 * std::asinh(newtonian_stress / tau0);
  };
  const auto rise_at = [&](double tau) { return tau * du * h / (12.0 * heat.thermal_conductivity_W_per_m_K); };
  const double isothermal = stress_at(0.0);
  if (!(heat.thermal_conductivity_W_per_m_K > 0.0)) {  // no heating modelled
    *rise_K = 0.0;
    return isothermal;
  }
  if (heat.temperature_viscosity_per_K == 0.0 || isothermal == 0.0) {  // the film heats, its viscosity does not follow
    *rise_K = rise_at(isothermal);
    return isothermal;
  }
  // g(τ) = τ − stress_at(ΔT(τ)) rises from −isothermal at 0 to ≥ 0 at `isothermal`: bisection to
  // the last bit (each step halves the bracket; 200 steps are far more than 53 bits need).
  double lo = 0.0, hi = isothermal;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid - stress_at(rise_at(mid)) < 0.0 ? lo : hi) = mid;
  }
  const double tau = 0.5 * (lo + hi);
  *rise_K = rise_at(tau);
  return tau;
}

// The inputs both tractions check; `load` in the unit of `load_unit`.
void check_traction_inputs(const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s, double eyring_stress_Pa, double load,
                           const char* load_name, const FilmHeating& heating) {
  validate(lubricant);
  if (!std::isfinite(sliding_speed_m_per_s))
    throw std::invalid_argument("EHL traction: the sliding speed must be finite, got " + numerics::shortest(sliding_speed_m_per_s) + " m/s");
  if (!(eyring_stress_Pa > 0.0))
    throw std::invalid_argument("EHL traction: the Eyring stress must be positive (infinite for a Newtonian film), got " +
                                numerics::shortest(eyring_stress_Pa) + " Pa");
  if (!(load > 0.0) || !std::isfinite(load))
    throw std::invalid_argument(std::string("EHL traction: the ") + load_name + " must be positive, got " + numerics::shortest(load));
  if (!(heating.thermal_conductivity_W_per_m_K >= 0.0) || !std::isfinite(heating.thermal_conductivity_W_per_m_K) ||
      !(heating.temperature_viscosity_per_K >= 0.0) || !std::isfinite(heating.temperature_viscosity_per_K))
    throw std::invalid_argument("EHL traction: the film's thermal conductivity and temperature-viscosity coefficient must be finite and >= 0, got " +
                                numerics::shortest(heating.thermal_conductivity_W_per_m_K) + " W/(m K) and " +
                                numerics::shortest(heating.temperature_viscosity_per_K) + " 1/K");
}

// The pressure at and below which a node counts as cavitated: 1e-9 of the peak, the EHL solvers'
// default tolerance on P in units of p_H. Their pressures in the cavitated zone are 0 only to
// round-off (±1e-11 Pa at 41², 10 N), and the sign of such a value must not decide whether the
// node's film shears — it moved μ by 5e-6 between two LU implementations.
double cavitation_floor_Pa(const std::vector<double>& pressure_Pa) {
  double peak = 0.0;
  for (double p : pressure_Pa) peak = std::max(peak, p);
  return 1e-9 * peak;
}

// τ at one node of pressure p and film h (0 where the film is cavitated, p ≤ floor), its sign Δu's;
// where() names the node in the error (formatted only then).
template <class Where>
double node_stress_Pa(const PiezoviscousLubricant& lubricant, double p, double floor_Pa, double h, double du, double tau0,
                      const FilmHeating& heating, double* rise_K, const Where& where) {
  *rise_K = 0.0;
  if (!(p > floor_Pa)) return 0.0;  // cavitated (or at the domain's edge)
  if (!(h > 0.0)) throw std::invalid_argument("EHL traction: non-positive film " + numerics::shortest(h) + " m at " + where());
  const double eta = lubricant.viscosity_Pa_s * viscosity_ratio(lubricant, p).ratio;
  return (du < 0.0 ? -1.0 : 1.0) * shear_stress_Pa(eta, std::abs(du), h, tau0, heating, rise_K);
}

}  // namespace

EhlTraction ehl_line_traction(const EhlLineResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                              double eyring_stress_Pa, double load_per_length_N_per_m, const FilmHeating& heating) {
  check_traction_inputs(lubricant, sliding_speed_m_per_s, eyring_stress_Pa, load_per_length_N_per_m, "load per length (N/m)", heating);
  const std::size_t n = film.x_m.size();
  if (n < 2 || film.pressure_Pa.size() != n || film.film_m.size() != n)
    throw std::invalid_argument("EHL traction: the film needs at least two nodes with x, pressure and film thickness each");
  EhlTraction out;
  std::vector<double> tau(n, 0.0);
  const double floor_Pa = cavitation_floor_Pa(film.pressure_Pa);
  for (std::size_t i = 0; i < n; ++i) {
    double rise_K = 0.0;
    tau[i] = node_stress_Pa(lubricant, film.pressure_Pa[i], floor_Pa, film.film_m[i], sliding_speed_m_per_s, eyring_stress_Pa, heating,
                            &rise_K, [&] { return "x = " + numerics::shortest(film.x_m[i]) + " m"; });
    out.max_shear_stress_Pa = std::max(out.max_shear_stress_Pa, std::abs(tau[i]));
    out.max_film_temperature_rise_K = std::max(out.max_film_temperature_rise_K, rise_K);
  }
  for (std::size_t i = 1; i < n; ++i) out.force_per_length_N_per_m += 0.5 * (tau[i] + tau[i - 1]) * (film.x_m[i] - film.x_m[i - 1]);
  out.friction_coefficient = out.force_per_length_N_per_m / load_per_length_N_per_m;
  return out;
}

EhlPointTraction ehl_point_traction(const EhlPointResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                                    double eyring_stress_Pa, double load_N, const FilmHeating& heating) {
  check_traction_inputs(lubricant, sliding_speed_m_per_s, eyring_stress_Pa, load_N, "load (N)", heating);
  const std::size_t nx = film.x_m.size(), ny = film.y_m.size();
  if (nx < 2 || ny < 2 || film.pressure_Pa.size() != nx * ny || film.film_m.size() != nx * ny)
    throw std::invalid_argument("EHL traction: the point contact's pressure and film need nx × ny = " + std::to_string(nx * ny) +
                                " values each, got " + std::to_string(film.pressure_Pa.size()) + " and " + std::to_string(film.film_m.size()));
  const double cell = (film.x_m[1] - film.x_m[0]) * (film.y_m[1] - film.y_m[0]);
  EhlPointTraction out;
  const double floor_Pa = cavitation_floor_Pa(film.pressure_Pa);
  for (std::size_t j = 0; j < ny; ++j)
    for (std::size_t i = 0; i < nx; ++i) {
      double rise_K = 0.0;
      const std::size_t k = i + nx * j;
      const double tau = node_stress_Pa(lubricant, film.pressure_Pa[k], floor_Pa, film.film_m[k], sliding_speed_m_per_s, eyring_stress_Pa,
                                        heating, &rise_K, [&] {
                                          return "x = " + numerics::shortest(film.x_m[i]) + " m, y = " + numerics::shortest(film.y_m[j]) + " m";
                                        });
      out.force_N += tau * cell;
      out.max_shear_stress_Pa = std::max(out.max_shear_stress_Pa, std::abs(tau));
      out.max_film_temperature_rise_K = std::max(out.max_film_temperature_rise_K, rise_K);
    }
  out.friction_coefficient = out.force_N / load_N;
  return out;
}

}  // namespace tribo::lubrication
