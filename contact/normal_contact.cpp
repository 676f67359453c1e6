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

#include "contact/vector_clones.h"
#include "numerics/huge_pages.h"

namespace tribo::contact {
namespace {

enum class Control { load, approach };

void check_field(const ElasticHalfSpace& hs, const Eigen::ArrayXXd& f, const char* name) {
  const Grid& g = hs.grid();
  if (!g.holds(f)) {
    throw std::invalid_argument(std::string(name) + " is " + std::to_string(f.rows()) + " x " +
                                std::to_string(f.cols()) + " but the half-space grid is " + std::to_string(g.nx) +
                                " x " + std::to_string(g.ny));
  }
  if (!f.allFinite()) throw std::invalid_argument(std::string(name) + " holds NaN or infinite values");
}

// Per-thread partial results merged in thread order (the order fixes the bits).
template <class Acc>
Acc merged(const std::vector<Acc>& part) {
  Acc acc = part[0];
  for (std::size_t k = 1; k < part.size(); ++k) acc.merge(part[k]);
  return acc;
}

// One pass over n cells in contiguous chunks, one per thread: `body(lo, hi)` returns the Acc of
// cells [lo, hi), and the chunks' results are merged in thread order, so a solve's bits depend
// on the thread count but not on the scheduling. A body can keep its sums in scalars and let
// `omp simd` vectorise its loop (a fixed order per chunk).
template <class Acc, class Body>
Acc grid_chunks(Eigen::Index n, Body&& body) {
  const int threads = n >= kParallelMinCells ? std::max(1, omp_get_max_threads()) : 1;
  if (threads == 1) return body(Eigen::Index{0}, n);
  std::vector<Acc> part(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const Eigen::Index t = omp_get_thread_num(), m = omp_get_num_threads();
    part[static_cast<std::size_t>(t)] = body(n * t / m, n * (t + 1) / m);
  }
  return merged(part);
}

// S(c), the cells strictly inside (0, cap), and min y and max y (for the bracket) on cells
// [lo, hi) (branch-free: the sets are scattered; the count is summed as a double, exact below
// 2^53 cells).
struct ShiftSums {
  double sum = 0.0, active = 0.0;
  double y_min = std::numeric_limits<double>::infinity(), y_max = -std::numeric_limits<double>::infinity();
  void merge(const ShiftSums& o) {
    sum += o.sum;
    active += o.active;
    y_min = std::min(y_min, o.y_min);
    y_max = std::max(y_max, o.y_max);
  }
};

TRIBO_VECTOR_CLONES
ShiftSums shift_cells(const double* __restrict y, Eigen::Index lo, Eigen::Index hi, double c, double cap) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  double sum = 0.0, active = 0.0, y_min = inf, y_max = -inf;
#pragma omp simd reduction(+ : sum, active) reduction(min : y_min) reduction(max : y_max)
  for (Eigen::Index i = lo; i < hi; ++i) {
    const double yi = y[i], v = yi - c;
    sum += std::min(std::max(v, 0.0), cap);
    active += (v > 0.0) & (v < cap) ? 1.0 : 0.0;
    y_min = std::min(y_min, yi);
    y_max = std::max(y_max, yi);
  }
  return {sum, active, y_min, y_max};
}

// Euclidean projection onto {0 ≤ p ≤ cap, Σ p = target}: p = clamp(y − c, 0, cap) with the
// shift c solving S(c) = Σ clamp(y_i − c, 0, cap) = target. S is continuous, non-increasing and
// piecewise linear, so a Newton step on the current piece, kept inside a shrinking bracket
// [c_lo, c_hi] (bisection when it would leave it), ends exactly on the right piece. The first
// Newton step starts from S(0) and the active count there: `at_zero` when a pass over y already
// took them (pass B), else a pass here. The first evaluation also brackets the root: below
// min y − cap every cell is at the cap (finite cap), below min y − target/n every cell holds
// more than target/n (infinite cap), and at max y every cell is at zero.
double projection_shift(const Eigen::ArrayXXd& y, double cap, double target, const ShiftSums* at_zero = nullptr) {
  const Eigen::Index n = y.size();
  const double* yp = y.data();
  auto at = [&](double c) {
    return grid_chunks<ShiftSums>(n, [&](Eigen::Index lo, Eigen::Index hi) { return shift_cells(yp, lo, hi, c, cap); });
  };
  const ShiftSums zero = at_zero != nullptr ? *at_zero : at(0.0);
  // y already on the load (a warm start at a solution): no shift. A Newton step from there would be
  // round-off, and a negative one lifts every open cell off zero.
  if (std::abs(zero.sum - target) <= 1e-14 * target) return 0.0;
  double c = zero.active > 0.0 ? (zero.sum - target) / zero.active : 0.0;
  double c_lo = -std::numeric_limits<double>::infinity(), c_hi = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 200; ++it) {
    const ShiftSums at_c = at(c);
    if (it == 0) {
      c_lo = std::isfinite(cap) ? at_c.y_min - cap : at_c.y_min - target / static_cast<double>(n);
      c_lo -= 1e-12 * std::abs(c_lo) + 1e-300;
      c_hi = at_c.y_max;
      // S(0) puts the root on one side of 0.
      if (zero.sum > target) {
        c_lo = std::max(c_lo, 0.0);
      } else {
        c_hi = std::min(c_hi, 0.0);
      }
    }
    const double f = at_c.sum - target;
    if (std::abs(f) <= 1e-14 * target) break;
    if (f > 0.0) {
      c_lo = std::max(c_lo, c);
    } else {
      c_hi = std::min(c_hi, c);
    }
    const double newton = at_c.active > 0.0 ? c + f / at_c.active : c_hi + 1.0;
    c = (newton > c_lo && newton < c_hi) ? newton : 0.5 * (c_lo + c_hi);
    if (c_hi - c_lo <= 1e-15 * (std::abs(c_lo) + std::abs(c_hi))) break;
  }
  return c;
}

// Pass B's sums: the residual, the trial's sets (for the load shift) and the slope of the energy
// along the step it makes (exact when the shift keeps every set, see pass C).
struct TrialStats {
  double res2 = 0.0;       // Σ r² of the current state
  double slope0 = 0.0;     // Σ (v − δ)(clamp(y) − p)
  double slope_free = 0.0; // Σ over the trial's free cells of (v − δ)
  double load = 0.0;       // Σ clamp(y, 0, cap)
  long free = 0;           // trial cells strictly inside (0, cap)
  double free_y_min = std::numeric_limits<double>::infinity(), free_y_max = -std::numeric_limits<double>::infinity();
  double open_y_max = -std::numeric_limits<double>::infinity();
  double plastic_y_min = std::numeric_limits<double>::infinity();

  void merge(const TrialStats& o) {
    res2 += o.res2;
    slope0 += o.slope0;
    slope_free += o.slope_free;
    load += o.load;
    free += o.free;
    free_y_min = std::min(free_y_min, o.free_y_min);
    free_y_max = std::max(free_y_max, o.free_y_max);
    open_y_max = std::max(open_y_max, o.open_y_max);
    plastic_y_min = std::min(plastic_y_min, o.plastic_y_min);
  }
};

// Pass B's constants: the bound, the approach δ, the conjugacy β, the trial length τ and the
// direction's mean shift.
struct TrialInput {
  double cap, delta, beta, tau, tmean;
};

// Pass B on cells [lo, hi): the residual r of the contact conditions (open cells may not overlap,
// plastic ones not open: r = min(g, 0), max(g, 0), g on free ones); the trial y = p − τ t with
// t = g − β s − t̄ on the free cells and g on the others (Polonsky & Keer's recovery: overlapping
// open cells gain pressure, opening plastic cells lose it), written over s; and the sums.
// Selects, not jumps: the sets are scattered over the grid, so a branch on them would be
// mispredicted about as often as a cell is in contact. Without a cap (kCapped false: an elastic
// solve) no cell is plastic, and the loop leaves the cap's tests out: they were about half of
// its work (bench/README.md).
template <bool kCapped>
TRIBO_VECTOR_CLONES TrialStats trial_cells(const double* __restrict p, const double* __restrict v, double* __restrict s,
                                           Eigen::Index lo, Eigen::Index hi, TrialInput in) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  const double cap = in.cap, d = in.delta, b = in.beta, tr = in.tau, tmean = in.tmean;
  double res2 = 0.0, slope0 = 0.0, slope_free = 0.0, load = 0.0, free = 0.0;
  double free_min = inf, free_max = -inf, open_max = -inf, plastic_min = inf;
#pragma omp simd reduction(+ : res2, slope0, slope_free, load, free) reduction(min : free_min, plastic_min) \
    reduction(max : free_max, open_max)
  for (Eigen::Index i = lo; i < hi; ++i) {
    const double q = p[i];
    const double g = v[i] - d;
    const bool q_open = q <= 0.0, q_plastic = kCapped && q >= cap;
    const double r = std::min(kCapped ? std::max(g, q_plastic ? 0.0 : -inf) : g, q_open ? 0.0 : inf);
    const double t = (q_open | q_plastic) ? g : g - b * s[i] - tmean;
    const double y = q - tr * t;
    s[i] = y;
    res2 += r * r;
    const bool open = y <= 0.0, plastic = kCapped && y >= cap, inside = !(open | plastic);
    const double py = kCapped ? std::min(std::max(y, 0.0), cap) : std::max(y, 0.0);
    open_max = std::max(open_max, open ? y : -inf);
    if constexpr (kCapped) {
      plastic_min = std::min(plastic_min, plastic ? y : inf);
      free_max = std::max(free_max, inside ? y : -inf);
    }
    free_min = std::min(free_min, inside ? y : inf);
    free += inside ? 1.0 : 0.0;
    slope_free += inside ? g : 0.0;
    load += py;
    slope0 += g * (py - q);
  }
  TrialStats a;
  a.res2 = res2, a.slope0 = slope0, a.slope_free = slope_free, a.load = load, a.free = static_cast<long>(free);
  a.free_y_min = free_min, a.free_y_max = free_max, a.open_y_max = open_max, a.plastic_y_min = plastic_min;
  return a;
}

// Pass C's: the largest multiple of the step that stays within [0, cap] (≥ 1: p and p + s both
// do), and the slope where pass B's could not be used.
struct StepStats {
  double alpha_max = std::numeric_limits<double>::infinity();
  double slope = 0.0;  // Σ (v − δ) s
  void merge(const StepStats& o) {
    alpha_max = std::min(alpha_max, o.alpha_max);
    slope += o.slope;
  }
};

// Pass C on cells [lo, hi): the step s = clamp(y − c, 0, cap) − p over the trial y in s, with
// α_max = min of p / −s (s < 0) and (cap − p) / s (s > 0), one division per cell (the distance
// to the bound the cell moves toward over |s|: the divider took half of this pass with two); and,
// where v is given, the slope Σ (v − δ) s. Without a cap only the cells that fall count.
template <bool kCapped>
[[gnu::always_inline]] inline double step_of(double y, double q, double cap, double c) {
  return kCapped ? std::min(std::max(y - c, 0.0), cap) - q : std::max(y - c, 0.0) - q;
}
template <bool kCapped>
[[gnu::always_inline]] inline double alpha_limit(double si, double q, double cap) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  if constexpr (kCapped) return si != 0.0 ? (si < 0.0 ? q : cap - q) / std::abs(si) : inf;
  return si < 0.0 ? q / -si : inf;
}

template <bool kCapped>
TRIBO_VECTOR_CLONES StepStats step_cells(const double* __restrict p, double* __restrict s, const double* __restrict v,
                                         Eigen::Index lo, Eigen::Index hi, double cap, double c, double delta) {
  double alpha_max = std::numeric_limits<double>::infinity(), slope = 0.0;
  if (v == nullptr) {
#pragma omp simd reduction(min : alpha_max)
    for (Eigen::Index i = lo; i < hi; ++i) {
      const double si = step_of<kCapped>(s[i], p[i], cap, c);
      s[i] = si;
      alpha_max = std::min(alpha_max, alpha_limit<kCapped>(si, p[i], cap));
    }
  } else {
#pragma omp simd reduction(min : alpha_max) reduction(+ : slope)
    for (Eigen::Index i = lo; i < hi; ++i) {
      const double si = step_of<kCapped>(s[i], p[i], cap, c);
      s[i] = si;
      alpha_max = std::min(alpha_max, alpha_limit<kCapped>(si, p[i], cap));
      slope += (v[i] - delta) * si;
    }
  }
  StepStats a;
  a.alpha_max = alpha_max, a.slope = slope;
  return a;
}

// Pass D's: the free set of the new state and its sums about `ref` (a nearby approach, so that
// Σ_F (v − δ)² follows without cancellation), for δ, Σ_F g² and the next direction.
struct StateStats {
  long free = 0;
  double s1 = 0.0, s2 = 0.0;     // Σ_F (v − ref), Σ_F (v − ref)²
  double w_sum = 0.0, vw = 0.0;  // Σ_F w, Σ_F (v − ref) w
  double s_sum = 0.0, vs = 0.0;  // Σ_F s, Σ_F (v − ref) s
  double sw = 0.0;               // Σ_F s w
  double usum = 0.0, usq = 0.0;  // Σ u, Σ u² (the elastic scale; 0 where the pass left it out)

  void merge(const StateStats& o) {
    free += o.free;
    s1 += o.s1;
    s2 += o.s2;
    w_sum += o.w_sum;
    vw += o.vw;
    s_sum += o.s_sum;
    vs += o.vs;
    sw += o.sw;
    usum += o.usum;
    usq += o.usq;
  }
};

// Pass D on cells [lo, hi): p += α s, v += α w (α = alpha_max lands cells on a bound: those
// within 2 ulp of the cap are put on it), and the new state's sums about ref (α = 0: the sums
// alone); with kScale, h for the elastic scale u = v − h (else h is not read). Without a cap no
// cell is plastic.
template <bool kCapped, bool kScale>
TRIBO_VECTOR_CLONES StateStats update_cells(double* __restrict p, double* __restrict v, const double* __restrict s,
                                            const double* __restrict w, const double* __restrict h, Eigen::Index lo,
                                            Eigen::Index hi, double alpha, double ref, double cap) {
  const double cap_snap = cap * (1.0 - 4e-16);
  double fr = 0.0, s1 = 0.0, s2 = 0.0, w_sum = 0.0, vw = 0.0, s_sum = 0.0, vs = 0.0, sw = 0.0, usum = 0.0, usq = 0.0;
#pragma omp simd reduction(+ : fr, s1, s2, w_sum, vw, s_sum, vs, sw, usum, usq)
  for (Eigen::Index i = lo; i < hi; ++i) {
    double pn = std::max(p[i] + alpha * s[i], 0.0);
    if constexpr (kCapped) pn = pn >= cap_snap ? cap : pn;
    p[i] = pn;
    const double vn = v[i] + alpha * w[i];
    v[i] = vn;
    const bool open = pn <= 0.0, plastic = kCapped && pn >= cap, in = !(open | plastic);
    const double dv = in ? vn - ref : 0.0, sf = in ? s[i] : 0.0, wf = in ? w[i] : 0.0;
    fr += in ? 1.0 : 0.0;
    s1 += dv;
    s2 += dv * dv;
    w_sum += wf;
    vw += dv * wf;
    s_sum += sf;
    vs += dv * sf;
    sw += sf * wf;
    if constexpr (kScale) {
      const double u = vn - h[i];
      usum += u;
      usq += u * u;
    }
  }
  StateStats a;
  a.free = static_cast<long>(fr);
  a.s1 = s1, a.s2 = s2, a.w_sum = w_sum, a.vw = vw, a.s_sum = s_sum, a.vs = vs, a.sw = sw;
  a.usum = usum, a.usq = usq;
  return a;
}

// Where no cell is free (each cell open or at the cap), the approach is only bracketed:
// plastic cells need δ ≥ v, open ones δ ≤ v. The bracket's ends on cells [lo, hi); rare, so not
// among pass D's sums.
struct ApproachBracket {
  double plastic_v_max = -std::numeric_limits<double>::infinity();
  double open_v_min = std::numeric_limits<double>::infinity();
  void merge(const ApproachBracket& o) {
    plastic_v_max = std::max(plastic_v_max, o.plastic_v_max);
    open_v_min = std::min(open_v_min, o.open_v_min);
  }
};

ApproachBracket bracket_cells(const double* p, const double* v, Eigen::Index lo, Eigen::Index hi, double cap) {
  ApproachBracket a;
  for (Eigen::Index i = lo; i < hi; ++i) {
    if (p[i] <= 0.0) a.open_v_min = std::min(a.open_v_min, v[i]);
    if (p[i] >= cap) a.plastic_v_max = std::max(a.plastic_v_max, v[i]);
  }
  return a;
}

// The elastic scale of the residual, ‖u − ū‖₂, is taken on every state whose residual (against
// the last scale) is within kScaleWindow of the tolerance, and at least every kScaleEvery
// updates; else it is left out of pass D.
constexpr double kScaleWindow = 10.0;
constexpr int kScaleEvery = 8;

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
  const bool capped = std::isfinite(cap);  // else an elastic solve: its passes leave the cap's tests out
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

  // State: the pressure p (feasible: 0 ≤ p ≤ cap, Σ p = target), v = h + u with u = G p exact
  // (every change of p is a multiple of a step whose product was taken) and the last step s; s
  // also holds the trial values between passes B and C. w = G s is a grid only on a padded
  // half-space: on a periodic one each line of w is used as the product makes it and kept nowhere
  // (ElasticHalfSpace::displacement_by_rows), which saves writing a grid and reading it back.
  const Eigen::Index nx = grid.nx;
  // Fresh in every solve, so on huge pages (numerics/huge_pages.h): fewer first-touch faults, and
  // fewer TLB misses in the passes.
  Eigen::ArrayXXd p = numerics::huge_page_array(grid.nx, grid.ny), v = numerics::huge_page_array(grid.nx, grid.ny);
  Eigen::ArrayXXd s = numerics::huge_page_array(grid.nx, grid.ny), w;
  s.setZero();
  if (!hs.periodic()) w = numerics::huge_page_array(grid.nx, grid.ny);
  if (warm != nullptr) {
    p = warm->max(0.0).min(cap);
  } else if (load_control) {
    p.setConstant(target / static_cast<double>(n));
  } else {
    p.setZero();
  }
  if (load_control) {
    const double c = projection_shift(p, cap, target);
    p = (p - c).max(0.0).min(cap);
  }
  const double* hp = h0.data();
  double* pp = p.data();
  double* vp = v.data();
  double* sp = s.data();
  double* wp = w.data();
  const std::vector<double> zero_line(static_cast<std::size_t>(nx), 0.0);
  const double hscale = (h0 - h0.mean()).matrix().norm();
  const double c0 = hs.self_compliance_m_per_Pa();
  int fft_pairs = 0;

  // v = h + G p by a double product: the start's, and where the single-precision products end.
  auto displacement_afresh = [&] {
    hs.displacement_and_energy(p, v);
    ++fft_pairs;
    v += h0;
  };
  displacement_afresh();

  // What the next direction needs from the state: δ (load control: the free cells' mean of v),
  // Σ_F g², and, against the last step, Σ_F g w, Σ_F s w, Σ_F s, Σ_F g s (g = v − δ); and the
  // elastic scale ‖u − ū‖₂ of the residual, taken `scale_age` updates ago.
  double delta = load_control ? h0.mean() + (v - h0).mean() : value;
  double g2 = 0.0, gw = 0.0, sw = 0.0, s_free = 0.0, gs = 0.0, scale = 0.0;
  int scale_age = 0;
  long free_count = 0;
  auto take_scale = [&](const StateStats& st) {
    scale = std::sqrt(std::max(st.usq - st.usum * st.usum / static_cast<double>(n), 0.0));
    scale_age = 0;
  };
  auto sums_about = [&](const StateStats& st, double ref, bool scaled) {
    if (scaled) {
      take_scale(st);
    } else {
      ++scale_age;
    }
    free_count = st.free;
    double dref = delta - ref;
    if (load_control) {
      if (st.free > 0) {
        dref = st.s1 / static_cast<double>(st.free);
      } else {
        // Without free cells δ is only bracketed: take the smallest admissible approach, or the
        // middle of an empty bracket.
        const ApproachBracket b = grid_chunks<ApproachBracket>(
            n, [&](Eigen::Index lo, Eigen::Index hi) { return bracket_cells(pp, vp, lo, hi, cap); });
        const double d = (!std::isfinite(b.open_v_min) || b.plastic_v_max <= b.open_v_min)
                             ? b.plastic_v_max
                             : 0.5 * (b.plastic_v_max + b.open_v_min);
        dref = d - ref;
      }
      delta = ref + dref;
    }
    const double f = static_cast<double>(st.free);
    g2 = st.s2 - 2.0 * dref * st.s1 + f * dref * dref;
    gw = st.vw - dref * st.w_sum;
    gs = st.vs - dref * st.s_sum;
    sw = st.sw;
    s_free = st.s_sum;
    return !(std::abs(dref * st.s1) > 1e8 * std::abs(g2));
  };
  // Pass D (update_cells) on the len cells from a, against w_at, the step's product there; the
  // elastic scale's sums where `scaled`.
  auto update_at = [&](Eigen::Index a, Eigen::Index len, const double* w_at, double alpha, double ref, bool scaled) {
    auto cells = [&](auto kernel) { return kernel(pp + a, vp + a, sp + a, w_at, hp + a, 0, len, alpha, ref, cap); };
    if (capped) return scaled ? cells(update_cells<true, true>) : cells(update_cells<true, false>);
    return scaled ? cells(update_cells<false, true>) : cells(update_cells<false, false>);
  };
  // Pass D on a padded half-space.
  auto update_pass = [&](double alpha, double ref, bool scaled) {
    return grid_chunks<StateStats>(
        n, [&](Eigen::Index lo, Eigen::Index hi) { return update_at(lo, hi - lo, wp + lo, alpha, ref, scaled); });
  };
  // Pass D without a step (α = 0): the state's sums about ref, against w = 0 (each line segment
  // against a line of zeros, so that no w grid is needed).
  auto state_pass = [&](double ref) {
    return grid_chunks<StateStats>(n, [&](Eigen::Index lo, Eigen::Index hi) {
      StateStats acc;
      for (Eigen::Index a = lo; a < hi;) {
        const Eigen::Index b = std::min(hi, (a / nx + 1) * nx);
        acc.merge(update_at(a, b - a, zero_line.data(), 0.0, ref, true));
        a = b;
      }
      return acc;
    });
  };
  // The state's sums from an update pass about ref; where Σ (v − ref)² ≫ Σ (v − δ)² leaves too
  // few digits, taken again about the new δ (rare: ref is the previous δ). The sums with w are
  // linear in the reference and are moved to δ instead: w is not kept.
  auto take_state = [&](const StateStats& st, double ref, bool scaled) {
    if (sums_about(st, ref, scaled)) return;
    StateStats again = state_pass(delta);
    again.w_sum = st.w_sum, again.sw = st.sw, again.vw = st.vw - (delta - ref) * st.w_sum;
    sums_about(again, delta, true);
  };
  take_state(state_pass(delta), delta, true);

  // Products in single precision until the residual reaches single_precision_above.
  bool single = hs.periodic() && opt.single_precision_above > opt.tolerance;
  int single_pairs = 0;
  double tau = 1.0 / c0;  // trial step length (m/Pa → Pa per m of gap)
  double residual = 0.0;
  bool converged = false, have_step = false;
  int it = 0;
  for (;;) {
    // The direction t = g − β s on the free cells (g the gap, s the last step): β makes t
    // G-conjugate to s (Daniel's formula; s is the step actually taken, so conjugacy survives
    // the projection), β = 0 where that would not leave a descent direction. For load control t
    // is made mean-free on the free set (Σ_F g = 0 defines δ, so only −β Σ_F s needs removing).
    double beta = 0.0;
    if (have_step && sw > 0.0) {
      beta = gw / sw;
      if (!(g2 - beta * gs > 0.1 * g2)) beta = 0.0;
    }
    const double tmean =
        load_control && free_count > 0 ? -beta * s_free / static_cast<double>(free_count) : 0.0;

    // Pass B (trial_cells): the residual, and the trial written over s.
    const TrialInput trial{cap, delta, beta, tau, tmean};
    const TrialStats tb = grid_chunks<TrialStats>(
        n, [&](Eigen::Index lo, Eigen::Index hi) {
          return capped ? trial_cells<true>(pp, vp, sp, lo, hi, trial) : trial_cells<false>(pp, vp, sp, lo, hi, trial);
        });
    auto relative = [&] { return std::sqrt(tb.res2) / std::max(scale, 1e-300 + 1e-12 * hscale); };
    residual = relative();
    // A scale taken updates ago only tells how far the tolerance is (the scale moves little
    // between updates once the contact has formed); the test itself, and the residual a solve
    // reports, take it on this state.
    if (scale_age > 0 && (!(residual > kScaleWindow * opt.tolerance) || it >= max_iterations)) {
      take_scale(state_pass(delta));
      residual = relative();
    }
    if (!std::isfinite(residual)) break;
    if (single && (!(residual > opt.single_precision_above) || it >= max_iterations)) {
      // The single products' round-off, added up in v, is near the residual now (or the solve
      // ends): u = G p again in double, the state's sums from it, and double from here on. The
      // last step's sums were of a single product: the next direction starts afresh. (A start
      // already this close took no single product: v is the start's double one.)
      single = false;
      if (single_pairs > 0) {
        displacement_afresh();
        take_state(state_pass(delta), delta, true);
        have_step = false;
        continue;
      }
    }
    if (residual <= opt.tolerance) {
      converged = true;
      break;
    }
    if (it >= max_iterations) break;

    // The load shift c: Σ clamp(y − c, 0, cap) = target. A Newton step from 0 is exact when it
    // moves no trial value across 0 or the cap (the common case; then pass B's slope holds);
    // otherwise the full projection.
    double c = 0.0;
    bool sets_kept = true;
    if (load_control) {
      const double c1 = tb.free > 0 ? (tb.load - target) / static_cast<double>(tb.free) : 0.0;
      // (With no trial value at the cap, plastic_y_min − cap would be ∞ − ∞ for an elastic solve.)
      const bool plastic_kept = !(tb.plastic_y_min < std::numeric_limits<double>::infinity()) ||
                                c1 <= tb.plastic_y_min - cap;
      if (tb.free > 0 && c1 < tb.free_y_min && c1 > tb.free_y_max - cap && c1 >= tb.open_y_max && plastic_kept) {
        c = c1;
      } else {
        ShiftSums at_zero;
        at_zero.sum = tb.load, at_zero.active = static_cast<double>(tb.free);
        c = projection_shift(s, cap, target, &at_zero);
        sets_kept = false;
      }
    }

    // Pass C (step_cells): the step, α_max, and the slope where pass B's could not be used. Then
    // the one half-space product of the iteration, w = G s with s·G s (Parseval), and the exact
    // minimum of the energy ½ p·G p + h·p along p + α s (Σ s = 0 for load control, so δ drops
    // out), within the feasible α ≤ α_max. Then pass D: p += α s, v += α w (exact), and the new
    // state's sums.
    const double* step_v = sets_kept ? nullptr : vp;
    const double ref = delta;
    // Pass D reads h for the elastic scale only near the tolerance, and every kScaleEvery
    // updates (else one of the four grids it reads, for sums that would go unused).
    const bool scaled = !(residual > kScaleWindow * opt.tolerance) || scale_age + 1 >= kScaleEvery;
    double alpha_best = 0.0, alpha = 0.0;
    auto line_minimum = [&](const StepStats& sc, double den) {
      const double slope = sets_kept ? tb.slope0 - c * tb.slope_free : sc.slope;
      if (!(den > 0.0) || !(slope < 0.0)) return false;
      alpha_best = -slope / den;
      alpha = std::min(alpha_best, sc.alpha_max);
      return true;
    };
    auto step_pass = [&](Eigen::Index lo, Eigen::Index hi) {
      return capped ? step_cells<true>(pp, sp, step_v, lo, hi, cap, c, delta)
                    : step_cells<false>(pp, sp, step_v, lo, hi, cap, c, delta);
    };
    bool descent = false;
    StateStats updated;
    if (hs.periodic()) {
      // Passes C and D fused into the product's line stages (ElasticHalfSpace::displacement_by_rows):
      // each line of s is transformed while in cache, and each line of w used as it comes back.
      const auto threads = static_cast<std::size_t>(hs.row_threads());
      std::vector<StepStats> steps(threads);
      std::vector<StateStats> states(threads);
      hs.displacement_by_rows(
          sp, nullptr,
          [&](int t, Eigen::Index j) { steps[static_cast<std::size_t>(t)].merge(step_pass(j * nx, (j + 1) * nx)); },
          [&](double den) { return descent = line_minimum(merged(steps), den); },
          [&](int t, Eigen::Index j, const double* w_line) {
            states[static_cast<std::size_t>(t)].merge(update_at(j * nx, nx, w_line, alpha, ref, scaled));
          },
          single ? ElasticHalfSpace::Precision::single : ElasticHalfSpace::Precision::full);
      single_pairs += single ? 1 : 0;
      if (descent) updated = merged(states);
    } else {
      const StepStats sc = grid_chunks<StepStats>(
          n, [&](Eigen::Index lo, Eigen::Index hi) { return step_pass(lo, hi); });
      descent = line_minimum(sc, hs.displacement_and_energy(s, w));
      if (descent) updated = update_pass(alpha, ref, scaled);
    }
    ++fft_pairs;
    ++it;
    if (!descent) {
      // Not a descent step (round-off near the solution, or a poor trial length): try again from
      // the gradient with half the length; p and v are untouched.
      tau *= 0.5;
      have_step = false;
      s.setZero();
      take_state(state_pass(delta), delta, true);
      continue;
    }
    take_state(updated, ref, scaled);
    // The next trial length: the best multiple of this one (CG's own step when nothing was
    // clamped), kept within a factor 4.
    tau *= std::clamp(alpha_best, 0.25, 4.0);
    have_step = true;
  }

  NormalContactResult out;
  out.pressure_Pa = std::move(p);
  const Eigen::ArrayXXd& pr = out.pressure_Pa;
  out.approach_m = delta;
  out.normal_load_N = pr.sum() * cell;
  const double contact_cells = static_cast<double>((pr > 0.0).count());
  out.real_area_m2 = contact_cells * cell;
  out.plastic_area_m2 = static_cast<double>((pr >= cap).count()) * cell;
  out.area_fraction = contact_cells / static_cast<double>(n);
  out.max_pressure_Pa = pr.maxCoeff();
  out.mean_gap_m = (v - delta).max(0.0).mean();
  if (opt.full_fields) {
    // The fields go into the iteration's grids, which are already touched: a fresh grid costs
    // its first-touch page faults again. v = h0 + u becomes the displacement last.
    s = (v - delta).max(0.0);
    out.gap_m = std::move(s);
    if (w.size() == 0) w = numerics::huge_page_array(grid.nx, grid.ny);
    w = (pr >= cap).select((delta - v).max(0.0), 0.0);
    out.plastic_increment_m = std::move(w);
    v -= h0;
    out.displacement_m = std::move(v);
  }
  out.summary.converged = converged;
  out.summary.iterations = it;
  out.summary.residual = residual;
  out.summary.fft_pairs = fft_pairs;
  out.summary.single_pairs = single_pairs;
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
  if (!(single_precision_above >= 0.0)) return fail("single_precision_above must be >= 0");
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
  Eigen::ArrayXXd h = numerics::huge_page_array(z.rows(), z.cols());  // every pass of a solve reads it
  h = z.maxCoeff() - z;
  return h;
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
