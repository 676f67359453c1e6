#include "gap/verdict.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>

namespace tribo::gap {

Multiplicity multiplicity(const std::vector<bool>& mask) {
  Multiplicity m(mask.size(), 0.0);
  for (std::size_t i = 0; i < mask.size(); ++i) m[i] = mask[i] ? 1.0 : 0.0;
  return m;
}

namespace {

// sqrt(Σ m r² / Σ m) per key of the items in the split.
template <class Key>
std::map<std::string, double> rms_by(const std::vector<Item>& items, const std::vector<double>& r, const Multiplicity& m, Key key) {
  std::map<std::string, std::pair<double, double>> acc;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (m[i] > 0.0) {
      auto& a = acc[key(items[i])];
      a.first += m[i] * r[i] * r[i];
      a.second += m[i];
    }
  std::map<std::string, double> out;
  for (const auto& [k, a] : acc) out[k] = std::sqrt(a.first / a.second);
  return out;
}

double mean_of(const std::map<std::string, double>& by_observable) {
  double sum = 0.0;
  for (const auto& [k, v] : by_observable) sum += v;
  return by_observable.empty() ? 0.0 : sum / static_cast<double>(by_observable.size());
}

}  // namespace

double gap(const std::vector<Item>& items, const std::vector<double>& r, const Multiplicity& m) {
  return mean_of(rms_by(items, r, m, [](const Item& it) { return it.observable; }));
}

GapBreakdown breakdown(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<bool>& mask) {
  const Multiplicity m = multiplicity(mask);
  GapBreakdown g;
  g.by_observable = rms_by(items, r, m, [](const Item& it) { return it.observable; });
  g.by_regime = rms_by(items, r, m, [](const Item& it) { return it.regime; });
  g.by_phase = rms_by(items, r, m, [](const Item& it) { return it.phase; });
  g.by_speed = rms_by(items, r, m, [](const Item& it) { return it.speed_class; });
  g.gap = mean_of(g.by_observable);
  return g;
}

std::vector<double> weights(const std::vector<Item>& items, const std::vector<bool>& mask) {
  std::map<std::string, int> count;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (mask[i]) ++count[items[i].observable];
  std::vector<double> w(items.size(), 0.0);
  for (std::size_t i = 0; i < items.size(); ++i)
    if (mask[i]) w[i] = 1.0 / std::sqrt(static_cast<double>(count[items[i].observable]) * static_cast<double>(count.size()));
  return w;
}

double weighted_sse(const std::vector<double>& r, const std::vector<double>& w, const Multiplicity& m) {
  double s = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) s += m[i] * w[i] * w[i] * r[i] * r[i];
  return s;
}

double criterion(double sse_after, double sse_before, double n, int extra_parameters) {
  return n * std::log(std::max(sse_after, 1e-300) / std::max(sse_before, 1e-300)) + extra_parameters * std::log(std::max(n, 2.0));
}

double gap_margin(const DiagnosisOptions& o, double floor) { return std::max(o.min_gap_reduction, o.floor_margin * floor); }

bool earns(double c, double after, double before, const DiagnosisOptions& o, double margin) {
  return c < 0.0 && after <= (1.0 - o.min_relative_shrink) * before && before - after >= margin;
}

// A candidate with more parameters is preferred to a simpler earning one only when it beats it by
// the margins an effect must beat the baseline by (held-out gap ≥ 20 % and ≥ min_gap_reduction
// lower) and by a criterion difference of 2, below which a BIC difference is "not worth more than
// a bare mention" (Kass & Raftery 1995, J. Am. Stat. Assoc. 90, 773). So a nested effect — thermal
// thinning with U_T far above the slip speeds is viscous friction — does not win on fitting noise.
constexpr double kIndifferentCriterion = 2.0;

int verdict_index(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const DiagnosisOptions& o, double margin) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cs.size(); ++i)
    if (st[i].earns) order.push_back(i);
  if (order.empty()) return -1;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (cs[a].extra_parameters != cs[b].extra_parameters) return cs[a].extra_parameters < cs[b].extra_parameters;
    return st[a].criterion < st[b].criterion;
  });
  std::size_t chosen = order.front();
  for (std::size_t i : order) {
    if (cs[i].extra_parameters <= cs[chosen].extra_parameters) continue;
    const Standing &c = st[i], &s = st[chosen];
    if (c.criterion < s.criterion - kIndifferentCriterion && c.heldout_gap <= (1.0 - o.min_relative_shrink) * s.heldout_gap &&
        s.heldout_gap - c.heldout_gap >= margin)
      chosen = i;
  }
  return static_cast<int>(chosen);
}

Decision decide(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const DiagnosisOptions& o, double margin,
                double gap_before, double floor) {
  const int k = verdict_index(cs, st, o, margin);
  if (!(floor > 0.0)) return {k, false};
  const auto excess = [floor](double g) { return std::sqrt(std::max(g * g - floor * floor, 0.0)); };
  const auto real = [&](double g) { return g > o.unexplained_floors * floor; };
  if (k >= 0 && (!real(st[static_cast<std::size_t>(k)].heldout_gap) ||
                 excess(st[static_cast<std::size_t>(k)].heldout_gap) <= 0.5 * excess(gap_before)))
    return {k, false};
  return {-1, real(gap_before)};
}

std::vector<Localization> localize(const std::vector<Item>& items, const std::vector<double>& r) {
  std::map<std::pair<std::string, std::string>, std::pair<double, std::size_t>> acc;
  double total = 0.0;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const double r2 = r[i] * r[i];
    auto& a = acc[{items[i].observable, items[i].phase + ", " + items[i].speed_class}];
    if (a.first == 0.0 || r2 > r[a.second] * r[a.second]) a.second = i;
    a.first += r2;
    total += r2;
  }
  std::vector<Localization> out;
  for (const auto& [key, a] : acc) out.push_back({key.first, key.second, items[a.second].where, total > 0.0 ? a.first / total : 0.0});
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.share > b.share; });
  return out;
}

Confidence bootstrap_confidence(const std::vector<Item>& items, const std::vector<bool>& heldout, const std::vector<double>& noise_r,
                                const std::vector<double>& baseline_residuals, const std::vector<Candidate>& candidates, int chosen,
                                const std::string& verdict, const DiagnosisOptions& o, const std::vector<Refit>& refits) {
  const std::size_t n = items.size();
  std::vector<int> units;
  for (std::size_t i = 0; i < n; ++i)
    if (heldout[i]) units.push_back(items[i].unit);
  std::sort(units.begin(), units.end());
  units.erase(std::unique(units.begin(), units.end()), units.end());
  if (units.empty() || o.bootstrap_samples <= 0) return {};
  // One block and nothing measured about its noise: every resample is the data itself, and their
  // agreement would say 100 % about nothing.
  bool noisy = false;
  for (std::size_t i = 0; i < n; ++i) noisy = noisy || (heldout[i] && noise_r[i] > 0.0);
  if (units.size() < 2 && !noisy) return {std::numeric_limits<double>::quiet_NaN(), 0.0};
  std::mt19937_64 rng(o.seed ^ 0x9e3779b97f4a7c15ULL);
  std::uniform_int_distribution<std::size_t> pick(0, units.size() - 1);
  std::normal_distribution<double> z;
  int agree = 0;
  double s1 = 0.0, s2 = 0.0;
  std::vector<double> shift(n, 0.0);
  const auto shifted = [&](const std::vector<double>& r) {
    std::vector<double> out = r;
    for (std::size_t i = 0; i < n; ++i) out[i] += shift[i];
    return out;
  };
  for (int b = 0; b < o.bootstrap_samples; ++b) {
    std::map<int, int> times;
    for (std::size_t k = 0; k < units.size(); ++k) ++times[units[pick(rng)]];
    for (std::size_t i = 0; i < n; ++i) shift[i] = heldout[i] && noise_r[i] > 0.0 ? noise_r[i] * z(rng) : 0.0;
    std::vector<bool> mask(n, false);
    Multiplicity m(n, 0.0);
    double drawn = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      if (heldout[i] && times.count(items[i].unit)) mask[i] = true, m[i] = times[items[i].unit], drawn += m[i];
    const Refit* refit = refits.empty() ? nullptr : &refits[static_cast<std::size_t>(b) % refits.size()];
    const auto fitted = [&](int k) -> const std::vector<double>& {
      if (k < 0) return refit ? refit->baseline : baseline_residuals;
      const std::size_t c = static_cast<std::size_t>(k);
      if (refit)
        if (const auto it = refit->candidates.find(c); it != refit->candidates.end()) return it->second;
      return candidates[c].residuals;
    };
    const std::vector<double> w = weights(items, mask), before = shifted(fitted(-1));
    const double sse_before = weighted_sse(before, w, m), gap_before = gap(items, before, m);
    const double floor = gap(items, noise_r, m), margin = gap_margin(o, floor);
    std::vector<Standing> standing;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      const std::vector<double> r = shifted(fitted(static_cast<int>(c)));
      const double crit = criterion(weighted_sse(r, w, m), sse_before, drawn, candidates[c].extra_parameters);
      const double after = gap(items, r, m);
      standing.push_back({crit, after, earns(crit, after, gap_before, o, margin)});
    }
    const Decision k = decide(candidates, standing, o, margin, gap_before, floor);
    const std::string winner =
        k.unexplained ? "unexplained" : k.index < 0 ? "none" : verdict_name(candidates[static_cast<std::size_t>(k.index)].effects);
    agree += winner == verdict;
    const double g = gap(items, shifted(fitted(chosen)), m);
    s1 += g, s2 += g * g;
  }
  const double B = o.bootstrap_samples;
  return {agree / B, B > 1 ? std::sqrt(std::max(0.0, (s2 - s1 * s1 / B) / (B - 1))) : 0.0};
}

}  // namespace tribo::gap
