#include "lubrication/cavitation_krylov.h"
#include "numerics/format.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <string>
#include <utility>

namespace tribo::lubrication {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// y = A x by rows. Eigen's own row-major product spreads over OpenMP threads above 20 000
// non-zeros, and a parallel region per GMRES iteration costs more in thread wake-ups and spinning
// (measured: half the CPU time at 128²) than the 5-point product itself.
void multiply(const RowMatrix& a, const Eigen::VectorXd& x, Eigen::VectorXd& y) {
  const int rows = static_cast<int>(a.rows());
  const int* outer = a.outerIndexPtr();
  const int* inner = a.innerIndexPtr();
  const double* value = a.valuePtr();
  y.resize(rows);
  for (int i = 0; i < rows; ++i) {
    double s = 0.0;
    for (int k = outer[i]; k < outer[i + 1]; ++k) s += value[k] * x[inner[k]];
    y[i] = s;
  }
}

}  // namespace

struct CavitationKrylovSolver::Impl {
  CavitationKrylovOptions options;
  int n = 0;
  RowMatrix a;                         // the system matrix, row-major for the products and sweeps
  std::vector<char> is_pressure;       // current split
  std::vector<char> amg_split;         // split the AMG hierarchy was built for
  AmgVCycle amg;                       // on the embedded pressure block
  int setups = 0, reuses = 0;
  // Transport block: cavitated unknowns in sweep order, and how A_ϑϑ is solved.
  std::vector<int> cavitated;          // ascending unknown indices
  enum class Sweep { forward, backward, lu } sweep = Sweep::forward;
  std::unique_ptr<SparseLinearSolver> block_lu;  // UMFPACK on A_ϑϑ when it is not triangular
  SparseMatrix block;                  // A_ϑϑ for block_lu (it keeps a pointer)
  std::vector<int> local_of;           // unknown → index in `cavitated`, −1 for pressure unknowns
  bool schur = false;                  // AMG is set up on S (else on A_pp)
  Eigen::VectorXd rp, xp;              // work vectors of the preconditioner
  std::vector<Eigen::VectorXd> basis;  // GMRES work space
  Eigen::VectorXd w, z, r;
  Eigen::VectorXd trial, trial_residual;  // an iterate tested against the max-norm tolerance

  // x = P⁻¹ r (see the header).
  LinearSolveStatus apply(const Eigen::VectorXd& r, Eigen::VectorXd& x) {
    x.setZero(n);
    rp = r;
    if (schur) {
      // r_p − A_pϑ A_ϑϑ⁻¹ r_ϑ: the transported part of the right-hand side reaches the
      // reformation rows before the pressure solve.
      if (LinearSolveStatus s = sweep_transport(r, x); !s.ok) return s;
      const int* outer = a.outerIndexPtr();
      const int* inner = a.innerIndexPtr();
      const double* value = a.valuePtr();
      for (int i = 0; i < n; ++i) {
        if (!is_pressure[i]) continue;
        for (int k = outer[i]; k < outer[i + 1]; ++k)
          if (!is_pressure[inner[k]]) rp[i] -= value[k] * x[inner[k]];
      }
    }
    for (int i : cavitated) rp[i] = 0.0;  // the embedded block's cavitated rows are decoupled
    if (LinearSolveStatus s = amg.apply(rp, xp); !s.ok) return s;
    x = xp;
    for (int i : cavitated) x[i] = 0.0;
    return sweep_transport(r, x);
  }

  // x_ϑ = A_ϑϑ⁻¹ (r_ϑ − A_ϑp x_p) with x_p taken from x (its ϑ entries must be 0 on entry).
  LinearSolveStatus sweep_transport(const Eigen::VectorXd& r, Eigen::VectorXd& x) {
    const int* outer = a.outerIndexPtr();
    const int* inner = a.innerIndexPtr();
    const double* value = a.valuePtr();
    // r_ϑ − A_ϑp x_p − (strictly triangular part of A_ϑϑ) x_ϑ, row by row in upwind order; the
    // not-yet-swept ϑ entries of x are 0, and for a triangular block their coefficients are too.
    auto row_update = [&](int i, double& diagonal) {
      double s = r[i];
      diagonal = 0.0;
      for (int k = outer[i]; k < outer[i + 1]; ++k) {
        if (inner[k] == i)
          diagonal = value[k];
        else
          s -= value[k] * x[inner[k]];
      }
      return s;
    };
    double d = 0.0;
    if (sweep == Sweep::forward) {
      for (int i : cavitated) x[i] = row_update(i, d) / d;
    } else if (sweep == Sweep::backward) {
      for (auto it = cavitated.rbegin(); it != cavitated.rend(); ++it) x[*it] = row_update(*it, d) / d;
    } else {
      // x_ϑ is 0 on entry, so row_update gives r_ϑ − A_ϑp x_p exactly.
      Eigen::VectorXd rc(static_cast<Eigen::Index>(cavitated.size())), xc;
      for (std::size_t c = 0; c < cavitated.size(); ++c) rc[static_cast<Eigen::Index>(c)] = row_update(cavitated[c], d);
      if (LinearSolveStatus s = block_lu->solve(rc, xc); !s.ok) return s;
      for (std::size_t c = 0; c < cavitated.size(); ++c) x[cavitated[c]] = xc[static_cast<Eigen::Index>(c)];
    }
    return {};
  }
};

CavitationKrylovSolver::CavitationKrylovSolver(CavitationKrylovOptions options) : impl_(std::make_unique<Impl>()) {
  impl_->options = options;
}
CavitationKrylovSolver::~CavitationKrylovSolver() = default;
void CavitationKrylovSolver::set_amg_reuse_changed_fraction(double fraction) {
  impl_->options.amg_reuse_changed_fraction = fraction;
}
int CavitationKrylovSolver::amg_setups() const { return impl_->setups; }
int CavitationKrylovSolver::amg_reuses() const { return impl_->reuses; }
bool CavitationKrylovSolver::triangular_transport_block() const { return impl_->sweep != Impl::Sweep::lu; }

LinearSolveStatus CavitationKrylovSolver::setup(const SparseMatrix& matrix, const std::vector<char>& is_pressure) {
  Impl& m = *impl_;
  if (matrix.rows() != matrix.cols() || matrix.rows() == 0)
    return solve_failure("block-triangular GMRES: matrix is not square or empty");
  if (is_pressure.size() != static_cast<std::size_t>(matrix.rows()))
    return solve_failure("block-triangular GMRES: split has the wrong size");
  const int n = static_cast<int>(matrix.rows());
  const bool same_size = m.n == n;
  m.n = n;
  m.a = matrix;
  m.is_pressure = is_pressure;
  m.cavitated.clear();
  m.local_of.assign(static_cast<std::size_t>(n), -1);
  for (int i = 0; i < n; ++i)
    if (!is_pressure[i]) {
      m.local_of[i] = static_cast<int>(m.cavitated.size());
      m.cavitated.push_back(i);
    }

  // Embedded pressure block: A_pp on the full-film rows and columns, the cavitated rows decoupled
  // with a diagonal of the pressure rows' mean size (AMG leaves such isolated points to the
  // smoother, which solves them exactly).
  const int* outer = m.a.outerIndexPtr();
  const int* inner = m.a.innerIndexPtr();
  const double* value = m.a.valuePtr();
  double diagonal_sum = 0.0;
  int pressure_rows = 0;
  bool lower = true, upper = true;
  for (int i = 0; i < n; ++i) {
    double diagonal = 0.0;
    for (int k = outer[i]; k < outer[i + 1]; ++k) {
      const int j = inner[k];
      if (j == i) diagonal = value[k];
      if (!is_pressure[i] && !is_pressure[j] && j != i && value[k] != 0.0) {
        if (j > i) lower = false;
        if (j < i) upper = false;
      }
    }
    if (is_pressure[i]) {
      diagonal_sum += std::abs(diagonal);
      ++pressure_rows;
    } else if (!(std::isfinite(diagonal) && diagonal != 0.0)) {
      return solve_failure("block-triangular GMRES: cavitated unknown " + std::to_string(i) +
                     " has transport diagonal " + numerics::fmt(diagonal, "%.3e") + " (no upwind outflow)");
    }
  }
  const double filler = pressure_rows > 0 ? diagonal_sum / pressure_rows : 1.0;
  std::vector<Eigen::Triplet<double, int>> triplets;
  triplets.reserve(static_cast<std::size_t>(m.a.nonZeros()));
  for (int i = 0; i < n; ++i) {
    if (!is_pressure[i]) {
      triplets.emplace_back(i, i, filler);
      continue;
    }
    for (int k = outer[i]; k < outer[i + 1]; ++k)
      if (is_pressure[inner[k]]) triplets.emplace_back(i, inner[k], value[k]);
  }

  // Schur complement S = A_pp − A_pϑ A_ϑϑ⁻¹ A_ϑp when A_ϑϑ is triangular. A_ϑϑ⁻¹ carries the
  // flow leaving a full-film node into a cavity along the streamline to the reformation front,
  // so S couples rupture and reformation nodes of the same streamline: a long-range term, one
  // per streamline crossing a cavity, that AMG on A_pp alone does not see (GMRES then needs about
  // one iteration per independent streamline, 35–70 at 128²). Row r of A_pϑ A_ϑϑ⁻¹ is yᵀ with
  // A_ϑϑᵀ y = a_{r,ϑ}ᵀ, a sparse triangular solve that walks the upwind chains from r's cavitated
  // neighbours back to the rupture front; S keeps the M-matrix sign pattern (A_pϑ, A_ϑp ≤ 0,
  // A_ϑϑ⁻¹ ≥ 0 for upwind transport), which AMG handles.
  const int nc = static_cast<int>(m.cavitated.size());
  m.schur = (lower || upper) && nc > 0 && m.options.schur_complement;
  if (m.schur) {
    std::vector<double> acc(static_cast<std::size_t>(n), 0.0);
    std::vector<int> stamp(static_cast<std::size_t>(n), -1);
    // Lower A_ϑϑ: a row's ϑ entries lie at smaller indices, so y is final in descending order.
    auto before = [lower](int x, int y) { return lower ? x < y : x > y; };
    std::priority_queue<int, std::vector<int>, decltype(before)> pending(before);
    for (int r = 0; r < n; ++r) {
      if (!is_pressure[r]) continue;
      for (int k = outer[r]; k < outer[r + 1]; ++k) {
        const int c = inner[k];
        if (is_pressure[c] || value[k] == 0.0) continue;
        if (stamp[c] != r) {
          stamp[c] = r;
          acc[c] = 0.0;
          pending.push(c);
        }
        acc[c] += value[k];
      }
      while (!pending.empty()) {
        const int i = pending.top();
        pending.pop();
        double diagonal = 0.0;
        for (int k = outer[i]; k < outer[i + 1]; ++k)
          if (inner[k] == i) diagonal = value[k];
        const double y = acc[i] / diagonal;
        for (int k = outer[i]; k < outer[i + 1]; ++k) {
          const int j = inner[k];
          if (j == i || value[k] == 0.0) continue;
          if (is_pressure[j]) {
            triplets.emplace_back(r, j, -y * value[k]);
          } else {
            if (stamp[j] != r) {
              stamp[j] = r;
              acc[j] = 0.0;
              pending.push(j);
            }
            acc[j] -= value[k] * y;
          }
        }
      }
    }
  }
  SparseMatrix pressure_block(n, n);
  pressure_block.setFromTriplets(triplets.begin(), triplets.end());

  // A hierarchy is rebuilt when the split has moved by more than the reuse threshold since it was
  // built; otherwise only its fine level is replaced.
  std::size_t changed = 0;
  const bool have = same_size && m.amg.ready() && m.amg_split.size() == is_pressure.size();
  if (have)
    for (int i = 0; i < n; ++i) changed += m.amg_split[i] != is_pressure[i];
  LinearSolveStatus s;
  if (have && static_cast<double>(changed) <= m.options.amg_reuse_changed_fraction * n) {
    s = m.amg.update_fine_matrix(pressure_block);
    if (s.ok) ++m.reuses;
  } else {
    s = m.amg.setup(pressure_block);
    if (s.ok) {
      ++m.setups;
      m.amg_split = is_pressure;
    } else {
      m.amg_split.clear();
    }
  }
  if (!s.ok) return s;

  // Transport block: substitution when triangular, else an exact LU of it.
  if (lower) {
    m.sweep = Impl::Sweep::forward;
  } else if (upper) {
    m.sweep = Impl::Sweep::backward;
  } else {
    m.sweep = Impl::Sweep::lu;
    triplets.clear();
    for (int i : m.cavitated)
      for (int k = outer[i]; k < outer[i + 1]; ++k)
        if (!is_pressure[inner[k]]) triplets.emplace_back(m.local_of[i], m.local_of[inner[k]], value[k]);
    const int nc = static_cast<int>(m.cavitated.size());
    m.block = SparseMatrix(nc, nc);
    m.block.setFromTriplets(triplets.begin(), triplets.end());
    if (!m.block_lu) m.block_lu = make_linear_solver(LinearSolverKind::umfpack);
    s = m.block_lu->analyze(m.block);  // the block's pattern changes with the split
    if (s.ok) s = m.block_lu->factorize(m.block);
    if (!s.ok) return solve_failure("block-triangular GMRES: transport block: " + s.message);
  }
  return {};
}

LinearSolveStatus CavitationKrylovSolver::solve(const Eigen::VectorXd& b, Eigen::VectorXd& x,
                                                double relative_tolerance, double max_norm_tolerance) {
  Impl& m = *impl_;
  if (m.n == 0 || !m.amg.ready()) return solve_failure("block-triangular GMRES: solve() before setup()");
  if (b.size() != m.n) return solve_failure("block-triangular GMRES: right-hand side has the wrong size");
  x = Eigen::VectorXd::Zero(m.n);
  const double b_norm = b.norm();
  if (b_norm == 0.0) return {};
  const double target = relative_tolerance * b_norm;
  const int restart = std::max(1, m.options.restart);
  // Arnoldi basis of the current cycle, kept between solves (vectors of a few MB: allocating
  // them per iteration costs page faults comparable to the iteration itself).
  std::vector<Eigen::VectorXd>& v = m.basis;
  if (v.size() < static_cast<std::size_t>(restart + 1)) v.resize(static_cast<std::size_t>(restart + 1));
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(restart + 1, restart);
  Eigen::VectorXd cs(restart), sn(restart), g(restart + 1);
  Eigen::VectorXd& w = m.w;
  Eigen::VectorXd& z = m.z;
  Eigen::VectorXd& r = m.r;
  r = b;  // x₀ = 0
  double r_norm = b_norm;
  int iterations = 0;
  LinearSolveStatus status;
  double max_norm_check = 16.0 * max_norm_tolerance;  // next 2-norm level for a max-norm test
  // x + P⁻¹ V y for the first k Arnoldi vectors (y = H⁻¹ g): the preconditioner is linear, so one
  // application to V y replaces keeping the k preconditioned vectors.
  auto update = [&](int k, Eigen::VectorXd& x_out) -> LinearSolveStatus {
    Eigen::VectorXd y = h.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    Eigen::VectorXd& vy = m.w;
    vy.setZero(m.n);
    for (int i = 0; i < k; ++i) vy += y[i] * v[i];
    if (LinearSolveStatus s = m.apply(vy, z); !s.ok) return s;
    x_out = x + z;
    return {};
  };
  while (true) {
    v[0] = r / r_norm;
    g.setZero();
    g[0] = r_norm;
    int k = 0;
    for (; k < restart && iterations < m.options.max_iterations; ++k) {
      if (LinearSolveStatus s = m.apply(v[k], z); !s.ok) return s;
      multiply(m.a, z, w);
      for (int i = 0; i <= k; ++i) {  // modified Gram–Schmidt
        h(i, k) = w.dot(v[i]);
        w -= h(i, k) * v[i];
      }
      h(k + 1, k) = w.norm();
      ++iterations;
      for (int i = 0; i < k; ++i) {  // earlier rotations
        const double t = cs[i] * h(i, k) + sn[i] * h(i + 1, k);
        h(i + 1, k) = -sn[i] * h(i, k) + cs[i] * h(i + 1, k);
        h(i, k) = t;
      }
      const double rho = std::hypot(h(k, k), h(k + 1, k));
      cs[k] = rho == 0.0 ? 1.0 : h(k, k) / rho;
      sn[k] = rho == 0.0 ? 0.0 : h(k + 1, k) / rho;
      const double sub = h(k + 1, k);
      h(k, k) = rho;
      h(k + 1, k) = 0.0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      const bool breakdown = !(sub > 0.0);  // invariant subspace: the cycle's solution is exact
      if (!breakdown) v[k + 1] = w / sub;
      if (std::abs(g[k + 1]) <= target || breakdown) {
        ++k;
        break;
      }
      if (max_norm_tolerance > 0.0 && std::abs(g[k + 1]) <= max_norm_check) {
        max_norm_check *= 0.5;
        if (LinearSolveStatus s = update(k + 1, m.trial); !s.ok) return s;
        multiply(m.a, m.trial, m.trial_residual);
        m.trial_residual = b - m.trial_residual;
        if (m.trial_residual.lpNorm<Eigen::Infinity>() <= max_norm_tolerance) {
          x = m.trial;
          status.iterations = iterations;
          status.relative_residual = m.trial_residual.norm() / b_norm;
          return status;
        }
      }
    }
    if (k > 0) {
      if (LinearSolveStatus s = update(k, x); !s.ok) return s;
    }
    multiply(m.a, x, r);
    r = b - r;
    r_norm = r.norm();
    status.iterations = iterations;
    status.relative_residual = r_norm / b_norm;
    if (!std::isfinite(r_norm)) break;
    if (r_norm <= target) return status;
    if (iterations >= m.options.max_iterations || k == 0) break;
  }
  status.ok = false;
  status.message = "block-triangular GMRES: relative residual " + numerics::fmt(status.relative_residual, "%.3e") + " after " +
                   std::to_string(iterations) + " iterations, tolerance " + numerics::fmt(relative_tolerance, "%.3e");
  return status;
}

}  // namespace tribo::lubrication
