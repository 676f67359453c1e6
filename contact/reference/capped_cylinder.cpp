#include "contact/reference/capped_cylinder.h"

#include "contact/reference/active_set.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <stdexcept>
#include <vector>

namespace tribo::contact::reference {
namespace {

double strip_antiderivative(double t) { return t == 0.0 ? 0.0 : t * std::log(std::abs(t)) - t; }

}  // namespace

CappedCylinderContact capped_cylinder_contact(double load_per_length_N_per_m, double radius_m, double e_star_Pa, double cap_Pa,
                                              int strips) {
  const double w = load_per_length_N_per_m;
  if (!(w > 0.0) || !(radius_m > 0.0) || !(e_star_Pa > 0.0) || !(cap_Pa > 0.0) || strips < 40 || strips % 2 != 0)
    throw std::invalid_argument("capped_cylinder_contact: load, radius, E* and cap must be positive and strips an even number ≥ 40");
  const double half_width = std::sqrt(4.0 * w * radius_m / (std::numbers::pi * e_star_Pa));
  const double x_max = std::max(3.0 * half_width, 1.5 * w / (2.0 * cap_Pa)), dx = 2.0 * x_max / strips;
  const int n = strips;
  Eigen::VectorXd mid(n);
  for (int i = 0; i < n; ++i) mid(i) = -x_max + (i + 0.5) * dx;
  Eigen::MatrixXd influence(n, n);  // deflection at mid(i) per unit pressure on strip j (up to a constant)
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = mid(j) - 0.5 * dx, b = mid(j) + 0.5 * dx;
      influence(i, j) = -2.0 / (std::numbers::pi * e_star_Pa) * (strip_antiderivative(mid(i) - a) - strip_antiderivative(mid(i) - b));
    }
  const Eigen::VectorXd crown = (mid.array().square() / (2.0 * radius_m)).matrix();

  std::vector<Element> state(n);
  for (int i = 0; i < n; ++i) state[i] = std::abs(mid(i)) < half_width ? Element::elastic : Element::free;
  std::set<std::vector<Element>> seen;
  Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
  double approach = 0.0;
  for (int sweep = 0; sweep < 4 * n; ++sweep) {
    // The elastic strips' pressures and δ: gap = crown + influence p − δ = 0 on them, the load w.
    std::vector<int> e;
    p.setZero();
    int capped = 0;
    for (int i = 0; i < n; ++i) {
      if (state[i] == Element::plastic) p(i) = cap_Pa, ++capped;
      if (state[i] == Element::elastic) e.push_back(i);
    }
    const int m = static_cast<int>(e.size());
    const Eigen::VectorXd from_plastic = influence * p;
    if (m > 0) {
      Eigen::MatrixXd a = Eigen::MatrixXd::Zero(m + 1, m + 1);
      Eigen::VectorXd rhs(m + 1);
      for (int r = 0; r < m; ++r) {
        for (int c = 0; c < m; ++c) a(r, c) = influence(e[r], e[c]);
        a(r, m) = -1.0;
        rhs(r) = -crown(e[r]) - from_plastic(e[r]);
        a(m, r) = dx;
      }
      rhs(m) = w - dx * capped * cap_Pa;
      const Eigen::VectorXd solved = a.partialPivLu().solve(rhs);
      for (int r = 0; r < m; ++r) p(e[r]) = solved(r);
      approach = solved(m);
    } else if (dx * capped * cap_Pa < w) {
      // Every loaded strip at the cap and the load not carried: the contact widens by a strip each side.
      std::vector<Element> next = state;
      for (int i = 0; i < n; ++i)
        if (state[i] == Element::free && ((i > 0 && state[i - 1] == Element::plastic) || (i + 1 < n && state[i + 1] == Element::plastic)))
          next[i] = Element::elastic;
      if (next == state) throw std::runtime_error("capped_cylinder_contact: the domain cannot carry the load under the cap");
      state = next;
      continue;
    } else {
      // All the load at the cap: δ where the gap closes at the contact's edge.
      int edge = 0;
      for (int i = 0; i < n; ++i)
        if (state[i] == Element::plastic) edge = i;
      approach = crown(edge) + from_plastic(edge);
    }
    const Eigen::VectorXd gap = crown + influence * p - Eigen::VectorXd::Constant(n, approach);  // ≥ 0 free, 0 elastic, ≤ 0 plastic
    const double p_tol = 1e-10 * cap_Pa, gap_tol = 1e-10 * half_width * half_width / radius_m;
    const bool changed = update_active_sets(state, p, gap, cap_Pa, p_tol, gap_tol, seen);
    if (changed) continue;
    CappedCylinderContact out;
    for (int i = 0; i < n; ++i) {
      const double pi = std::clamp(p(i), 0.0, cap_Pa);
      out.strip_x_m.push_back(mid(i));
      out.strip_pressure_Pa.push_back(pi);
      if (pi <= 0.0) continue;
      out.contact_half_width_m = std::max(out.contact_half_width_m, std::abs(mid(i)) + 0.5 * dx);
      if (pi >= cap_Pa) out.plastic_half_width_m = std::max(out.plastic_half_width_m, std::abs(mid(i)) + 0.5 * dx);
      out.peak_pressure_Pa = std::max(out.peak_pressure_Pa, pi);
    }
    return out;
  }
  throw std::runtime_error("capped_cylinder_contact: the active-set iteration did not settle");
}

double pressure_at_Pa(const CappedCylinderContact& c, double x_m) {
  const std::vector<double>&x = c.strip_x_m, &p = c.strip_pressure_Pa;
  if (x.empty() || x_m < x.front() || x_m > x.back()) return 0.0;
  const std::size_t i = std::min(static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), x_m) - x.begin()), x.size() - 1);
  const double t = (x_m - x[i - 1]) / (x[i] - x[i - 1]);
  return (1.0 - t) * p[i - 1] + t * p[i];
}

}  // namespace tribo::contact::reference
