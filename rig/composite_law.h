// The composite friction law: baseline Coulomb / kinetic curve plus friction effects, combined
// through the fixed channels documented in effect.h (order-independent by construction).
//
// With a homogenised base (BaselineLaw::homogenised, rig/homogenised_law.h) the base's state
// [h̄, ΔT] comes first in the law's state, then the effects' states, and the channels act on the
// solid load N_s(h̄) instead of W:
//   F_static = χ(U = 0) · (μs(φ̇) + Σ static_increment_e) · N_s(h̄)
//   F_k      = χ · (τ_i A_r(h̄) + Σ kinetic_increment_e · N_s(h̄)) + η|U| S(h̄) + Σ fluid_force_e
// The effects see μs(φ̇) of the table's locus and μk = τ_i A_r(h̄)/N_s(h̄).
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "contact/junction_locus.h"
#include "rig/effect.h"
#include "rig/friction_law.h"
#include "rig/friction_model.h"

namespace tribo::rig {

class CompositeLaw final : public FrictionLaw {
 public:
  // `locus` replaces the constant μs when a static-friction effect is present.
  CompositeLaw(BaselineLaw baseline, std::optional<contact::JunctionLocus> locus,
               std::vector<std::unique_ptr<FrictionEffect>> effects);

  std::string name() const override;
  std::size_t state_size() const override { return state_size_; }
  void initial_state(std::span<double> state) const override;
  void state_tolerances(std::span<double> atol, double mu_tolerance) const override;
  double static_limit_N(const FrictionContext& c) const override;
  double reattach_limit_N(const FrictionContext& c) const override { return static_limit_N(c); }
  double kinetic_force_N(const FrictionContext& c) const override;
  void state_rates(const FrictionContext& c, std::span<double> rates) const override;
  void on_slip_onset(const FrictionContext& c, std::span<double> state) const override;
  bool stiff(double normal_load_N, double natural_frequency_rad_per_s) const override;

  // Channel 1: μs at the context's load rate.
  double static_coefficient(const FrictionContext& c) const;
  double baseline_kinetic_coefficient(double speed_m_per_s) const;

 private:
  // The effects' channel sums at one instant (effect.h): χ = Π solid_fraction, Σ kinetic_increment
  // (started from `increment_start`, the baseline μk, so the Coulomb path's sum is unchanged), Σ fluid,
  // Σ static_increment.
  struct Channels {
    double solid_fraction = 1.0;
    double kinetic = 0.0;
    double fluid_N = 0.0;
    double static_increment = 0.0;
    std::optional<double> mu_s;  // channel 1, when the effects needed it
  };
  Channels channels(const FrictionContext& c, double increment_start) const;
  // Calls visit(i, context with effect i's state) for every effect, the shared part of the context
  // (μs, a root solve on a junction locus, and the baseline μk) computed once; returns that μs, or
  // nothing when there are no effects.
  template <class Visit>
  std::optional<double> for_each_effect(const FrictionContext& c, Visit&& visit) const;
  std::span<const double> base_state(const FrictionContext& c) const { return c.state.first(base_size_); }
  template <class S>
  S slice(S state, std::size_t i) const { return state.subspan(offsets_[i], effects_[i]->state_size()); }

  BaselineLaw baseline_;
  std::optional<contact::JunctionLocus> locus_;
  std::vector<std::unique_ptr<FrictionEffect>> effects_;
  std::vector<std::size_t> offsets_;
  std::size_t base_size_ = 0;   // 2 with a homogenised base, else 0
  std::size_t state_size_ = 0;
};

}  // namespace tribo::rig
