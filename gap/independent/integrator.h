// The independent generator's rig integrator (issue 15): the same machine as thesis (4.2.1),
//
//     M ẍ + r ẋ + k x = F(U, state),   U = v(t) − ẋ (disc speed v minus slider speed),
//
// with the disc driven at a piecewise-constant speed v(t) (DriveHistory: a constant speed,
// velocity steps, slide-hold-slide with v = 0 during a hold), integrated by a method of its own,
// not rig/'s CVODE stepper: classical fourth-order Runge–Kutta at a fixed step Δt while slipping,
// and an *exact* stick — while stuck the slider moves with the disc, x = x_s + ∫v dt, ẋ = v, and
// the friction is whatever holds it, F = k x + r v. Events are located inside a step by bisection
// on the step fraction (40 halvings: Δt·1e-12):
//   stick → slip   |k x + r v| exceeds the static threshold χ(0) μ_th W (μ_th from the law: μs,
//                  stick-time ageing, rate hardening, or the rate-and-state μ(0, θ));
//   slip → stick   U reaches zero (a single RK4 step of the located length) and the force needed
//                  to hold the slider is within the threshold; otherwise slip continues with the
//                  friction reversing with U.
// A jump of the drive speed is a time the steps land on (a step that contains one is split there),
// and at the jump itself
//   stuck      the contact is rigid: ẋ jumps with v (the impulse M Δv passes through the contact;
//              a real drive ramps over milliseconds, M Δv/τ ≈ 1 N for 1 kg and 1 mm/s in 1 ms),
//              then the holding force k x + r v is tested against the threshold (breakaway at
//              the jump);
//   slipping   ẋ is continuous (the friction is finite) and U jumps: U = 0 (to 1e-9 of the
//              jump: a slider at rest in steady sliding when the drive stops) is the slip → stick
//              test above, a U of the other sign reverses the friction.
// The law's state (θ, h, time at rest) is continuous across a jump. Internal state integrated
// alongside: the rate-and-state θ (s), the film thickness h (m), the time at rest. Output is
// uniform at Δt, or every n-th step of it — the measuring chain (measuring_chain.h) filters and
// decimates it to the recorder's rate, as an anti-aliased data logger would.
#pragma once

#include <string>
#include <vector>

#include "gap/independent/laws.h"

namespace tribo::gap::independent {

// The rig constants as they *are* (the bundle may tell the diagnosis other, nominal values).
// Defaults: the thesis rig, Appendix I (59.2 lb/in, 5.70e-3 lb s²/in, 0.99e-2 lb s/in, 21.1 lb).
struct RigConstants {
  double mass_kg = 0.99822;
  double stiffness_N_per_m = 10367.5;
  double damping_N_s_per_m = 1.7338;
  double normal_load_N = 93.857;
  double slider_radius_m = 4.7625e-3;
};

struct IntegratorOptions {
  double step_s = 1e-5;          // Δt; ω_n Δt ≈ 1e-3 on the thesis rig
  double duration_s = 2.0;
  double initial_displacement_m = 0.0;
  double initial_speed_m_per_s = 0.0;  // slider speed ẋ at t = 0
  bool start_stuck = true;             // at rest on the disc (ẋ = v); else slipping from ẋ0
  int record_every = 1;                // keep every n-th step in the record (long, slow runs)
};

// The drive speed v(t) = speed_m_per_s[j] on [start_s[j], start_s[j + 1]), the last segment to the
// end of the run; start_s[0] = 0, strictly increasing. At a jump v is taken right-continuous.
struct DriveHistory {
  std::vector<double> start_s, speed_m_per_s;

  static DriveHistory constant(double v_m_per_s) { return {{0.0}, {v_m_per_s}}; }
  // Throws std::invalid_argument unless the segments are as stated above.
  void validate() const;
  std::size_t segment_at(double t_s) const;
  double speed_at(double t_s) const { return speed_m_per_s[segment_at(t_s)]; }
  double displacement_at(double t_s) const;  // ∫₀ᵗ v dt, exact
};

struct RawRecord {
  double step_s = 0.0;                                      // spacing of the record: Δt · record_every
  std::vector<double> t_s, x_m, xdot_m_per_s, friction_N;  // uniform at step_s, t = 0 first
  std::vector<double> breakaway_t_s, reattach_t_s;          // located event times
  bool completed = true;
  std::string message;
};

RawRecord integrate(const RigConstants& rig, const IndependentLaw& law, const DriveHistory& drive, const IntegratorOptions& options);
// At a constant drive speed.
RawRecord integrate(const RigConstants& rig, const IndependentLaw& law, double drive_speed_m_per_s, const IntegratorOptions& options);

// Reference (textbook, Den Hartog): undamped Coulomb stick-slip with μs > μk at drive speed v,
// Δ = (μs − μk) W / k. Slip is a free oscillation about x_k = μk W/k of amplitude
// A = √(Δ² + (v/ω_n)²) that starts at x_k + Δ with speed v and ends at x_k − Δ, where the slider
// matches the disc again: stick spans 2Δ in x (and 2Δk in friction) and lasts 2Δ/v, slip lasts
// (π + 2 atan(v/(ω_n Δ)))/ω_n, and x spans 2A peak to peak.
struct CoulombStickSlip {
  double stick_span_m, peak_to_peak_m, stick_time_s, slip_time_s;
};
CoulombStickSlip coulomb_stick_slip(const RigConstants& rig, double mu_s, double mu_k, double drive_speed_m_per_s);

}  // namespace tribo::gap::independent
