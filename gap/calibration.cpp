#include "gap/calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>

namespace tribo::gap {

FrictionLevels friction_levels_from_data(const std::vector<Item>& items, const FrictionLevels& fallback) {
  std::map<std::string, std::pair<double, int>> m;
  for (const Item& it : items) m[it.observable].first += it.measured, ++m[it.observable].second;
  const auto avg = [&](const char* k) { return m.count(k) ? m[k].first / m[k].second : std::numeric_limits<double>::quiet_NaN(); };
  double mu_s = avg("mu_peak");
  if (!std::isfinite(mu_s)) mu_s = avg("mu_s_vs_load_rate");
  double mu_k = std::isfinite(avg("mu_trough")) && std::isfinite(avg("mu_peak")) ? 0.5 * (avg("mu_peak") + avg("mu_trough")) : avg("steady_mu");
  if (!std::isfinite(mu_k)) mu_k = avg("mean_mu");
  if (!std::isfinite(mu_s)) mu_s = std::isfinite(mu_k) ? mu_k : fallback.mu_s;
  if (!std::isfinite(mu_k)) mu_k = fallback.mu_k;
  FrictionLevels out;
  out.mu_s = std::clamp(mu_s, 0.011, 1.49);
  out.mu_k = std::clamp(mu_k, 0.05 * out.mu_s, out.mu_s);
  return out;
}

Healing healing_from_data(const std::vector<Item>& items, const std::vector<bool>& use) {
  std::vector<const Item*> peaks;
  for (std::size_t i = 0; i < items.size(); ++i)
    if (use[i] && items[i].observable == "peak_after_hold" && items[i].hold_s > 0.0 && items[i].v_m_per_s > 0.0) peaks.push_back(&items[i]);
  Healing best;
  if (peaks.size() < 2) return best;
  // Growth with the hold: the peaks' covariance with ln t_h must be positive.
  double mean_l = 0.0, mean_y = 0.0, cov = 0.0;
  for (const Item* p : peaks) mean_l += std::log(p->hold_s) / peaks.size(), mean_y += p->measured / peaks.size();
  for (const Item* p : peaks) cov += (std::log(p->hold_s) - mean_l) * (p->measured - mean_y);
  if (!(cov > 0.0)) return best;
  double best_sse = std::numeric_limits<double>::infinity();
  constexpr int kPerDecade = 20;
  for (int j = 0; j <= 6 * kPerDecade; ++j) {
    const double dc = 1e-8 * std::pow(10.0, static_cast<double>(j) / kPerDecade);
    double gg = 0.0, gy = 0.0, yy = 0.0;
    for (const Item* p : peaks) {
      const double g = std::log1p(p->hold_s * p->v_m_per_s / dc);
      gg += g * g, gy += g * p->measured, yy += p->measured * p->measured;
    }
    if (!(gg > 0.0)) continue;
    const double b = gy / gg, sse = yy - b * gy;
    if (b > 0.0 && sse < best_sse) best_sse = sse, best = {b, dc};
  }
  return best;
}

}  // namespace tribo::gap
