// The features of one friction record (docs/gap.md, step 2), read alike off a measured trace and
// off its simulation: a constant-speed run's friction extrema, slip drops, rise time, period and
// mean μ; a drive history's steady levels, peaks after holds and μ binned after a step; and their
// standard errors from the record itself. gap/compare.h plans the simulations, reads both sides
// with these and turns the features into items.
#pragma once

#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "gap/compare.h"

namespace tribo::gap::trace {

// Slip-drop points after each friction maximum (slip_drop, j = 1..kSlipDropPoints).
inline constexpr int kSlipDropPoints = 4;
// Bins of μ − μ_before after a velocity step (mu_after_step).
inline constexpr int kStepBins = 24;
// Shortest drive segment, in samples: its steady level is the mean of its last 30 % in four
// blocks (steady_mu and its noise), which needs a few samples each.
inline constexpr std::size_t kMinSegmentSamples = 20;

// Features by name: a constant-speed run's mean_mu, mu_peak, mu_trough, period_s, rise_time_s,
// slip_drop_j, peak_to_peak_m; a drive history's steady_mu_k, steady_scatter_k, peak_after_hold_k and
// after_step_k_j (segment k, bin j).
using Features = std::map<std::string, double>;

struct Signal {
  std::vector<double> t, mu, x, x_drive;  // x, x_drive may be empty
};

struct DriveSegments {
  std::vector<double> start_s, speed_m_per_s;
};

// y at `at`, linear between the samples either side: y's first value at and before the record's
// start, NaN at and past its end.
double interp(const std::vector<double>& t, const std::vector<double>& y, double at);

// The same, with the last sample's value at and past the record's end (a simulation read at
// instants that run to its last one).
double interp_to_end(const std::vector<double>& t, const std::vector<double>& y, double at);

// Mean of y[i − 1], y[i], y[i + 1] (0 < i < size − 1): a peak read off a noisy record.
double three_sample_mean(const std::vector<double>& y, std::size_t i);

// Sensor noise of a record: the median absolute second difference, which is 0.6745 √6 σ for white
// noise of std σ (a signal smooth at the sampling rate adds little to it, impulsive spikes do not
// move a median).
double high_pass_noise(const std::vector<double>& y);

// Steady μ of a drive segment [t_a, t_b]: the mean over its last 30 %, after the transient.
double steady_mu(const Signal& s, double t_a, double t_b);

// Friction maxima and minima of a constant-speed run (cycle_turning_points), on μ smoothed and read
// every `spacing_s` (the measured record's median spacing, on both sides).
// `slip_step_s` ≤ 0 asks for the measured Δ (returned through it). The window starts at
// `window_start_s`, by default after the start-up part of what `s` holds. Whether the run
// oscillates at all is read off the slider's displacement where the record has one (`x_regime`,
// rig::classify_regime of it: anything but steady sliding), else off μ's span (more than 5 % of
// its mean). The span is a cliff that sensor noise decides near it — a weak stick-slip whose μ
// spans 3.9 % read as oscillating on the noisy record and as steady on its noise-free prediction
// (validation seed 14011's test block, docs/gap.md) — while the displacement's regime is read alike
// on both sides (RunPlan::regime_from_x) and its noise floor is the record's.
Features analyse_constant_speed(const Signal& s, double spacing_s, double& slip_step_s, std::string* regime,
                                double window_start_s = std::numeric_limits<double>::quiet_NaN(),
                                const std::string* x_regime = nullptr);

// The noise of a constant-speed run's features: its analysis window cut into kNoiseBlocks
// contiguous blocks, each analysed as a run of its own (same sampling, same slip-drop Δ); the
// blocks' scatter / √blocks is the standard error of the whole window's feature.
Features block_noise(const Signal& s, double spacing_s, double slip_step_s, const std::string* x_regime);

// Drive segments of a recorded drive speed (a velocity step, slide-hold-slide): the segment
// starts (times from the record's start) and speeds. A change point is a jump between samples by
// more than max(1e-3 v_max, 6 σ), σ the record's high-pass noise, so sensor noise on a measured
// drive does not cut it into pieces; a segment shorter than kMinSegmentSamples samples (a glitch,
// a servo's overshoot) joins the one before it, and neighbours whose speeds differ by less than the
// threshold merge. A segment's speed is the median of its samples; one below the threshold is a
// hold (speed 0).
DriveSegments drive_segments(const std::vector<double>& t, const std::vector<double>& v);

// Velocity steps: steady μ per drive segment and μ − μ_before binned in load-point displacement.
// With `noise`, the standard error of every feature from the record itself (see compare.h).
Features analyse_drive_history(const Signal& s, const RunPlan& plan, std::vector<std::vector<double>>* edges_out,
                               Features* noise = nullptr);

}  // namespace tribo::gap::trace
