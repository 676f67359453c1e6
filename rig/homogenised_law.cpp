#include "rig/homogenised_law.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "contact/junction_locus.h"
#include "rig/internal/exact_decimal.h"

namespace tribo::rig {
namespace {

const LawTable& validated(const LawTable& t) {
  validate(t);
  return t;
}

}  // namespace

HomogenisedBase::HomogenisedBase(LawTable table, double normal_load_N)
    : table_(std::move(table)),
      normal_load_N_(normal_load_N),
      solid_load_(validated(table_).separation_m, table_.solid_load_N, "separation_m"),
      real_area_(table_.separation_m, table_.real_area_m2, "separation_m"),
      lift_(table_.separation_m, table_.lift_per_eta_u_m, "separation_m"),
      squeeze_(table_.separation_m, table_.squeeze_per_eta_m, "separation_m"),
      shear_(table_.separation_m, table_.shear_per_eta_u_m, "separation_m") {
  const double n_front = table_.solid_load_N.front();
  if (!std::isfinite(normal_load_N) || !(normal_load_N > 0.0) || normal_load_N > n_front) {
    throw std::invalid_argument("normal_load_N = " + internal::exact_decimal(normal_load_N) + " N lies outside the law table's solid-load range (0, " +
                                internal::exact_decimal(n_front) + "] N (" + (table_.source.empty() ? std::string("table") : table_.source) +
                                ": table.solid_load_N); the film's equilibrium N_s(h) = W must lie inside the table");
  }
  if (!table_.eta_u_Pa_m.empty()) solid_shear_.emplace(table_.separation_m, table_.eta_u_Pa_m, table_.solid_shear_Pa);
  if (!table_.film_share.empty()) film_share_.emplace(table_.separation_m, table_.eta_u_Pa_m, table_.film_share);
  if (table_.has_ball_film()) {
    const double solved = table_.pin.normal_load_N;
    if (!(std::abs(normal_load_N - solved) <= 1e-9 * solved))
      throw std::invalid_argument("normal_load_N = " + internal::exact_decimal(normal_load_N) + " N differs from the load the ball's film was solved at, " +
                                  internal::exact_decimal(solved) + " N (" + (table_.source.empty() ? std::string("table") : table_.source) +
                                  ": pin.normal_load_N): its Hertz circle and film shares are that load's; homogenise again at this load");
    ball_.emplace(table_.ball_share, table_.eta_u_Pa_m, table_.ball_central_film_m, table_.ball_traction_N, solved);
  }
  lubricant_.viscosity_Pa_s = table_.lubricant.viscosity_Pa_s;
  lubricant_.pressure_viscosity_per_Pa = 0.0;  // ambient pressure: the rig's film is not EHL
  lubricant_.temperature_viscosity_per_K = table_.lubricant.temperature_viscosity_per_K;
  lubricant_.reference_temperature_K = table_.lubricant.reference_temperature_K;
  jaeger_.slider_conductivity_W_per_m_K = table_.thermal.slider_conductivity_W_per_m_K;
  jaeger_.disc_conductivity_W_per_m_K = table_.thermal.disc_conductivity_W_per_m_K;
  jaeger_.slider_diffusivity_m2_per_s = table_.thermal.slider_diffusivity_m2_per_s;
  h0_m_ = balanced_separation_m(0.0);
}

double HomogenisedBase::balanced_separation_m(double eta_u_Pa_m) const {
  const auto carried = [&](double h) { return solid_load_N(h) + fluid_load_N(h, eta_u_Pa_m); };
  double lo = table_.separation_m.front(), hi = table_.separation_m.back();
  if (carried(lo) <= normal_load_N_) return lo;  // W = N_s(front) at rest
  if (carried(hi) > normal_load_N_)
    throw std::out_of_range("film balance at eta U = " + internal::exact_decimal(eta_u_Pa_m) +
                            " Pa m: the lift carries the load above the table's largest separation " +
                            internal::exact_decimal(hi) + " m; extend the table towards full film");
  // Bisection to the last representable bit: the bracket keeps carried(lo) ≥ W > carried(hi).
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (carried(mid) >= normal_load_N_ ? lo : hi) = mid;
  }
  // Of the two bracketing neighbours take the one whose load is nearer W.
  return std::abs(carried(lo) - normal_load_N_) <= std::abs(carried(hi) - normal_load_N_) ? lo : hi;
}

double HomogenisedBase::fluid_load_N(double h, double eta_u) const {
  return eta_u * lift_per_eta_u_m(h) + (ball_ ? ball_->at(h, eta_u).load_N : 0.0);
}

double HomogenisedBase::fluid_shear_N(double h, double eta_u) const {
  return eta_u * shear_per_eta_u_m(h) + (ball_ ? ball_->at(h, eta_u).shear_N : 0.0);
}

void HomogenisedBase::initial_state(std::span<double> state) const {
  state[kSeparation] = h0_m_;
  state[kTemperatureRise] = 0.0;
}

void HomogenisedBase::state_tolerances(std::span<double> atol) const {
  atol[kSeparation] = 1e-6 * table_.separation_m.front();
  atol[kTemperatureRise] = 1e-6;
}

double HomogenisedBase::viscosity_Pa_s(double temperature_rise_K) const {
  if (lubricant_.viscosity_Pa_s == 0.0) return 0.0;  // dry table (lubrication::validate rejects η0 = 0)
  return lubrication::viscosity_Pa_s(lubricant_, 0.0, lubricant_.reference_temperature_K + temperature_rise_K);
}

double HomogenisedBase::static_coefficient(const FrictionContext& c) const {
  return contact::static_friction_from_load_rate(table_.junction.locus, c.tangential_load_rate_per_s);
}

double HomogenisedBase::solid_shear_Pa(double h, double eta_u) const {
  return solid_shear_ ? solid_shear_->value(h, eta_u) : table_.junction.interface_shear_strength_Pa;
}

double HomogenisedBase::film_share(double h, double eta_u) const { return film_share_ ? film_share_->value(h, eta_u) : 0.0; }

double HomogenisedBase::solid_kinetic_coefficient(std::span<const double> state, double u) const {
  const double h = state[kSeparation], n_s = solid_load_N(h);
  const double eta_u = viscosity_Pa_s(state[kTemperatureRise]) * std::abs(u);
  return n_s > 0.0 ? solid_shear_Pa(h, eta_u) * real_area_m2(h) / n_s : 0.0;
}

double HomogenisedBase::static_limit_N(const FrictionContext& c, double solid_fraction, double static_increment) const {
  return solid_fraction * (static_coefficient(c) + static_increment) * solid_load_N(c.state[kSeparation]);
}

double HomogenisedBase::kinetic_force_N(const FrictionContext& c, double solid_fraction, double kinetic_increment,
                                        double fluid_force_N) const {
  const double h = c.state[kSeparation];
  const double eta = viscosity_Pa_s(c.state[kTemperatureRise]);
  const double solid = solid_shear_Pa(h, eta * std::abs(c.relative_speed_m_per_s)) * real_area_m2(h) + kinetic_increment * solid_load_N(h);
  const double u = c.relative_speed_m_per_s;
  const double viscous = u < 0.0 ? -fluid_shear_N(h, -eta * u) : fluid_shear_N(h, eta * u);
  return solid_fraction * solid + viscous + fluid_force_N;
}

double HomogenisedBase::separation_rate_m_per_s(double h, double dT, double u, double load_N) const {
  const double eta = viscosity_Pa_s(dT);
  if (eta == 0.0) return 0.0;  // dry: the algebraic limit N_s(h̄) = W, h̄ = h̄0
  const double fluid = eta * u * lift_per_eta_u_m(h) + (ball_ ? ball_->at(h, eta * std::abs(u)).load_N : 0.0);
  return (solid_load_N(h) + fluid - load_N) / (eta * squeeze_per_eta_m(h));
}

double HomogenisedBase::jaeger_temperature_rise_K(double power_W, double h, double u) const {
  // A ball's friction heat — its film's shear and its asperities' — is made over its Hertz circle,
  // and its film's viscosity is the inlet's, at the surfaces' mean temperature there.
  const double area = ball_ ? table_.pin.nominal_area_m2 : std::max(real_area_m2(h), kJaegerAreaFloorFraction * table_.pin.nominal_area_m2);
  return lubrication::jaeger_flash_temperature_rise_K(jaeger_, power_W, area, u);
}

double HomogenisedBase::film_relaxation_time_s(double h, double dT, double u) const {
  const double eta = viscosity_Pa_s(dT);
  const double eta_u = eta * std::abs(u);
  const double stiffness = -(solid_load_slope_N_per_m(h) + eta_u * lift_.slope(h) + (ball_ ? ball_->at(h, eta_u).load_slope_N_per_m : 0.0));
  const double damping = eta * squeeze_per_eta_m(h);
  if (damping == 0.0) return 0.0;
  return stiffness > 0.0 ? damping / stiffness : std::numeric_limits<double>::infinity();
}

void HomogenisedBase::state_rates(const FrictionContext& c, double kinetic_force_N, std::span<double> rates) const {
  const double h = c.state[kSeparation], dT = c.state[kTemperatureRise], u = c.relative_speed_m_per_s;
  rates[kSeparation] = separation_rate_m_per_s(h, dT, u, c.normal_load_N);
  const double power_W = kinetic_force_N * u;
  rates[kTemperatureRise] = (jaeger_temperature_rise_K(power_W, h, u) - dT) / table_.thermal.time_constant_s;
}

std::shared_ptr<const HomogenisedBase> load_homogenised_base(const std::filesystem::path& path, double normal_load_N) {
  return std::make_shared<const HomogenisedBase>(read_law_table(path), normal_load_N);
}

HomogenisedLaw::HomogenisedLaw(std::shared_ptr<const HomogenisedBase> base) : base_(std::move(base)) {
  if (!base_) throw std::invalid_argument("homogenised law: no table");
}

void HomogenisedLaw::state_rates(const FrictionContext& c, std::span<double> rates) const {
  const double fk = c.relative_speed_m_per_s > 0.0 ? kinetic_force_N(c) : 0.0;
  base_->state_rates(c, fk, rates);
}

}  // namespace tribo::rig
