// Structured-grid multigrid for the full-film Reynolds system: conjugate gradients preconditioned
// by one V-cycle of hypre's PFMG (Ashby & Falgout, Nucl. Sci. Eng. 124, 1996; Falgout & Jones,
// Multigrid Methods VI, 2000): semi-coarsening by two in the direction of strongest coupling,
// Galerkin coarse operators on the same box grid, symmetric red/black Gauss–Seidel smoothing.
//
// Why beside BoomerAMG (linear_solver.h): the rectangular Reynolds grid is a box with a 5-point
// stencil, which is what PFMG is built for. Its setup is a few stencil products on halving boxes
// with no coarsening search and no CSR copies, and its V-cycle streams over arrays; at 1024² the
// full-film solve costs half the BoomerAMG one (bench/README.md). The disc domain is
// not a box and stays on BoomerAMG.
//
// The matrix comes as the same compressed-column matrix the other backends take, with unknowns
// numbered row by row on an ni × nj box (unknown u at i = u mod ni, j = u div ni; optionally
// periodic in j). Every entry must couple a node with itself or one of its four box neighbours
// (through the period in j if periodic); anything else is refused. Stopping rule as the other
// iterative backends: ‖b − A x‖₂ ≤ relative_tolerance · ‖b‖₂, the true residual recomputed
// after the solve; a miss returns ok = false with the iterate, iterations and residual.
#pragma once

#include "lubrication/linear_solver.h"

#include <memory>

namespace tribo::lubrication {

struct BoxGrid {
  int ni = 0, nj = 0;       // unknowns along i (fastest) and j
  bool periodic_j = false;  // j wraps: (i, nj − 1) couples with (i, 0)
};

// Whether PFMG can take this box: at least 3 × 3 (4 along a periodic j), and a periodic j of
// 2^k nodes — PFMG halves the period on every coarsening in j and needs it to stay even.
bool pfmg_supports(const BoxGrid& box);

// PFMG-preconditioned CG on `box` (kind() == LinearSolverKind::pfmg_pcg). analyze() checks the
// size and the stencil; factorize() copies A to hypre's struct matrix and sets PFMG up.
std::unique_ptr<SparseLinearSolver> make_pfmg_solver(const BoxGrid& box, const IterativeSolveOptions& iterative = {});

}  // namespace tribo::lubrication
