// Friction laws as small state machines the rig integrates (DESIGN §4).
//
// Sign convention: U = v − ẋ is the velocity of the driven surface relative to the slider. While
// stuck (U = 0) the contact supplies whatever force keeps ẋ = v, up to the static limit. While
// slipping with direction d = ±1 (d = sign U, fixed for the phase and changed only by events) the
// friction on the slider is d · F_k ≥ 0-magnitude, dragging the slider along with the surface.
// A law never evaluates sign(U) itself: the rig decides the phase and direction at named events.
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace tribo::rig {

enum class Phase { stick, slip };

// What a law may look at. `state` is the law's own state (its slice of the integrated vector).
struct FrictionContext {
  double t_s = 0.0;
  Phase phase = Phase::stick;
  int slip_direction = 0;                  // ±1 during slip, 0 during stick
  double relative_speed_m_per_s = 0.0;     // |U| = |v − ẋ|
  double drive_speed_m_per_s = 0.0;        // v
  double normal_load_N = 0.0;              // W
  // φ̇ = |dF/dt| / W at which a stuck contact is (or, while slipping, would be) loaded by the
  // drive: |k v + r v̇| / W (thesis 3.1.20–3.1.21).
  double tangential_load_rate_per_s = 0.0;
  double slip_distance_m = 0.0;            // ∫|U| dt since the last slip onset
  double time_in_phase_s = 0.0;            // time since the current phase began
  std::span<const double> state;
};

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  // Short identifier for reports.
  virtual std::string name() const = 0;

  // Number of state variables the law integrates (film thickness, temperature, ...).
  virtual std::size_t state_size() const { return 0; }
  virtual void initial_state(std::span<double> /*state*/) const {}
  // Absolute error tolerance of each state variable for the integrator, in the state's units.
  // `mu_tolerance` is the error in μ the integrator allows on the displacement (x's tolerance is
  // SimulationOptions::displacement_tolerance_fraction × W/k, a spring force of that fraction of
  // W): a state that moves friction by μ per unit takes it as is, so that no state is integrated
  // more finely than the force it acts through.
  virtual void state_tolerances(std::span<double> atol, double /*mu_tolerance*/) const {
    for (double& a : atol) a = 1e-12;
  }

  // Largest tangential force (N) a stuck contact holds before it breaks away.
  virtual double static_limit_N(const FrictionContext& c) const = 0;

  // A slipping contact re-attaches at a velocity match only if the force needed to keep ẋ = v
  // does not exceed this (N). Defaults to the static limit; a fluid film can lower it.
  virtual double reattach_limit_N(const FrictionContext& c) const { return static_limit_N(c); }

  // Magnitude (N, ≥ 0) of the friction force while slipping at |U| = c.relative_speed_m_per_s.
  virtual double kinetic_force_N(const FrictionContext& c) const = 0;

  // d(state)/dt in either phase.
  virtual void state_rates(const FrictionContext& /*c*/, std::span<double> rates) const {
    for (double& r : rates) r = 0.0;
  }

  // A law whose friction varies so steeply with slip speed that it acts as a damper far stiffer
  // than the rig's own (rate-and-state's direct effect: dF/dU = a W / U), or whose state relaxes
  // far faster than the rig oscillates at load W and natural frequency ω_n (a squeeze film of
  // sub-millisecond squeeze-out time), makes the rig's equations stiff; the stepper then
  // integrates with BDF instead of Adams (rig/simulator.h).
  virtual bool stiff(double /*normal_load_N*/, double /*natural_frequency_rad_per_s*/) const { return false; }

  // Event hooks: the state may jump when a slip begins or a stick begins.
  virtual void on_slip_onset(const FrictionContext& /*c*/, std::span<double> /*state*/) const {}
  virtual void on_stick_onset(const FrictionContext& /*c*/, std::span<double> /*state*/) const {}
};

}  // namespace tribo::rig
