// Krylov solver for the reduced Newton systems of the JFO cavitation solve (lubrication/reynolds.h)
// with a block-triangular (Schur complement) preconditioner.
//
// After the NCP rows are eliminated each unknown is either a pressure increment Δp (full-film node)
// or a film-fraction increment Δϑ (cavitated node). Ordered by that split the reduced matrix is
//
//     A = [ A_pp  A_pϑ ]      A_pp: Poiseuille diffusion among full-film nodes (an M-matrix: where
//         [ A_ϑp  A_ϑϑ ]            AMG works, ≈ 7 PCG iterations for the full film),
//                             A_ϑϑ: Couette transport of ϑ, first-order upwind (+ squeeze storage on
//                                   the diagonal): lower-triangular in the flow direction,
//     A_pϑ, A_ϑp: couplings across the rupture and reformation boundaries only.
//
// One BoomerAMG V-cycle on the whole A treats the transport rows as if they were diffusion and
// needs 35–85 GMRES iterations that grow with the grid (bench/README.md). The preconditioner here
// is the block LU factorisation with the transport block solved exactly and the Schur complement
// by one AMG V-cycle (Elman, Silvester & Wathen, Finite Elements and Fast Iterative Solvers, 2nd
// ed., OUP 2014, §9.2; Murphy, Golub & Wathen, SIAM J. Sci. Comput. 21, 2000):
//
//     A = [ I  A_pϑ A_ϑϑ⁻¹ ] [ S     0   ],   S = A_pp − A_pϑ A_ϑϑ⁻¹ A_ϑp,
//         [ 0      I       ] [ A_ϑp  A_ϑϑ ]
//
//     P⁻¹ r:  t_ϑ = A_ϑϑ⁻¹ r_ϑ,  x_p = V(S) (r_p − A_pϑ t_ϑ),  x_ϑ = A_ϑϑ⁻¹ (r_ϑ − A_ϑp x_p),
//
// two upwind sweeps and one V-cycle per iteration. With an exact solve of S, GMRES converges in one
// iteration (checked at 128²). S is assembled explicitly: A_ϑϑ⁻¹ carries the flow that leaves a
// full-film node into a cavity along its streamline to the reformation front, so S adds to A_pp one
// long-range coupling per streamline crossing a cavity — the term a block Gauss–Seidel
// preconditioner with AMG on A_pp alone misses (measured: 40–70 iterations per step at 128², no
// better than AMG on the whole matrix). S keeps the M-matrix sign pattern, which AMG handles; it
// needs 17–34 iterations to 1e-10 where the full film needs 7, the cost of S's non-symmetric
// long-range entries.
//
// A_ϑϑ is solved by forward (or backward, for sliding towards −x) substitution when its entries are
// triangular in the unknowns' row-major order — always for the minimum NCP function, whose
// cavitated columns carry only the upwind Couette coefficients. Otherwise (Fischer–Burmeister mixes
// diffusion into them) it is factorised by UMFPACK and the preconditioner falls back to block
// Gauss–Seidel, P = [A_pp 0; A_ϑp A_ϑϑ] with AMG on A_pp: still exact in the transport block, weaker
// in the pressure block.
//
// S (or A_pp) is embedded in an n × n matrix whose cavitated rows are decoupled diagonals, so its
// size does not change with the split: while few unknowns changed side since the hierarchy was built
// (CavitationKrylovOptions::amg_reuse_changed_fraction) the hierarchy can be kept and only the
// fine-level matrix replaced (AmgVCycle::update_fine_matrix). GMRES runs on the true A either way, so
// reuse changes the iteration count, never the answer. For the minimum function an unchanged split
// means an unchanged matrix, so this option's default reuses exactly then; ReynoldsOptions keeps a
// hierarchy while ≤ 0.3 % of the unknowns moved (reynolds.h).
//
// The Krylov method is right-preconditioned restarted GMRES (Saad & Schultz 1986, modified
// Gram–Schmidt, Givens rotations), stopped on ‖b − A x‖₂ ≤ τ‖b‖₂ for the true residual recomputed
// at the end of every cycle; a solve that misses τ within max_iterations returns ok = false with
// its iterate, iteration count and relative residual.
#pragma once

#include "lubrication/linear_solver.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <vector>

namespace tribo::lubrication {

struct CavitationKrylovOptions {
  int restart = 40;           // GMRES(m): Krylov vectors kept per cycle (memory m·n doubles)
  int max_iterations = 200;   // total GMRES iterations per solve
  // Keep the AMG hierarchy of the pressure block while at most this share of the unknowns changed
  // side (full film ↔ cavitated) since it was built; 0 reuses it only for an identical split.
  double amg_reuse_changed_fraction = 0.0;
  // Set AMG up on the Schur complement S = A_pp − A_pϑ A_ϑϑ⁻¹ A_ϑp (block LU preconditioner)
  // instead of A_pp (block Gauss–Seidel); used when A_ϑϑ is triangular.
  bool schur_complement = true;
};

class CavitationKrylovSolver {
 public:
  explicit CavitationKrylovSolver(CavitationKrylovOptions options = {});
  ~CavitationKrylovSolver();
  CavitationKrylovSolver(const CavitationKrylovSolver&) = delete;
  CavitationKrylovSolver& operator=(const CavitationKrylovSolver&) = delete;

  // Builds the preconditioner of A (square, compressed) for the split is_pressure (1: Δp unknown,
  // 0: Δϑ unknown). Fails (ok = false, message) if a diagonal entry of A_ϑϑ is zero or not finite,
  // or on a hypre / UMFPACK error. A is copied.
  LinearSolveStatus setup(const SparseMatrix& a, const std::vector<char>& is_pressure);
  // Solves A x = b to ‖b − A x‖₂ ≤ relative_tolerance·‖b‖₂ (x₀ = 0) or, when max_norm_tolerance
  // > 0, to ‖b − A x‖∞ ≤ max_norm_tolerance, whichever comes first. The max-norm test is made on
  // the true residual (one more preconditioner application and product) each time GMRES's 2-norm
  // estimate falls below 16, 8, 4, … times max_norm_tolerance: a Newton step needs its residual
  // small at every node, and the 2-norm over n nodes is several times the largest entry.
  LinearSolveStatus solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, double relative_tolerance,
                          double max_norm_tolerance = 0.0);

  // Changes CavitationKrylovOptions::amg_reuse_changed_fraction for the next setup() calls.
  void set_amg_reuse_changed_fraction(double fraction);

  int amg_setups() const;  // hierarchies built so far
  int amg_reuses() const;  // setup() calls that kept the hierarchy
  bool triangular_transport_block() const;  // the last setup solved A_ϑϑ by substitution

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tribo::lubrication
