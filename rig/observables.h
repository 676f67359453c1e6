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
  int breakaways = 0;
  int reattachments = 0;
  int reversals = 0;
};

// Summarises the part of a run after `window_start_s` (usually analysis_start_s(0, end of run)).
// Needs samples ordered in time.
RunObservables summarise(const RigParameters& rig, const std::vector<Sample>& samples,
                         const std::vector<Event>& events, double window_start_s);


}  // namespace tribo::rig
