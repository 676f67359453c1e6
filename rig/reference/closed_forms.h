// Closed-form references for the rig (DESIGN §6), shared by tests, benchmarks and reports.
//
// Free vibration of M ẍ + r ẋ + k x = 0:  x ∝ e^{−βt} cos(ω_d t),  β = r/2M,  ω_d = √(k/M − β²).
// Coulomb friction (μk W), no damping: the amplitude falls by 4 μk W / k per full cycle
// (2 μk W / k per half cycle), the period stays 2π/ω_n.
// Classic stick-slip, constant μs > μk, constant drive speed v: with Δ = (μs − μk) W / k and
// r = 0, each slip is an arc of radius √(Δ² + (v/ω_n)²) about x_k = μk W / k in the
// (x, ẋ/ω_n) plane, so
//     peak-to-peak = 2 √(Δ² + (v/ω_n)²) ≈ 2Δ,
//     period       = 2Δ/v + (π + 2 atan(v / (ω_n Δ))) / ω_n.
// With r > 0 the slip is the damped arc; its end (ẋ = v again) is found by bisection on the
// exact solution — still a closed form in time, evaluated to machine precision.
// Stability of steady sliding on a kinetic curve μk(U) (thesis Appendix II): linearising about
// ẋ = 0 gives M ξ̈ + (r + W dμk/dU) ξ̇ + k ξ = 0, so small oscillations grow iff −W dμk/dU > r.
#pragma once

#include "rig/parameters.h"

namespace tribo::rig::reference {

struct StickSlipCycle {
  double slip_start_displacement_m;  // x where the stick ends: (μs W − r v) / k
  double max_displacement_m;
  double min_displacement_m;
  double peak_to_peak_m;
  double slip_time_s;
  double stick_time_s;
  double period_s;
};

// The steady stick-slip cycle of the Coulomb law at constant drive speed (any r ≥ 0).
// Throws std::invalid_argument unless μs > μk ≥ 0 and v > 0.
StickSlipCycle coulomb_stick_slip(const RigParameters& rig, double mu_s, double mu_k, double drive_speed_m_per_s);

// Amplitude lost per full cycle of Coulomb free vibration, 4 μk W / k (undamped rig).
double coulomb_amplitude_loss_per_cycle_m(const RigParameters& rig, double mu_k);

// Growth rate (1/s, negative = decay) of small oscillations about steady sliding on a kinetic
// curve of slope dμk/dU: σ = −(r + W dμk/dU) / 2M.
double steady_sliding_growth_rate_per_s(const RigParameters& rig, double dmu_dU_per_m_per_s);

}  // namespace tribo::rig::reference
