// Sparse linear solvers for the Reynolds systems, behind a small factory (STYLE §7).
//
//   CHOLMOD  — the no-cavitation Reynolds operator −∇·(h³/12η ∇) with Dirichlet or periodic
//              boundaries is symmetric positive definite: supernodal LLᵀ with AMD/METIS ordering.
//   UMFPACK  — unsymmetric multifrontal LU for the cavitation (Fischer–Burmeister–Newton)
//              Jacobians.
//   AMG-PCG  — the same SPD operator by conjugate gradients preconditioned with one V-cycle of
//              hypre's BoomerAMG (algebraic multigrid: Falgout coarsening, classical
//              interpolation, symmetric hybrid Gauss–Seidel smoothing; Henson & Yang, Appl.
//              Numer. Math. 41, 2002). Cost O(n) per iteration and a grid-independent iteration
//              count, against the super-linear fill of a direct factor. It stops when
//                  ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂
//              (two-norm of the true residual, recomputed after the solve) or after
//              max_iterations; a solve that does not reach the tolerance returns ok = false with
//              its iterate in x, its iteration count and its relative residual.
//   AMG-GMRES — the same preconditioner and stopping rule for nonsymmetric matrices (the reduced
//              cavitation Newton systems): restarted GMRES(50), right-preconditioned.
//
// analyze() runs the symbolic phase (ordering, elimination tree / symbolic LU) once; factorize()
// may be called again for any matrix with the same sparsity pattern and reuses it (for AMG-PCG
// factorize() is the multigrid setup: coarse grids and interpolation of this matrix). Every
// SuiteSparse and hypre status is checked: a failure is returned as a message, never ignored.
// The solvers own their C handles and are move-only (STYLE §12).
//
// hypre on Debian 12 (libhypre-dev 2.26) is built with MPI (Open MPI) and needs MPI_Init before
// its first call. The AMG backend initialises MPI itself on first use (MPI_Init_thread with
// MPI_THREAD_SERIALIZED, unless the program already did; Open MPI's singleton start needs no
// mpirun), calls HYPRE_Init once, and finalises both at exit. Every matrix lives on
// MPI_COMM_SELF: one process, no communication. hypre keeps global state (error flag, memory
// handle), so all hypre calls in the process are serialised by one mutex: AMG solves on several
// OpenMP threads are correct but run one at a time.
#pragma once

#include <Eigen/SparseCore>

#include <memory>
#include <string>
#include <utility>

namespace tribo::lubrication {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

// pfmg_pcg: structured-grid multigrid for box grids (lubrication/struct_multigrid.h).
enum class LinearSolverKind { cholmod, umfpack, amg_pcg, amg_gmres, pfmg_pcg };

std::string to_string(LinearSolverKind kind);

// Stopping rule of the iterative backends (ignored by the direct ones).
struct IterativeSolveOptions {
  // Stops when ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂ (x₀ = 0).
  double relative_tolerance = 1e-10;
  int max_iterations = 200;
};

// Outcome of one phase; `message` names the SuiteSparse or hypre routine and status on failure.
struct LinearSolveStatus {
  bool ok = true;
  std::string message;
  int iterations = 0;              // Krylov iterations of an iterative solve (0 for direct)
  double relative_residual = 0.0;  // ‖b − A x‖₂ / ‖b‖₂ after an iterative solve
};

// A failed status carrying `message`.
inline LinearSolveStatus solve_failure(std::string message) { return {false, std::move(message)}; }

class SparseLinearSolver {
 public:
  virtual ~SparseLinearSolver() = default;
  virtual LinearSolverKind kind() const = 0;
  // Symbolic analysis of the pattern of `a` (compressed; for CHOLMOD only the lower triangle
  // is read, the matrix must be symmetric).
  virtual LinearSolveStatus analyze(const SparseMatrix& a) = 0;
  // Numeric factorisation; the pattern must equal the analysed one.
  virtual LinearSolveStatus factorize(const SparseMatrix& a) = 0;
  // Solves A x = b with the last factorisation.
  virtual LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x) = 0;
  // True once analyze() succeeded; the caller re-analyses when its pattern changes.
  virtual bool analyzed() const = 0;
};

// The direct LU (UMFPACK): iterative refinement steps per solve (UMFPACK_IRSTEP, its default 2).
// 0 where the factor is a preconditioner, whose inexactness the Krylov iteration absorbs: each step
// costs another pair of triangular solves.
struct DirectSolveOptions {
  int refinement_steps = 2;
};

// Any kind but pfmg_pcg, which needs its box (make_pfmg_solver; std::invalid_argument here).
std::unique_ptr<SparseLinearSolver> make_linear_solver(LinearSolverKind kind,
                                                       const IterativeSolveOptions& iterative = {},
                                                       const DirectSolveOptions& direct = {});

// One BoomerAMG V-cycle (x₀ = 0) as a fixed linear operator x ≈ A⁻¹ r, for block preconditioners
// of GMRES that apply multigrid to one block of a larger system (lubrication/cavitation_krylov.h):
// the coarsening of the AMG backends above, aggressive on the first level, and a non-symmetric
// cycle (forward Gauss–Seidel down, backward up) that GMRES does not mind and costs half. Same
// MPI/hypre runtime and mutex as the backends.
class AmgVCycle {
 public:
  AmgVCycle();
  ~AmgVCycle();
  AmgVCycle(const AmgVCycle&) = delete;
  AmgVCycle& operator=(const AmgVCycle&) = delete;
  AmgVCycle(AmgVCycle&&) noexcept;
  AmgVCycle& operator=(AmgVCycle&&) noexcept;

  // Copies A (square) to hypre and builds the multigrid hierarchy of it.
  LinearSolveStatus setup(const SparseMatrix& a);
  // Replaces the fine-level matrix by A (same size) and keeps the coarse levels and interpolation
  // of the last setup(): hypre's V-cycle smooths with the matrix it is given and restricts with
  // the stored hierarchy, so a hierarchy of a nearby matrix stays a valid (slightly weaker)
  // preconditioner at the cost of one matrix copy instead of a setup.
  LinearSolveStatus update_fine_matrix(const SparseMatrix& a);
  // x = one V-cycle applied to r.
  LinearSolveStatus apply(const Eigen::VectorXd& r, Eigen::VectorXd& x);
  bool ready() const;
  int size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribo::lubrication
