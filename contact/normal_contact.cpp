#include "contact/normal_contact.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace tribo::contact {
namespace {

enum class Control { load, approach };

// Below this many cells a loop's work is smaller than the cost of waking a thread team (and on
// a busy machine far smaller than a descheduled spinning thread), so it runs serially.
constexpr Eigen::Index kParallelMinCells = Eigen::Index{1} << 15;

void check_field(const ElasticHalfSpace& hs, const Eigen::ArrayXXd& f, const char* name) {
  const Grid& g = hs.grid();
  if (!g.holds(f)) {
    throw std::invalid_argument(std::string(name) + " is " + std::to_string(f.rows()) + " x " +
                                std::to_string(f.cols()) + " but the half-space grid is " + std::to_string(g.nx) +
                                " x " + std::to_string(g.ny));
  }
  if (!f.allFinite()) throw std::invalid_argument(std::string(name) + " holds NaN or infinite values");
}

// Euclidean projection onto {0 ≤ p ≤ cap, Σ p = target}: p = clamp(y − c, 0, cap) with the
// shift c solving S(c) = Σ clamp(y_i − c, 0, cap) = target. S is continuous, non-increasing and
// piecewise linear, so a Newton step on the current piece, kept inside a shrinking bracket
// [c_lo, c_hi] (bisection when it would leave it), ends exactly on the right piece.
double projection_shift(const Eigen::ArrayXXd& y, double cap, double target) {
  const Eigen::Index n = y.size();
  const double* yp = y.data();
  // Bracket: below c_lo every cell is at the cap (finite cap) or S(c) ≥ Σ y − n c ≥ target
  // (infinite cap); at c_hi every cell is at zero.
  const double y_min = y.minCoeff();
  double c_lo = std::isfinite(cap) ? y_min - cap : std::min(y_min, (y.sum() - target) / static_cast<double>(n));
  c_lo -= 1e-12 * std::abs(c_lo) + 1e-300;
  double c_hi = y.maxCoeff();
  double c = 0.0;
  if (c <= c_lo || c >= c_hi) c = 0.5 * (c_lo + c_hi);
  for (int it = 0; it < 200; ++it) {
    double sum = 0.0;
    long active = 0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : sum, active) schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double v = yp[i] - c;
      if (v >= cap) {
        sum += cap;
      } else if (v > 0.0) {
        sum += v;
        ++active;
      }
    }
    const double f = sum - target;
    if (std::abs(f) <= 1e-14 * target) break;
    (f > 0.0 ? c_lo : c_hi) = c;
    const double newton = active > 0 ? c + f / static_cast<double>(active) : c_hi + 1.0;
    c = (newton > c_lo && newton < c_hi) ? newton : 0.5 * (c_lo + c_hi);
    if (c_hi - c_lo <= 1e-15 * (std::abs(c_lo) + std::abs(c_hi))) break;
  }
  return c;
}

NormalContactResult solve(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h0, Control control, double value,
                          const NormalContactOptions& opt, const Eigen::ArrayXXd* warm) {
  std::string why;
  if (!opt.is_valid(&why)) throw std::invalid_argument("normal contact options: " + why);
  check_field(hs, h0, "initial gap");
  if (warm != nullptr) check_field(hs, *warm, "warm-start pressure");
  const Grid& grid = hs.grid();
  const Eigen::Index n = h0.size();
  const double cell = grid.cell_area_m2();
  const double cap = opt.pressure_cap_Pa;
  const double target = control == Control::load ? value / cell : 0.0;  // Σ p_i for load control
  if (control == Control::load) {
    if (!(std::isfinite(value) && value > 0.0)) throw std::invalid_argument("normal load must be positive and finite");
    if (target > cap * static_cast<double>(n) * (1.0 + 1e-12)) {
      std::ostringstream os;
      os << "normal load " << value << " N exceeds the saturation load p_cap * area = " << cap * grid.area_m2()
         << " N: the whole domain would flow plastically";
      throw std::invalid_argument(os.str());
    }
  } else if (!std::isfinite(value)) {
    throw std::invalid_argument("approach must be finite");
  }
  const int max_iterations = opt.max_iterations > 0
                                 ? opt.max_iterations
                                 : 1000 + 4 * static_cast<int>(std::max(grid.nx, grid.ny));

  Eigen::ArrayXXd p(grid.nx, grid.ny), u(grid.nx, grid.ny), t = Eigen::ArrayXXd::Zero(grid.nx, grid.ny),
      r(grid.nx, grid.ny), y(grid.nx, grid.ny);
  if (warm != nullptr) {
    p = warm->max(0.0).min(cap);
  } else if (control == Control::load) {
    p.setConstant(target / static_cast<double>(n));
  } else {
    p.setZero();
  }
  if (control == Control::load) {
    y = p;
    p = (y - projection_shift(y, cap, target)).max(0.0).min(cap);
  }

  double* pp = p.data();
  double* up = u.data();
  double* tp = t.data();
  double* rp = r.data();
  double* yp = y.data();
  const double* hp = h0.data();
  const double hscale = (h0 - h0.mean()).matrix().norm();

  bool exact_u = false;  // u = G p by FFT rather than updated incrementally
  bool conjugate = false;
  double g_norm_old = 1.0, step = 1.0 / hs.self_compliance_m_per_Pa(), delta = value, residual = 0.0;
  int it = 0, since_exact = 0, fft_pairs = 0;
  bool converged = false;
  for (;; ++it) {
    if (!exact_u || since_exact >= 32) {
      hs.displacement(p, u);
      ++fft_pairs;
      exact_u = true;
      since_exact = 0;
    }
    // Load control: δ is the mean of h + u over the free cells, which makes their mean gap zero.
    if (control == Control::load) {
      double sum_free = 0.0, plastic_max = -std::numeric_limits<double>::infinity(),
             open_min = std::numeric_limits<double>::infinity();
      long free = 0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : sum_free, free) reduction(max : plastic_max) \
    reduction(min : open_min) schedule(static)
      for (Eigen::Index i = 0; i < n; ++i) {
        const double g = hp[i] + up[i];
        if (pp[i] <= 0.0) {
          open_min = std::min(open_min, g);
        } else if (pp[i] >= cap) {
          plastic_max = std::max(plastic_max, g);
        } else {
          sum_free += g;
          ++free;
        }
      }
      // Without free cells δ is only bracketed: plastic cells need δ ≥ h + u, open ones δ ≤ h + u.
      // Take the smallest admissible approach, or the middle of an empty bracket.
      if (free > 0) {
        delta = sum_free / static_cast<double>(free);
      } else if (!std::isfinite(open_min) || plastic_max <= open_min) {
        delta = plastic_max;
      } else {
        delta = 0.5 * (plastic_max + open_min);
      }
    }
    // Residual of the contact conditions against the elastic scale ‖u − ū‖₂; the free-cell
    // gradient norm and Σ t_old over the free cells for the conjugate direction.
    double res2 = 0.0, usum = 0.0, usq = 0.0, g_norm = 0.0, t_old_sum = 0.0;
    long free = 0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : res2, usum, usq, g_norm, t_old_sum, free) \
    schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double g = hp[i] + up[i] - delta;
      double ri;
      if (pp[i] <= 0.0) {
        ri = std::min(g, 0.0);
      } else if (pp[i] >= cap) {
        ri = std::max(g, 0.0);
      } else {
        ri = g;
        g_norm += g * g;
        t_old_sum += tp[i];
        ++free;
      }
      res2 += ri * ri;
      usum += up[i];
      usq += up[i] * up[i];
    }
    const double uvar = std::max(usq - usum * usum / static_cast<double>(n), 0.0);
    residual = std::sqrt(res2) / std::max(std::sqrt(uvar), 1e-300 + 1e-12 * hscale);
    if (!std::isfinite(residual)) break;
    if (residual <= opt.tolerance) {
      if (since_exact == 0) {
        converged = true;
        break;
      }
      exact_u = false;  // confirm on an exactly recomputed displacement
      --it;
      continue;
    }
    if (it >= max_iterations) break;

    // Conjugate direction on the free cells (Polonsky & Keer), made mean-free there for load
    // control so that a step along it keeps Σ p. The gap has zero mean over the free cells
    // (that defines δ), so the mean of g + β t_old is β Σ t_old / free.
    const double beta = conjugate ? g_norm / g_norm_old : 0.0;
    g_norm_old = g_norm;
    const double tmean = control == Control::load && free > 0 ? beta * t_old_sum / static_cast<double>(free) : 0.0;
#pragma omp parallel for if (n >= kParallelMinCells) schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      tp[i] = (pp[i] > 0.0 && pp[i] < cap) ? hp[i] + up[i] - delta + beta * tp[i] - tmean : 0.0;
    }
    // Step τ = Σ g t / Σ (G t) t over the free cells (exact line minimum along t).
    hs.displacement(t, r);
    ++fft_pairs;
    double num = 0.0, den = 0.0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : num, den) schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      if (pp[i] > 0.0 && pp[i] < cap) {
        num += (hp[i] + up[i] - delta) * tp[i];
        den += rp[i] * tp[i];
      }
    }
    const bool cg_step = free > 0 && den > 0.0 && std::isfinite(num / den) && num / den > 0.0;
    if (cg_step) step = num / den;
    // Trial pressure y: the CG step on free cells, a gradient step of the same length on the
    // others (Polonsky & Keer's recovery: overlapping cells out of contact gain pressure, opening
    // plastic cells lose it). Then p = clamp(y − c, 0, cap), the projection onto the
    // constraints, with c = 0 unless the clamped sum misses the load. Fused in one pass: the
    // clamp at c = 0, its sum, the count of cells that change set, and u − τ G t.
    long changed = 0;
    double clamped_sum = 0.0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : changed, clamped_sum) schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double g = hp[i] + up[i] - delta;
      const bool was_free = pp[i] > 0.0 && pp[i] < cap;
      if (was_free) {
        yp[i] = cg_step ? pp[i] - step * tp[i] : pp[i];
      } else {
        yp[i] = pp[i] - step * g;
      }
      const double v = std::clamp(yp[i], 0.0, cap);
      if (was_free != (v > 0.0 && v < cap) || (!was_free && v != pp[i])) ++changed;
      pp[i] = v;
      clamped_sum += v;
      if (cg_step) up[i] -= step * rp[i];
    }
    // With no cell changing set, Σ t = 0 on the free cells makes the load mismatch pure round-off
    // (~1e-16 relative per step); shifting for it would force a fresh u = G p every iteration.
    if (control == Control::load && (changed > 0 || std::abs(clamped_sum - target) > 1e-10 * target)) {
      const double shift = projection_shift(y, cap, target);
      long shifted_changed = 0;
#pragma omp parallel for if (n >= kParallelMinCells) reduction(+ : shifted_changed) schedule(static)
      for (Eigen::Index i = 0; i < n; ++i) {
        const double v = std::clamp(yp[i] - shift, 0.0, cap);
        if (v != pp[i]) ++shifted_changed;
        pp[i] = v;
      }
      changed += shifted_changed;
    }
    // Conjugacy is kept through recovery steps: restarting CG whenever a cell enters, as
    // Polonsky & Keer do, cost 2.4× (512²) to 3.7× (1024²) the iterations on rough surfaces.
    conjugate = cg_step;
    if (changed == 0 && cg_step) {
      ++since_exact;  // same free set, nothing projected: u − τ G t is exact
    } else {
      exact_u = false;
    }
  }

  NormalContactResult out;
  if (since_exact != 0) hs.displacement(p, u);
  out.pressure_Pa = p;
  out.displacement_m = u;
  const Eigen::ArrayXXd g = h0 + u - delta;
  out.gap_m = g.max(0.0);
  out.plastic_increment_m = (p >= cap).select((-g).max(0.0), 0.0);
  out.approach_m = delta;
  out.normal_load_N = p.sum() * cell;
  const double contact_cells = static_cast<double>((p > 0.0).count());
  out.real_area_m2 = contact_cells * cell;
  out.plastic_area_m2 = static_cast<double>((p >= cap).count()) * cell;
  out.area_fraction = contact_cells / static_cast<double>(n);
  out.max_pressure_Pa = p.maxCoeff();
  out.mean_gap_m = out.gap_m.mean();
  out.summary.converged = converged;
  out.summary.iterations = it;
  out.summary.residual = residual;
  out.summary.fft_pairs = fft_pairs + (since_exact != 0 ? 1 : 0);
  std::ostringstream msg;
  if (converged) {
    msg << "converged in " << it << " iterations, residual " << residual << " <= " << opt.tolerance;
  } else if (!std::isfinite(residual)) {
    msg << "diverged: non-finite residual after " << it << " iterations";
  } else {
    msg << "not converged: residual " << residual << " > tolerance " << opt.tolerance << " after " << it
        << " iterations";
  }
  out.summary.message = msg.str();
  return out;
}

}  // namespace

bool NormalContactOptions::is_valid(std::string* why) const {
  auto fail = [&](const char* m) {
    if (why != nullptr) *why = m;
    return false;
  };
  if (!(tolerance > 0.0 && tolerance < 1.0)) return fail("tolerance must lie in (0, 1)");
  if (max_iterations < 0) return fail("max_iterations must be >= 0");
  if (!(pressure_cap_Pa > 0.0)) return fail("pressure cap (hardness) must be positive");
  return true;
}

NormalContactResult solve_normal_load(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h0, double w,
                                      const NormalContactOptions& opt, const Eigen::ArrayXXd* warm) {
  return solve(hs, h0, Control::load, w, opt, warm);
}

NormalContactResult solve_approach(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h0, double approach_m,
                                   const NormalContactOptions& opt, const Eigen::ArrayXXd* warm) {
  return solve(hs, h0, Control::approach, approach_m, opt, warm);
}

NormalContactResult solve_mean_gap(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h0, double mean_gap_m,
                                   const NormalContactOptions& opt, const Eigen::ArrayXXd* warm) {
  if (!hs.periodic()) throw std::invalid_argument("mean-gap control needs a periodic half-space");
  if (!(std::isfinite(mean_gap_m) && mean_gap_m >= 0.0)) throw std::invalid_argument("mean gap must be >= 0 and finite");
  check_field(hs, h0, "initial gap");
  return solve(hs, h0, Control::approach, h0.mean() - mean_gap_m, opt, warm);
}

std::vector<LoadGapPoint> load_gap_curve(ElasticHalfSpace& hs, const Eigen::ArrayXXd& h0,
                                         const std::vector<double>& loads, const NormalContactOptions& opt) {
  for (std::size_t k = 0; k < loads.size(); ++k) {
    if (!(std::isfinite(loads[k]) && loads[k] > 0.0) || (k > 0 && !(loads[k] > loads[k - 1]))) {
      throw std::invalid_argument("load-gap curve: loads must be positive, finite and strictly increasing");
    }
  }
  std::vector<LoadGapPoint> curve;
  Eigen::ArrayXXd warm;
  for (double w : loads) {
    const NormalContactResult r = solve_normal_load(hs, h0, w, opt, warm.size() > 0 ? &warm : nullptr);
    curve.push_back({r.normal_load_N, r.mean_gap_m, r.approach_m, r.real_area_m2, r.summary});
    warm = r.pressure_Pa;
  }
  return curve;
}

Eigen::ArrayXXd gap_from_heights(const Eigen::ArrayXXd& z) {
  if (z.size() == 0 || !z.allFinite()) throw std::invalid_argument("surface heights must be finite and non-empty");
  return z.maxCoeff() - z;
}

Eigen::ArrayXXd sphere_gap(const Grid& grid, double radius_m) {
  validate(grid);
  if (!(std::isfinite(radius_m) && radius_m > 0.0)) throw std::invalid_argument("sphere radius_m must be positive");
  Eigen::ArrayXXd h = grid.field();
  for (Eigen::Index j = 0; j < grid.ny; ++j) {
    const double y = (static_cast<double>(j) + 0.5) * grid.dy_m - 0.5 * grid.period_y_m();
    for (Eigen::Index i = 0; i < grid.nx; ++i) {
      const double x = (static_cast<double>(i) + 0.5) * grid.dx_m - 0.5 * grid.period_x_m();
      h(i, j) = (x * x + y * y) / (2.0 * radius_m);
    }
  }
  return h;
}

}  // namespace tribo::contact
