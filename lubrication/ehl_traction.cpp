#include "lubrication/ehl_traction.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "numerics/format.h"

namespace tribo::lubrication {

namespace {

// The shear stress at one node: τ = min(τ0 asinh(η e^{−γΔT(τ)} Δu/(τ0 h)), τ_L) for Δu ≥ 0 (the
// caller carries the sign), ΔT(τ) = film_rise(τ) the film's mean temperature rise, which grows
// with τ (Walls below), τ_L = limit_Pa e^{−β ΔT} (limit_Pa +∞: no limit; β = limit_beta). No
// heating when `heated` is false; the isothermal stress (with the rise it makes) when γ = β = 0.
// *limited tells whether the limit is the smaller at the stress found.
template <class FilmRise>
double shear_stress_Pa(double viscosity_Pa_s, double du, double h, double tau0, double limit_Pa, double limit_beta, bool heated,
                       double gamma, const FilmRise& film_rise, double* rise_K, bool* limited) {
  const bool newtonian = std::isinf(tau0);
  const auto eyring_at = [&](double temperature_rise_K) {
    const double newtonian_stress = viscosity_Pa_s * std::exp(-gamma * temperature_rise_K) * du / h;
    return newtonian ? newtonian_stress : tau0 * std::asinh(newtonian_stress / tau0);
  };
  const auto limit_at = [&](double temperature_rise_K) {
    return limit_beta == 0.0 ? limit_Pa : limit_Pa * std::exp(-limit_beta * temperature_rise_K);
  };
  const auto stress_at = [&](double temperature_rise_K) { return std::min(eyring_at(temperature_rise_K), limit_at(temperature_rise_K)); };
  const auto found = [&](double tau, double temperature_rise_K) {
    *rise_K = temperature_rise_K;
    *limited = du > 0.0 && eyring_at(temperature_rise_K) >= limit_at(temperature_rise_K);
    return tau;
  };
  if (!heated) return found(stress_at(0.0), 0.0);
  // The stress cannot exceed the one at the rise the walls alone make (τ = 0).
  const double ceiling = stress_at(film_rise(0.0));
  // The film heats, but neither its viscosity nor its limit follows.
  if ((gamma == 0.0 && limit_beta == 0.0) || ceiling == 0.0) return found(ceiling, film_rise(ceiling));
  // At a limit that does not follow the temperature, when the film is still above it at the heat
  // the limit makes: τ_L exactly (the bisection would end a few ulps short of it).
  if (limit_beta == 0.0 && ceiling == limit_Pa && stress_at(film_rise(limit_Pa)) == limit_Pa) return found(limit_Pa, film_rise(limit_Pa));
  // g(τ) = τ − stress_at(ΔT(τ)) rises from −ceiling at 0 to ≥ 0 at the ceiling (the limit does
  // not change that: both the Eyring stress and the limit fall as the film warms, and so does
  // their minimum): bisection to the last bit (each step halves the bracket; 200 steps are far
  // more than 53 bits need).
  double lo = 0.0, hi = ceiling;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (mid - stress_at(film_rise(mid)) < 0.0 ? lo : hi) = mid;
  }
  const double tau = 0.5 * (lo + hi);
  return found(tau, film_rise(tau));
}

// The solid of the surface moving at u2 (FilmHeating::second_surface, else the first's).
const HeatedSolid& second_solid(const FilmHeating& heat) { return heat.second_surface ? *heat.second_surface : *heat.surfaces; }

// The surfaces' speeds u1,2 = u_m ± Δu/2.
struct SurfaceSpeeds {
  double u1, u2;
};
SurfaceSpeeds surface_speeds(const FilmHeating& heat, double sliding_speed_m_per_s) {
  return {heat.mean_speed_m_per_s + 0.5 * sliding_speed_m_per_s, heat.mean_speed_m_per_s - 0.5 * sliding_speed_m_per_s};
}

// The two walls of one line of nodes along x (the header's partition): their flash temperatures
// from the heat handed to them at and upstream of each node; at the bulk temperature without
// FilmHeating::surfaces. Nodes are visited in increasing x: prepare(i), then settle(i, …) once τ
// is known.
class Walls {
 public:
  Walls(const std::vector<double>& x_m, double sliding_speed_m_per_s, const FilmHeating& heat)
      : x_m_(x_m), heat_(heat), k_(heat.thermal_conductivity_W_per_m_K) {
    if (!heat.surfaces) return;
    const SurfaceSpeeds u = surface_speeds(heat, sliding_speed_m_per_s);
    first_.emplace(x_m, u.u1, *heat.surfaces);
    second_.emplace(x_m, u.u2, second_solid(heat));
    q1_.assign(x_m.size(), 0.0), q2_.assign(x_m.size(), 0.0);
  }
  // Start the line of nodes at y (0 for a line contact: `point` false), with its interface heat.
  void new_line(bool point, double y_m) {
    if (!first_) return;
    std::fill(q1_.begin(), q1_.end(), 0.0);
    std::fill(q2_.begin(), q2_.end(), 0.0);
    interface_.assign(x_m_.size(), 0.0);
    const double r = heat_.interface_heat_half_width_m;
    for (std::size_t i = 0; i < x_m_.size(); ++i)
      if ((point ? x_m_[i] * x_m_[i] + y_m * y_m <= r * r : std::abs(x_m_[i]) <= r)) interface_[i] = heat_.interface_heat_W_per_m2;
  }
  void prepare(std::size_t i) {
    if (!first_) return;
    a1_ = first_->upstream_rise_K(i, q1_.data()), a2_ = second_->upstream_rise_K(i, q2_.data());
    s1_ = first_->own_weight(i), s2_ = second_->own_weight(i);
    extra_ = interface_[i];
  }
  // The film's mean temperature rise at the prepared node for the heat Q = |τΔu| (W/m²) it makes in a film h.
  double film_rise_K(double heat_W_per_m2, double h) const {
    const Split w = split(heat_W_per_m2, h);
    return 0.5 * (w.t1 + w.t2) + heat_W_per_m2 * h / (12.0 * k_);
  }
  // Keep the prepared node's heat. Where the film does not shear (heat 0, h ignored) it does not
  // conduct either: the interface heat there enters each surface half and half.
  void settle(std::size_t i, double heat_W_per_m2, double h) {
    if (!first_) return;
    const double half = 0.5 * extra_;
    const Split w = heat_W_per_m2 > 0.0 ? split(heat_W_per_m2, h) : Split{a1_ + s1_ * half, a2_ + s2_ * half, half, half};
    q1_[i] = w.q1, q2_[i] = w.q2;
    max_rise_K_ = std::max({max_rise_K_, w.t1, w.t2});
  }
  double max_surface_rise_K() const { return max_rise_K_; }

 private:
  struct Split {
    double t1, t2, q1, q2;
  };
  // With Q the film's heat plus the interface's, wall 1 takes q1 = Q/2 + c D, wall 2 q2 = Q − q1,
  // with c = k/h and D = T2 − T1, T_i = a_i + s_i q_i: D (1 + c (s1 + s2)) = a2 − a1 + (s2 − s1) Q/2.
  Split split(double heat, double h) const {
    if (!first_) return {0.0, 0.0, 0.5 * heat, 0.5 * heat};
    const double c = k_ / h, total = heat + extra_;
    const double d = (a2_ - a1_ + (s2_ - s1_) * 0.5 * total) / (1.0 + c * (s1_ + s2_));
    const double q1 = 0.5 * total + c * d, q2 = total - q1;
    return {a1_ + s1_ * q1, a2_ + s2_ * q2, q1, q2};
  }
  const std::vector<double>& x_m_;
  const FilmHeating& heat_;
  double k_;
  std::optional<MovingSurface> first_, second_;
  std::vector<double> q1_, q2_, interface_;
  double a1_ = 0.0, a2_ = 0.0, s1_ = 0.0, s2_ = 0.0, extra_ = 0.0, max_rise_K_ = 0.0;
};

// The smaller of the two surfaces' Péclet numbers over the half-length of the sheared zone [x_lo, x_hi].
double surface_peclet(const FilmHeating& heat, double sliding_speed_m_per_s, double x_lo, double x_hi) {
  if (!heat.surfaces || !(x_hi > x_lo)) return 0.0;
  const double l = 0.5 * (x_hi - x_lo);
  const SurfaceSpeeds u = surface_speeds(heat, sliding_speed_m_per_s);
  return std::min(peclet_number(*heat.surfaces, u.u1, l), peclet_number(second_solid(heat), u.u2, l));
}

// The inputs both tractions check; `load` in the unit of `load_unit`.
void check_traction_inputs(const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s, double eyring_stress_Pa, double load,
                           const char* load_name, const FilmHeating& heating, const LimitingShear& limit) {
  validate(lubricant);
  validate(limit, "EHL traction");
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
  if (!(heating.interface_heat_W_per_m2 >= 0.0) || !std::isfinite(heating.interface_heat_W_per_m2) ||
      !(heating.interface_heat_half_width_m >= 0.0) || !std::isfinite(heating.interface_heat_half_width_m))
    throw std::invalid_argument("EHL traction: the interface heat and its half-width must be finite and >= 0, got " +
                                numerics::shortest(heating.interface_heat_W_per_m2) + " W/m2 over " +
                                numerics::shortest(heating.interface_heat_half_width_m) + " m");
  if (heating.second_surface && !heating.surfaces)
    throw std::invalid_argument("EHL traction: a second surface's solid without the first's (FilmHeating::surfaces)");
  if (heating.surfaces) {
    if (!(heating.thermal_conductivity_W_per_m_K > 0.0))
      throw std::invalid_argument("EHL traction: the surfaces' heating needs the film's thermal conductivity (the heat reaches them through it)");
    validate(*heating.surfaces);
    if (heating.second_surface) validate(*heating.second_surface);
    if (!(std::abs(sliding_speed_m_per_s) < 2.0 * heating.mean_speed_m_per_s))
      throw std::invalid_argument("EHL traction: the surfaces' heating needs both surfaces moving through the contact, |sliding speed| < 2 × mean speed; got " +
                                  numerics::shortest(sliding_speed_m_per_s) + " and " + numerics::shortest(heating.mean_speed_m_per_s) +
                                  " m/s (a surface at rest sees a stationary heat source, outside the fast-source model)");
  }
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
// the node's heat is handed to `walls` (prepared for this node); *limited tells whether τ is at
// the limit. where() names the node in the error (formatted only then).
template <class Where>
double node_stress_Pa(const PiezoviscousLubricant& lubricant, double p, double floor_Pa, double h, double du, double tau0,
                      const LimitingShear& limit, const FilmHeating& heating, Walls& walls, std::size_t node, double* rise_K,
                      bool* limited, const Where& where) {
  *rise_K = 0.0;
  *limited = false;
  if (!(p > floor_Pa)) {  // cavitated (or at the domain's edge)
    walls.settle(node, 0.0, h);
    return 0.0;
  }
  if (!(h > 0.0)) throw std::invalid_argument("EHL traction: non-positive film " + numerics::shortest(h) + " m at " + where());
  const double eta = lubricant.viscosity_Pa_s * viscosity_ratio(lubricant, p).ratio, speed = std::abs(du);
  const double tau = shear_stress_Pa(eta, speed, h, tau0, limit.at(p), limit.temperature_coefficient_per_K,
                                     heating.thermal_conductivity_W_per_m_K > 0.0, heating.temperature_viscosity_per_K,
                                     [&](double t) { return walls.film_rise_K(t * speed, h); }, rise_K, limited);
  walls.settle(node, tau * speed, h);
  return du < 0.0 ? -tau : tau;
}

// The nodes whose film shears (p above the floor): their x-range, for the surfaces' Péclet number,
// and how many of them are at the limiting shear stress.
struct ShearedRange {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  long nodes = 0, limited = 0;
  void add(double x, bool at_limit) { lo = std::min(lo, x), hi = std::max(hi, x), ++nodes, limited += at_limit ? 1 : 0; }
  double limited_share() const { return nodes > 0 ? static_cast<double>(limited) / static_cast<double>(nodes) : 0.0; }
};

}  // namespace

EhlTraction ehl_line_traction(const EhlLineResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                              double eyring_stress_Pa, double load_per_length_N_per_m, const FilmHeating& heating,
                              const LimitingShear& limit) {
  check_traction_inputs(lubricant, sliding_speed_m_per_s, eyring_stress_Pa, load_per_length_N_per_m, "load per length (N/m)", heating, limit);
  const std::size_t n = film.x_m.size();
  if (n < 2 || film.pressure_Pa.size() != n || film.film_m.size() != n)
    throw std::invalid_argument("EHL traction: the film needs at least two nodes with x, pressure and film thickness each");
  EhlTraction out;
  std::vector<double> tau(n, 0.0);
  const double floor_Pa = cavitation_floor_Pa(film.pressure_Pa);
  Walls walls(film.x_m, sliding_speed_m_per_s, heating);
  walls.new_line(false, 0.0);
  ShearedRange sheared;
  for (std::size_t i = 0; i < n; ++i) {
    double rise_K = 0.0;
    bool limited = false;
    walls.prepare(i);
    tau[i] = node_stress_Pa(lubricant, film.pressure_Pa[i], floor_Pa, film.film_m[i], sliding_speed_m_per_s, eyring_stress_Pa, limit, heating,
                            walls, i, &rise_K, &limited, [&] { return "x = " + numerics::shortest(film.x_m[i]) + " m"; });
    if (film.pressure_Pa[i] > floor_Pa) sheared.add(film.x_m[i], limited);
    out.max_shear_stress_Pa = std::max(out.max_shear_stress_Pa, std::abs(tau[i]));
    out.max_film_temperature_rise_K = std::max(out.max_film_temperature_rise_K, rise_K);
  }
  for (std::size_t i = 1; i < n; ++i) out.force_per_length_N_per_m += 0.5 * (tau[i] + tau[i - 1]) * (film.x_m[i] - film.x_m[i - 1]);
  out.friction_coefficient = out.force_per_length_N_per_m / load_per_length_N_per_m;
  out.max_surface_temperature_rise_K = walls.max_surface_rise_K();
  out.surface_peclet_number = surface_peclet(heating, sliding_speed_m_per_s, sheared.lo, sheared.hi);
  out.limited_node_share = sheared.limited_share();
  return out;
}

EhlPointTraction ehl_point_traction(const EhlPointResult& film, const PiezoviscousLubricant& lubricant, double sliding_speed_m_per_s,
                                    double eyring_stress_Pa, double load_N, const FilmHeating& heating, const LimitingShear& limit) {
  check_traction_inputs(lubricant, sliding_speed_m_per_s, eyring_stress_Pa, load_N, "load (N)", heating, limit);
  const std::size_t nx = film.x_m.size(), ny = film.y_m.size();
  if (nx < 2 || ny < 2 || film.pressure_Pa.size() != nx * ny || film.film_m.size() != nx * ny)
    throw std::invalid_argument("EHL traction: the point contact's pressure and film need nx × ny = " + std::to_string(nx * ny) +
                                " values each, got " + std::to_string(film.pressure_Pa.size()) + " and " + std::to_string(film.film_m.size()));
  const double cell = (film.x_m[1] - film.x_m[0]) * (film.y_m[1] - film.y_m[0]);
  EhlPointTraction out;
  const double floor_Pa = cavitation_floor_Pa(film.pressure_Pa);
  Walls walls(film.x_m, sliding_speed_m_per_s, heating);  // each line of nodes along x in turn
  ShearedRange sheared;
  for (std::size_t j = 0; j < ny; ++j) {
    walls.new_line(true, film.y_m[j]);
    for (std::size_t i = 0; i < nx; ++i) {
      double rise_K = 0.0;
      bool limited = false;
      const std::size_t k = i + nx * j;
      walls.prepare(i);
      const double tau = node_stress_Pa(lubricant, film.pressure_Pa[k], floor_Pa, film.film_m[k], sliding_speed_m_per_s, eyring_stress_Pa,
                                        limit, heating, walls, i, &rise_K, &limited, [&] {
                                          return "x = " + numerics::shortest(film.x_m[i]) + " m, y = " + numerics::shortest(film.y_m[j]) + " m";
                                        });
      if (film.pressure_Pa[k] > floor_Pa) sheared.add(film.x_m[i], limited);
      out.force_N += tau * cell;
      out.max_shear_stress_Pa = std::max(out.max_shear_stress_Pa, std::abs(tau));
      out.max_film_temperature_rise_K = std::max(out.max_film_temperature_rise_K, rise_K);
    }
  }
  out.friction_coefficient = out.force_N / load_N;
  out.max_surface_temperature_rise_K = walls.max_surface_rise_K();
  out.surface_peclet_number = surface_peclet(heating, sliding_speed_m_per_s, sheared.lo, sheared.hi);
  out.limited_node_share = sheared.limited_share();
  return out;
}

}  // namespace tribo::lubrication
