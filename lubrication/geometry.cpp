#include "lubrication/geometry.h"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace tribo::lubrication {

ReynoldsProblem parallel_discs_problem(double radius_m, double gap_m, double gap_rate_m_per_s, double viscosity_Pa_s,
                                       double sliding_speed_m_per_s, int n) {
  if (n < 5) throw std::invalid_argument("parallel discs: grid n must be >= 5 (got " + std::to_string(n) + ")");
  if (!(std::isfinite(radius_m) && radius_m > 0))
    throw std::invalid_argument("parallel discs: radius_m must be finite and > 0");
  ReynoldsProblem pr;
  const double d = 2.0 * radius_m / (n - 3);
  pr.grid = Grid{n, n, d, d};
  pr.gap_m.assign(pr.grid.size(), gap_m);
  pr.gap_rate_m_per_s.assign(pr.grid.size(), gap_rate_m_per_s);
  pr.viscosity_Pa_s = viscosity_Pa_s;
  pr.sliding_speed_m_per_s = sliding_speed_m_per_s;
  const double c = 0.5 * (n - 1) * d;
  pr.disc = DiscDomain{c, c, radius_m};
  return pr;
}

std::vector<double> rough_pair_gap_m(const std::vector<double>& upper, const std::vector<double>& lower,
                                     double mean_gap_m, double min_gap_m, std::size_t* contact_nodes) {
  if (upper.size() != lower.size() || upper.empty())
    throw std::invalid_argument("rough pair: the two surfaces must be non-empty and on the same grid");
  if (!(std::isfinite(mean_gap_m) && mean_gap_m > 0)) throw std::invalid_argument("rough pair: mean_gap_m must be > 0");
  if (!(std::isfinite(min_gap_m) && min_gap_m > 0 && min_gap_m < mean_gap_m))
    throw std::invalid_argument("rough pair: min_gap_m must be in (0, mean_gap_m)");
  const double n = static_cast<double>(upper.size());
  const double mu = std::accumulate(upper.begin(), upper.end(), 0.0) / n;
  const double ml = std::accumulate(lower.begin(), lower.end(), 0.0) / n;
  std::vector<double> h(upper.size());
  std::size_t touching = 0;
  for (std::size_t k = 0; k < h.size(); ++k) {
    if (!std::isfinite(upper[k]) || !std::isfinite(lower[k])) throw std::invalid_argument("rough pair: non-finite height");
    h[k] = mean_gap_m + (upper[k] - mu) - (lower[k] - ml);
    if (h[k] < min_gap_m) {
      h[k] = min_gap_m;
      ++touching;
    }
  }
  if (contact_nodes) *contact_nodes = touching;
  return h;
}

}  // namespace tribo::lubrication
