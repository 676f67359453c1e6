// Sparse direct solvers for the Reynolds systems, behind a small factory (STYLE §7).
//
//   CHOLMOD  — the no-cavitation Reynolds operator −∇·(h³/12η ∇) with Dirichlet or periodic
//              boundaries is symmetric positive definite: supernodal LLᵀ with AMD/METIS ordering.
//   UMFPACK  — unsymmetric multifrontal LU for the cavitation (Fischer–Burmeister–Newton)
//              Jacobians.
//
// analyze() runs the symbolic phase (ordering, elimination tree / symbolic LU) once; factorize()
// may be called again for any matrix with the same sparsity pattern and reuses it. Every
// SuiteSparse status is checked: a failure is returned as a message, never ignored. The solvers
// own their C handles and are move-only (STYLE §12).
#pragma once

#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace tribo::lubrication {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class LinearSolverKind { cholmod, umfpack };

std::string to_string(LinearSolverKind kind);

// Outcome of one phase; `message` names the SuiteSparse routine and status on failure.
struct LinearSolveStatus {
  bool ok = true;
  std::string message;
};

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

std::unique_ptr<SparseLinearSolver> make_linear_solver(LinearSolverKind kind);

}  // namespace tribo::lubrication
