#include "gap/trace_features.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "numerics/median.h"
#include "rig/observables.h"

namespace tribo::gap::trace {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// The slip drops are read from the fall's start, extrapolated from where the fall has covered
// these shares of the way from the maximum to the next minimum (analyse_constant_speed).
constexpr double kFallLevels[2] = {0.1, 0.3};
constexpr int kNoiseBlocks = 4;  // repeats a run's window is cut into for its items' noise

// Linear between the samples either side of `at` (i the first sample after it).
double interp_at(const std::vector<double>& t, const std::vector<double>& y, double at, std::size_t i) {
  const double w = (at - t[i - 1]) / (t[i] - t[i - 1]);
  return y[i - 1] + w * (y[i] - y[i - 1]);
}

// The first sample after `at`, searched forward from `i` (which must not lie past it): one walk
// over a record for instants that increase, where a search per instant costs a log each.
std::size_t advance_past(const std::vector<double>& t, double at, std::size_t i) {
  while (i < t.size() && t[i] <= at) ++i;
  return i;
}

// A record smoothed over a fixed time: S(t) is the time average of the linear interpolant of the
// samples over [t − h, t + h] (clipped to the record). A running mean over a fixed number of
// samples would span a different time wherever the samples are not uniform — a simulated record
// has extra samples at its events — and jump as an event sample passes an output sample; S moves
// continuously with the samples, so the features read off it do too, which a least-squares fit on
// numeric derivatives needs.
class SmoothedSignal {
 public:
  SmoothedSignal(const std::vector<double>& t, const std::vector<double>& y, double half_width_s)
      : t_(t), y_(y), cum_(t.size(), 0.0), h_(half_width_s) {
    for (std::size_t i = 1; i < t.size(); ++i) cum_[i] = cum_[i - 1] + 0.5 * (y[i] + y[i - 1]) * (t[i] - t[i - 1]);
  }
  double front() const { return t_.front(); }
  double back() const { return t_.back(); }
  double at(double t) const {
    const double a = std::max(t_.front(), t - h_), b = std::min(t_.back(), t + h_);
    return b > a ? (integral_to(b, first_after(b)) - integral_to(a, first_after(a))) / (b - a) : interp(t_, y_, t);
  }
  // S at increasing instants: the same values as at(), by one walk over the samples.
  std::vector<double> at_increasing(const std::vector<double>& times) const {
    std::vector<double> out;
    out.reserve(times.size());
    std::size_t ia = 0, ib = 0;
    for (double t : times) {
      const double a = std::max(t_.front(), t - h_), b = std::min(t_.back(), t + h_);
      if (!(b > a)) {
        out.push_back(interp(t_, y_, t));
        continue;
      }
      ia = advance_past(t_, a, ia), ib = advance_past(t_, b, ib);
      out.push_back((integral_to(b, ib) - integral_to(a, ia)) / (b - a));
    }
    return out;
  }

 private:
  std::size_t first_after(double at) const { return static_cast<std::size_t>(std::upper_bound(t_.begin(), t_.end(), at) - t_.begin()); }
  // Integral of the interpolant from the first sample to `at` (inside the record; i its first
  // sample after it).
  double integral_to(double at, std::size_t i) const {
    if (i == 0) return 0.0;
    if (i == t_.size()) return cum_.back();
    const double dt = at - t_[i - 1], w = dt / (t_[i] - t_[i - 1]);
    return cum_[i - 1] + dt * (y_[i - 1] + 0.5 * w * (y_[i] - y_[i - 1]));
  }
  const std::vector<double>& t_;
  const std::vector<double>& y_;
  std::vector<double> cum_;
  double h_;
};

double mean(const std::vector<double>& v) {
  if (v.empty()) return kNaN;
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// Standard deviation of independent repeats / √repeats: the standard error of their average
// (NaN for fewer than two).
double standard_error(const std::vector<double>& v) {
  if (v.size() < 2) return kNaN;
  const double m = mean(v);
  double ss = 0.0;
  for (double x : v) ss += (x - m) * (x - m);
  return std::sqrt(ss / static_cast<double>(v.size() - 1) / static_cast<double>(v.size()));
}

// Time average of y over [t_a, t_b] from the samples inside it.
double window_mean(const std::vector<double>& t, const std::vector<double>& y, double t_a, double t_b) {
  double s = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_a && t[i] <= t_b) s += y[i], ++n;
  return n ? s / n : kNaN;
}

// Scatter of y about its least-squares line over [t_a, t_b], less the sensor's white noise:
// √max(0, var_detrended − noise²). A drift across the window is not scatter; stick-slip, ringing
// or a slowly wandering level are. NaN with fewer than three samples.
double excess_scatter(const std::vector<double>& t, const std::vector<double>& y, double t_a, double t_b, double noise) {
  double n = 0, st = 0, sy = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_a && t[i] <= t_b) ++n, st += t[i], sy += y[i];
  if (n < 3) return kNaN;
  const double tm = st / n, ym = sy / n;
  double stt = 0, sty = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_a && t[i] <= t_b) stt += (t[i] - tm) * (t[i] - tm), sty += (t[i] - tm) * (y[i] - ym);
  const double slope = stt > 0 ? sty / stt : 0.0;
  double var = 0;
  for (std::size_t i = 0; i < t.size(); ++i)
    if (t[i] >= t_a && t[i] <= t_b) {
      const double r = y[i] - ym - slope * (t[i] - tm);
      var += r * r;
    }
  return std::sqrt(std::max(0.0, var / n - noise * noise));
}

// Trapezoidal time average of y over [a, b] (t_front ≤ a < b ≤ t_back), ends interpolated.
double time_average(const std::vector<double>& t, const std::vector<double>& y, double a, double b) {
  double area = 0.0, t_prev = a, y_prev = interp(t, y, a);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] <= a) continue;
    const double ti = std::min(t[i], b), yi = t[i] <= b ? y[i] : interp(t, y, b);
    area += 0.5 * (y_prev + yi) * (ti - t_prev);
    t_prev = ti, y_prev = yi;
    if (t[i] >= b) break;
  }
  return area / (b - a);
}

struct Extremum {
  double t, value;
};

// The extremum of S between the grid points either side of the sampled one, by golden-section
// search: its value then moves continuously with the model's parameters instead of with the phase
// of the grid — at a re-attachment S has a corner, where a parabola through three grid points
// misplaces it by a fraction of the jump.
Extremum locate_extremum(const SmoothedSignal& S, double ta, double tb, bool maximum) {
  const double sign = maximum ? -1.0 : 1.0, g = 0.5 * (std::sqrt(5.0) - 1.0);
  double a = std::max(ta, S.front()), b = std::min(tb, S.back());
  double c = b - g * (b - a), d = a + g * (b - a), fc = sign * S.at(c), fd = sign * S.at(d);
  for (int i = 0; i < 40; ++i) {  // 0.618^40 ≈ 4e-9 of the bracket
    if (fc < fd) {
      b = d, d = c, fd = fc, c = b - g * (b - a), fc = sign * S.at(c);
    } else {
      a = c, c = d, fc = fd, d = a + g * (b - a), fd = sign * S.at(d);
    }
  }
  const double tv = 0.5 * (a + b);
  return {tv, S.at(tv)};
}

// The turning points of a run's μ — alternating maxima and minima — by hysteresis at 30 % and 70 %
// of its range (`lo_v` and `range`): a maximum is the highest value above the upper level before μ
// next falls below the lower one, a minimum the converse.
struct TurningPoints {
  std::vector<std::size_t> peaks, troughs;
  // Per peak, the position in `troughs` of the first trough after it (troughs.size() when none):
  // the trough its fall ends in; the one before that position, when there is one, ends its rise.
  std::vector<std::size_t> next_trough() const {
    std::vector<std::size_t> out;
    for (std::size_t p : peaks) out.push_back(static_cast<std::size_t>(std::upper_bound(troughs.begin(), troughs.end(), p) - troughs.begin()));
    return out;
  }
};

TurningPoints band_turning_points(const std::vector<double>& y, double lo_v, double range) {
  const double hi = lo_v + 0.7 * range, lo = lo_v + 0.3 * range;
  TurningPoints out;
  int state = 0;  // +1 above hi (tracking a maximum), −1 below lo (tracking a minimum)
  std::size_t cand = 0;
  // An extremum tracked from the window's first sample may be that sample, not a turning point
  // (the window opened on its far side); it is left out, else it jumps as the cycle moves past t0.
  bool from_edge = true;
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (y[k] > hi) {
      if (state != +1) {
        if (state == -1 && !from_edge) out.troughs.push_back(cand);
        from_edge = k == 0;
        state = +1, cand = k;
      } else if (y[k] > y[cand]) {
        cand = k;
      }
    } else if (y[k] < lo) {
      if (state != -1) {
        if (state == +1 && !from_edge) out.peaks.push_back(cand);
        from_edge = k == 0;
        state = -1, cand = k;
      } else if (y[k] < y[cand]) {
        cand = k;
      }
    }
  }
  return out;
}

// The turning points of y as a zigzag: each maximum and minimum confirmed once y has come back from
// it by at least `reversal`, whatever its level. The first, tracked from the window's first sample,
// is kept only where y came to it from that sample by 3/4 of the reversal (the band's rule above,
// for a reversal of 40 % of the range); the last, never confirmed, is not one.
TurningPoints zigzag_turning_points(const std::vector<double>& y, double reversal) {
  TurningPoints out;
  std::size_t hi = 0, lo = 0;  // the running maximum and minimum since the last turning point
  int state = 0;               // +1 tracking a maximum, −1 a minimum, 0 neither yet
  const auto kept = [&](std::size_t k) { return state != 0 || std::abs(y[k] - y.front()) >= 0.75 * reversal; };
  for (std::size_t k = 1; k < y.size(); ++k) {
    if (state >= 0 && y[k] > y[hi]) hi = k;
    if (state <= 0 && y[k] < y[lo]) lo = k;
    if (state >= 0 && y[k] <= y[hi] - reversal) {
      if (kept(hi)) out.peaks.push_back(hi);
      state = -1, lo = k;
    } else if (state <= 0 && y[k] >= y[lo] + reversal) {
      if (kept(lo)) out.troughs.push_back(lo);
      state = +1, hi = k;
    }
  }
  return out;
}

// A run's cycles: the band's turning points, unless μ's level wanders by more than a cycle's drop
// and the band reads the wander's extremes for the cycle's. Paper on paper at k = 168 N/m and
// 42 µm/s (docs/gap.md) drops by 0.04 every 2 s on a level that wanders by 0.2 along the track: the
// band saw four "cycles" of 100 s. The zigzag at 40 % of the run's typical fall (the 90th
// percentile of its falls at a tenth of the range) reads the drops whatever the level. It is taken
// where it finds more than twice the band's cycles and two more — a regular cycle gives both the
// same count, and a slip-phase hump the zigzag may count beside each drop stays below that — and
// where its cycles are stick-slip's, falling in under a third of the time they rise (the median of
// each): a noisy slide's swings, or a wander's, rise and fall alike.
TurningPoints cycle_turning_points(const std::vector<double>& y, double lo_v, double range) {
  TurningPoints band = band_turning_points(y, lo_v, range);
  const TurningPoints fine = zigzag_turning_points(y, 0.1 * range);
  std::vector<double> falls;
  const std::vector<std::size_t> fine_next = fine.next_trough();
  for (std::size_t i = 0; i < fine.peaks.size(); ++i)
    if (fine_next[i] < fine.troughs.size()) falls.push_back(y[fine.peaks[i]] - y[fine.troughs[fine_next[i]]]);
  if (falls.empty()) return band;
  const auto q = falls.begin() + static_cast<long>(0.9 * static_cast<double>(falls.size() - 1));
  std::nth_element(falls.begin(), q, falls.end());
  TurningPoints zigzag = zigzag_turning_points(y, std::max(0.1 * range, 0.4 * *q));
  if (!(zigzag.peaks.size() > 2 * band.peaks.size() + 2)) return band;
  std::vector<double> rise, fall;
  const std::vector<std::size_t> next = zigzag.next_trough();
  for (std::size_t i = 0; i < zigzag.peaks.size(); ++i) {
    const std::size_t p = zigzag.peaks[i], n = next[i];
    if (n < zigzag.troughs.size()) fall.push_back(static_cast<double>(zigzag.troughs[n] - p));
    if (n > 0) rise.push_back(static_cast<double>(p - zigzag.troughs[n - 1]));
  }
  if (rise.empty() || fall.empty()) return band;
  return 3.0 * numerics::median(fall) <= numerics::median(rise) ? zigzag : band;
}

// The ratio q ≥ 1 with 1 + q + … + q^(n−1) = total (in units of the first term): bisection.
double geometric_ratio(double total, int n) {
  if (total <= n) return 1.0;
  double lo = 1.0, hi = 2.0;
  auto sum = [n](double q) { return (std::pow(q, n) - 1.0) / (q - 1.0); };
  while (sum(hi) < total) hi *= 2.0;
  for (int i = 0; i < 100; ++i) {
    const double mid = 0.5 * (lo + hi);
    (sum(mid) < total ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

double interp(const std::vector<double>& t, const std::vector<double>& y, double at) {
  if (at <= t.front()) return y.front();
  if (at >= t.back()) return kNaN;
  return interp_at(t, y, at, static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), at) - t.begin()));
}

double interp_to_end(const std::vector<double>& t, const std::vector<double>& y, double at) {
  return at >= t.back() ? y.back() : interp(t, y, at);
}

double three_sample_mean(const std::vector<double>& y, std::size_t i) { return (y[i - 1] + y[i] + y[i + 1]) / 3.0; }

double high_pass_noise(const std::vector<double>& y) {
  std::vector<double> d;
  for (std::size_t i = 1; i + 1 < y.size(); ++i) d.push_back(std::abs(y[i + 1] - 2.0 * y[i] + y[i - 1]));
  return d.empty() ? 0.0 : numerics::median(std::move(d)) / (0.6745 * std::sqrt(6.0));
}

double steady_mu(const Signal& s, double t_a, double t_b) { return window_mean(s.t, s.mu, t_b - 0.3 * (t_b - t_a), t_b); }

Features analyse_constant_speed(const Signal& s, double spacing_s, double& slip_step_s, std::string* regime,
                                double window_start_s, const std::string* x_regime) {
  Features f;
  const double t0 = std::isfinite(window_start_s) ? window_start_s : rig::analysis_start_s(s.t.front(), s.t.back());
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < s.t.size(); ++i)
    if (s.t[i] >= t0) idx.push_back(i);
  if (idx.size() < 3) return f;
  // Half-width two spacings: five samples of a uniform record.
  const SmoothedSignal S(s.t, s.mu, 2.0 * spacing_s);
  std::vector<double> tw;
  for (double t = t0; t <= s.t.back(); t += spacing_s) tw.push_back(t);
  if (tw.size() < 3) return f;
  const std::vector<double> muw = S.at_increasing(tw);
  const auto [lo_it, hi_it] = std::minmax_element(muw.begin(), muw.end());
  const double lo_v = *lo_it, hi_v = *hi_it;
  f["mean_mu"] = mean(muw);
  // Between the 5th and 95th percentiles of x over time in [from, to] (read on the uniform grid,
  // so that a record sampled densely in slip does not weigh slip more): the extremes themselves
  // grow with the record's noise and, over many cycles, with the breakaway's scatter from cycle to
  // cycle, which a deterministic simulation does not have (a foreign Coulomb control with 2 %
  // scatter: its range 4 % above the truth's amplitude).
  const auto x_range = [&](double from, double to) {
    std::vector<double> xs;
    std::size_t i = 0;
    for (double t : tw) {
      if (t < from || t > to) continue;
      i = advance_past(s.t, t, i);  // as interp_to_end(s.t, s.x, t), without a search per instant
      xs.push_back(t >= s.t.back() ? s.x.back() : t <= s.t.front() ? s.x.front() : interp_at(s.t, s.x, t, i));
    }
    if (xs.empty()) return kNaN;
    // The order statistics alone (nth_element, not a sort: this runs in every prediction).
    const auto rank = [&](double q) { return xs.begin() + static_cast<long>(q * static_cast<double>(xs.size() - 1)); };
    std::nth_element(xs.begin(), rank(0.95), xs.end());
    const double upper = *rank(0.95);
    std::nth_element(xs.begin(), rank(0.05), rank(0.95));
    return upper - *rank(0.05);
  };
  if (!s.x.empty()) f["peak_to_peak_m"] = x_range(tw.front(), tw.back());
  const double range = hi_v - lo_v;
  const bool oscillates = x_regime ? *x_regime != "steady_sliding" : range > 0.05 * std::abs(f["mean_mu"]);
  if (!oscillates || !(range > 0.0)) {
    if (regime) *regime = "steady_sliding";
    return f;
  }
  const TurningPoints turning = cycle_turning_points(muw, lo_v, range);
  const std::vector<std::size_t>& peaks = turning.peaks;
  const std::vector<std::size_t>& troughs = turning.troughs;
  if (peaks.empty()) {
    if (regime) *regime = "steady_sliding";
    return f;
  }
  if (regime) *regime = "stick_slip";
  std::vector<Extremum> peak, trough;
  auto locate = [&](std::size_t k, bool maximum) { return locate_extremum(S, tw[k] - spacing_s, tw[k] + spacing_s, maximum); };
  for (std::size_t p : peaks) peak.push_back(locate(p, true));
  for (std::size_t q : troughs) trough.push_back(locate(q, false));
  std::vector<double> mp, mt, rise, fall, period;
  std::vector<double> bottom;  // per peak: the next minimum's value (the window's lowest without one)
  for (const Extremum& e : peak) mp.push_back(e.value);
  for (const Extremum& e : trough) mt.push_back(e.value);
  for (std::size_t i = 1; i < peak.size(); ++i) period.push_back(peak[i].t - peak[i - 1].t);
  // Over whole cycles, so that neither depends on where in a cycle the window ends (a simulated
  // window holds more cycles than a slow measured one, RunPlan::simulated_extra_s).
  if (peak.size() >= 2 && peak.back().t > peak.front().t) {
    f["mean_mu"] = time_average(tw, muw, peak.front().t, peak.back().t);
    if (!s.x.empty()) f["peak_to_peak_m"] = x_range(peak.front().t, peak.back().t);
  }
  const std::vector<std::size_t> next = turning.next_trough();
  for (std::size_t i = 0; i < peaks.size(); ++i) {
    const std::size_t n = next[i];
    if (n < troughs.size()) fall.push_back(trough[n].t - peak[i].t);
    if (n > 0) rise.push_back(peak[i].t - trough[n - 1].t);
    bottom.push_back(n < troughs.size() ? trough[n].value : lo_v);
  }
  f["mu_peak"] = mean(mp);
  if (!mt.empty()) f["mu_trough"] = mean(mt);
  if (!period.empty()) f["period_s"] = mean(period);
  if (!rise.empty()) f["rise_time_s"] = mean(rise);
  if (slip_step_s <= 0.0 && !fall.empty()) slip_step_s = mean(fall) / (kSlipDropPoints + 1);
  if (slip_step_s > 0.0) {
    // The drops are read from where the fall starts, not from the maximum's time: on a slow
    // run's shallow stick ramp the record's noise puts the maximum of the smoothed signal
    // anywhere on the ramp's flat top, up to a slip step before the fall (independent validation
    // seed 14523, 4.5 mm/s: 11 ms early with Δ = 9.3 ms, so the first drop read 0.015 against the
    // fall's 0.085 and the noise-free simulation's 0.093). The fall's start is extrapolated from
    // where the signal, after the maximum, crosses 10 % and 30 % of the way down to the next
    // minimum — levels the noise does not reach (there 0.017 and 0.05 in μ, against a smoothed
    // noise of about 0.002) — back to the maximum's value along the line through the two, and no
    // earlier than the maximum: a step's edge, a linear fall's corner. Crossings by bisection on S,
    // so that the start moves continuously with a model's parameters.
    const auto crossing = [&](std::size_t from, double t_from, double level) {
      for (std::size_t k = from + 1; k < tw.size(); ++k) {
        if (muw[k] >= level) continue;
        double a = std::max(tw[k - 1], t_from), b = tw[k];
        for (int it = 0; it < 40; ++it) {  // S(a) ≥ level > S(b)
          const double c = 0.5 * (a + b);
          (S.at(c) >= level ? a : b) = c;
        }
        return a;
      }
      return kNaN;
    };
    std::vector<double> fall_start;
    for (std::size_t i = 0; i < peak.size(); ++i) {
      const double depth = peak[i].value - bottom[i];
      const double t1 = crossing(peaks[i], peak[i].t, peak[i].value - kFallLevels[0] * depth);
      const double t2 = std::isfinite(t1) ? crossing(peaks[i], t1, peak[i].value - kFallLevels[1] * depth) : kNaN;
      const double back = (t2 - t1) * kFallLevels[0] / (kFallLevels[1] - kFallLevels[0]);
      fall_start.push_back(std::isfinite(t2) ? std::max(peak[i].t, t1 - back) : peak[i].t);
    }
    for (int j = 1; j <= kSlipDropPoints; ++j) {
      std::vector<double> drops;
      for (std::size_t i = 0; i < peak.size(); ++i) {
        const double at = fall_start[i] + j * slip_step_s;
        const double m = at <= s.t.back() ? S.at(at) : kNaN;
        if (std::isfinite(m)) drops.push_back(peak[i].value - m);
      }
      if (!drops.empty()) f["slip_drop_" + std::to_string(j)] = mean(drops);
    }
  }
  return f;
}

Features block_noise(const Signal& s, double spacing_s, double slip_step_s, const std::string* x_regime) {
  const double t0 = rig::analysis_start_s(s.t.front(), s.t.back());
  const double block = (s.t.back() - t0) / kNoiseBlocks;
  // The analysis skips the start-up window of what it is given: each block's signal starts that
  // much earlier, so that the part analysed is the block itself.
  const double lead = block * rig::kStartupFraction / (1.0 - rig::kStartupFraction);
  std::map<std::string, std::vector<double>> values;
  for (int b = 0; b < kNoiseBlocks; ++b) {
    const double from = t0 + b * block - lead, to = t0 + (b + 1) * block;
    Signal part;
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      if (s.t[i] < from || s.t[i] > to) continue;
      part.t.push_back(s.t[i]);
      part.mu.push_back(s.mu[i]);
      if (!s.x.empty()) part.x.push_back(s.x[i]);
    }
    if (part.t.size() < 3) continue;
    double step = slip_step_s;
    for (const auto& [key, value] : analyse_constant_speed(part, spacing_s, step, nullptr, kNaN, x_regime))
      if (std::isfinite(value)) values[key].push_back(value);
  }
  Features out;
  for (const auto& [key, v] : values)
    if (const double e = standard_error(v); std::isfinite(e)) out[key] = e;
  return out;
}

DriveSegments drive_segments(const std::vector<double>& t, const std::vector<double>& v) {
  const double v_max = std::max(std::abs(*std::max_element(v.begin(), v.end())), std::abs(*std::min_element(v.begin(), v.end())));
  const double threshold = std::max(1e-3 * v_max, 6.0 * high_pass_noise(v));
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 1; i < v.size(); ++i)
    if (std::abs(v[i] - v[i - 1]) > threshold) starts.push_back(i);
  starts.push_back(v.size());
  auto median_speed = [&](std::size_t a, std::size_t b) {
    const double m = numerics::median({v.begin() + static_cast<long>(a), v.begin() + static_cast<long>(b)});
    return std::abs(m) <= threshold ? 0.0 : m;
  };
  std::vector<std::size_t> kept{0};
  for (std::size_t k = 1; k + 1 < starts.size(); ++k)
    if (starts[k + 1] - starts[k] >= kMinSegmentSamples) kept.push_back(starts[k]);
  kept.push_back(v.size());
  DriveSegments out;
  for (std::size_t k = 0; k + 1 < kept.size(); ++k) {
    const double speed = median_speed(kept[k], kept[k + 1]);
    if (!out.speed_m_per_s.empty() && std::abs(speed - out.speed_m_per_s.back()) <= threshold) continue;
    out.start_s.push_back(t[kept[k]] - t.front());
    out.speed_m_per_s.push_back(speed);
  }
  out.start_s.front() = 0.0;
  return out;
}

Features analyse_drive_history(const Signal& s, const RunPlan& plan, std::vector<std::vector<double>>* edges_out,
                               Features* noise) {
  Features f;
  const double sample_noise = noise ? high_pass_noise(s.mu) : 0.0;
  const std::size_t segments = plan.step_times_s.size();
  const double t_first = s.t.front();
  auto segment_end = [&](std::size_t k) { return k + 1 < segments ? t_first + plan.step_times_s[k + 1] : s.t.back(); };
  auto hold = [&](std::size_t k) { return plan.step_speeds_m_per_s[k] == 0.0; };
  // A segment's steady window stops half a sample short of the next step: the sample at the step
  // belongs to what the step starts (a simulated contact re-locked at a hold reads the kinetic law
  // at U = 0 there, 7a below the level for rate_and_state — a scatter of 0.8a in one sample).
  const double half_sample_s = s.t.size() > 1 ? 0.5 * (s.t.back() - s.t.front()) / static_cast<double>(s.t.size() - 1) : 0.0;
  std::vector<double> steady(segments, kNaN);
  for (std::size_t k = 0; k < segments; ++k) {
    const double a = t_first + plan.step_times_s[k], b = segment_end(k) - (k + 1 < segments ? half_sample_s : 0.0);
    if (hold(k)) {
      // Slide-hold-slide: the peak on re-sliding above the steady level before the hold — static
      // friction grown with the hold time (healing) — within the first half of the next slide.
      if (k == 0 || k + 1 >= segments || hold(k - 1)) continue;
      const double t_on = t_first + plan.step_times_s[k + 1], t_search = t_on + 0.5 * (segment_end(k + 1) - t_on);
      double peak = -std::numeric_limits<double>::infinity();
      std::size_t in_window = 0;
      for (std::size_t i = 1; i + 1 < s.t.size(); ++i) {
        if (s.t[i] <= t_on || s.t[i] > t_search) continue;
        ++in_window;
        peak = std::max(peak, three_sample_mean(s.mu, i));
      }
      if (!in_window || !std::isfinite(steady[k - 1])) continue;
      const std::string key = "peak_after_hold_" + std::to_string(k);
      f[key] = peak - steady[k - 1];
      if (noise) (*noise)[key] = std::hypot(sample_noise / std::sqrt(3.0), (*noise)["steady_mu_" + std::to_string(k - 1)]);
      continue;
    }
    steady[k] = steady_mu(s, a, b);
    f["steady_mu_" + std::to_string(k)] = steady[k];
    // The same window's scatter: a record that slides steadily there has only its noise (and slow
    // wander); a model that stick-slips or rings there has the oscillation. The record's white
    // noise is taken off (sample_noise, 0 for a simulation, which has none).
    const double from = b - 0.3 * (b - a);
    f["steady_scatter_" + std::to_string(k)] = excess_scatter(s.t, s.mu, from, b, sample_noise);
    if (noise) {
      std::vector<double> parts, scatters;
      const double width = (b - from) / kNoiseBlocks;
      for (int j = 0; j < kNoiseBlocks; ++j) {
        const double lo = from + j * width, hi = from + (j + 1) * width;
        if (const double m = window_mean(s.t, s.mu, lo, hi); std::isfinite(m)) parts.push_back(m);
        if (const double e = excess_scatter(s.t, s.mu, lo, hi, sample_noise); std::isfinite(e)) scatters.push_back(e);
      }
      (*noise)["steady_mu_" + std::to_string(k)] = standard_error(parts);
      (*noise)["steady_scatter_" + std::to_string(k)] = standard_error(scatters);
    }
  }
  for (std::size_t k = 1; k < segments; ++k) {
    const double t_step = t_first + plan.step_times_s[k], t_end = segment_end(k);
    const double x_step = interp(s.t, s.x_drive, t_step);
    std::vector<double> edges;
    // Bins only after a step between two slides: into a hold the load point does not travel, and
    // out of one the peak above is the observable.
    if (hold(k) || hold(k - 1)) {
      if (edges_out) edges_out->push_back({});
      continue;
    }
    if (edges_out) {
      // Widths growing geometrically from the load-point travel of one sample, so the first bins
      // (one or two samples each) resolve the transient and alternate between train and
      // held-out; kStepBins of them reach the end of the segment.
      const double span = (t_end >= s.t.back() ? s.x_drive.back() : interp(s.t, s.x_drive, t_end)) - x_step;
      const double first = std::min(plan.step_speeds_m_per_s[k] * plan.sample_spacing_s, span / kStepBins);
      const double growth = geometric_ratio(span / first, kStepBins);
      edges.push_back(0.0);
      for (int j = 0; j < kStepBins; ++j) edges.push_back(j + 1 == kStepBins ? span : edges.back() + first * std::pow(growth, j));
      edges_out->push_back(edges);
    } else {
      edges = plan.step_bin_edges_m[k - 1];
    }
    std::vector<double> sum(kStepBins, 0.0);
    std::vector<int> count(kStepBins, 0);
    for (std::size_t i = 0; i < s.t.size(); ++i) {
      if (s.t[i] < t_step || s.t[i] > t_end) continue;
      const double d = s.x_drive[i] - x_step;
      const auto it = std::upper_bound(edges.begin(), edges.end(), d);
      if (it == edges.begin() || it == edges.end()) continue;
      const std::size_t b = static_cast<std::size_t>(it - edges.begin()) - 1;
      sum[b] += s.mu[i] - steady[k - 1];
      ++count[b];
    }
    for (int j = 0; j < kStepBins; ++j) {
      const int in_bin = count[static_cast<std::size_t>(j)];
      if (!in_bin) continue;
      const std::string key = "after_step_" + std::to_string(k) + "_" + std::to_string(j);
      f[key] = sum[static_cast<std::size_t>(j)] / in_bin;
      if (noise) (*noise)[key] = sample_noise / std::sqrt(static_cast<double>(in_bin));
    }
  }
  return f;
}

}  // namespace tribo::gap::trace
