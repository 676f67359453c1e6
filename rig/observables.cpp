#include "rig/observables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tribo::rig {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double mean(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  double s = 0.0;
  for (double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Peak-to-peak of x over samples with t in [t0, t1).
double peak_to_peak(const std::vector<Sample>& samples, double t0, double t1) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Sample& s : samples) {
    if (s.t_s < t0 || s.t_s >= t1) continue;
    lo = std::min(lo, s.x_m);
    hi = std::max(hi, s.x_m);
  }
  return hi >= lo ? hi - lo : 0.0;
}
}  // namespace

RunObservables summarise(const RigParameters& rig, const std::vector<Sample>& samples,
                         const std::vector<Event>& events, double window_start_s) {
  RunObservables o;
  o.window_start_s = window_start_s;
  const double t_end = samples.empty() ? window_start_s : samples.back().t_s;
  const double period_d = 2.0 * std::numbers::pi / rig.damped_frequency_rad_per_s();

  std::vector<double> mu_s, phi_dot, stick, slip, breakaway_times;
  double max_slip = 0.0;
  for (const Event& e : events) {
    if (e.t_s < window_start_s) continue;
    switch (e.kind) {
      case EventKind::breakaway:
        ++o.breakaways;
        mu_s.push_back(e.mu);
        phi_dot.push_back(e.load_rate_per_s);
        breakaway_times.push_back(e.t_s);
        if (e.t_s - e.phase_duration_s >= window_start_s) stick.push_back(e.phase_duration_s);
        break;
      case EventKind::reattach:
        ++o.reattachments;
        if (e.t_s - e.phase_duration_s >= window_start_s) slip.push_back(e.phase_duration_s);
        max_slip = std::max(max_slip, e.phase_duration_s);
        break;
      case EventKind::reversal: ++o.reversals; break;
    }
  }
  o.mu_s_mean = mean(mu_s);
  o.load_rate_mean_per_s = mean(phi_dot);
  o.stick_time_s = mean(stick);
  o.slip_time_s = mean(slip);
  o.peak_to_peak_m = peak_to_peak(samples, window_start_s, std::numeric_limits<double>::infinity());

  // Time averages by the trapezoidal rule over the window.
  double span = 0.0, fx = 0.0, xx = 0.0;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const Sample &a = samples[i - 1], &b = samples[i];
    if (a.t_s < window_start_s) continue;
    const double dt = b.t_s - a.t_s;
    span += dt;
    fx += 0.5 * (a.friction_N + b.friction_N) * dt;
    xx += 0.5 * (a.x_m + b.x_m) * dt;
  }
  o.mean_friction_N = span > 0.0 ? fx / span : kNaN;
  o.mean_displacement_m = span > 0.0 ? xx / span : kNaN;

  if (breakaway_times.size() >= 2) {
    o.period_s = (breakaway_times.back() - breakaway_times.front()) / static_cast<double>(breakaway_times.size() - 1);
  } else {
    // Upward crossings of the mean displacement give the period of a slipping oscillation.
    std::vector<double> crossings;
    for (std::size_t i = 1; i < samples.size(); ++i) {
      const Sample &a = samples[i - 1], &b = samples[i];
      if (a.t_s < window_start_s) continue;
      const double da = a.x_m - o.mean_displacement_m, db = b.x_m - o.mean_displacement_m;
      if (da < 0.0 && db >= 0.0) crossings.push_back(a.t_s + (b.t_s - a.t_s) * (-da) / (db - da));
    }
    o.period_s = crossings.size() >= 2
                     ? (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1)
                     : kNaN;
  }

  const bool any_stick_in_window =
      std::any_of(samples.begin(), samples.end(), [&](const Sample& s) { return s.t_s >= window_start_s && s.phase == Phase::stick; });
  if (o.breakaways > 0 && o.reattachments > 0) {
    // A slip that runs through a velocity match without re-attaching (a reversal) or lasts
    // longer than 1.5 damped periods spans several cycles; a single slip is under one period.
    o.regime = (o.reversals > 0 || max_slip > 1.5 * period_d) ? "multi_cycle_slip" : "stick_slip";
  } else if (o.breakaways == 0 && o.reattachments == 0 && any_stick_in_window) {
    o.regime = "stuck";
  } else {
    // Slipping throughout: does the oscillation persist? Compare the last quarter of the run
    // with the quarter before it; below 1e-6 W/k it is noise-free steady sliding.
    const double t3 = window_start_s + 0.5 * (t_end - window_start_s);
    const double ptp_late = peak_to_peak(samples, t3, std::numeric_limits<double>::infinity());
    const double ptp_early = peak_to_peak(samples, window_start_s, t3);
    const double floor = 1e-6 * rig.normal_load_N / rig.stiffness_N_per_m;
    o.regime = (ptp_late > floor && ptp_late >= 0.9 * ptp_early) ? "quasi_harmonic" : "steady_sliding";
  }
  return o;
}

}  // namespace tribo::rig
