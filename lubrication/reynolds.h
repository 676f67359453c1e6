// Reynolds equation for a thin incompressible Newtonian film on a regular 2-D grid.
//
//     ∇·( h³/(12η) ∇p ) = (U/2) ∂(ϑh)/∂x + ϑ ∂h/∂t                    (DESIGN §3; thesis App. III)
//
// p gauge pressure (Pa), h(x, y) the gap (m), η the viscosity (Pa·s), U = U₁ + U₂ the sum of the
// two surface speeds along +x (m/s), ∂h/∂t the squeeze rate (m/s; < 0 when the gap closes) and
// ϑ ∈ (0, 1] the fraction of the gap filled with liquid (ϑ = 1 where p > 0).
//
// Discretisation (finite volumes on the nodes x_i = i·dx, y_j = j·dy, node-centred cells):
// mass flux through the face between nodes P and N, per unit face length,
//
//     q = −(h³/12η)_f (p_N − p_P)/d + (U/2) h̃_f ϑ_up,
//
// with the face conductance and Couette gap from the exact 1-D integral of the flux between the
// nodes, evaluated by the trapezoid rule (second order for smooth h, exact for a step at the
// face):  (h³)_f = 2 / (h_P⁻³ + h_N⁻³),  h̃_f = (h_P⁻² + h_N⁻²) / (h_P⁻³ + h_N⁻³).
// Cell balance: Σ_faces q·(face length) + ϑ_P ḣ_P dx dy = 0.
//
// Boundaries: p = p_inlet at x = 0, p = p_outlet at x = Lx (ambient 0 by default); in y either
// ambient (p = 0 on y = 0, Ly) or periodic (period ny·dy, for homogenisation cells). The circular
// domain (parallel discs) masks the grid with a disc and treats the cut links by the symmetric
// ghost-value method of Gibou, Fedkiw, Cheng & Kang (J. Comput. Phys. 176, 2002): a link from
// node P to the rim, cut at fraction θ of the spacing, carries the conductance k/θ towards the
// rim pressure. The matrix stays symmetric and the solution second-order accurate.
//
// Without cavitation the pressure system is SPD and solved by CHOLMOD, or on large grids by
// conjugate gradients preconditioned with algebraic multigrid (hypre BoomerAMG; see
// linear_solver.h and ReynoldsOptions::pressure_solver); on the multigrid path the cavitation
// Newton steps below use GMRES + BoomerAMG instead of UMFPACK. With cavitation the
// Jakobsson–Floberg–Olsson conditions are imposed as the complementarity problem
//     p ≥ 0,  1 − ϑ ≥ 0,  p (1 − ϑ) = 0
// (Giacopini, Fowell, Dini & Strozzi, J. Tribol. 132, 2010) and solved by Fischer–Burmeister–
// Newton (Woloszynski, Podsiadlo & Stachowiak, Tribol. Lett. 58, 2015): each node carries the
// mass balance and an NCP row φ(p/p_s, 1 − ϑ) = 0 — the minimum function (default; its
// semismooth Newton step is a primal–dual active-set step) or Fischer–Burmeister
// a + b − √(a² + b²) — the Couette flux takes ϑ from the upwind node, and each Newton step is an
// unsymmetric sparse solve (UMFPACK) whose pattern is fixed, so its symbolic analysis is reused.
// On the multigrid path the Newton steps are solved by GMRES with a block-triangular preconditioner
// (lubrication/cavitation_krylov.h) to Eisenstat–Walker forcing terms, starting from the same
// problem solved on a grid twice as coarse (see ReynoldsOptions).
//
// Piezoviscosity: with Barus' law η = η₀ e^{ψp} (lubrication/viscosity.h) the reduced pressure
// q = (1 − e^{−ψp})/ψ turns the Poiseuille flux h³/(12η)∇p into h³/(12η₀)∇q while the Couette
// and squeeze terms do not involve η, so q solves the isoviscous problem exactly (with q ≥ 0 ⇔
// p ≥ 0, cavitation included) and p = −ln(1 − ψq)/ψ. Where ψq reaches 1 the pressure has no
// finite solution (the Barus "blow-up"); the solve then reports non-convergence.
//
// Average flow model (Patir & Cheng, J. Lubr. Technol. 100, 1978, 12–17): optional per-node
// pressure flow factors φx, φy > 0 and a Couette film t ≥ 0 turn the equation into
//
//     ∂/∂x( φx h³/(12η) ∂p/∂x ) + ∂/∂y( φy h³/(12η) ∂p/∂y ) = (U/2) ∂(ϑt)/∂x + ϑ ∂h/∂t,
//
// i.e. the mean flows q̄x = −φx h³/(12η) ∂p/∂x + (U/2) t ϑ, q̄y = −φy h³/(12η) ∂p/∂y. (Patir–Cheng's
// t = h̄_T + σΦs; the squeeze storage stays ϑ·gap_rate, so a caller of the average model passes
// gap_rate = (dh̄_T/dh)·ḣ.) The faces use the same exact 1-D integral of a constant flux between
// P and N, now with k = φh³/(12η) and the Couette film t: by the trapezoid rule on ∫dx/k and
// ∫(t/k)dx,
//     k_f = 2 / (1/k_P + 1/k_N),      t̃_f = (t_P/k_P + t_N/k_N) / (1/k_P + 1/k_N),
// which for φ ≡ 1, t ≡ h is the plain face above. Rim links (disc domain) interpolate φ like the
// gap. With all three fields empty the plain equation is solved bit for bit as without them.
//
// Grid and fields (contact/grid.h, read as nodes): nx × ny nodes (≥ 3 each) at x_i = i·dx,
// y_j = j·dy, i along x (the sliding direction); every field is an nx × ny Eigen::ArrayXXd, value
// (i, j) at linear index j·nx + i. An optional field is empty (size 0).
#pragma once

#include "contact/grid.h"
#include "lubrication/complementarity.h"
#include "lubrication/linear_solver.h"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>

namespace tribo::lubrication {

enum class BoundaryY { ambient, periodic };
enum class Cavitation { none, mass_conserving };
// Backend of the full-film (SPD) pressure solve: CHOLMOD, BoomerAMG-preconditioned CG, or the
// latter from ReynoldsOptions::multigrid_min_unknowns unknowns on (automatic).
enum class PressureSolver { automatic, direct, multigrid };
// Preconditioner of GMRES for the cavitation Newton steps on the multigrid path:
//   block_triangular — block LU: exact upwind sweeps of the cavitated (film-fraction transport)
//                      block and one BoomerAMG V-cycle of the pressure Schur complement
//                      (lubrication/cavitation_krylov.h);
//   amg              — one BoomerAMG V-cycle of the whole reduced matrix (poor on the transport
//                      rows: 35–85 GMRES iterations per step, growing with the grid).
enum class CavitationPreconditioner { block_triangular, amg };

// Circular film domain (parallel discs): nodes with |x − c| < R are wetted, the rim is at p = 0.
struct DiscDomain {
  double centre_x_m = 0, centre_y_m = 0, radius_m = 0;
};

struct ReynoldsProblem {
  contact::Grid grid;
  Eigen::ArrayXXd gap_m;                    // nx × ny, every value finite and > 0
  Eigen::ArrayXXd gap_rate_m_per_s;         // ∂h/∂t per node; empty means 0
  double viscosity_Pa_s = 0.021;            // η₀ at ambient pressure
  double pressure_viscosity_per_Pa = 0.0;   // Barus ψ (≥ 0); 0 = isoviscous
  double sliding_speed_m_per_s = 0.0;       // U = U₁ + U₂ along +x
  double inlet_pressure_Pa = 0.0;           // p at x = 0 (rectangular domain)
  double outlet_pressure_Pa = 0.0;          // p at x = Lx
  BoundaryY boundary_y = BoundaryY::ambient;
  std::optional<DiscDomain> disc;           // circular domain; x, y boundaries then ambient
  Cavitation cavitation = Cavitation::none;
  // Average flow model (Patir & Cheng 1978): the Poiseuille conductance of a node is
  // φx h³/(12η) along x and φy h³/(12η) along y, and the Couette flux transports the film
  // t (m) instead of h:  q̄x = −φx h³/(12η) ∂p/∂x + (U/2) t,  q̄y = −φy h³/(12η) ∂p/∂y.
  Eigen::ArrayXXd pressure_flow_factor_x;   // φx per node (> 0); empty = 1
  Eigen::ArrayXXd pressure_flow_factor_y;   // φy per node (> 0); empty = 1
  Eigen::ArrayXXd couette_film_m;           // t per node (≥ 0); empty = gap_m
};

// Throws std::invalid_argument naming the first bad input (grid < 3, h ≤ 0, NaN, η ≤ 0, a flow
// factor ≤ 0 or a Couette film < 0 with its field and node, …).
void validate(const ReynoldsProblem& problem);

struct ReynoldsOptions {
  // Newton stops when max(|mass imbalance of a cell| / mass scale, |φ_NCP|) ≤ tolerance; the mass
  // scale is the largest forcing of the full-film system (|Couette + squeeze + boundary| flux of
  // one cell), so the test is relative to the problem's own flux. p_s = max |p| of the full film.
  double newton_tolerance = 1e-10;
  // The minimum function needs about half the Newton steps of Fischer–Burmeister on the tests'
  // bearings and rough gaps (3 vs 9 on the four-step bearing) for the same answer.
  Complementarity complementarity = Complementarity::minimum;
  int max_newton_iterations = 60;
  // Armijo back-tracking on ½‖F‖² (sufficient-decrease constant, smallest step).
  double armijo_constant = 1e-4;
  double min_step = 1e-8;
  // Full-film pressure system A p = b (also the cavitating solve's starting point): direct
  // (CHOLMOD LLᵀ) or multigrid (PCG + one BoomerAMG V-cycle, O(n) per iteration; the cavitation
  // Newton steps then use GMRES + BoomerAMG, see cavitation_preconditioner). automatic uses
  // multigrid from multigrid_min_unknowns unknowns on (≈ 200² nodes). Multigrid is already 2×
  // faster at 128² and 7× at 1024² (bench/README.md), but hypre calls are serialised process-wide
  // (linear_solver.h) while CHOLMOD solves run in parallel, so the threshold sits above the
  // 96²–128² homogenisation cells that flow_factors spreads over OpenMP threads.
  PressureSolver pressure_solver = PressureSolver::automatic;
  int multigrid_min_unknowns = 40000;
  // On the multigrid path, the full-film system of a rectangular domain is solved by PCG with
  // hypre's structured PFMG (lubrication/struct_multigrid.h: a box grid, 5-point stencil) instead
  // of BoomerAMG: same stopping rule, half the time at 1024² (bench/README.md). Taken when the
  // box allows it (a periodic y needs 2^k nodes); the disc domain and other boxes stay on BoomerAMG.
  bool structured_multigrid = true;
  // Multigrid PCG stops when ‖b − A p‖₂ ≤ multigrid_tolerance · ‖b‖₂ (true residual, checked
  // after the solve; b holds the Couette, squeeze and boundary fluxes of each cell). A solve that
  // misses it within multigrid_max_iterations is reported as not converged with that residual.
  // The pressure error is then ‖δp‖₂/‖p‖₂ ≤ κ(A)·tolerance; κ(A) ≈ 8k_max/(k_min·(π/nx)²).
  double multigrid_tolerance = 1e-10;
  int multigrid_max_iterations = 200;
  // Multigrid path with cavitation: the Newton steps' preconditioner (see CavitationPreconditioner),
  // and for block_triangular the share of unknowns that may change side (full film ↔ cavitated)
  // before the pressure block's AMG hierarchy is rebuilt (kept otherwise, with its fine level
  // updated; the answer does not depend on it, only the GMRES iteration count). Applied after a
  // coarse start, whose fine steps move 0.03–0.1 % of the unknowns: a setup of S costs as much as
  // 10–13 GMRES iterations (0.85 s at 1024²), and keeping the hierarchy through such steps cost 0–10
  // more (512² 2.3 → 2.1 s, 1024² 14.5 → 13.4 s). From the full film, whose steps move fronts by
  // whole bands, only an identical split keeps it (3e-3 there: 434 → 553 iterations at 512²).
  CavitationPreconditioner cavitation_preconditioner = CavitationPreconditioner::block_triangular;
  double amg_reuse_changed_fraction = 3e-3;
  // Inexact Newton on the block-triangular path: each step's GMRES stops at the Eisenstat–Walker
  // forcing term η_k ∈ [multigrid_tolerance, max_forcing] instead of multigrid_tolerance (early
  // steps need 1–5 iterations instead of 20–40). The Newton test on the residual is unchanged.
  // The cap depends on the start. From the relaxed coarse answer (grid sequencing, below) the
  // fronts are nearly in place: 1e-2 takes the same steps as 1e-3 and saves 10 % of the GMRES
  // work (1024²: 14.5 → 13.6 s); 3e-2 takes 2 more steps. From the full film each step moves the
  // fronts by a band and a loose step costs more steps, each with its own AMG setup (512²: 43
  // against 22 solved exactly with 1e-2, 26 with 1e-3; 65²: 10 against 8), hence the tighter cap.
  bool inexact_newton = true;
  double max_forcing = 1e-2;
  double max_forcing_full_film_start = 1e-3;
  // Grid sequencing on the multigrid path with cavitation (rectangular domains whose nodes
  // coarsen by two: nx − 1 even, ny even if periodic else ny − 1 even): the Newton iteration
  // starts from the bilinear interpolation of the same problem solved on every other node
  // (recursively, while the coarse grid keeps at least grid_sequencing_min_nodes per side and
  // still takes the multigrid path), instead of from the full film. Only the start changes; the
  // fine solve meets the same tolerance (and is repeated from the full film if it fails).
  bool grid_sequencing = true;
  int grid_sequencing_min_nodes = 64;
  // The coarse solves stop at max(newton_tolerance, grid_sequencing_tolerance): they only start
  // the fine iteration, and the coarse grid's discretisation error is far above 1e-6.
  double grid_sequencing_tolerance = 1e-6;
  // After a coarse answer is interpolated, symmetric sweeps (forward, then backward over the
  // unknowns) of projected nonlinear Gauss–Seidel on the JFO conditions, before Newton: each node
  // takes the (p, ϑ) that balances its own cell. The coarse fronts sit about a fine cell off the
  // fine ones (first-order upwind transport), a local error the sweeps remove, and a sweep in the
  // flow direction carries ϑ across a cavity in one pass. 20 sweeps cut the fine Newton steps from
  // 8 to 4 at 512² (10 left 6). Only the start changes; 0 starts Newton from the interpolation.
  // (From the full film, whose fronts are far off, the same sweeps halved the steps on the textured
  // film but left rough lift cells and the Fischer–Burmeister 1-D bearing with a start from which
  // the line search crawled a node per step: not used there.)
  int coarse_start_sweeps = 20;
};

struct ReynoldsSummary {
  bool converged = false;
  int iterations = 0;          // Newton iterations on this grid (1 for the linear no-cavitation
                               // solve; a grid-sequenced solve reports its coarse steps in message)
  double residual = 0.0;       // final scaled residual (see ReynoldsOptions)
  std::string message;         // why it stopped, or the SuiteSparse / hypre failure
  std::string linear_solver;   // "cholmod" / "umfpack", or "pfmg-pcg" / "boomeramg-pcg" / "boomeramg-gmres" (last used)
  double linear_solver_s = 0;  // wall time inside the linear solvers (analyse/setup + factorise + solve)
  // Multigrid path: Krylov iterations summed over the solve (PCG of the full film + GMRES of each
  // cavitation Newton step, coarse grids of grid sequencing included) and the largest relative residual ‖b − A x‖₂/‖b‖₂ they ended with
  // (0 on the direct path). A full-film multigrid solve that misses its tolerance sets
  // converged = false, residual = its relative residual and says so in message; a Newton step
  // whose GMRES misses it is redone by UMFPACK (message counts these fallbacks and quotes the last
  // GMRES failure with its residual). With inexact_newton, linear_residual covers the solves held
  // to multigrid_tolerance (the full film and steps whose forcing term reached that floor); the
  // other steps are held to their own forcing term, met or redone by UMFPACK.
  int linear_iterations = 0;
  double linear_residual = 0.0;
  double wall_s = 0;           // total wall time of the solve
};

struct ReynoldsSolution {
  Eigen::ArrayXXd pressure_Pa;        // per node (boundary values included)
  Eigen::ArrayXXd fill_fraction;      // ϑ per node (1 outside cavitated zones)
  Eigen::ArrayXX<bool> wetted;        // node inside the film domain
  double load_N = 0;                  // ∫ p dA (trapezoid along rows, with cut rims for discs)
  double max_pressure_Pa = 0;
  double cavitated_fraction = 0;      // share of wetted area with ϑ < 1
  ReynoldsSummary summary;
};

// Mass balance of a solution from its discrete face fluxes (m³/s): flow into the film through
// the x = 0 boundary, out through x = Lx, net out through every boundary (rim included), and the
// squeeze storage ∫ϑ ḣ dA. Conservation means net_outflow + squeeze_storage = 0.
struct FilmFlow {
  double inflow_x0_m3_per_s = 0, outflow_xL_m3_per_s = 0;
  double net_outflow_m3_per_s = 0, squeeze_storage_m3_per_s = 0;
  // Largest |Σ face outflow + ϑ ḣ dx dy| over the cells: zero (to the solver tolerance) for a
  // mass-conserving solution, not for a half-Sommerfeld one.
  double max_cell_imbalance_m3_per_s = 0;
};
FilmFlow film_flow(const ReynoldsProblem& problem, const ReynoldsSolution& solution);

// Flow per unit width (m²/s) along +x through the face between nodes (i, j) and (i + 1, j) — the
// discrete face flux the solver balances, −k_f (p_N − p_P)/dx + (U/2) t̃_f ϑ_upwind (reduced
// pressure under Barus) — as an (nx − 1) × ny array, face (i, j) at linear index j·(nx − 1) + i.
// Rectangular domains only (throws std::invalid_argument for a disc domain).
Eigen::ArrayXXd x_face_flow_m2_per_s(const ReynoldsProblem& problem, const ReynoldsSolution& solution);

// A solver that keeps its SuiteSparse factorisations (or multigrid setup) between solves: repeated solves on the same
// grid and domain (realisations, time steps, Newton iterations) reuse the symbolic analysis.
class ReynoldsSolver {
 public:
  explicit ReynoldsSolver(ReynoldsOptions options = {});
  ~ReynoldsSolver();
  ReynoldsSolver(const ReynoldsSolver&) = delete;
  ReynoldsSolver& operator=(const ReynoldsSolver&) = delete;
  ReynoldsSolver(ReynoldsSolver&&) noexcept;
  ReynoldsSolver& operator=(ReynoldsSolver&&) noexcept;

  ReynoldsSolution solve(const ReynoldsProblem& problem);
  // How many symbolic analyses have run (tests check reuse).
  int symbolic_analyses() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One-shot convenience: ReynoldsSolver(options).solve(problem).
ReynoldsSolution solve_reynolds(const ReynoldsProblem& problem, const ReynoldsOptions& options = {});

}  // namespace tribo::lubrication
