#include "contact/greenwood_williamson.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace tribo::contact {

void validate(const GreenwoodWilliamson& gw) {
  auto positive = [](double v, const char* name) {
    if (!(std::isfinite(v) && v > 0.0)) throw std::invalid_argument(std::string("Greenwood-Williamson: ") + name + " must be positive");
  };
  positive(gw.summit_density_per_m2, "summit_density_per_m2");
  positive(gw.summit_radius_m, "summit_radius_m");
  positive(gw.summit_std_m, "summit_std_m");
  positive(gw.e_star_Pa, "e_star_Pa");
}

double gw_integral(SummitDistribution dist, double k, double h) {
  if (dist == SummitDistribution::exponential) {
    // Heights start at s = 0: below it every summit is in contact and F_k = ∫_0^∞ (s − h)^k e^{−s} ds.
    if (h >= 0.0) return std::tgamma(k + 1.0) * std::exp(-h);
    if (k == 0.0) return 1.0;
    if (k == 1.0) return 1.0 - h;
    // General k for h < 0: composite Simpson on [0, 40] (e^{-40} is below round-off).
    const int m = 4000;
    const double step = 40.0 / m;
    double sum = 0.0;
    for (int i = 0; i <= m; ++i) {
      const double s = i * step;
      const double v = std::pow(s - h, k) * std::exp(-s);
      sum += v * (i == 0 || i == m ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
    }
    return sum * step / 3.0;
  }
  const double phi = std::exp(-0.5 * h * h) / std::sqrt(2.0 * std::numbers::pi);
  const double tail = 0.5 * std::erfc(h / std::numbers::sqrt2);
  if (k == 0.0) return tail;
  if (k == 1.0) return phi - h * tail;
  // F_k by substitution s = h + x: ∫_0^∞ x^k φ(h + x) dx. For k = 3/2 the integrand vanishes
  // like x^{3/2} at 0; substitute x = v² to make it smooth (2 v^{2k+1} φ(h + v²)), then Simpson
  // on v ∈ [0, v_max] where φ has decayed below 1e-300 of its peak on [h, ∞).
  const double x_max = std::max(0.0, -h) + 40.0;
  const double v_max = std::sqrt(x_max);
  const int m = 4000;
  const double step = v_max / m;
  double sum = 0.0;
  for (int i = 0; i <= m; ++i) {
    const double v = i * step, s = h + v * v;
    const double f = 2.0 * std::pow(v, 2.0 * k + 1.0) * std::exp(-0.5 * s * s) / std::sqrt(2.0 * std::numbers::pi);
    sum += f * (i == 0 || i == m ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0));
  }
  return sum * step / 3.0;
}

GwState gw_at_separation(const GreenwoodWilliamson& gw, double d) {
  validate(gw);
  if (!std::isfinite(d)) throw std::invalid_argument("Greenwood-Williamson: separation must be finite");
  const double h = d / gw.summit_std_m;
  GwState s;
  s.separation_m = d;
  s.summits_per_m2 = gw.summit_density_per_m2 * gw_integral(gw.distribution, 0.0, h);
  s.area_fraction = std::numbers::pi * gw.summit_density_per_m2 * gw.summit_radius_m * gw.summit_std_m *
                    gw_integral(gw.distribution, 1.0, h);
  s.pressure_Pa = 4.0 / 3.0 * gw.summit_density_per_m2 * gw.e_star_Pa * std::sqrt(gw.summit_radius_m) *
                  std::pow(gw.summit_std_m, 1.5) * gw_integral(gw.distribution, 1.5, h);
  return s;
}

GwState gw_at_pressure(const GreenwoodWilliamson& gw, double pressure) {
  validate(gw);
  if (!(std::isfinite(pressure) && pressure > 0.0)) {
    throw std::invalid_argument("Greenwood-Williamson: nominal pressure must be positive");
  }
  // Bracket the separation in units of σ_s: pressure falls monotonically with d.
  double lo = -10.0, hi = 10.0;
  while (gw_at_separation(gw, lo * gw.summit_std_m).pressure_Pa < pressure) lo *= 2.0;
  while (gw_at_separation(gw, hi * gw.summit_std_m).pressure_Pa > pressure && hi < 1e3) hi *= 1.5;
  for (int i = 0; i < 200 && hi - lo > 1e-13 * std::max(1.0, std::abs(hi)); ++i) {
    const double mid = 0.5 * (lo + hi);
    (gw_at_separation(gw, mid * gw.summit_std_m).pressure_Pa > pressure ? lo : hi) = mid;
  }
  return gw_at_separation(gw, 0.5 * (lo + hi) * gw.summit_std_m);
}

GreenwoodWilliamson gw_from_statistics(const SurfaceStatistics& st, double e_star_Pa, SummitDistribution dist) {
  if (!(st.rq_m > 0.0 && st.rms_slope > 0.0 && st.rms_curvature_per_m > 0.0)) {
    throw std::invalid_argument("Greenwood-Williamson: surface needs positive Rq, rms slope and rms curvature");
  }
  const double m0 = st.rq_m * st.rq_m;
  const double m2 = 0.5 * st.rms_slope * st.rms_slope;
  // ⟨(∇²h)²⟩ = 4 ⟨(½∇²h)²⟩ and m4 = (3/8) ⟨(∇²h)²⟩ for an isotropic surface.
  const double m4 = 1.5 * st.rms_curvature_per_m * st.rms_curvature_per_m;
  GreenwoodWilliamson gw;
  gw.summit_density_per_m2 = m4 / (6.0 * std::numbers::pi * std::sqrt(3.0) * m2);
  gw.summit_radius_m = 0.375 * std::sqrt(std::numbers::pi / m4);
  const double var = m0 - 3.717e-4 / std::pow(gw.summit_density_per_m2 * gw.summit_radius_m, 2);
  if (!(var > 0.0)) {
    throw std::invalid_argument("Greenwood-Williamson: spectrum too narrow for McCool's summit statistics "
                                "(m0 - 3.717e-4/(eta beta)^2 <= 0)");
  }
  gw.summit_std_m = std::sqrt(var);
  gw.e_star_Pa = e_star_Pa;
  gw.distribution = dist;
  validate(gw);
  return gw;
}

}  // namespace tribo::contact
