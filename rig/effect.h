// Friction effects: composable components of the rig's friction law (DESIGN §4, §8).
//
// The composite law (composite_law.h) combines the baseline Coulomb/kinetic curve with effects
// through fixed channels, so the result does not depend on the order effects are listed in:
//
//   μs,eff   = locus μs(φ̇) if a static-friction effect is present, else μs          (channel 1)
//   χ        = Π solid_fraction_e                 (share of W carried by solid contact) (channel 2)
//   F_static = χ(U = 0) · (μs,eff + Σ static_increment_e) · W                         (channel 5)
//   F_k      = χ · (μk(U) + Σ kinetic_increment_e) · W + Σ fluid_force_e              (channels 3, 4)
//   F_reattach = F_static
//
// Each effect has named parameters with units and physical bounds, so a fitter can vary them
// as a vector, and optional state integrated with the rig.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rig/friction_law.h"

namespace tribo::rig {

// Where the gap diagnosis searches a parameter (gap/diagnosis.h): inside the physical bounds,
// log-spaced when the range spans decades (a log range needs lower > 0).
struct FitRange {
  double lower = 0.0, upper = 0.0;
  bool log = false;
  // Named: the search runs over this parameter times that one of the same effect, divided by the
  // rig's normal load (a friction coefficient; lower and upper bound it), in place of the parameter
  // itself. For a pair whose product the data fix and whose ratio they see only weakly (a hump's
  // height and its speed), the search then moves along the valley on one coordinate.
  std::string times_per_normal_load = {};
};

// A named, bounded, documented parameter.
struct ParameterSpec {
  std::string name;         // config key, e.g. "mu_s_max"
  std::string unit;         // SI unit, "1" for dimensionless
  double default_value;
  double lower;             // physical bounds, inclusive
  double upper;
  std::string meaning;
  // Fitted by the diagnosis over this range; none: data of the kinds it reads cannot identify it
  // apart from the others, so it keeps its value (the default, or what the model says).
  std::optional<FitRange> fit = std::nullopt;
};

// What an effect sees: the rig's context plus the baseline's view.
struct EffectContext {
  const FrictionContext* rig = nullptr;
  double mu_s = 0.0;               // effective static coefficient at this instant (channel 1)
  double mu_k_baseline = 0.0;      // baseline kinetic coefficient at |U|
  std::span<const double> state;   // this effect's own state
};

class FrictionEffect {
 public:
  virtual ~FrictionEffect() = default;
  virtual std::string name() const = 0;

  virtual std::size_t state_size() const { return 0; }
  virtual void initial_state(std::span<double> /*state*/) const {}
  // As FrictionLaw::state_tolerances.
  virtual void state_tolerances(std::span<double> atol, double /*mu_tolerance*/) const {
    for (double& a : atol) a = 1e-10;
  }
  virtual void state_rates(const EffectContext& /*c*/, std::span<double> rates) const {
    for (double& r : rates) r = 0.0;
  }
  virtual void on_slip_onset(const EffectContext& /*c*/, std::span<double> /*state*/) const {}
  // True when the effect makes the rig's equations stiff (FrictionLaw::stiff).
  virtual bool stiff(double /*normal_load_N*/, double /*natural_frequency_rad_per_s*/) const { return false; }

  // Channel 2: fraction (0..1] of the normal load still carried by solid contact.
  virtual double solid_fraction(const EffectContext& /*c*/) const { return 1.0; }
  // Channel 3: addition to the solid kinetic coefficient.
  virtual double kinetic_increment(const EffectContext& /*c*/) const { return 0.0; }
  // Channel 4: force (N, ≥ 0, along the slip) carried by fluid shear.
  virtual double fluid_force_N(const EffectContext& /*c*/) const { return 0.0; }
  // Channel 5: addition to μs,eff, evaluated at U = 0 (a stuck contact, or one re-attaching): the
  // static limit a state such as contact age sets, e.g. rate_and_state's healing during a hold.
  virtual double static_increment(const EffectContext& /*c*/) const { return 0.0; }
};

}  // namespace tribo::rig
