// Elastohydrodynamic circular point contact: a ball of reduced radius R on a flat (or two balls),
// load W, entrained along x at the mean surface speed u_m = (u1 + u2)/2, steady, isothermal,
// smooth surfaces — the contact of a ball-on-disc tribometer — or with ridges across the track on
// the stationary surface (mixed lubrication, below).
//
// Equations (Hamrock & Dowson 1976; the dimensionless form of Venner & Lubrecht 2000, ch. 9):
//   Reynolds   ∂/∂x(ρh³/(12η) ∂p/∂x) + ∂/∂y(ρh³/(12η) ∂p/∂y) = u_m ∂(ρh)/∂x,   p ≥ 0 with the
//              Reynolds residual complementary to it (Swift–Stieber cavitation, as ehl_line.h)
//   film       h(x, y) = h0 + (x² + y²)/(2R) + (2/(π E')) ∫∫ p(s, t)/√((x−s)² + (y−t)²) ds dt
//   load       ∫∫ p dx dy = W
//   fluid      η(p), ρ(p) of piezoviscous.h.
// Scaled by the dry Hertz contact (reference/ehl_point_film.h): a, p_H, X = x/a, P = p/p_H,
// H = h R/a²: H = H0 + (X² + Y²)/2 + (2/π²) ∫∫ P/ρ dS dT, ∫∫ P dX dY = 2π/3, and
// ∇·(ε ∇P) = ∂(ρ̄H)/∂X with ε = ρ̄H³/(η̄λ), λ = 12 η0 u_m R²/(a³ p_H).
//
// Discretisation: nx × ny nodes on [X_in, X_out] × [−Y_side, Y_side], P = 0 on the boundary; the
// Poiseuille terms by central differences with ε at the half nodes (the mean of its neighbours),
// the wedge term by second-order upwind differences along x (first order at the first interior
// column), the deformation with P constant on each node's cell — the exact integral of 1/r over a
// rectangle (Love 1929), so the elastic operator is a dense matrix with the Toeplitz structure of
// the grid.
//
// Method: ehl_newton.h — Newton on pressures and H0 together (step limits, line search and
// continuation in λ, as the line contact; the cavitation by the minimum NCP function, a
// primal–dual active-set step, by default), the Newton step solved one of two ways:
//   dense LU    the Jacobian with the dense elastic kernel, LU by LAPACK: O(N³) for N unknowns —
//               41 × 41 nodes ≈ 0.1 s a step, 61 × 61 ≈ 0.6 s (BM_EhlPoint, bench/README.md);
//   Newton–Krylov  GMRES (numerics/gmres.h, SUNDIALS SPGMR) on the Jacobian applied, the elastic
//               kernel by FFT (contact/halfspace.h: the same cell integrals, zero-padded), right-
//               preconditioned by the sparse LU (UMFPACK) of the Jacobian with the kernel cut to
//               the nodes within `preconditioner_reach` of each other (0: each node's own cell —
//               the fastest on 129² and 257²; the wider near fields of 1–2 cut GMRES iterations by
//               a third but fill the LU more), its dense load row and H0 column by their Schur
//               complement. The LU is analysed once per grid — on a second thread while the
//               coarser grid that starts this one is solved — and refactorised only when GMRES
//               slows down; GMRES (classical Gram–Schmidt) solves no more exactly than Newton's
//               progress can use (Eisenstat–Walker) or the tolerance needs; the start is the solve
//               on a grid half as fine, interpolated by cubics. Memory and cost grow like N log N a
//               GMRES iteration: 129² ≈ 0.2–0.3 s, 257² ≈ 0.9–1.4 s at 10 and 20 N, 513²
//               ≈ 5.0–6.8 s (BM_EhlPoint, 2026-11-30, bench/README.md), 4–5 Newton steps on each grid.
// Both solve the half Y ≥ 0 (`symmetric_in_y`): the unknowns of a row below the centre line are
// those of its mirror image, so the load row counts them twice and the elastic kernel's column of
// an unknown sums both cells; the film is still computed on every node (the FFT on the full grid).
// `linear_solver = automatic` takes the dense LU up to 21 × 21 nodes and Newton–Krylov beyond
// (measured with the minimum NCP function, 2–50 N: 25² 0.04–0.07 s against 0.09–0.10 s dense, 31²
// 0.07–0.12 s against 0.18–0.21 s, 41² 0.07–0.38 s against 0.56–0.65 s; 17²–21² the same to 0.01 s).
// Venner & Lubrecht's multilevel methods remain what reaches 10⁶ nodes in seconds.
//
// Mixed lubrication (solve_ehl_point with an EhlRoughness): the stationary surface carries ridges
// r(x) uniform across the track (a ball held still over a sliding disc keeps the problem steady;
// the contact stays symmetric in y) and, if given, a height map r(x, y) (then the full grid is
// solved: symmetric_in_y is overridden), the film is h − r, and where it closes the surfaces touch —
// Hu & Zhu's unified treatment as in ehl_line.h: ε = ρ̄ (H − H_c)₊³/(η̄λ), at a half node the mean of
// ρ̄/(η̄λ) times the harmonic mean of (H − H_c)₊³ (ehl_roughness.h: face_flow — with the mean of ε a
// node closed at a side edge of the contact drained into its open neighbour and Newton stalled at
// every speed below 0.05 m/s on the tests' ball), the wedge through the upwind faces' mass with a
// limited slope as the line's (ehl_roughness.h: limited_mass_face), Newton's film limit and
// continuation as the line's (ehl_newton.h). A node within EhlRoughness::contact_margin_m of the
// layers is in contact. A thick film is the smooth solver's plus the layers carried through, within
// 0.1 % of the film on 129² (the first-order wedge, until 2026-12-02, was 14 % thick there;
// tests/lubrication/ehl_point_mixed_slow_test.cpp).
// At high loads a coarse grid may not resolve the contact at all: at 100 N on the tests' ball
// (Moes M ≈ 540) 25² and 31² drive the film to zero at a node and end `not converged` (Newton
// stalled), while 41² converges in 7 steps — refine when it says so. Where a coarse grid does
// converge its error can be large (20 N, M ≈ 100: h_c 46 nm on 25², 80 nm on 31 × 25, 109 nm on
// 41²): refine until the film settles.
// With a hardness (EhlRoughness::hardness_Pa) the touching surface is elastic–perfectly-plastic, as
// the BEM's: an unknown q is the pressure up to the cap, P = min(q, P_cap), and beyond it the plastic
// flow that raises the node's film by K_self (q − P_cap) — so each node keeps its flow-balance row
// and the map from q is continuous (a yielded node's film is what its neighbours carry in). Solved
// from the elastic answer by lowering the cap onto the hardness (ehl_newton.h: lower_cap). On the
// tests' ball crawling at 0.8 p_H: the elastic–plastic sphere of contact/reference/capped_sphere.h —
// the yielded nodes its plastic disc to half a node, the elastic ring to 2.6 % of p_H on 31²
// (ehl_point_mixed_test.cpp), 2.6 s; down to 0.6 p_H on 31², not at 0.4 (Newton stalls). The line
// contact likewise (ehl_line.h).
#pragma once

#include <string>
#include <vector>

#include "lubrication/complementarity.h"
#include "lubrication/ehl_roughness.h"
#include "lubrication/piezoviscous.h"

namespace tribo::lubrication {

struct EhlPointContact {
  double load_N = 0.0;              // W > 0
  double reduced_radius_m = 0.0;    // R = 1/(1/R1 + 1/R2) > 0
  double reduced_modulus_Pa = 0.0;  // E' = 2 E* > 0
  double mean_speed_m_per_s = 0.0;  // u_m = (u1 + u2)/2 > 0 (entrainment, along x)
};

enum class EhlPointLinearSolver { automatic, dense_lu, newton_krylov };

// The inexact Newton step of the Krylov method: GMRES stops at ‖J s + F‖₂ ≤ relative_tolerance ‖F‖₂.
struct EhlPointKrylovOptions {
  double relative_tolerance = 1e-6;
  int krylov_dimension = 60;
  int max_restarts = 4;
};

struct EhlPointOptions {
  double inlet_over_radius = -3.5;   // X_in = x_in / a (the inlet must not starve the film)
  double outlet_over_radius = 1.5;   // X_out = x_out / a (past the cavitation front)
  double side_over_radius = 2.5;     // the domain spans |Y| ≤ this
  // ≥ 11 each. 129²: the central film within ≈ 1 % of its grid-converged value on the tests' ball
  // (second order, 2–20 N), ≈ 1 s by Newton–Krylov; 41², the default before 2026-11-29, was 12 % low.
  int nodes_x = 129, nodes_y = 129;
  // Converged when the scaled residual ‖F‖∞ ≤ tolerance, F = (φ(P, −c R_Reynolds) in units of p_H,
  // load balance ΔXΔY ΣP − 2π/3), and the pressures' error left is at most 10·tolerance·max(1, max P)
  // (the last step, or after a full step that step times the contraction: ehl_newton.h).
  // 1e-7 (1e-9 until 2026-11-30): on the tests' ball at 2, 10 and 20 N the central and minimum
  // film and the peak pressure equal 1e-9's to 3e-9 of their value on 129² and 257², where one
  // grid's refinement moves them by 1 %; the solve is a Newton step shorter on 257² at 10 N.
  double tolerance = 1e-7;
  int max_newton_iterations = 30;   // per solve (the direct one and each continuation step)
  int max_continuation_steps = 24;  // solves in the continuation (decades down, then steps up)
  // The NCP function of the cavitation (complementarity.h). The minimum function: Newton stays
  // quadratic to the end (6 steps on each grid of the tests' ball where Fischer–Burmeister took 11–14,
  // linear near the cavitation front), full steps from the Hertz start (33² at 10 N: 6 steps against
  // 14 damped ones) — with the other changes of 2026-11-29, 257² in 4–4.5 s instead of 9.5–12
  // (BM_EhlPoint; 2.0–2.7 s since 2026-11-30, the header's method).
  Complementarity complementarity = Complementarity::minimum;
  EhlPointLinearSolver linear_solver = EhlPointLinearSolver::automatic;
  int preconditioner_reach = 0;     // Newton–Krylov: kernel entries within ±reach nodes in x and y (0–16)
  // Newton–Krylov: start from the solve on a grid about half as fine (recursively; the dense LU
  // once it is small; each to ‖F‖∞ ≤ max(tolerance, 1e-4), a start needing no more: the finer
  // grid's residual at it, ≈ 0.07, is the two discretisations' difference), interpolated —
  // within Newton's reach where the Hertz start needs the continuation (129² on the tests' ball at
  // 10 N: 5 Newton steps; with Fischer–Burmeister 11, and 160 through the continuation from the
  // Hertz start). Where the coarser solve does not converge (its continuation limited to 4 solves),
  // the Hertz start. With roughness the coarser grids take the first-order upwind wedge, which holds
  // on grids that do not resolve the surface (ehl_point.cpp: RoughWedge).
  bool start_from_coarser_grid = true;
  // Solve for the half |Y| ≥ 0 only (Hamrock & Dowson 1976 did the same): the smooth contact,
  // entrained along x, is symmetric in y, so a node and its mirror image share one unknown. Half
  // the unknowns for the sparse LU, GMRES and the Jacobian; the film by the same full-grid FFT.
  // The full grid (false) is the reference the tests compare it with.
  bool symmetric_in_y = true;
  EhlPointKrylovOptions krylov;
};

struct EhlPointResult {
  std::vector<double> x_m, y_m;           // node coordinates
  std::vector<double> pressure_Pa, film_m;  // nx × ny, x fastest (index i + nx j)
  double central_film_m = 0.0;   // at the Hertz centre (x = y = 0, interpolated)
  double minimum_film_m = 0.0;   // smallest nodal film
  double max_pressure_Pa = 0.0;
  double hertz_radius_m = 0.0, hertz_pressure_Pa = 0.0;
  double load_balance_error = 0.0;  // (∫∫p − W)/W
  bool converged = false;
  int iterations = 0;             // Newton iterations, continuation steps included
  int continuation_steps = 0;
  double residual = 0.0;          // ‖F‖∞ at return
  std::string linear_solver;      // "dense LU" or "GMRES, sparse LU preconditioner"
  int krylov_iterations = 0;      // GMRES iterations over the solve (0 for the dense LU)
  int preconditioner_factorisations = 0;  // sparse LUs of the Krylov preconditioner (reused while GMRES converges fast)
  // With roughness: the nodes where the surfaces touch (film below contact_film_m + contact_margin_m;
  // in_contact by node, x fastest, empty without), their count and the share of the load they carry.
  std::vector<bool> in_contact;
  int contact_nodes = 0;
  double contact_load_share = 0.0;
  // The nodes whose pressure is at the hardness (EhlRoughness::hardness_Pa: their surface yielded) and
  // the share of the load they carry.
  int plastic_nodes = 0;
  double plastic_load_share = 0.0;
  // By node (x fastest; empty without roughness): how far the surface's plastic flow raised the
  // film, K_self (q − P_cap) of a yielded node (ehl_point.cpp PointProblem), 0 where it is elastic.
  std::vector<double> plastic_flow_m;
  std::string message;
};

// `given` with its domain fitted to the film the solve expects (its nodes and the rest kept): the
// inlet at 1.5 m*, m* Hamrock & Dowson's fully flooded inlet boundary (reference/ehl_point_film.h)
// for their central film (G at least 1000, as the start's) plus the boundary layers'
// `contact_film_m` (EhlRoughness; 0 for a smooth contact), but within [1.5 a, 3.5 a] (3.5 a the default's); the sides as far, at most
// 2.5 a; the outlet at 1.5 a. Their film is only approached (the tests' flat ball at 0.5 m/s,
// m* = 1.96 a, a/32: −1.2 % at 1.25 m*, −0.5 % at 1.5 m*, −0.2 % at the default's 3.5 a, against
// 4.5 a); crawling at 1 mm/s, 1.5 a gives the default domain's film to 1e-4 at the same spacing. A
// thin film is then solved on the nodes its inlet needs: a crawling or mixed contact's films near
// the layers converge slowly with the spacing (the flat ball's half-load speed 0.036 mm/s on the
// default domain's 41², 0.79 mm/s on 513² of ±1.5 a; ≈ 0.85 extrapolated), and on the default
// domain three fifths of the nodes along the flow sat in an inlet that carries no pressure.
// Throws std::invalid_argument as solve_ehl_point does, and for a negative or non-finite layer.
EhlPointOptions fit_domain_to_film(const EhlPointContact& contact, const PiezoviscousLubricant& lubricant, double contact_film_m,
                                   EhlPointOptions given);

// Throws std::invalid_argument for bad input (non-positive or non-finite contact data, a domain
// that does not contain the Hertz circle's centre with room before it, fewer than 11 nodes a
// side); never throws for non-convergence (see `converged` and `message`).
EhlPointResult solve_ehl_point(const EhlPointContact& contact, const PiezoviscousLubricant& lubricant,
                               const EhlPointOptions& options = {});
// The same contact with transverse ridges on the stationary surface, where films may close (header:
// mixed lubrication); also throws std::invalid_argument for a bad profile.
EhlPointResult solve_ehl_point(const EhlPointContact& contact, const EhlRoughness& roughness,
                               const PiezoviscousLubricant& lubricant, const EhlPointOptions& options = {});

}  // namespace tribo::lubrication
