#include "contact/normal_contact.h"

#include <omp.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

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
// What a pass over y already knows, so the projection can skip its own first passes: S(0),
// the cells strictly inside (0, cap) at c = 0, min y and max y.
struct ShiftStart {
  double sum0 = 0.0;
  long active0 = 0;
  double y_min = 0.0, y_max = 0.0;
};

double projection_shift(const Eigen::ArrayXXd& y, double cap, double target, const ShiftStart* start = nullptr) {
  const Eigen::Index n = y.size();
  const double* yp = y.data();
  // Bracket: below c_lo every cell is at the cap (finite cap) or S(c) ≥ Σ y − n c ≥ target
  // (infinite cap); at c_hi every cell is at zero.
  double c_lo, c_hi, c = 0.0;
  if (start == nullptr) {
    const double y_min = y.minCoeff();
    c_lo = std::isfinite(cap) ? y_min - cap : std::min(y_min, (y.sum() - target) / static_cast<double>(n));
    c_hi = y.maxCoeff();
  } else {
    // With S(0) known the root lies on one side of 0; on the other side the bracket is as above
    // (for an infinite cap, at y_min − target/n every cell holds more than target/n).
    c_lo = std::isfinite(cap) ? start->y_min - cap : start->y_min - target / static_cast<double>(n);
    c_hi = start->y_max;
    if (start->sum0 > target) {
      c_lo = std::max(c_lo, 0.0);
    } else {
      c_hi = std::min(c_hi, 0.0);
    }
    if (start->active0 > 0) c = (start->sum0 - target) / static_cast<double>(start->active0);
  }
  c_lo -= 1e-12 * std::abs(c_lo) + 1e-300;
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

// Which of the three sets a cell belongs to, from its pressure (or trial value) q.
enum CellSet : int { kOpen = 0, kFree = 1, kPlastic = 2 };
inline int cell_set(double q, double cap) { return q <= 0.0 ? kOpen : (q >= cap ? kPlastic : kFree); }

// What the iteration needs to know about the sets after a pass over the grid, with v = h + u:
// the free cells' sums of v − ref (ref a nearby approach, so that the rms gap Σ (v − δ)² follows
// from them without cancellation), the bracket of δ when nothing is free, Σ p, and the extreme
// trial values per set (they tell whether a uniform load shift keeps every cell in its set).
struct SetStats {
  long free = 0;
  double s1 = 0.0, s2 = 0.0;  // Σ_F (v − ref), Σ_F (v − ref)²
  double t_sum = 0.0;         // Σ_F t of the direction the pass saw
  double plastic_v_max = -std::numeric_limits<double>::infinity();
  double open_v_min = std::numeric_limits<double>::infinity();
  double load = 0.0;  // Σ clamp(q, 0, cap)
  double free_q_min = std::numeric_limits<double>::infinity(), free_q_max = -std::numeric_limits<double>::infinity();
  double open_q_max = -std::numeric_limits<double>::infinity();
  double plastic_q_min = std::numeric_limits<double>::infinity();
  double q_min = std::numeric_limits<double>::infinity(), q_max = -std::numeric_limits<double>::infinity();
  long changed = 0;     // update pass: cells whose set or (outside the free set) pressure changed
  double drift2 = 0.0;  // update pass: Σ e², e = pressure change not along the CG direction

  void add(double q, double v, double t, double ref, double cap) {
    q_min = std::min(q_min, q);
    q_max = std::max(q_max, q);
    switch (cell_set(q, cap)) {
      case kOpen:
        open_v_min = std::min(open_v_min, v);
        open_q_max = std::max(open_q_max, q);
        break;
      case kPlastic:
        plastic_v_max = std::max(plastic_v_max, v);
        plastic_q_min = std::min(plastic_q_min, q);
        load += cap;
        break;
      default: {
        const double d = v - ref;
        ++free;
        s1 += d;
        s2 += d * d;
        t_sum += t;
        load += q;
        free_q_min = std::min(free_q_min, q);
        free_q_max = std::max(free_q_max, q);
      }
    }
  }
  void merge(const SetStats& o) {
    free += o.free;
    s1 += o.s1;
    s2 += o.s2;
    t_sum += o.t_sum;
    plastic_v_max = std::max(plastic_v_max, o.plastic_v_max);
    open_v_min = std::min(open_v_min, o.open_v_min);
    load += o.load;
    free_q_min = std::min(free_q_min, o.free_q_min);
    free_q_max = std::max(free_q_max, o.free_q_max);
    open_q_max = std::max(open_q_max, o.open_q_max);
    plastic_q_min = std::min(plastic_q_min, o.plastic_q_min);
    q_min = std::min(q_min, o.q_min);
    q_max = std::max(q_max, o.q_max);
    changed += o.changed;
    drift2 += o.drift2;
  }
};

struct DirectionStats {
  double res2 = 0.0, num = 0.0, g2 = 0.0;  // Σ r², Σ_F g t, Σ_F g²
  void merge(const DirectionStats& o) {
    res2 += o.res2;
    num += o.num;
    g2 += o.g2;
  }
};

struct ScaleStats {
  double usum = 0.0, usq = 0.0, err2 = 0.0;  // Σ u, Σ u², Σ (u_carried − G p)²
  SetStats sets;
  void merge(const ScaleStats& o) {
    usum += o.usum;
    usq += o.usq;
    err2 += o.err2;
    sets.merge(o.sets);
  }
};

// One statically scheduled pass over n cells; `body(i, acc)` accumulates into a thread-local
// Acc, and the partial results are merged in thread order, so a solve's bits depend on the
// thread count but not on the scheduling.
template <class Acc, class Body>
Acc grid_pass(Eigen::Index n, Body&& body) {
  const int threads = n >= kParallelMinCells ? std::max(1, omp_get_max_threads()) : 1;
  if (threads == 1) {
    Acc acc;
    for (Eigen::Index i = 0; i < n; ++i) body(i, acc);
    return acc;
  }
  std::vector<Acc> part(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    Acc local;  // thread-local, so the partial sums do not share cache lines
#pragma omp for schedule(static) nowait
    for (Eigen::Index i = 0; i < n; ++i) body(i, local);
    part[static_cast<std::size_t>(omp_get_thread_num())] = local;
  }
  Acc acc = part[0];
  for (std::size_t k = 1; k < part.size(); ++k) acc.merge(part[k]);
  return acc;
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
  const bool load_control = control == Control::load;
  const double target = load_control ? value / cell : 0.0;  // Σ p_i for load control
  if (load_control) {
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

  // State. The pressure is p = clamp(y − shift, 0, cap): y holds the last trial values, shift the
  // load-control projection of them (Euclidean projection onto Σ p = target, see
  // projection_shift), applied lazily by every pass instead of in a pass of its own. v = h + u,
  // carried incrementally between exact products. t_old / t_new: the last and the next search
  // direction (two buffers, so a re-synchronisation does not lose the conjugate direction);
  // r = G t_new.
  Eigen::ArrayXXd y(grid.nx, grid.ny), v(grid.nx, grid.ny), t_old = Eigen::ArrayXXd::Zero(grid.nx, grid.ny),
      t_new(grid.nx, grid.ny), r(grid.nx, grid.ny);
  double shift = 0.0;
  if (warm != nullptr) {
    y = warm->max(0.0).min(cap);
  } else if (load_control) {
    y.setConstant(target / static_cast<double>(n));
  } else {
    y.setZero();
  }
  if (load_control) shift = projection_shift(y, cap, target);

  const double* hp = h0.data();
  double* yp = y.data();
  double* vp = v.data();
  const double hscale = (h0 - h0.mean()).matrix().norm();
  const double c0 = hs.self_compliance_m_per_Pa();

  double delta = load_control ? 0.0 : value;  // approach; for load control the free cells' mean of v
  bool have_delta = !load_control;
  double scale = 0.0;         // ‖u − ū‖₂ at the last exact product
  double g_norm_est = 0.0;    // Σ_F (v − δ)² of the current state (from the last pass' sums)
  double t_sum = 0.0;         // Σ_F t_old over the current free set
  long free_count = 0;
  int fft_pairs = 0, resyncs = 0, since_sync = 0;
  double drift = 0.0;         // estimate of ‖u_carried − G p‖₂ (m)
  double last_error = 0.0, max_error = 0.0;  // measured ‖u_carried − G p‖₂ / ‖u − ū‖₂ at re-syncs

  // δ (load control) and Σ_F g² from a pass' set sums taken about `ref`.
  auto take_stats = [&](const SetStats& st, double ref) {
    free_count = st.free;
    t_sum = st.t_sum;
    if (!load_control) {
      g_norm_est = st.s2 - 2.0 * (delta - ref) * st.s1 + static_cast<double>(st.free) * (delta - ref) * (delta - ref);
      return true;
    }
    have_delta = true;
    if (st.free > 0) {
      const double mean = st.s1 / static_cast<double>(st.free);
      delta = ref + mean;
      g_norm_est = st.s2 - mean * st.s1;
      // Cancellation: Σ (v − ref)² ≫ Σ (v − δ)² leaves too few digits; the caller repeats the
      // pass about the new δ (rare: ref is the previous iteration's δ).
      return !(mean * st.s1 > 1e8 * g_norm_est) && g_norm_est >= 0.0;
    }
    // Without free cells δ is only bracketed: plastic cells need δ ≥ h + u, open ones δ ≤ h + u.
    // Take the smallest admissible approach, or the middle of an empty bracket.
    if (!std::isfinite(st.open_v_min) || st.plastic_v_max <= st.open_v_min) {
      delta = st.plastic_v_max;
    } else {
      delta = 0.5 * (st.plastic_v_max + st.open_v_min);
    }
    g_norm_est = 0.0;
    return true;
  };
  // The set sums of the current state (v, y − shift) with the direction t, about δ.
  auto set_pass = [&](const Eigen::ArrayXXd& t) {
    const double* tp = t.data();
    const double ref = delta;
    const SetStats st = grid_pass<SetStats>(n, [&](Eigen::Index i, SetStats& a) {
      a.add(yp[i] - shift, vp[i], tp[i], ref, cap);
    });
    if (!take_stats(st, ref)) take_stats(grid_pass<SetStats>(n, [&](Eigen::Index i, SetStats& a) {
                                            a.add(yp[i] - shift, vp[i], tp[i], delta, cap);
                                          }),
                                          delta);
  };
  // Exact re-synchronisation: v = h + G p, the elastic scale, the sets. t_new is scratch here.
  auto resync = [&] {
    double* sp = t_new.data();
#pragma omp parallel for if (n >= kParallelMinCells) schedule(static)
    for (Eigen::Index i = 0; i < n; ++i) sp[i] = std::clamp(yp[i] - shift, 0.0, cap);
    hs.displacement_and_energy(t_new, r);
    ++fft_pairs;
    ++resyncs;
    const double* rp = r.data();
    const double* tp = t_old.data();
    // Before the first exact product δ is unknown (load control); the mean of h + u is a
    // reference close enough for the sums (re-done about δ if not).
    const double ref = have_delta ? delta : (h0.mean() + r.mean());
    // v still holds the carried h + u: the pass measures its error (v is written anyway).
    const ScaleStats st = grid_pass<ScaleStats>(n, [&](Eigen::Index i, ScaleStats& a) {
      const double vi = hp[i] + rp[i];
      a.err2 += (vp[i] - vi) * (vp[i] - vi);
      vp[i] = vi;
      a.usum += rp[i];
      a.usq += rp[i] * rp[i];
      a.sets.add(yp[i] - shift, vi, tp[i], ref, cap);
    });
    scale = std::sqrt(std::max(st.usq - st.usum * st.usum / static_cast<double>(n), 0.0));
    if (since_sync > 0) {
      last_error = std::sqrt(st.err2) / std::max(scale, 1e-300);
      max_error = std::max(max_error, last_error);
    }
    if (!take_stats(st.sets, ref)) set_pass(t_old);
    drift = 0.0;
    since_sync = 0;
  };

  v.setZero();  // the first re-sync measures nothing (since_sync = 0) but reads v
  resync();
  bool conjugate = false, converged = false;
  double g_norm_old = 1.0, step = 1.0 / c0, residual = 0.0, res_abs = std::numeric_limits<double>::infinity();
  int it = 0;
  for (;;) {
    if (since_sync > 0 && (since_sync >= opt.resync_interval || drift > opt.resync_drift * res_abs)) resync();

    // Pass 1: the residual of the contact conditions (against the elastic scale ‖u − ū‖₂) and
    // the conjugate direction on the free cells (Polonsky & Keer), made mean-free there for load
    // control so that a step along it keeps Σ p. The gap has zero mean over the free cells
    // (that defines δ), so the mean of g + β t_old is β Σ t_old / free.
    const double beta = conjugate ? g_norm_est / g_norm_old : 0.0;
    const double tmean = load_control && free_count > 0 ? beta * t_sum / static_cast<double>(free_count) : 0.0;
    {
      const double* top = t_old.data();
      double* tnp = t_new.data();
      const double d = delta, s = shift;
      const DirectionStats ds = grid_pass<DirectionStats>(n, [&](Eigen::Index i, DirectionStats& a) {
        const double q = yp[i] - s;
        const double g = vp[i] - d;
        double ri, ti = 0.0;
        if (q <= 0.0) {
          ri = std::min(g, 0.0);
        } else if (q >= cap) {
          ri = std::max(g, 0.0);
        } else {
          ri = g;
          ti = g + beta * top[i] - tmean;
          a.num += g * ti;
          a.g2 += g * g;
        }
        tnp[i] = ti;
        a.res2 += ri * ri;
      });
      res_abs = std::sqrt(ds.res2);
      residual = res_abs / std::max(scale, 1e-300 + 1e-12 * hscale);
      if (!std::isfinite(residual)) break;
      if (residual <= opt.tolerance) {
        if (since_sync == 0) {
          converged = true;
          break;
        }
        resync();  // confirm on an exactly recomputed displacement
        continue;
      }
      if (it >= max_iterations) break;
      g_norm_old = ds.g2;

      // One half-space product: r = G t and t·G t (Parseval), hence the exact line minimum
      // τ = Σ_F g t / Σ_F t G t along t (t vanishes off the free set).
      const double den = hs.displacement_and_energy(t_new, r);
      ++fft_pairs;
      const bool cg_step = free_count > 0 && den > 0.0 && std::isfinite(ds.num / den) && ds.num / den > 0.0;
      if (cg_step) step = ds.num / den;

      // Pass 2: trial pressure y: the CG step on free cells, a gradient step of the same length
      // on the others (Polonsky & Keer's recovery: overlapping cells out of contact gain pressure,
      // opening plastic cells lose it); v − τ G t; and the set sums of the new state, taken at
      // zero shift (below: the shift that restores the load usually keeps every set).
      const double tau = step, tau_v = cg_step ? step : 0.0;
      const double* rp = r.data();
      const SetStats st = grid_pass<SetStats>(n, [&](Eigen::Index i, SetStats& a) {
        const double q = yp[i] - s;
        const double p_old = std::clamp(q, 0.0, cap);
        const bool was_free = q > 0.0 && q < cap;
        const double vn = vp[i] - tau_v * rp[i];
        double yn, along;  // trial value; pressure the carried u accounts for
        if (was_free) {
          yn = cg_step ? p_old - tau * tnp[i] : p_old;
          along = yn;
        } else {
          yn = p_old - tau * (vp[i] - d);
          along = p_old;
        }
        const double pn = std::clamp(yn, 0.0, cap);
        const double e = pn - along;
        a.drift2 += e * e;
        if (cell_set(yn, cap) != cell_set(q, cap) || (!was_free && pn != p_old)) ++a.changed;
        a.add(yn, vn, tnp[i], d, cap);
        yp[i] = yn;
        vp[i] = vn;
      });
      conjugate = cg_step;
      ++it;
      ++since_sync;

      // Load control: the shift c with Σ clamp(y − c, 0, cap) = target. When no cell changed set
      // the mismatch is round-off (Σ_F t = 0) and shifting for it is not worth an error in u. A
      // Newton step from c = 0 is exact when it moves no cell across 0 or the cap (the common
      // case); otherwise the full projection and a pass for the sets it makes.
      double new_shift = 0.0;
      bool sets_valid = true;
      if (load_control && (st.changed > 0 || std::abs(st.load - target) > 1e-10 * target)) {
        const double c1 = st.free > 0 ? (st.load - target) / static_cast<double>(st.free) : 0.0;
        if (st.free > 0 && c1 < st.free_q_min && c1 > st.free_q_max - cap && c1 >= st.open_q_max &&
            c1 <= st.plastic_q_min - cap) {
          new_shift = c1;
        } else {
          const ShiftStart start{st.load, st.free, st.q_min, st.q_max};
          new_shift = projection_shift(y, cap, target, &start);
          sets_valid = false;
        }
      }
      const double d_old = delta;
      shift = new_shift;
      double shift_cells = static_cast<double>(st.free);
      if (sets_valid) {
        if (!take_stats(st, d_old)) set_pass(t_new);
      } else {
        set_pass(t_new);
        shift_cells = static_cast<double>(free_count + st.changed);
      }
      // Estimate of ‖G e‖₂: c₀ ‖e‖₂ (c₀ the self-compliance) for the clamps, which are scattered
      // cells; for the shift, uniform over the free cells, c₀ |c| |F|: a uniform pressure on a
      // patch of m cells displaces each by ~ c₀ c √m, so √m × √m over the patch. (With √|F|
      // alone the plastic case, where F is most of the grid, re-synchronised too late and took
      // 16–25 iterations instead of 13 at 512²; measured in bench/README.md.)
      drift += c0 * (std::sqrt(st.drift2) + std::abs(new_shift) * shift_cells);
      std::swap(t_old, t_new);
    }
  }

  if (since_sync != 0) resync();
  t_old.resize(0, 0), t_new.resize(0, 0), r.resize(0, 0);  // the iteration's grids, before the result's
  NormalContactResult out;
  out.pressure_Pa = (y - shift).max(0.0).min(cap);
  const Eigen::ArrayXXd& p = out.pressure_Pa;
  if (opt.full_fields) {
    out.displacement_m = v - h0;
    out.gap_m = (v - delta).max(0.0);
    out.plastic_increment_m = (p >= cap).select((delta - v).max(0.0), 0.0);
  }
  out.approach_m = delta;
  out.normal_load_N = p.sum() * cell;
  const double contact_cells = static_cast<double>((p > 0.0).count());
  out.real_area_m2 = contact_cells * cell;
  out.plastic_area_m2 = static_cast<double>((p >= cap).count()) * cell;
  out.area_fraction = contact_cells / static_cast<double>(n);
  out.max_pressure_Pa = p.maxCoeff();
  out.mean_gap_m = (v - delta).max(0.0).mean();
  out.summary.converged = converged;
  out.summary.iterations = it;
  out.summary.residual = residual;
  out.summary.fft_pairs = fft_pairs;
  out.summary.resyncs = resyncs;
  out.summary.carried_error = last_error;
  out.summary.carried_error_max = max_error;
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
  if (resync_interval < 1) return fail("resync_interval must be >= 1");
  if (!(resync_drift >= 0.0)) return fail("resync_drift must be >= 0");
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
