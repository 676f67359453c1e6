#include "contact/reference/capped_sphere.h"

#include "contact/reference/active_set.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <set>
#include <vector>

namespace tribo::contact::reference {
namespace {

// Deflection at radius r per unit pressure on a disc of radius a (Johnson (3.33)), times E*.
double disc_deflection(double r, double a) {
  if (a <= 0.0) return 0.0;
  const double c = 4.0 / std::numbers::pi;
  if (r <= a) return c * a * std::comp_ellint_2(r / a);
  const double k = a / r;
  return c * r * (std::comp_ellint_2(k) - (1.0 - k * k) * std::comp_ellint_1(k));
}

struct Loaded {
  Eigen::VectorXd pressure;
  double load = 0.0;
};

}  // namespace

CappedSphereContact capped_sphere_contact(double load_N, double radius_m, double e_star_Pa, double cap_Pa, int rings) {
  if (!(load_N > 0.0) || !(radius_m > 0.0) || !(e_star_Pa > 0.0) || !(cap_Pa > 0.0) || rings < 20)
    throw std::invalid_argument("capped_sphere_contact: load, radius, E* and cap must be positive and rings ≥ 20");
  const double hertz_radius = std::cbrt(3.0 * load_N * radius_m / (4.0 * e_star_Pa));
  const double plastic_radius = std::sqrt(load_N / (std::numbers::pi * cap_Pa));
  const double r_max = std::max(4.0 * hertz_radius, 2.0 * plastic_radius), dr = r_max / rings;
  const int n = rings;
  Eigen::VectorXd mid(n), ring_area(n);
  for (int i = 0; i < n; ++i) {
    mid(i) = (i + 0.5) * dr;
    ring_area(i) = std::numbers::pi * dr * dr * ((i + 1.0) * (i + 1.0) - 1.0 * i * i);
  }
  Eigen::MatrixXd influence(n, n);  // deflection at mid(i) per unit pressure on ring j
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      influence(i, j) = (disc_deflection(mid(i), (j + 1) * dr) - disc_deflection(mid(i), j * dr)) / e_star_Pa;

  // The pressure for the approach δ: active sets on the target deflection t = δ − r²/2R.
  auto solve = [&](double approach) {
    const Eigen::VectorXd target = (approach - mid.array().square() / (2.0 * radius_m)).matrix();
    std::vector<Element> state(n);
    for (int i = 0; i < n; ++i) state[i] = target(i) > 0.0 ? Element::elastic : Element::free;
    Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
    std::set<std::vector<Element>> seen;
    for (int sweep = 0; sweep < 4 * n; ++sweep) {
      std::vector<int> e;
      p.setZero();
      for (int i = 0; i < n; ++i) {
        if (state[i] == Element::plastic) p(i) = cap_Pa;
        if (state[i] == Element::elastic) e.push_back(i);
      }
      if (!e.empty()) {
        const int m = static_cast<int>(e.size());
        Eigen::MatrixXd a(m, m);
        Eigen::VectorXd b(m);
        const Eigen::VectorXd from_plastic = influence * p;
        for (int r = 0; r < m; ++r) {
          b(r) = target(e[r]) - from_plastic(e[r]);
          for (int c = 0; c < m; ++c) a(r, c) = influence(e[r], e[c]);
        }
        const Eigen::VectorXd pe = a.partialPivLu().solve(b);
        for (int r = 0; r < m; ++r) p(e[r]) = pe(r);
      }
      // Tolerances of 1e-10 of the scales keep round-off from flipping a ring (active_set.h); on a
      // cycle the clipped pressures of this state are returned.
      const Eigen::VectorXd gap = influence * p - target;  // ≥ 0 free, = 0 elastic, ≤ 0 plastic
      const double p_tol = 1e-10 * cap_Pa, gap_tol = 1e-10 * std::max(approach, 1e-300);
      const bool changed = update_active_sets(state, p, gap, cap_Pa, p_tol, gap_tol, seen);
      if (!changed) {
        const Eigen::VectorXd clipped = p.cwiseMax(0.0).cwiseMin(cap_Pa);
        return Loaded{clipped, ring_area.dot(clipped)};
      }
    }
    throw std::runtime_error("capped_sphere_contact: the active-set iteration did not settle");
  };

  double lo = 0.0, hi = hertz_radius * hertz_radius / radius_m;
  while (solve(hi).load < load_N) {
    lo = hi;
    hi *= 2.0;
    if (std::sqrt(2.0 * radius_m * hi) > r_max)
      throw std::runtime_error("capped_sphere_contact: the domain cannot carry the load under the cap");
  }
  for (int k = 0; k < 200 && hi - lo > 1e-10 * hi; ++k) {
    const double mid_approach = 0.5 * (lo + hi);
    (solve(mid_approach).load < load_N ? lo : hi) = mid_approach;
  }
  const double approach = 0.5 * (lo + hi);
  const Loaded s = solve(approach);
  CappedSphereContact out;
  out.approach_m = approach;
  for (int i = 0; i < n; ++i) {
    out.ring_radius_m.push_back((i + 0.5) * dr);
    out.ring_pressure_Pa.push_back(s.pressure(i));
    if (s.pressure(i) <= 0.0) continue;
    out.area_m2 += ring_area(i);
    out.contact_radius_m = (i + 1) * dr;
    if (s.pressure(i) >= cap_Pa) out.plastic_radius_m = (i + 1) * dr;
    out.peak_pressure_Pa = std::max(out.peak_pressure_Pa, s.pressure(i));
  }
  return out;
}

double pressure_at_Pa(const CappedSphereContact& c, double r_m) {
  const std::vector<double>&r = c.ring_radius_m, &p = c.ring_pressure_Pa;
  if (r.empty() || r_m > r.back()) return 0.0;
  if (r_m <= r.front()) return p.front();
  const std::size_t i = static_cast<std::size_t>(std::upper_bound(r.begin(), r.end(), r_m) - r.begin());
  const double t = (r_m - r[i - 1]) / (r[i] - r[i - 1]);
  return (1.0 - t) * p[i - 1] + t * p[i];
}

}  // namespace tribo::contact::reference
