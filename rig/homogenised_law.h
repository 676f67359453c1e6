// The homogenised friction law (DESIGN §4): the pin's mixed-lubrication state integrated from the
// tables of law.json (rig/law_table.h). State [h̄ (m), ΔT (K)]: the mean separation of the pin face
// and the film's temperature rise above the lubricant's reference temperature T0.
//
//   viscosity            η(ΔT) = η0 exp(−γ ΔT)                 (lubrication/viscosity.h at p = 0)
//   load balance         W = N_s(h̄) + η|U| L(h̄) − η K(h̄) dh̄/dt  (solid + lift + squeeze, DESIGN §4)
//     ⇒  dh̄/dt = [N_s(h̄) + η|U| L(h̄) − W] / (η K(h̄));   η = 0 (dry): dh̄/dt = 0, h̄ stays at h̄0
//     a ball's table adds its EHL film's load W_f(h̄, η|U|) to the lift (law_table.h)
//   initial film         N_s(h̄0) = W, ΔT0 = 0                  (the slider starts at rest, unheated)
//   kinetic force        F_k = τ̄ A_r(h̄) + η(ΔT)|U| S(h̄)      (boundary shear + viscous shear)
//     + a ball's EHL traction F_f(h̄, η|U|), in the direction of U
//     τ̄ = τ_i ("tribo-law-1"), or τ̄(h̄, η(ΔT)|U|) of the asperity tops' EHL films ("tribo-law-2",
//     lubrication/micro_ehl.h): the flash temperature thins those films through η(ΔT)
//   static limit         F_s = μs(φ̇) N_s(h̄)                    (junction locus, thesis (3.1.24); re-attach alike)
//   flash temperature    thesis (5.2.1) in SI (Jaeger; the gravity g and heat-work J constants drop):
//       ΔT_J = P b / (1.9 √A [1.1 ξ2 b + 0.7 ξ1 A^{1/4} √|U|]),   P = F_k |U|,  b = √(κ_slider)
//     with ξ1, ξ2 the slider's and disc's conductivities, κ the slider's diffusivity and
//     A = max(A_r(h̄), 1e-5 · A_nominal): Jaeger's heat source is the solid contact; when the contact
//     vanishes the floor keeps the film's shear heat on a finite path instead of ΔT_J → ∞ as A → 0.
//     A ball's table: A = its Hertz circle (pin.nominal_area_m2) — film and asperities heat it
//     together, and the EHL film's viscosity is its inlet's, at the surfaces' mean temperature.
//       dΔT/dt = (ΔT_J − ΔT) / t_T                              (t_T = thermal.time_constant_s)
//     While stuck |U| = 0, P = 0 and ΔT relaxes to 0.
//
// Film stiffness: near a balanced h̄ the load balance relaxes with the time constant
// t_h = η K / −d(N_s + η|U| L)/dh̄ (film_relaxation_time_s), over the slip distance |U| t_h; the rig integrator (CVODE Adams) is efficient only while t_h is not
// far below the rig period 2π/ω_n ≈ 0.06 s.
//
// Effects of the catalogue compose on top of this base in CompositeLaw (rig/effect.h channels, with
// N_s(h̄) in place of W):  F_static = χ (μs + Σ Δμs,e) N_s,  F_k = χ (τ_i A_r + Σ Δμ_e N_s) + η|U| S + Σ F_fluid,e.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "lubrication/viscosity.h"
#include "rig/ball_film.h"
#include "rig/friction_law.h"
#include "rig/law_table.h"

namespace tribo::rig {

// The tables and constants of one law.json at one rig load, and the physics of the two-variable
// state. Immutable: share one between laws and threads.
class HomogenisedBase {
 public:
  static constexpr std::size_t kStateSize = 2;
  static constexpr std::size_t kSeparation = 0;      // h̄ (m)
  static constexpr std::size_t kTemperatureRise = 1; // ΔT (K)
  // Jaeger's heat-path area never falls below this share of the pin's nominal area.
  static constexpr double kJaegerAreaFloorFraction = 1e-5;

  // Validates the table. Throws std::invalid_argument naming normal_load_N unless
  // 0 < normal_load_N ≤ N_s(separation_m.front()) (the film's equilibrium must lie in the table),
  // and, for a ball's table, unless normal_load_N is the load it was solved at (pin.normal_load_N,
  // to 1e-9 of it).
  HomogenisedBase(LawTable table, double normal_load_N);

  const LawTable& table() const { return table_; }
  double normal_load_N() const { return normal_load_N_; }
  double initial_separation_m() const { return h0_m_; }   // N_s(h̄0) = W

  // The steady film: h̄ with N_s(h̄) + ηU L(h̄) = W (ηU = 0: the film at rest, h̄0), by bisection to the
  // last bit. Throws std::out_of_range when the lift carries W above the table's largest separation.
  double balanced_separation_m(double eta_u_Pa_m) const;

  void initial_state(std::span<double> state) const;      // [h̄0, 0]
  void state_tolerances(std::span<double> atol) const;    // [1e-6 h̄_front, 1e-6 K]

  // Table columns at h̄ (std::out_of_range outside the table: never extrapolated).
  double solid_load_N(double h_m) const { return solid_load_.value(h_m); }
  double solid_load_slope_N_per_m(double h_m) const { return solid_load_.slope(h_m); }
  double real_area_m2(double h_m) const { return real_area_.value(h_m); }
  double lift_per_eta_u_m(double h_m) const { return lift_.value(h_m); }
  double squeeze_per_eta_m(double h_m) const { return squeeze_.value(h_m); }
  double shear_per_eta_u_m(double h_m) const { return shear_.value(h_m); }
  // The film's load at h̄ and ηU ≥ 0: ηU L(h̄), plus a ball's EHL film W_f(h̄, ηU).
  double fluid_load_N(double h_m, double eta_u_Pa_m) const;
  // The film's shear force at h̄ and ηU ≥ 0: ηU S(h̄), plus a ball's EHL traction F_f(h̄, ηU).
  double fluid_shear_N(double h_m, double eta_u_Pa_m) const;

  // η(ΔT) = η0 exp(−γ ΔT); 0 for a dry table (η0 = 0).
  double viscosity_Pa_s(double temperature_rise_K) const;
  // μs at the context's load rate from the table's junction locus, thesis (3.1.24).
  double static_coefficient(const FrictionContext& c) const;
  // τ̄ of the real contact area at h̄ and ηU (τ_i in a "tribo-law-1" table); std::out_of_range
  // outside the table's ηU axis.
  double solid_shear_Pa(double h_m, double eta_u_Pa_m) const;
  // The share of A_r(h̄) the asperity-top films separate at ηU (0 without the column).
  double film_share(double h_m, double eta_u_Pa_m) const;
  // τ̄ A_r(h̄) / N_s(h̄) at the sliding speed: the solid contact's kinetic coefficient (0 once N_s = 0).
  double solid_kinetic_coefficient(std::span<const double> state, double speed_m_per_s) const;

  // Channels with the effects' contributions (χ = 1, no increments, no fluid force for the bare law):
  //   F_static = χ (μs + Δμs) N_s(h̄)
  double static_limit_N(const FrictionContext& c, double solid_fraction, double static_increment) const;
  //   F_k = χ (τ̄ A_r(h̄) + Δμ N_s(h̄)) + η(ΔT)|U| S(h̄) + F_fluid
  double kinetic_force_N(const FrictionContext& c, double solid_fraction, double kinetic_increment,
                         double fluid_force_N) const;

  // dh̄/dt = [N_s + η|U| L − W] / (η K); 0 when η = 0.
  double separation_rate_m_per_s(double h_m, double temperature_rise_K, double speed_m_per_s, double normal_load_N) const;
  // Jaeger's ΔT_J (5.2.1) for friction power P (W) at h̄ and |U|; 0 when P = 0.
  double jaeger_temperature_rise_K(double power_W, double h_m, double speed_m_per_s) const;
  // t_h = η K / −d(N_s + η|U| L)/dh̄ (the linearised film ODE about a balanced h̄); +∞ where the
  // load balance is flat, 0 when dry.
  double film_relaxation_time_s(double h_m, double temperature_rise_K, double speed_m_per_s = 0.0) const;

  // d[h̄, ΔT]/dt given the kinetic force F_k (used for P = F_k |U| while slipping).
  void state_rates(const FrictionContext& c, double kinetic_force_N, std::span<double> rates) const;

 private:
  LawTable table_;
  double normal_load_N_;
  MonotoneTable solid_load_, real_area_, lift_, squeeze_, shear_;
  std::optional<EtaUTable> solid_shear_, film_share_;  // "tribo-law-2" only (the film share optional)
  std::optional<BallFilm> ball_;                       // a ball's EHL film only
  lubrication::Lubricant lubricant_;
  lubrication::JaegerContact jaeger_;
  double h0_m_ = 0.0;
};

// Reads law.json and builds the base for a rig of normal load W (both steps throw
// std::invalid_argument naming the file / normal_load_N).
std::shared_ptr<const HomogenisedBase> load_homogenised_base(const std::filesystem::path& path, double normal_load_N);

// The bare homogenised law, "homogenised": the base with no effects. (With effects, put the base in
// BaselineLaw::homogenised and build a CompositeLaw through make_friction_law; with none, that
// CompositeLaw and this law give identical numbers.)
class HomogenisedLaw final : public FrictionLaw {
 public:
  explicit HomogenisedLaw(std::shared_ptr<const HomogenisedBase> base);

  std::string name() const override { return "homogenised"; }
  std::size_t state_size() const override { return HomogenisedBase::kStateSize; }
  void initial_state(std::span<double> state) const override { base_->initial_state(state); }
  // The film's own scales: h̄ and the temperature act through the tables, not as a μ increment.
  void state_tolerances(std::span<double> atol, double /*mu_tolerance*/) const override { base_->state_tolerances(atol); }
  double static_limit_N(const FrictionContext& c) const override { return base_->static_limit_N(c, 1.0, 0.0); }
  double kinetic_force_N(const FrictionContext& c) const override { return base_->kinetic_force_N(c, 1.0, 0.0, 0.0); }
  void state_rates(const FrictionContext& c, std::span<double> rates) const override;

  const HomogenisedBase& base() const { return *base_; }

 private:
  std::shared_ptr<const HomogenisedBase> base_;
};

}  // namespace tribo::rig
