#include "rig/observables.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "numerics/median.h"

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

  std::vector<double> mu_s, phi_dot, stick, slip, breakaway_times, mu_reversal;
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
      case EventKind::reversal:
        ++o.reversals;
        mu_reversal.push_back(e.mu);
        break;
      case EventKind::relock: break;  // the drive's doing, not the contact's: no regime evidence
    }
  }
  o.mu_s_mean = mean(mu_s);
  o.mu_at_reversal_mean = mean(mu_reversal);
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

  RegimeEvidence e;
  e.breakaways = o.breakaways;
  e.reattachments = o.reattachments;
  e.reversals = o.reversals;
  e.longest_slip_s = max_slip;
  e.sticks = std::any_of(samples.begin(), samples.end(),
                         [&](const Sample& s) { return s.t_s >= window_start_s && s.phase == Phase::stick; });
  const double t_mid = window_start_s + 0.5 * (t_end - window_start_s);
  e.peak_to_peak_early_m = peak_to_peak(samples, window_start_s, t_mid);
  e.peak_to_peak_late_m = peak_to_peak(samples, t_mid, std::numeric_limits<double>::infinity());
  e.amplitude_floor_m = 1e-6 * rig.normal_load_N / rig.stiffness_N_per_m;  // noise-free: any oscillation
  o.regime = classify_regime(rig, e);
  return o;
}

std::string classify_regime(const RigParameters& rig, const RegimeEvidence& e) {
  if (e.breakaways > 0 && e.reattachments > 0) {
    // A slip that runs through a velocity match without re-attaching (a reversal) or lasts
    // longer than 1.5 damped periods spans several cycles; a single slip is under one period.
    const double period_d = 2.0 * std::numbers::pi / rig.damped_frequency_rad_per_s();
    return (e.reversals > 0 || e.longest_slip_s > 1.5 * period_d) ? "multi_cycle_slip" : "stick_slip";
  }
  if (e.breakaways == 0 && e.reattachments == 0 && e.sticks) return "stuck";
  // Slipping throughout: does the oscillation persist above what the record resolves?
  return (e.peak_to_peak_late_m > e.amplitude_floor_m && e.peak_to_peak_late_m >= 0.9 * e.peak_to_peak_early_m)
             ? "quasi_harmonic"
             : "steady_sliding";
}

RegimeEvidence recorded_regime_evidence(const RigParameters& rig, const std::vector<double>& t,
                                        const std::vector<double>& x, double v_drive, double window_start_s) {
  constexpr double kEnterStick = 0.05, kLeaveStick = 0.2;
  RegimeEvidence e;
  const std::size_t n = std::min(t.size(), x.size());
  if (n < 3 || !(v_drive != 0.0)) return e;
  const double V = std::abs(v_drive);
  const double period_d = 2.0 * std::numbers::pi / rig.damped_frequency_rad_per_s();
  const double t_mid = window_start_s + 0.5 * (t[n - 1] - window_start_s);
  auto peak_to_peak_between = [&](double t0, double t1) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < n; ++i)
      if (t[i] >= t0 && t[i] < t1) lo = std::min(lo, x[i]), hi = std::max(hi, x[i]);
    return hi >= lo ? hi - lo : 0.0;
  };
  e.peak_to_peak_early_m = peak_to_peak_between(window_start_s, t_mid);
  e.peak_to_peak_late_m = peak_to_peak_between(t_mid, std::numeric_limits<double>::infinity());
  // Noise on x: a sample's deviation from the chord of its neighbours has, for white noise of std
  // σ, std σ √(1 + w² + (1 − w)²) ≥ σ √1.5 (w the chord's weight); its median |·| is 0.6745 of that.
  std::vector<double> deviation;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    if (t[i] < window_start_s || !(t[i + 1] > t[i - 1])) continue;
    const double w = (t[i + 1] - t[i]) / (t[i + 1] - t[i - 1]);
    deviation.push_back(std::abs(x[i] - (w * x[i - 1] + (1.0 - w) * x[i + 1])));
  }
  double sigma = deviation.empty() ? 0.0 : numerics::median(deviation) / (0.6745 * std::sqrt(1.5));
  // A record quantised more coarsely than its noise (an encoder, a fixed-point logger) lies on the
  // chord at most samples, so the median sees no noise, yet its rounding still flickers a short
  // chord. Quantised: every step between samples is a whole multiple of the smallest nonzero one,
  // q (to 1 % of q, for decimals written to a file); a smooth record's steps are not. The rounding
  // is then the deviations up to q, whose rms over all samples is σ √1.5 as above; the corners of
  // the motion deviate by more and are left out.
  std::vector<double> moves;
  for (std::size_t i = 1; i < n; ++i)
    if (t[i] >= window_start_s && x[i] != x[i - 1]) moves.push_back(std::abs(x[i] - x[i - 1]));
  const double q = moves.empty() ? 0.0 : *std::min_element(moves.begin(), moves.end());
  if (q > 0.0 && !deviation.empty() &&
      std::all_of(moves.begin(), moves.end(), [q](double d) { return std::abs(d / q - std::round(d / q)) <= 0.01; })) {
    double rounding_sq = 0.0;
    for (const double d : deviation) rounding_sq += d <= q ? d * d : 0.0;
    sigma = std::max(sigma, std::sqrt(rounding_sq / static_cast<double>(deviation.size()) / 1.5));
  }
  e.amplitude_floor_m = std::max(1e-6 * rig.normal_load_N / rig.stiffness_N_per_m, 12.0 * sigma);

  // The half span h of the slope: T_d/40, widened until the slope's noise is at most
  // kLeaveStick/5 of the drive speed — a stuck slider then leaves the stick band by noise alone
  // less than once in a million samples — but not beyond T_d/8, a quarter of a slip. The least-
  // squares slope of N samples spaced Δt has the standard error σ √(12 / (N (N² − 1))) / Δt.
  std::vector<double> steps;
  for (std::size_t i = 1; i < n; ++i)
    if (t[i] >= window_start_s && t[i] > t[i - 1]) steps.push_back(t[i] - t[i - 1]);
  const double spacing = steps.empty() ? 0.0 : numerics::median(std::move(steps));
  double half_span_s = period_d / 40.0;
  if (sigma > 0.0 && spacing > 0.0) {
    const double slope_sd_max = kLeaveStick / 5.0 * V;
    for (double h = half_span_s; h <= period_d / 8.0; h += spacing) {
      half_span_s = h;
      const double N = 2.0 * std::floor(h / spacing) + 1.0;
      if (sigma * std::sqrt(12.0 / (N * (N * N - 1.0))) / spacing <= slope_sd_max) break;
    }
  }

  enum class State { unknown, stuck, forward, backward } state = State::unknown;
  double slip_start = t[0];
  std::size_t j0 = 0, j1 = 0;
  for (std::size_t i = 0; i < n; ++i) {
    // ẋ over [t − h, t + h], at least one sample either side: the least-squares slope.
    while (j0 < i && t[j0] < t[i] - half_span_s) ++j0;
    if (j0 == i && i > 0) j0 = i - 1;
    j1 = std::max(j1, std::min(i + 1, n - 1));
    while (j1 + 1 < n && t[j1 + 1] <= t[i] + half_span_s) ++j1;
    if (i == 0 || i + 1 == n) continue;
    double tm = 0.0, xm = 0.0;
    for (std::size_t j = j0; j <= j1; ++j) tm += t[j], xm += x[j];
    tm /= static_cast<double>(j1 - j0 + 1), xm /= static_cast<double>(j1 - j0 + 1);
    double stt = 0.0, stx = 0.0;
    for (std::size_t j = j0; j <= j1; ++j) stt += (t[j] - tm) * (t[j] - tm), stx += (t[j] - tm) * (x[j] - xm);
    const double u = v_drive - stx / stt;
    const bool in_window = t[i] >= window_start_s;
    State next = state;
    if (std::abs(u) < kEnterStick * V) {
      next = State::stuck;
    } else if (u > kLeaveStick * V) {
      next = State::forward;
    } else if (u < -kLeaveStick * V) {
      next = State::backward;
    }
    if (next != state) {
      const bool was_slipping = state == State::forward || state == State::backward;
      if (state == State::stuck) {
        slip_start = t[i];
        if (in_window) ++e.breakaways;
      } else if (was_slipping && next == State::stuck) {
        if (in_window) ++e.reattachments, e.longest_slip_s = std::max(e.longest_slip_s, t[i] - slip_start);
      } else if (was_slipping) {
        if (in_window) ++e.reversals;
      } else {
        slip_start = t[i];  // the record starts slipping
      }
    }
    state = next;
    if (in_window && state == State::stuck) e.sticks = true;
  }
  return e;
}

}  // namespace tribo::rig
