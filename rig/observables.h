// What an experimentalist reads off a run: per-cycle static friction μs and load rate φ̇
// (thesis §5.1), amplitude, period, stick time, and the regime (thesis §5.2):
//   stick_slip        — the slider re-attaches every cycle, slip lasts under one period
//   multi_cycle_slip  — it re-attaches, but a slip runs through a velocity match (reversal)
//                       or lasts longer than 1.5 periods 2π/ω_d
//   quasi_harmonic    — it never re-attaches and the oscillation does not decay
//   steady_sliding    — it never re-attaches and the oscillation decays (or never started)
//   stuck             — it never breaks away
#pragma once

#include <string>
#include <vector>

#include "rig/parameters.h"
#include "rig/simulator.h"

namespace tribo::rig {

// The start-up window: every analysis of a run — its regime and observables here, the sweeps, the
// gap diagnosis' features of measured and simulated records alike — skips the first
// kStartupFraction of it, where the start-up transient (the slider taken from rest to the drive
// speed) has not died away.
inline constexpr double kStartupFraction = 0.5;

// Where the analysed part of a record over [t_begin_s, t_end_s] starts.
inline double analysis_start_s(double t_begin_s, double t_end_s) {
  return t_begin_s + kStartupFraction * (t_end_s - t_begin_s);
}

struct RunObservables {
  std::string regime;
  double window_start_s = 0.0;        // observables use samples and events from here on
  double period_s = 0.0;              // NaN when no oscillation is found
  double peak_to_peak_m = 0.0;        // of x in the window
  double mean_displacement_m = 0.0;
  double stick_time_s = 0.0;          // mean stick duration (NaN without sticks)
  double slip_time_s = 0.0;           // mean slip duration (NaN without complete slips)
  double mu_s_mean = 0.0;             // mean μs at breakaway (NaN without)
  double load_rate_mean_per_s = 0.0;  // mean φ̇ at breakaway (NaN without)
  double mean_friction_N = 0.0;       // time average of the true friction
  // Mean μ at the reversals — where a slip runs through a velocity match and goes on: the kinetic
  // friction at zero relative speed on the stable branch of the slip, where viscous drag is zero
  // (thesis §5.2a: ≈ 0.03 on Fig 5.2.2's multi-cycle slip, "the load supported by the film"). NaN
  // without reversals.
  double mu_at_reversal_mean = 0.0;
  int breakaways = 0;
  int reattachments = 0;
  int reversals = 0;
};

// Summarises the part of a run after `window_start_s` (usually analysis_start_s(0, end of run)).
// Needs samples ordered in time.
RunObservables summarise(const RigParameters& rig, const std::vector<Sample>& samples,
                         const std::vector<Event>& events, double window_start_s);

// What the regime of an analysis window is read from — the stepper's events and phases for a
// simulated run, the slider's recorded motion for a measured one (recorded_regime_evidence).
struct RegimeEvidence {
  int breakaways = 0;
  int reattachments = 0;
  int reversals = 0;                  // slips that ran through a velocity match
  double longest_slip_s = 0.0;        // longest slip phase ending in the window
  bool sticks = false;                // the slider is stuck somewhere in the window
  double peak_to_peak_early_m = 0.0;  // slider displacement, first half of the window
  double peak_to_peak_late_m = 0.0;   // second half
  // The smallest oscillation the record resolves: 1e-6 W/k for a simulated run, raised to the
  // sensor noise for a recorded one (noise alone has a peak-to-peak that does not decay).
  double amplitude_floor_m = 0.0;
};

// The one classification (the regimes at the top of this file): re-attachments mean stick-slip,
// multi-cycle when a slip reversed or outlasted 1.5 damped periods of `rig`; no events but a stuck
// slider, stuck; slipping throughout, quasi-harmonic when the late half's oscillation is at least
// 90 % of the early half's and above the amplitude floor, else steady sliding.
std::string classify_regime(const RigParameters& rig, const RegimeEvidence& evidence);

// Regime evidence of a recorded slider displacement x (m) at times t (s, increasing, any spacing)
// driven at the constant speed v_drive_m_per_s, from window_start_s on. The sliding speed
// u = v_drive − ẋ (ẋ equals the drive speed while stuck) takes ẋ as the least-squares slope over
// ±h (at least one sample each side): h = T_d/40 of `rig`'s damped period, short against a slip
// (≈ T_d/2), widened up to T_d/8 until the slope's noise (from σ below) is at most 4 % of the drive
// speed — a slow run's sensor noise over ±T_d/40 can exceed the stick band itself and read a
// stick-slip as reversals without a stick. The slider counts as stuck when |u| falls below 5 % of the drive
// speed and as slipping again when it exceeds 20 % — the hysteresis keeps noise near either
// threshold from adding events. A reversal is a slip whose u changes sign beyond ±20 %.
// The amplitude floor is 12 σ of the noise on x (σ from the median deviation of each sample from
// the chord of its neighbours, robust to the kinks of stick-slip), at least 1e-6 W/k: white noise
// stays within ±6 σ over any record length in practice, so a decayed oscillation buried in noise
// is steady sliding. It needs ≳ 20 samples per period, else the curvature reads as noise.
RegimeEvidence recorded_regime_evidence(const RigParameters& rig, const std::vector<double>& t_s,
                                        const std::vector<double>& x_m, double v_drive_m_per_s, double window_start_s);

}  // namespace tribo::rig
