#include "lubrication/struct_multigrid.h"

#include "lubrication/hypre_runtime.h"  // first: mpi.h before hypre's headers
#include "numerics/format.h"
#include <HYPRE_struct_ls.h>

#include <cmath>
#include <utility>
#include <vector>

namespace tribo::lubrication {
namespace {

using detail::hypre_error;
using detail::hypre_runtime;
using detail::start_hypre_locked;

// The 5-point stencil: centre, west, east, south, north (offsets in i, j).
constexpr int kStencilSize = 5;
constexpr HYPRE_Int kOffsets[kStencilSize][2] = {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}};

class PfmgPcgSolver final : public SparseLinearSolver {
 public:
  PfmgPcgSolver(const BoxGrid& box, const IterativeSolveOptions& options) : box_(box), options_(options) {}
  ~PfmgPcgSolver() override {
    std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
    release_locked();
  }
  PfmgPcgSolver(const PfmgPcgSolver&) = delete;
  PfmgPcgSolver& operator=(const PfmgPcgSolver&) = delete;

  LinearSolverKind kind() const override { return LinearSolverKind::pfmg_pcg; }
  bool analyzed() const override { return analyzed_; }

  // Checks the box and the size; the stencil is checked entry by entry when the values are copied.
  LinearSolveStatus analyze(const SparseMatrix& a) override {
    analyzed_ = false;
    if (!pfmg_supports(box_))
      return solve_failure("pfmg-pcg: box " + std::to_string(box_.ni) + " x " + std::to_string(box_.nj) +
                     (box_.periodic_j ? " (periodic in j)" : "") + " is not one PFMG takes");
    const long n = static_cast<long>(box_.ni) * box_.nj;
    if (a.rows() != n || a.cols() != n)
      return solve_failure("pfmg-pcg: matrix is " + std::to_string(a.rows()) + " x " + std::to_string(a.cols()) +
                     ", the box has " + std::to_string(n) + " unknowns");
    analyzed_ = true;
    return {};
  }

  LinearSolveStatus factorize(const SparseMatrix& a) override {
    if (!analyzed_) return solve_failure("pfmg-pcg: factorize() before analyze()");
    matrix_ = nullptr;  // no solve() with an earlier hierarchy if this one fails
    if (a.rows() != static_cast<long>(box_.ni) * box_.nj || a.cols() != a.rows())
      return solve_failure("pfmg-pcg: matrix size differs from the analysed one");
    // Stencil values per box point, the layout HYPRE_StructMatrixSetBoxValues reads (i fastest).
    const std::size_t n = static_cast<std::size_t>(a.rows());
    std::vector<double> values(kStencilSize * n, 0.0);
    for (int c = 0; c < a.outerSize(); ++c)
      for (int k = a.outerIndexPtr()[c]; k < a.outerIndexPtr()[c + 1]; ++k) {
        const int r = a.innerIndexPtr()[k];
        const int s = stencil_slot(r, c);
        if (s < 0)
          return solve_failure("pfmg-pcg: entry (" + std::to_string(r) + ", " + std::to_string(c) +
                         ") is not a 5-point coupling on the box");
        values[kStencilSize * static_cast<std::size_t>(r) + static_cast<std::size_t>(s)] += a.valuePtr()[k];
      }
    matrix_ = &a;

    std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
    if (std::string e = start_hypre_locked(); !e.empty()) return solve_failure(e);
    release_locked();
    auto fail = [&](const char* routine, HYPRE_Int code) {
      std::string m = hypre_error(routine, code);
      release_locked();
      return solve_failure(m);
    };
    HYPRE_Int lower[2] = {0, 0}, upper[2] = {box_.ni - 1, box_.nj - 1};
    HYPRE_Int periodic[2] = {0, box_.periodic_j ? box_.nj : 0};
    HYPRE_Int e;
    if ((e = HYPRE_StructGridCreate(MPI_COMM_SELF, 2, &grid_))) return fail("HYPRE_StructGridCreate", e);
    if ((e = HYPRE_StructGridSetExtents(grid_, lower, upper))) return fail("HYPRE_StructGridSetExtents", e);
    if ((e = HYPRE_StructGridSetPeriodic(grid_, periodic))) return fail("HYPRE_StructGridSetPeriodic", e);
    if ((e = HYPRE_StructGridAssemble(grid_))) return fail("HYPRE_StructGridAssemble", e);
    if ((e = HYPRE_StructStencilCreate(2, kStencilSize, &stencil_))) return fail("HYPRE_StructStencilCreate", e);
    for (HYPRE_Int s = 0; s < kStencilSize; ++s)
      if ((e = HYPRE_StructStencilSetElement(stencil_, s, const_cast<HYPRE_Int*>(kOffsets[s]))))
        return fail("HYPRE_StructStencilSetElement", e);
    if ((e = HYPRE_StructMatrixCreate(MPI_COMM_SELF, grid_, stencil_, &matrix_hypre_)))
      return fail("HYPRE_StructMatrixCreate", e);
    if ((e = HYPRE_StructMatrixInitialize(matrix_hypre_))) return fail("HYPRE_StructMatrixInitialize", e);
    HYPRE_Int entries[kStencilSize] = {0, 1, 2, 3, 4};
    if ((e = HYPRE_StructMatrixSetBoxValues(matrix_hypre_, lower, upper, kStencilSize, entries, values.data())))
      return fail("HYPRE_StructMatrixSetBoxValues", e);
    if ((e = HYPRE_StructMatrixAssemble(matrix_hypre_))) return fail("HYPRE_StructMatrixAssemble", e);
    for (HYPRE_StructVector* v : {&b_, &x_}) {
      if ((e = HYPRE_StructVectorCreate(MPI_COMM_SELF, grid_, v))) return fail("HYPRE_StructVectorCreate", e);
      if ((e = HYPRE_StructVectorInitialize(*v))) return fail("HYPRE_StructVectorInitialize", e);
      if ((e = HYPRE_StructVectorAssemble(*v))) return fail("HYPRE_StructVectorAssemble", e);
    }

    // One V-cycle per CG iteration: zero initial guess, one pre- and one post-smoothing sweep of
    // symmetric red/black Gauss–Seidel (red–black before, black–red after: a symmetric cycle, as
    // CG needs), Galerkin coarse operators (exact for the variable conductances of a rough film).
    if ((e = HYPRE_StructPFMGCreate(MPI_COMM_SELF, &pfmg_))) return fail("HYPRE_StructPFMGCreate", e);
    const HYPRE_Int pfmg_codes[] = {HYPRE_StructPFMGSetMaxIter(pfmg_, 1),   HYPRE_StructPFMGSetTol(pfmg_, 0.0),
                                    HYPRE_StructPFMGSetZeroGuess(pfmg_),    HYPRE_StructPFMGSetRAPType(pfmg_, 0),
                                    HYPRE_StructPFMGSetRelaxType(pfmg_, 2), HYPRE_StructPFMGSetNumPreRelax(pfmg_, 1),
                                    HYPRE_StructPFMGSetNumPostRelax(pfmg_, 1), HYPRE_StructPFMGSetSkipRelax(pfmg_, 0),
                                    HYPRE_StructPFMGSetPrintLevel(pfmg_, 0), HYPRE_StructPFMGSetLogging(pfmg_, 0)};
    for (HYPRE_Int code : pfmg_codes)
      if (code) return fail("HYPRE_StructPFMGSet*", code);
    if ((e = HYPRE_StructPCGCreate(MPI_COMM_SELF, &pcg_))) return fail("HYPRE_StructPCGCreate", e);
    const HYPRE_Int pcg_codes[] = {
        HYPRE_StructPCGSetTol(pcg_, options_.relative_tolerance), HYPRE_StructPCGSetAbsoluteTol(pcg_, 0.0),
        HYPRE_StructPCGSetMaxIter(pcg_, options_.max_iterations), HYPRE_StructPCGSetTwoNorm(pcg_, 1),
        HYPRE_StructPCGSetRelChange(pcg_, 0),                     HYPRE_StructPCGSetPrintLevel(pcg_, 0),
        HYPRE_StructPCGSetLogging(pcg_, 1),
        HYPRE_StructPCGSetPrecond(pcg_, HYPRE_StructPFMGSolve, HYPRE_StructPFMGSetup, pfmg_)};
    for (HYPRE_Int code : pcg_codes)
      if (code) return fail("HYPRE_StructPCGSet*", code);
    // The setup reads only the matrix (b and x are placeholders here).
    if ((e = HYPRE_StructPCGSetup(pcg_, matrix_hypre_, b_, x_))) return fail("HYPRE_StructPCGSetup", e);
    return {};
  }

  LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!pcg_ || !matrix_) return solve_failure("pfmg-pcg: solve() before factorize()");
    if (b.size() != matrix_->rows()) return solve_failure("pfmg-pcg: right-hand side has the wrong size");
    x = Eigen::VectorXd::Zero(b.size());
    const double b_norm = b.norm();
    if (b_norm == 0.0) return {};  // x = 0 solves A x = 0 exactly
    int iterations = 0;
    {
      std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
      if (hypre_runtime().finalized) return solve_failure("pfmg-pcg: hypre already finalised");
      HYPRE_Int lower[2] = {0, 0}, upper[2] = {box_.ni - 1, box_.nj - 1};
      HYPRE_Int e;
      if ((e = HYPRE_StructVectorSetBoxValues(b_, lower, upper, const_cast<double*>(b.data()))))
        return solve_failure(hypre_error("HYPRE_StructVectorSetBoxValues", e));
      if ((e = HYPRE_StructVectorSetBoxValues(x_, lower, upper, x.data())))
        return solve_failure(hypre_error("HYPRE_StructVectorSetBoxValues", e));
      e = HYPRE_StructPCGSolve(pcg_, matrix_hypre_, b_, x_);
      // HYPRE_ERROR_CONV only says the tolerance was not met: judged below from the true residual.
      if (e & HYPRE_ERROR_CONV) HYPRE_ClearError(HYPRE_ERROR_CONV);
      if (e & ~HYPRE_ERROR_CONV) return solve_failure(hypre_error("HYPRE_StructPCGSolve", e));
      HYPRE_Int its = 0;
      if ((e = HYPRE_StructPCGGetNumIterations(pcg_, &its))) return solve_failure(hypre_error("HYPRE_StructPCGGetNumIterations", e));
      iterations = static_cast<int>(its);
      if ((e = HYPRE_StructVectorGetBoxValues(x_, lower, upper, x.data())))
        return solve_failure(hypre_error("HYPRE_StructVectorGetBoxValues", e));
    }
    LinearSolveStatus s;
    s.iterations = iterations;
    s.relative_residual = (b - *matrix_ * x).norm() / b_norm;
    if (!std::isfinite(s.relative_residual) || s.relative_residual > options_.relative_tolerance) {
      s.ok = false;
      s.message = "pfmg-pcg: relative residual " + numerics::fmt(s.relative_residual, "%.3e") + " after " +
                  std::to_string(iterations) + " iterations, tolerance " + numerics::fmt(options_.relative_tolerance, "%.3e");
    }
    return s;
  }

 private:
  // Stencil slot of the entry coupling row r to column c, or −1 if they are not box neighbours.
  int stencil_slot(int r, int c) const {
    const int ri = r % box_.ni, rj = r / box_.ni, ci = c % box_.ni, cj = c / box_.ni;
    const int di = ci - ri;
    int dj = cj - rj;
    if (box_.periodic_j && dj == box_.nj - 1) dj = -1;
    if (box_.periodic_j && dj == 1 - box_.nj) dj = 1;
    for (int s = 0; s < kStencilSize; ++s)
      if (kOffsets[s][0] == di && kOffsets[s][1] == dj) return s;
    return -1;
  }

  // Frees every hypre object (mutex held). After finalisation at exit they are left to the OS.
  void release_locked() {
    if (!hypre_runtime().finalized) {
      if (pcg_) HYPRE_StructPCGDestroy(pcg_);
      if (pfmg_) HYPRE_StructPFMGDestroy(pfmg_);
      if (x_) HYPRE_StructVectorDestroy(x_);
      if (b_) HYPRE_StructVectorDestroy(b_);
      if (matrix_hypre_) HYPRE_StructMatrixDestroy(matrix_hypre_);
      if (stencil_) HYPRE_StructStencilDestroy(stencil_);
      if (grid_) HYPRE_StructGridDestroy(grid_);
    }
    pcg_ = pfmg_ = nullptr;
    x_ = b_ = nullptr;
    matrix_hypre_ = nullptr;
    stencil_ = nullptr;
    grid_ = nullptr;
  }

  BoxGrid box_;
  IterativeSolveOptions options_;
  bool analyzed_ = false;
  const SparseMatrix* matrix_ = nullptr;  // for the true residual; owned by the caller
  HYPRE_StructGrid grid_ = nullptr;
  HYPRE_StructStencil stencil_ = nullptr;
  HYPRE_StructMatrix matrix_hypre_ = nullptr;
  HYPRE_StructVector b_ = nullptr, x_ = nullptr;
  HYPRE_StructSolver pfmg_ = nullptr, pcg_ = nullptr;
};

}  // namespace

bool pfmg_supports(const BoxGrid& box) {
  if (box.ni < 3 || box.nj < 3) return false;
  if (!box.periodic_j) return true;
  return box.nj >= 4 && (box.nj & (box.nj - 1)) == 0;
}

std::unique_ptr<SparseLinearSolver> make_pfmg_solver(const BoxGrid& box, const IterativeSolveOptions& iterative) {
  return std::make_unique<PfmgPcgSolver>(box, iterative);
}

}  // namespace tribo::lubrication
