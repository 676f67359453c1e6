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

}  // namespace tribo::gap
