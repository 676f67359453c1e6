// The independent generator's rig integrator (issue 15): the same machine as thesis (4.2.1),
//
//     M ẍ + r ẋ + k x = F(U, state),   U = v − ẋ (disc speed v minus slider speed),
//
// integrated by a method of its own, not rig/'s CVODE stepper: classical fourth-order Runge–Kutta
// at a fixed step Δt while slipping, and an *exact* stick — while stuck the slider moves with the
// disc, x = x_s + v (t − t_s), ẋ = v, and the friction is whatever holds it, F = k x + r v. Events
// are located inside a step by bisection on the step fraction (40 halvings: Δt·1e-12):
//   stick → slip   |k x + r v| exceeds the static threshold χ(0) μ_th W (μ_th from the law: μs,
//                  stick-time ageing, rate hardening, or the rate-and-state μ(0, θ));
//   slip → stick   U reaches zero (a single RK4 step of the located length) and the force needed
//                  to hold the slider is within the threshold; otherwise slip continues with the
//                  friction reversing with U.
// Internal state integrated alongside: the rate-and-state θ (s), the film thickness h (m), the
// time at rest. Output is uniform at Δt — the measuring chain (measuring_chain.h) filters and
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
};

struct RawRecord {
  double step_s = 0.0;
  std::vector<double> t_s, x_m, xdot_m_per_s, friction_N;  // uniform at step_s, t = 0 first
  std::vector<double> breakaway_t_s, reattach_t_s;          // located event times
  bool completed = true;
  std::string message;
};

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
