#include "lubrication/linear_solver.h"

#include <cholmod.h>
#include <umfpack.h>

#include "lubrication/hypre_runtime.h"  // before hypre's other headers (mpi.h first)
#include "numerics/format.h"
#include <HYPRE.h>
#include <HYPRE_IJ_mv.h>
#include <HYPRE_parcsr_ls.h>

#include <cmath>
#include <cstdlib>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <utility>
#include <vector>

namespace tribo::lubrication {

std::string to_string(LinearSolverKind kind) {
  switch (kind) {
    case LinearSolverKind::cholmod: return "cholmod";
    case LinearSolverKind::umfpack: return "umfpack";
    case LinearSolverKind::amg_pcg: return "boomeramg-pcg";
    case LinearSolverKind::amg_gmres: return "boomeramg-gmres";
    case LinearSolverKind::pfmg_pcg: return "pfmg-pcg";
  }
  return "unknown";
}

namespace {

using detail::hypre_error;
using detail::hypre_runtime;
using detail::start_hypre_locked;

// A non-owning cholmod_sparse view of an Eigen compressed column matrix.
cholmod_sparse view_of(const SparseMatrix& a, int stype) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(a.rows());
  s.ncol = static_cast<size_t>(a.cols());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<int*>(a.outerIndexPtr());
  s.i = const_cast<int*>(a.innerIndexPtr());
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = stype;
  s.itype = CHOLMOD_INT;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

class CholmodSolver final : public SparseLinearSolver {
 public:
  CholmodSolver() {
    cholmod_start(&common_);
    common_.print = 0;
  }
  ~CholmodSolver() override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_finish(&common_);
  }
  CholmodSolver(const CholmodSolver&) = delete;
  CholmodSolver& operator=(const CholmodSolver&) = delete;

  LinearSolverKind kind() const override { return LinearSolverKind::cholmod; }
  bool analyzed() const override { return factor_ != nullptr; }

  LinearSolveStatus analyze(const SparseMatrix& a) override {
    if (factor_) cholmod_free_factor(&factor_, &common_);
    cholmod_sparse view = view_of(a, -1);  // lower triangle holds the symmetric matrix
    factor_ = cholmod_analyze(&view, &common_);
    if (!factor_ || common_.status != CHOLMOD_OK) return solve_failure("cholmod_analyze failed, status " + std::to_string(common_.status));
    return {};
  }

  LinearSolveStatus factorize(const SparseMatrix& a) override {
    if (!factor_) return solve_failure("cholmod: factorize() before analyze()");
    cholmod_sparse view = view_of(a, -1);
    const int ok = cholmod_factorize(&view, factor_, &common_);
    if (!ok || common_.status == CHOLMOD_NOT_POSDEF)
      return solve_failure("cholmod_factorize: matrix not positive definite (status " + std::to_string(common_.status) +
                     ", column " + std::to_string(factor_->minor) + ")");
    if (common_.status != CHOLMOD_OK) return solve_failure("cholmod_factorize failed, status " + std::to_string(common_.status));
    return {};
  }

  LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!factor_) return solve_failure("cholmod: solve() before factorize()");
    cholmod_dense rhs{};
    rhs.nrow = static_cast<size_t>(b.size());
    rhs.ncol = 1;
    rhs.nzmax = rhs.nrow;
    rhs.d = rhs.nrow;
    rhs.x = const_cast<double*>(b.data());
    rhs.xtype = CHOLMOD_REAL;
    rhs.dtype = CHOLMOD_DOUBLE;
    cholmod_dense* sol = cholmod_solve(CHOLMOD_A, factor_, &rhs, &common_);
    if (!sol || common_.status != CHOLMOD_OK) {
      if (sol) cholmod_free_dense(&sol, &common_);
      return solve_failure("cholmod_solve failed, status " + std::to_string(common_.status));
    }
    x = Eigen::Map<Eigen::VectorXd>(static_cast<double*>(sol->x), b.size());
    cholmod_free_dense(&sol, &common_);
    return {};
  }

 private:
  cholmod_common common_{};
  cholmod_factor* factor_ = nullptr;
};

class UmfpackSolver final : public SparseLinearSolver {
 public:
  explicit UmfpackSolver(const DirectSolveOptions& o) {
    umfpack_di_defaults(control_);
    control_[UMFPACK_IRSTEP] = o.refinement_steps;
    // The reduced Newton matrices have the 5-point pattern of a grid: METIS nested dissection
    // fills less than the default AMD/COLAMD (≈ 25 % faster factorisations at 128², measured
    // with lubrication_bench).
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_METIS;
  }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  LinearSolverKind kind() const override { return LinearSolverKind::umfpack; }
  bool analyzed() const override { return symbolic_ != nullptr; }

  LinearSolveStatus analyze(const SparseMatrix& a) override {
    release();
    const int status = umfpack_di_symbolic(static_cast<int>(a.rows()), static_cast<int>(a.cols()), a.outerIndexPtr(),
                                           a.innerIndexPtr(), a.valuePtr(), &symbolic_, control_, info_);
    if (status != UMFPACK_OK) {
      symbolic_ = nullptr;
      return solve_failure("umfpack_di_symbolic failed, status " + std::to_string(status));
    }
    return {};
  }

  LinearSolveStatus factorize(const SparseMatrix& a) override {
    if (!symbolic_) return solve_failure("umfpack: factorize() before analyze()");
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    const int status =
        umfpack_di_numeric(a.outerIndexPtr(), a.innerIndexPtr(), a.valuePtr(), symbolic_, &numeric_, control_, info_);
    if (status != UMFPACK_OK) {
      // UMFPACK_WARNING_singular_matrix still returns a factor, but a solve with it is meaningless.
      if (numeric_) umfpack_di_free_numeric(&numeric_);
      numeric_ = nullptr;
      return solve_failure("umfpack_di_numeric failed, status " + std::to_string(status) +
                     (status == UMFPACK_WARNING_singular_matrix ? " (singular matrix)" : ""));
    }
    matrix_ = &a;
    return {};
  }

  LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!numeric_ || !matrix_) return solve_failure("umfpack: solve() before factorize()");
    x.resize(b.size());
    const int status = umfpack_di_solve(UMFPACK_A, matrix_->outerIndexPtr(), matrix_->innerIndexPtr(),
                                        matrix_->valuePtr(), x.data(), b.data(), numeric_, control_, info_);
    if (status != UMFPACK_OK) return solve_failure("umfpack_di_solve failed, status " + std::to_string(status));
    return {};
  }

 private:
  void release() {
    if (numeric_) umfpack_di_free_numeric(&numeric_);
    if (symbolic_) umfpack_di_free_symbolic(&symbolic_);
    numeric_ = symbolic_ = nullptr;
  }
  double control_[UMFPACK_CONTROL]{};
  double info_[UMFPACK_INFO]{};
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  const SparseMatrix* matrix_ = nullptr;  // iterative refinement in umfpack_di_solve needs A
};


// ---- hypre BoomerAMG-preconditioned CG / GMRES ---------------------------------------------------------

// Krylov solver (CG for SPD matrices, GMRES otherwise) preconditioned by one BoomerAMG V-cycle.
class AmgKrylovSolver final : public SparseLinearSolver {
 public:
  AmgKrylovSolver(const IterativeSolveOptions& options, bool symmetric) : options_(options), symmetric_(symmetric) {}
  ~AmgKrylovSolver() override {
    std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
    release_locked();
  }
  AmgKrylovSolver(const AmgKrylovSolver&) = delete;
  AmgKrylovSolver& operator=(const AmgKrylovSolver&) = delete;

  LinearSolverKind kind() const override { return symmetric_ ? LinearSolverKind::amg_pcg : LinearSolverKind::amg_gmres; }
  const char* name() const { return symmetric_ ? "boomeramg-pcg" : "boomeramg-gmres"; }
  bool analyzed() const override { return analyzed_; }

  // AMG has no symbolic phase separate from its setup; only the size is recorded.
  LinearSolveStatus analyze(const SparseMatrix& a) override {
    if (a.rows() != a.cols()) return solve_failure(std::string(name()) + ": matrix is not square");
    n_ = static_cast<int>(a.rows());
    indices_.resize(static_cast<std::size_t>(n_));
    std::iota(indices_.begin(), indices_.end(), HYPRE_BigInt{0});
    analyzed_ = true;
    return {};
  }

  // Copies A into a hypre ParCSR matrix and runs the BoomerAMG setup (coarse grids, interpolation).
  LinearSolveStatus factorize(const SparseMatrix& a) override {
    if (!analyzed_) return solve_failure(std::string(name()) + ": factorize() before analyze()");
    if (a.rows() != n_ || a.cols() != n_)
      return solve_failure(std::string(name()) + ": matrix size differs from the analysed one");
    matrix_ = &a;
    std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
    if (std::string e = start_hypre_locked(); !e.empty()) return solve_failure(e);
    release_locked();
    // hypre takes rows: the transpose of the column-major A is its row-major form (A is
    // symmetric for this backend, but the copy stays correct for any A).
    const Eigen::SparseMatrix<double, Eigen::RowMajor, int> r = a;
    std::vector<HYPRE_Int> counts(static_cast<std::size_t>(n_));
    for (int i = 0; i < n_; ++i) counts[i] = r.outerIndexPtr()[i + 1] - r.outerIndexPtr()[i];
    std::vector<HYPRE_BigInt> columns(r.innerIndexPtr(), r.innerIndexPtr() + r.nonZeros());
    HYPRE_Int e;
    const HYPRE_BigInt last = n_ - 1;
    if ((e = HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, last, 0, last, &ij_matrix_)))
      return release_with(hypre_error("HYPRE_IJMatrixCreate", e));
    if ((e = HYPRE_IJMatrixSetObjectType(ij_matrix_, HYPRE_PARCSR)))
      return release_with(hypre_error("HYPRE_IJMatrixSetObjectType", e));
    if ((e = HYPRE_IJMatrixSetRowSizes(ij_matrix_, counts.data())))
      return release_with(hypre_error("HYPRE_IJMatrixSetRowSizes", e));
    if ((e = HYPRE_IJMatrixInitialize(ij_matrix_))) return release_with(hypre_error("HYPRE_IJMatrixInitialize", e));
    if ((e = HYPRE_IJMatrixSetValues(ij_matrix_, n_, counts.data(), indices_.data(), columns.data(), r.valuePtr())))
      return release_with(hypre_error("HYPRE_IJMatrixSetValues", e));
    if ((e = HYPRE_IJMatrixAssemble(ij_matrix_))) return release_with(hypre_error("HYPRE_IJMatrixAssemble", e));
    void* object = nullptr;
    if ((e = HYPRE_IJMatrixGetObject(ij_matrix_, &object))) return release_with(hypre_error("HYPRE_IJMatrixGetObject", e));
    parcsr_ = static_cast<HYPRE_ParCSRMatrix>(object);
    if (LinearSolveStatus s = make_vector_locked(&ij_b_, &par_b_); !s.ok) return release_with(s.message);
    if (LinearSolveStatus s = make_vector_locked(&ij_x_, &par_x_); !s.ok) return release_with(s.message);

    // One V-cycle per PCG iteration. Falgout coarsening + classical interpolation needed 7
    // iterations to 1e-10 on the 1000² Poisson problem against 9–18 for HMIS/ext+i and
    // aggressive coarsening, in less total time (prototype on this machine).
    if ((e = HYPRE_BoomerAMGCreate(&amg_))) return release_with(hypre_error("HYPRE_BoomerAMGCreate", e));
    const HYPRE_Int amg_codes[] = {
        HYPRE_BoomerAMGSetPrintLevel(amg_, 0),     HYPRE_BoomerAMGSetCoarsenType(amg_, 6),
        HYPRE_BoomerAMGSetInterpType(amg_, 0),     HYPRE_BoomerAMGSetRelaxType(amg_, 6),
        HYPRE_BoomerAMGSetStrongThreshold(amg_, 0.25), HYPRE_BoomerAMGSetPMaxElmts(amg_, 4),
        HYPRE_BoomerAMGSetNumSweeps(amg_, 1),      HYPRE_BoomerAMGSetMaxIter(amg_, 1),
        HYPRE_BoomerAMGSetTol(amg_, 0.0)};
    for (HYPRE_Int code : amg_codes)
      if (code) return release_with(hypre_error("HYPRE_BoomerAMGSet*", code));
    if (symmetric_) {
      if ((e = HYPRE_ParCSRPCGCreate(MPI_COMM_SELF, &krylov_)))
        return release_with(hypre_error("HYPRE_ParCSRPCGCreate", e));
      const HYPRE_Int pcg_codes[] = {
          HYPRE_PCGSetTol(krylov_, options_.relative_tolerance), HYPRE_PCGSetAbsoluteTol(krylov_, 0.0),
          HYPRE_PCGSetMaxIter(krylov_, options_.max_iterations), HYPRE_PCGSetTwoNorm(krylov_, 1),
          HYPRE_PCGSetRecomputeResidual(krylov_, 0),           HYPRE_PCGSetPrintLevel(krylov_, 0),
          HYPRE_PCGSetLogging(krylov_, 1),
          HYPRE_PCGSetPrecond(krylov_, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                              reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg_)};
      for (HYPRE_Int code : pcg_codes)
        if (code) return release_with(hypre_error("HYPRE_PCGSet*", code));
      // The setup reads only the matrix; b and x are placeholders here.
      if ((e = HYPRE_ParCSRPCGSetup(krylov_, parcsr_, par_b_, par_x_)))
        return release_with(hypre_error("HYPRE_ParCSRPCGSetup", e));
    } else {
      if ((e = HYPRE_ParCSRGMRESCreate(MPI_COMM_SELF, &krylov_)))
        return release_with(hypre_error("HYPRE_ParCSRGMRESCreate", e));
      const HYPRE_Int gmres_codes[] = {
          HYPRE_GMRESSetKDim(krylov_, 50),
          HYPRE_GMRESSetTol(krylov_, options_.relative_tolerance), HYPRE_GMRESSetAbsoluteTol(krylov_, 0.0),
          HYPRE_GMRESSetMaxIter(krylov_, options_.max_iterations), HYPRE_GMRESSetPrintLevel(krylov_, 0),
          HYPRE_GMRESSetLogging(krylov_, 1),
          HYPRE_GMRESSetPrecond(krylov_, reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSolve),
                                reinterpret_cast<HYPRE_PtrToSolverFcn>(HYPRE_BoomerAMGSetup), amg_)};
      for (HYPRE_Int code : gmres_codes)
        if (code) return release_with(hypre_error("HYPRE_GMRESSet*", code));
      if ((e = HYPRE_ParCSRGMRESSetup(krylov_, parcsr_, par_b_, par_x_)))
        return release_with(hypre_error("HYPRE_ParCSRGMRESSetup", e));
    }
    return {};
  }

  LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) override {
    if (!krylov_ || !matrix_) return solve_failure(std::string(name()) + ": solve() before factorize()");
    if (b.size() != n_) return solve_failure(std::string(name()) + ": right-hand side has the wrong size");
    x = Eigen::VectorXd::Zero(n_);
    const double b_norm = b.norm();
    if (b_norm == 0.0) return {};  // x = 0 solves A x = 0 exactly
    int iterations = 0;
    {
      std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
      if (hypre_runtime().finalized) return solve_failure(std::string(name()) + ": hypre already finalised");
      HYPRE_Int e;
      if (LinearSolveStatus s = set_vector_locked(ij_b_, &par_b_, b); !s.ok) return s;
      if (LinearSolveStatus s = set_vector_locked(ij_x_, &par_x_, x); !s.ok) return s;
      e = symmetric_ ? HYPRE_ParCSRPCGSolve(krylov_, parcsr_, par_b_, par_x_)
                     : HYPRE_ParCSRGMRESSolve(krylov_, parcsr_, par_b_, par_x_);
      // HYPRE_ERROR_CONV only says the tolerance was not met: judged below from the true residual.
      if (e & HYPRE_ERROR_CONV) HYPRE_ClearError(HYPRE_ERROR_CONV);
      if (e & ~HYPRE_ERROR_CONV)
        return solve_failure(hypre_error(symmetric_ ? "HYPRE_ParCSRPCGSolve" : "HYPRE_ParCSRGMRESSolve", e));
      HYPRE_Int its = 0;
      e = symmetric_ ? HYPRE_PCGGetNumIterations(krylov_, &its) : HYPRE_GMRESGetNumIterations(krylov_, &its);
      if (e) return solve_failure(hypre_error("HYPRE_*GetNumIterations", e));
      iterations = static_cast<int>(its);
      if ((e = HYPRE_IJVectorGetValues(ij_x_, n_, indices_.data(), x.data())))
        return solve_failure(hypre_error("HYPRE_IJVectorGetValues", e));
    }
    LinearSolveStatus s;
    s.iterations = iterations;
    s.relative_residual = (b - *matrix_ * x).norm() / b_norm;
    if (!std::isfinite(s.relative_residual) || s.relative_residual > options_.relative_tolerance) {
      s.ok = false;
      s.message = std::string(name()) + ": relative residual " + numerics::fmt(s.relative_residual, "%.3e") + " after " +
                  std::to_string(iterations) + " iterations, tolerance " + numerics::fmt(options_.relative_tolerance, "%.3e");
    }
    return s;
  }

 private:
  LinearSolveStatus set_vector_locked(HYPRE_IJVector ij, HYPRE_ParVector* par, const Eigen::VectorXd& v) {
    HYPRE_Int e;
    if ((e = HYPRE_IJVectorSetValues(ij, n_, indices_.data(), v.data())))
      return solve_failure(hypre_error("HYPRE_IJVectorSetValues", e));
    if ((e = HYPRE_IJVectorAssemble(ij))) return solve_failure(hypre_error("HYPRE_IJVectorAssemble", e));
    void* object = nullptr;
    if ((e = HYPRE_IJVectorGetObject(ij, &object))) return solve_failure(hypre_error("HYPRE_IJVectorGetObject", e));
    *par = static_cast<HYPRE_ParVector>(object);
    return {};
  }
  LinearSolveStatus make_vector_locked(HYPRE_IJVector* ij, HYPRE_ParVector* par) {
    HYPRE_Int e;
    const HYPRE_BigInt last = n_ - 1;
    if ((e = HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, last, ij))) return solve_failure(hypre_error("HYPRE_IJVectorCreate", e));
    if ((e = HYPRE_IJVectorSetObjectType(*ij, HYPRE_PARCSR)))
      return solve_failure(hypre_error("HYPRE_IJVectorSetObjectType", e));
    if ((e = HYPRE_IJVectorInitialize(*ij))) return solve_failure(hypre_error("HYPRE_IJVectorInitialize", e));
    if ((e = HYPRE_IJVectorAssemble(*ij))) return solve_failure(hypre_error("HYPRE_IJVectorAssemble", e));
    void* object = nullptr;
    if ((e = HYPRE_IJVectorGetObject(*ij, &object))) return solve_failure(hypre_error("HYPRE_IJVectorGetObject", e));
    *par = static_cast<HYPRE_ParVector>(object);
    return {};
  }
  LinearSolveStatus release_with(std::string message) {
    release_locked();
    return solve_failure(std::move(message));
  }
  // Frees every hypre object (mutex held). After finalisation at exit they are left to the OS.
  void release_locked() {
    if (!hypre_runtime().finalized) {
      if (krylov_ && symmetric_) HYPRE_ParCSRPCGDestroy(krylov_);
      if (krylov_ && !symmetric_) HYPRE_ParCSRGMRESDestroy(krylov_);
      if (amg_) HYPRE_BoomerAMGDestroy(amg_);
      if (ij_x_) HYPRE_IJVectorDestroy(ij_x_);
      if (ij_b_) HYPRE_IJVectorDestroy(ij_b_);
      if (ij_matrix_) HYPRE_IJMatrixDestroy(ij_matrix_);
    }
    krylov_ = amg_ = nullptr;
    ij_x_ = ij_b_ = nullptr;
    ij_matrix_ = nullptr;
    parcsr_ = nullptr;
    par_b_ = par_x_ = nullptr;
  }

  IterativeSolveOptions options_;
  bool symmetric_ = true;
  int n_ = 0;
  std::vector<HYPRE_BigInt> indices_;  // 0 … n − 1, for hypre's vector accessors
  bool analyzed_ = false;
  const SparseMatrix* matrix_ = nullptr;  // for the true residual; owned by the caller
  HYPRE_IJMatrix ij_matrix_ = nullptr;
  HYPRE_ParCSRMatrix parcsr_ = nullptr;
  HYPRE_IJVector ij_b_ = nullptr, ij_x_ = nullptr;
  HYPRE_ParVector par_b_ = nullptr, par_x_ = nullptr;
  HYPRE_Solver amg_ = nullptr, krylov_ = nullptr;
};

// Copies the column-major A into a new hypre IJ/ParCSR matrix (mutex held). On failure the
// partly built matrix is destroyed and a message returned.
std::string make_parcsr_locked(const SparseMatrix& a, const std::vector<HYPRE_BigInt>& indices, HYPRE_IJMatrix* ij,
                               HYPRE_ParCSRMatrix* par) {
  const int n = static_cast<int>(a.rows());
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> r = a;  // hypre takes rows
  std::vector<HYPRE_Int> counts(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) counts[i] = r.outerIndexPtr()[i + 1] - r.outerIndexPtr()[i];
  std::vector<HYPRE_BigInt> columns(r.innerIndexPtr(), r.innerIndexPtr() + r.nonZeros());
  const HYPRE_BigInt last = n - 1;
  HYPRE_Int e;
  *ij = nullptr;
  *par = nullptr;
  auto fail = [&](const char* routine, HYPRE_Int code) {
    std::string m = hypre_error(routine, code);
    if (*ij) HYPRE_IJMatrixDestroy(*ij);
    *ij = nullptr;
    *par = nullptr;
    return m;
  };
  if ((e = HYPRE_IJMatrixCreate(MPI_COMM_SELF, 0, last, 0, last, ij))) return fail("HYPRE_IJMatrixCreate", e);
  if ((e = HYPRE_IJMatrixSetObjectType(*ij, HYPRE_PARCSR))) return fail("HYPRE_IJMatrixSetObjectType", e);
  if ((e = HYPRE_IJMatrixSetRowSizes(*ij, counts.data()))) return fail("HYPRE_IJMatrixSetRowSizes", e);
  if ((e = HYPRE_IJMatrixInitialize(*ij))) return fail("HYPRE_IJMatrixInitialize", e);
  if ((e = HYPRE_IJMatrixSetValues(*ij, n, counts.data(), indices.data(), columns.data(), r.valuePtr())))
    return fail("HYPRE_IJMatrixSetValues", e);
  if ((e = HYPRE_IJMatrixAssemble(*ij))) return fail("HYPRE_IJMatrixAssemble", e);
  void* object = nullptr;
  if ((e = HYPRE_IJMatrixGetObject(*ij, &object))) return fail("HYPRE_IJMatrixGetObject", e);
  *par = static_cast<HYPRE_ParCSRMatrix>(object);
  return "";
}

std::string make_par_vector_locked(int n, HYPRE_IJVector* ij, HYPRE_ParVector* par) {
  HYPRE_Int e;
  if ((e = HYPRE_IJVectorCreate(MPI_COMM_SELF, 0, n - 1, ij))) return hypre_error("HYPRE_IJVectorCreate", e);
  if ((e = HYPRE_IJVectorSetObjectType(*ij, HYPRE_PARCSR))) return hypre_error("HYPRE_IJVectorSetObjectType", e);
  if ((e = HYPRE_IJVectorInitialize(*ij))) return hypre_error("HYPRE_IJVectorInitialize", e);
  if ((e = HYPRE_IJVectorAssemble(*ij))) return hypre_error("HYPRE_IJVectorAssemble", e);
  void* object = nullptr;
  if ((e = HYPRE_IJVectorGetObject(*ij, &object))) return hypre_error("HYPRE_IJVectorGetObject", e);
  *par = static_cast<HYPRE_ParVector>(object);
  return "";
}

}  // namespace

// ---- one BoomerAMG V-cycle as an operator ----------------------------------------------------------------

struct AmgVCycle::Impl {
  int n = 0;
  std::vector<HYPRE_BigInt> indices;
  // The matrix the hierarchy was built from (kept alive with it) and the current fine-level matrix
  // (the same object unless update_fine_matrix() replaced it).
  HYPRE_IJMatrix setup_ij = nullptr, fine_ij = nullptr;
  HYPRE_ParCSRMatrix setup_par = nullptr, fine_par = nullptr;
  HYPRE_IJVector ij_b = nullptr, ij_x = nullptr;
  HYPRE_ParVector par_b = nullptr, par_x = nullptr;
  HYPRE_Solver amg = nullptr;

  ~Impl() {
    std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
    release_locked();
  }
  void release_fine_locked() {
    if (fine_ij && fine_ij != setup_ij && !hypre_runtime().finalized) HYPRE_IJMatrixDestroy(fine_ij);
    fine_ij = nullptr;
    fine_par = nullptr;
  }
  void release_locked() {
    release_fine_locked();
    if (!hypre_runtime().finalized) {
      if (amg) HYPRE_BoomerAMGDestroy(amg);
      if (setup_ij) HYPRE_IJMatrixDestroy(setup_ij);
      if (ij_b) HYPRE_IJVectorDestroy(ij_b);
      if (ij_x) HYPRE_IJVectorDestroy(ij_x);
    }
    amg = nullptr;
    setup_ij = nullptr;
    setup_par = nullptr;
    ij_b = ij_x = nullptr;
    par_b = par_x = nullptr;
    n = 0;
  }
};

AmgVCycle::AmgVCycle() : impl_(std::make_unique<Impl>()) {}
AmgVCycle::~AmgVCycle() = default;
AmgVCycle::AmgVCycle(AmgVCycle&&) noexcept = default;
AmgVCycle& AmgVCycle::operator=(AmgVCycle&&) noexcept = default;
bool AmgVCycle::ready() const { return impl_ && impl_->amg != nullptr; }
int AmgVCycle::size() const { return impl_ ? impl_->n : 0; }

LinearSolveStatus AmgVCycle::setup(const SparseMatrix& a) {
  if (a.rows() != a.cols() || a.rows() == 0) return solve_failure("boomeramg v-cycle: matrix is not square or empty");
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
  if (std::string e = start_hypre_locked(); !e.empty()) return solve_failure(e);
  m.release_locked();
  m.n = static_cast<int>(a.rows());
  m.indices.resize(static_cast<std::size_t>(m.n));
  std::iota(m.indices.begin(), m.indices.end(), HYPRE_BigInt{0});
  auto fail = [&](std::string message) {
    m.release_locked();
    return solve_failure(std::move(message));
  };
  if (std::string e = make_parcsr_locked(a, m.indices, &m.setup_ij, &m.setup_par); !e.empty()) return fail(e);
  m.fine_ij = m.setup_ij;
  m.fine_par = m.setup_par;
  if (std::string e = make_par_vector_locked(m.n, &m.ij_b, &m.par_b); !e.empty()) return fail(e);
  if (std::string e = make_par_vector_locked(m.n, &m.ij_x, &m.par_x); !e.empty()) return fail(e);
  HYPRE_Int e;
  if ((e = HYPRE_BoomerAMGCreate(&m.amg))) return fail(hypre_error("HYPRE_BoomerAMGCreate", e));
  // The coarsening and interpolation of the AMG-PCG backend (see AmgKrylovSolver::factorize), but
  // a cheaper cycle, since the caller is GMRES and needs no symmetric preconditioner: one forward
  // hybrid Gauss–Seidel sweep going down and one backward sweep coming up (symmetric GS does both
  // each way), and aggressive (two-stage) coarsening on the first level, which thins the first
  // coarse grid and so the setup and every cycle. On the JFO benchmark (512², bench/README.md)
  // the pair cut the solve from 4.3 to 3.5 s and 1024² from 25 to 19 s, with more GMRES
  // iterations (331 → 413 at 512²) each much cheaper; HMIS coarsening with ext+i interpolation,
  // a second aggressive level, or a sparser interpolation (PMaxElmts 2) were slower.
  const HYPRE_Int codes[] = {
      HYPRE_BoomerAMGSetPrintLevel(m.amg, 0),         HYPRE_BoomerAMGSetCoarsenType(m.amg, 6),
      HYPRE_BoomerAMGSetInterpType(m.amg, 0),         HYPRE_BoomerAMGSetRelaxType(m.amg, 6),
      HYPRE_BoomerAMGSetCycleRelaxType(m.amg, 3, 1),  HYPRE_BoomerAMGSetCycleRelaxType(m.amg, 4, 2),
      HYPRE_BoomerAMGSetAggNumLevels(m.amg, 1),
      HYPRE_BoomerAMGSetStrongThreshold(m.amg, 0.25), HYPRE_BoomerAMGSetPMaxElmts(m.amg, 4),
      HYPRE_BoomerAMGSetNumSweeps(m.amg, 1),          HYPRE_BoomerAMGSetMaxIter(m.amg, 1),
      HYPRE_BoomerAMGSetTol(m.amg, 0.0)};
  for (HYPRE_Int code : codes)
    if (code) return fail(hypre_error("HYPRE_BoomerAMGSet*", code));
  if ((e = HYPRE_BoomerAMGSetup(m.amg, m.setup_par, m.par_b, m.par_x)))
    return fail(hypre_error("HYPRE_BoomerAMGSetup", e));
  return {};
}

LinearSolveStatus AmgVCycle::update_fine_matrix(const SparseMatrix& a) {
  Impl& m = *impl_;
  if (!m.amg) return solve_failure("boomeramg v-cycle: update_fine_matrix() before setup()");
  if (a.rows() != m.n || a.cols() != m.n) return solve_failure("boomeramg v-cycle: matrix size differs from the set-up one");
  std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
  if (hypre_runtime().finalized) return solve_failure("boomeramg v-cycle: hypre already finalised");
  m.release_fine_locked();
  if (std::string e = make_parcsr_locked(a, m.indices, &m.fine_ij, &m.fine_par); !e.empty()) {
    m.fine_ij = m.setup_ij;  // the hierarchy's own matrix stays usable
    m.fine_par = m.setup_par;
    return solve_failure(e);
  }
  return {};
}

LinearSolveStatus AmgVCycle::apply(const Eigen::VectorXd& r, Eigen::VectorXd& x) {
  Impl& m = *impl_;
  if (!m.amg) return solve_failure("boomeramg v-cycle: apply() before setup()");
  if (r.size() != m.n) return solve_failure("boomeramg v-cycle: vector has the wrong size");
  x.setZero(m.n);
  std::lock_guard<std::mutex> lock(hypre_runtime().mutex);
  if (hypre_runtime().finalized) return solve_failure("boomeramg v-cycle: hypre already finalised");
  HYPRE_Int e;
  if ((e = HYPRE_IJVectorSetValues(m.ij_b, m.n, m.indices.data(), r.data())))
    return solve_failure(hypre_error("HYPRE_IJVectorSetValues", e));
  if ((e = HYPRE_IJVectorSetValues(m.ij_x, m.n, m.indices.data(), x.data())))
    return solve_failure(hypre_error("HYPRE_IJVectorSetValues", e));
  if ((e = HYPRE_IJVectorAssemble(m.ij_b))) return solve_failure(hypre_error("HYPRE_IJVectorAssemble", e));
  if ((e = HYPRE_IJVectorAssemble(m.ij_x))) return solve_failure(hypre_error("HYPRE_IJVectorAssemble", e));
  // One cycle with tolerance 0 always ends with HYPRE_ERROR_CONV unset (no residual is computed).
  if ((e = HYPRE_BoomerAMGSolve(m.amg, m.fine_par, m.par_b, m.par_x)))
    return solve_failure(hypre_error("HYPRE_BoomerAMGSolve", e));
  if ((e = HYPRE_IJVectorGetValues(m.ij_x, m.n, m.indices.data(), x.data())))
    return solve_failure(hypre_error("HYPRE_IJVectorGetValues", e));
  return {};
}

std::unique_ptr<SparseLinearSolver> make_linear_solver(LinearSolverKind kind, const IterativeSolveOptions& iterative,
                                                       const DirectSolveOptions& direct) {
  if (kind == LinearSolverKind::amg_pcg) return std::make_unique<AmgKrylovSolver>(iterative, true);
  if (kind == LinearSolverKind::amg_gmres) return std::make_unique<AmgKrylovSolver>(iterative, false);
  if (kind == LinearSolverKind::cholmod) return std::make_unique<CholmodSolver>();
  if (kind == LinearSolverKind::pfmg_pcg)
    throw std::invalid_argument("make_linear_solver: pfmg_pcg needs its box grid; use make_pfmg_solver");
  if (direct.refinement_steps < 0) throw std::invalid_argument("make_linear_solver: refinement_steps must be ≥ 0");
  return std::make_unique<UmfpackSolver>(direct);
}

}  // namespace tribo::lubrication
