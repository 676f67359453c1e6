#include "gap/verdict.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "numerics/normal.h"

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

std::vector<double> item_noise(const std::vector<Item>& items, const std::vector<double>& noise_r) {
  std::map<std::string, std::pair<double, int>> pooled;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (noise_r[i] > 0.0) pooled[items[i].observable].first += noise_r[i] * noise_r[i], ++pooled[items[i].observable].second;
  std::vector<double> s(items.size(), 0.0);
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (noise_r[i] > 0.0) {
      s[i] = noise_r[i];
    } else if (const auto p = pooled.find(items[i].observable); p != pooled.end()) {
      s[i] = std::sqrt(p->second.first / p->second.second);
    }
  }
  return s;
}

Predictive predictive(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& s,
                      const std::vector<bool>& train, const std::vector<double>& parameter_variance) {
  assert(parameter_variance.empty() || parameter_variance.size() == items.size());
  std::map<std::string, std::pair<double, int>> in_train, in_all;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const double excess = r[i] * r[i] - s[i] * s[i];
    auto& a = in_all[items[i].observable];
    a.first += excess, ++a.second;
    if (train[i]) {
      auto& t = in_train[items[i].observable];
      t.first += excess, ++t.second;
    }
  }
  Predictive p;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const auto t = in_train.find(items[i].observable);
    const auto& acc = t != in_train.end() ? t->second : in_all.at(items[i].observable);
    const double tau2 = std::max(0.0, acc.first / acc.second);
    const double v = parameter_variance.empty() ? 0.0 : parameter_variance[i];
    p.sd.push_back(std::max(std::sqrt(s[i] * s[i] + tau2 + v), Predictive::kResolution));
    p.dof.push_back(acc.second);
  }
  return p;
}

std::vector<double> likelihood_weights(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& s,
                                       const std::vector<bool>& train) {
  const Predictive p = predictive(items, r, s, train);
  std::vector<double> w(items.size(), 0.0);
  for (std::size_t i = 0; i < items.size(); ++i)
    if (train[i]) w[i] = 1.0 / p.sd[i];
  return w;
}

std::vector<double> log_density(const std::vector<double>& r, const Predictive& p) {
  constexpr double kLogPi = 1.1447298858494002;
  std::vector<double> out(r.size(), 0.0);
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double nu = p.dof[i], z = r[i] / p.sd[i];
    out[i] = std::lgamma(0.5 * (nu + 1.0)) - std::lgamma(0.5 * nu) - 0.5 * (std::log(nu) + kLogPi) - std::log(p.sd[i]) -
             0.5 * (nu + 1.0) * std::log1p(z * z / nu);
  }
  return out;
}

Evidence evidence(const std::vector<double>& lpd_a, const std::vector<double>& lpd_b, const Multiplicity& m) {
  double n = 0.0, sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (!(m[i] > 0.0)) continue;
    const double d = lpd_a[i] - lpd_b[i];
    n += m[i], sum += m[i] * d, sum2 += m[i] * d * d;
  }
  if (!(n > 0.0)) return {};
  const double mean = sum / n, var = n > 1.0 ? std::max(0.0, (sum2 - n * mean * mean) / (n - 1.0)) : 0.0;
  return {sum, std::sqrt(n * var)};
}

double decisive_z(int comparisons) {
  assert(comparisons >= 1);
  return numerics::standard_normal_quantile(std::pow(numerics::standard_normal_cdf(2.0), 1.0 / comparisons));
}

bool decisive(const Evidence& e, double heldout_gap_a, double heldout_gap_b, int comparisons) {
  return e.gain > Evidence::kStrong && (e.gain > decisive_z(comparisons) * e.se || heldout_gap_a <= 0.5 * heldout_gap_b);
}

Standing standing_of(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& v,
                     const std::vector<double>& s, const std::vector<bool>& train, const std::vector<double>& baseline_lpd, double baseline_gap, const Multiplicity& m,
                     int comparisons) {
  Standing st;
  st.lpd = log_density(r, predictive(items, r, s, train, v));
  st.heldout_gap = gap(items, r, m);
  st.evidence = evidence(st.lpd, baseline_lpd, m);
  st.earns = decisive(st.evidence, st.heldout_gap, baseline_gap, comparisons);
  return st;
}

namespace {

// Single effects alike_at_constant_speed (a name outside the catalogue is alike to nothing).
bool alike_singles(const Candidate& a, const Candidate& b) {
  return a.effects.size() == 1 && b.effects.size() == 1 && rig::find_effect_info(a.effects.front()) != nullptr &&
         alike_at_constant_speed(a.effects, b.effects);
}

}  // namespace

int verdict_index(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const Multiplicity& m) {
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < cs.size(); ++i)
    if (st[i].earns) order.push_back(i);
  if (order.empty()) return -1;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    if (cs[a].extra_parameters != cs[b].extra_parameters) return cs[a].extra_parameters < cs[b].extra_parameters;
    return st[a].evidence.gain > st[b].evidence.gain;
  });
  const auto beaten = [&](std::size_t i) {
    for (std::size_t j : order)
      if (cs[j].extra_parameters > cs[i].extra_parameters && decisive(evidence(st[j].lpd, st[i].lpd, m), st[j].heldout_gap, st[i].heldout_gap))
        return true;
    return false;
  };
  // The leaders of the parameter counts, fewest first; the largest count's leader is never beaten.
  std::size_t chosen = order.front();
  for (std::size_t k = 0; k < order.size(); ++k) {
    const bool leader = k == 0 || cs[order[k]].extra_parameters != cs[order[k - 1]].extra_parameters;
    if (!leader) continue;
    chosen = order[k];
    if (!beaten(chosen)) break;
  }
  // On the development data (352 journalled cases: validation sets 9001-9022, development data
  // since, and the selftest's development runs; docs/gap.md) this moves 9 verdicts, 5 to the
  // withheld effect (4 cases: one is journalled twice) and 2 away from it.
  const std::size_t simplest = chosen;
  for (std::size_t i : order)
    if (alike_singles(cs[simplest], cs[i]) && st[i].evidence.gain > st[chosen].evidence.gain) chosen = i;
  return static_cast<int>(chosen);
}

std::vector<int> indistinguishable(const std::vector<Standing>& st, int chosen, const Multiplicity& m) {
  std::vector<int> out;
  if (chosen < 0) return out;
  const Standing& v = st[static_cast<std::size_t>(chosen)];
  for (std::size_t i = 0; i < st.size(); ++i) {
    if (static_cast<int>(i) == chosen || !st[i].earns) continue;
    if (!decisive(evidence(st[i].lpd, v.lpd, m), st[i].heldout_gap, v.heldout_gap) &&
        !decisive(evidence(v.lpd, st[i].lpd, m), v.heldout_gap, st[i].heldout_gap))
      out.push_back(static_cast<int>(i));
  }
  return out;
}

Decision decide(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const Multiplicity& m, const DiagnosisOptions& o,
                double gap_before, double floor) {
  const int k = verdict_index(cs, st, m);
  if (!(floor > 0.0)) return {k, false};
  const auto real = [&](double g) { return beyond_noise(g, floor, o); };
  if (k >= 0 && (!real(st[static_cast<std::size_t>(k)].heldout_gap) || halves_excess(st[static_cast<std::size_t>(k)].heldout_gap, gap_before, floor)))
    return {k, false};
  if (!real(gap_before)) return {-1, false};
  int simplest = -1;
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (!halves_excess(st[i].heldout_gap, gap_before, floor)) continue;
    const auto s = static_cast<std::size_t>(simplest);
    if (simplest < 0 || cs[i].extra_parameters < cs[s].extra_parameters ||
        (cs[i].extra_parameters == cs[s].extra_parameters && st[i].heldout_gap < st[s].heldout_gap))
      simplest = static_cast<int>(i);
  }
  if (simplest >= 0) return {simplest, false, true};
  return {-1, true};
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
                                const std::vector<double>& baseline_residuals, const std::vector<double>& baseline_variance,
                                const std::vector<Candidate>& candidates, int chosen, const std::string& verdict, const DiagnosisOptions& o,
                                const std::vector<Refit>& refits) {
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
  const std::vector<double> s = item_noise(items, noise_r);
  std::vector<bool> train(n);
  for (std::size_t i = 0; i < n; ++i) train[i] = !heldout[i];
  const auto shifted = [&](const std::vector<double>& r) {
    std::vector<double> out = r;
    for (std::size_t i = 0; i < n; ++i) out[i] += shift[i];
    return out;
  };
  for (int b = 0; b < o.bootstrap_samples; ++b) {
    std::map<int, int> times;
    for (std::size_t k = 0; k < units.size(); ++k) ++times[units[pick(rng)]];
    for (std::size_t i = 0; i < n; ++i) shift[i] = heldout[i] && noise_r[i] > 0.0 ? noise_r[i] * z(rng) : 0.0;
    Multiplicity m(n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      if (heldout[i] && times.count(items[i].unit)) m[i] = times[items[i].unit];
    const Refit* refit = refits.empty() ? nullptr : &refits[static_cast<std::size_t>(b) % refits.size()];
    const auto fitted = [&](int k) -> const std::vector<double>& {
      if (k < 0) return refit ? refit->baseline : baseline_residuals;
      const std::size_t c = static_cast<std::size_t>(k);
      if (refit)
        if (const auto it = refit->candidates.find(c); it != refit->candidates.end()) return it->second;
      return candidates[c].residuals;
    };
    const std::vector<double> before = shifted(fitted(-1));
    const double gap_before = gap(items, before, m), floor = gap(items, noise_r, m);
    const std::vector<double> baseline_lpd = log_density(before, predictive(items, before, s, train, baseline_variance));
    std::vector<Standing> standing;
    for (std::size_t c = 0; c < candidates.size(); ++c)
      standing.push_back(standing_of(items, shifted(fitted(static_cast<int>(c))), candidates[c].parameter_variance, s, train, baseline_lpd, gap_before, m,
                                     static_cast<int>(candidates.size())));
    const Decision k = decide(candidates, standing, m, o, gap_before, floor);
    const std::string winner =
        k.unexplained ? "unexplained" : k.index < 0 ? "none" : verdict_name(candidates[static_cast<std::size_t>(k.index)].effects);
    agree += winner == verdict;
    const double g = gap(items, shifted(fitted(chosen)), m);
    s1 += g, s2 += g * g;
  }
  const double B = o.bootstrap_samples;
  return {agree / B, B > 1 ? std::sqrt(std::max(0.0, (s2 - s1 * s1 / B) / (B - 1))) : 0.0};
}

bool alike_at_constant_speed(const std::vector<std::string>& a, const std::vector<std::string>& b) {
  return std::any_of(a.begin(), a.end(), [&](const std::string& e) {
    const std::vector<std::string>& t = rig::effect_info(e).alike_at_constant_speed;
    return std::any_of(b.begin(), b.end(), [&](const std::string& f) { return std::count(t.begin(), t.end(), f) > 0; });
  });
}

std::vector<std::string> alike_mechanisms(const std::vector<Candidate>& cs, int chosen, double gap_before, double floor) {
  std::vector<std::string> out;
  if (chosen < 0 || !(floor > 0.0)) return out;
  const std::vector<std::string>& verdict = cs[static_cast<std::size_t>(chosen)].effects;
  for (const Candidate& c : cs) {
    if (c.effects.size() != 1 || std::count(verdict.begin(), verdict.end(), c.effects.front())) continue;
    if (alike_at_constant_speed(verdict, c.effects) && halves_excess(c.heldout_gap_after, gap_before, floor)) out.push_back(c.effects.front());
  }
  return out;
}

double verdict_confidence(double agreement, const std::string& verdict, const DiagnosisOptions& o, bool shared) {
  if (verdict == "none") return agreement * o.none_reliability;
  return shared && verdict != "unexplained" ? 0.5 * agreement : agreement;
}

}  // namespace tribo::gap
