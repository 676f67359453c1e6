// Multigrid full-film Reynolds solve (CG preconditioned by hypre's structured PFMG on box grids,
// lubrication/struct_multigrid.h, or by BoomerAMG elsewhere, lubrication/linear_solver.h) against
// the direct CHOLMOD path, which stays the reference.
//
// Tolerance. PCG stops at ‖b − A p‖₂ ≤ τ‖b‖₂; with A e = r for the error e = p_mg − p and
// ‖b‖₂ ≤ ‖A‖₂‖p‖₂ this gives ‖e‖₂/‖p‖₂ ≤ κ(A)·τ (the direct solution's own error, κ·ε_machine,
// is 10⁻⁶ of that). κ(A) is bounded from the problem, not fitted to the result:
//   λ_max ≤ 2·max diagonal (Gershgorin: a row's off-diagonals sum to at most its diagonal)
//         ≤ 4 k_max (dy/dx + dx/dy) / θ_min,
//   λ_min ≥ k_min (dy/dx) · 4 sin²(π / (2(nx − 1))),
// with k = h³/(12η) between its smallest and largest nodal value (the face value is a harmonic
// mean of two nodes), θ_min the smallest cut-link fraction of a disc rim (1 without a rim;
// kMinRimFraction = 1e-3 in reynolds.cpp) and the second line because A ≥ k_min·(graph Laplacian
// of the unknowns with their Dirichlet links), which is ≥ its x part: chains of at most nx − 2
// unknowns with Dirichlet ends, whose smallest eigenvalue is 4 sin²(π/(2(nx − 1))) (a shorter
// chain, as in a disc row, has a larger one).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "lubrication/geometry.h"
#include "lubrication/reynolds.h"
#include "tests/lubrication/fixture.h"

namespace tribo::lubrication {
namespace {

using fixture::kEta;

// The bound on ‖p_mg − p‖₂/‖p‖₂ described at the top.
double relative_error_bound(const ReynoldsProblem& pr, double tolerance, double theta_min) {
  const double h_min = pr.gap_m.minCoeff(), h_max = pr.gap_m.maxCoeff();
  const double k_min = h_min * h_min * h_min / (12 * pr.viscosity_Pa_s);
  const double k_max = h_max * h_max * h_max / (12 * pr.viscosity_Pa_s);
  const double rx = pr.grid.dy_m / pr.grid.dx_m, ry = pr.grid.dx_m / pr.grid.dy_m;
  const double lambda_max = 4 * k_max * (rx + ry) / theta_min;
  const double s = std::sin(std::numbers::pi / (2.0 * (pr.grid.nx - 1)));
  const double lambda_min = k_min * rx * 4 * s * s;
  return lambda_max / lambda_min * tolerance;
}

ReynoldsOptions with(PressureSolver backend, double tolerance = 1e-10, bool structured = true) {
  ReynoldsOptions o;
  o.pressure_solver = backend;
  o.multigrid_tolerance = tolerance;
  o.structured_multigrid = structured;
  return o;
}

// ‖a − b‖₂ / ‖b‖₂ over the wetted nodes.
double relative_difference(const ReynoldsSolution& a, const ReynoldsSolution& b) {
  double num = 0, den = 0;
  for (Eigen::Index n = 0; n < b.pressure_Pa.size(); ++n) {
    if (!b.wetted(n)) continue;
    num += std::pow(a.pressure_Pa(n) - b.pressure_Pa(n), 2);
    den += std::pow(b.pressure_Pa(n), 2);
  }
  return std::sqrt(num / den);
}

// Solves directly and by multigrid (structured where the grid allows it, unless `structured` is
// false); checks that the multigrid backend is `backend` and that the pressures agree to the bound.
// Returns the observed relative difference.
double expect_agreement(const ReynoldsProblem& pr, double tolerance, double theta_min, const std::string& backend,
                        bool structured = true) {
  const ReynoldsSolution direct = solve_reynolds(pr, with(PressureSolver::direct));
  const ReynoldsSolution mg = solve_reynolds(pr, with(PressureSolver::multigrid, tolerance, structured));
  EXPECT_TRUE(direct.summary.converged) << direct.summary.message;
  EXPECT_TRUE(mg.summary.converged) << mg.summary.message;
  EXPECT_EQ(direct.summary.linear_solver, "cholmod");
  EXPECT_EQ(mg.summary.linear_solver, backend);
  EXPECT_GT(mg.summary.linear_iterations, 0);
  EXPECT_LE(mg.summary.linear_residual, tolerance);
  const double bound = relative_error_bound(pr, tolerance, theta_min);
  const double diff = relative_difference(mg, direct);
  std::printf("  %d x %d nodes, %s: %d PCG iterations, residual %.2e, |p_mg - p|/|p| = %.2e (bound %.2e)\n",
              static_cast<int>(pr.grid.nx), static_cast<int>(pr.grid.ny), backend.c_str(), mg.summary.linear_iterations,
              mg.summary.linear_residual, diff, bound);
  EXPECT_LE(diff, bound);
  // The load is Σ w p with node weights w ≤ dx·dy: |ΔW| ≤ ‖w‖₂‖p_mg − p‖₂ (Cauchy–Schwarz).
  double p_norm = 0;
  for (Eigen::Index n = 0; n < direct.pressure_Pa.size(); ++n)
    if (direct.wetted(n)) p_norm += direct.pressure_Pa(n) * direct.pressure_Pa(n);
  const double weight_norm = pr.grid.cell_area_m2() * std::sqrt(static_cast<double>(pr.grid.size()));
  EXPECT_NEAR(mg.load_N, direct.load_N, weight_norm * bound * std::sqrt(p_norm));
  return diff;
}

// The benchmark film (fixture::textured_film), sliding at 1 m/s.
ReynoldsProblem textured(int n, Cavitation cavitation = Cavitation::none, BoundaryY boundary_y = BoundaryY::periodic) {
  return fixture::textured_film(n, 1.0, cavitation, boundary_y);
}

// Inclined pad of reynolds_test (Hamrock et al. §8.4), h = h₀(1 + K(1 − x/L)), K = 1.5: a 1-D
// film (ny = 3, periodic) whose conductance varies 15× along x. A period of 3 nodes is not one
// PFMG can halve, so this box goes to BoomerAMG.
TEST(MultigridPressure, AgreesWithDirectOnInclinedPad) {
  const double length = 5e-3, h0 = 2e-6, k = 1.5;
  ReynoldsProblem pr;
  const int nx = 401;
  pr.grid = contact::Grid{nx, 3, length / (nx - 1), 1e-4 / 3};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < nx; ++i) pr.gap_m(i, j) = h0 * (1.0 + k * (1.0 - i * pr.grid.dx_m / length));
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = 1.0;
  pr.boundary_y = BoundaryY::periodic;
  expect_agreement(pr, 1e-10, 1.0, "boomeramg-pcg");
}

// Squeeze film between parallel discs (thesis App. III): the masked domain with Gibou cut links
// at the rim. The rim links widen the κ bound by 1/θ_min = 10³, so τ = 1e-12 here.
TEST(MultigridPressure, AgreesWithDirectOnParallelDiscs) {
  const ReynoldsProblem pr = parallel_discs_problem(4.7625e-3, 1e-6, -1e-6, kEta, 0.3, 83);
  expect_agreement(pr, 1e-12, 1e-3, "boomeramg-pcg");
}

// A genuinely 2-D film with sub-ambient regions, on an odd and an even grid: periodic in y with a
// period of 2^6 nodes (PFMG, and BoomerAMG when asked) or of 97 (not halvable: BoomerAMG).
TEST(MultigridPressure, AgreesWithDirectOnTexturedFilm) {
  expect_agreement(textured(64), 1e-10, 1.0, "pfmg-pcg");
  expect_agreement(textured(64), 1e-10, 1.0, "boomeramg-pcg", false);
  expect_agreement(textured(97), 1e-10, 1.0, "boomeramg-pcg");
}

// Ambient in y (p = 0 on y = 0 and Ly): a box of any size is PFMG's; odd and even node counts.
TEST(MultigridPressure, StructuredAgreesWithDirectOnOddAndEvenBoxes) {
  expect_agreement(textured(64, Cavitation::none, BoundaryY::ambient), 1e-10, 1.0, "pfmg-pcg");
  expect_agreement(textured(97, Cavitation::none, BoundaryY::ambient), 1e-10, 1.0, "pfmg-pcg");
}

// JFO cavitation: on the multigrid path the full film is solved by AMG-PCG and every reduced
// Newton step by AMG-GMRES (to ‖r‖₂ ≤ 1e-10‖b‖₂) instead of UMFPACK; both runs must converge to the
// same complementarity solution. Each meets the Newton tolerance 1e-10 on the scaled residual, so
// the answers differ by at most that times the Newton matrix's conditioning — 1e-7 relative on the
// load leaves ≥ 10² of margin for κ ≲ 10⁵ at 65²; the cavitated set must be identical.
TEST(MultigridPressure, CavitationAgreesWithDirect) {
  for (int n : {64, 97}) {
    const ReynoldsProblem pr = textured(n, Cavitation::mass_conserving);
    const ReynoldsSolution direct = solve_reynolds(pr, with(PressureSolver::direct));
    const ReynoldsSolution mg = solve_reynolds(pr, with(PressureSolver::multigrid));
    ASSERT_TRUE(direct.summary.converged) << direct.summary.message;
    ASSERT_TRUE(mg.summary.converged) << mg.summary.message;
    EXPECT_EQ(direct.summary.linear_solver, "umfpack");
    EXPECT_EQ(mg.summary.linear_solver, "boomeramg-gmres");
    EXPECT_EQ(mg.summary.message.find("fell back"), std::string::npos) << mg.summary.message;
    EXPECT_LE(mg.summary.linear_residual, 1e-10);
    EXPECT_GT(direct.cavitated_fraction, 0.1);
    std::printf("  %d^2 JFO: Newton %d (direct %d), %d Krylov iterations, load ratio - 1 = %.2e\n", n,
                mg.summary.iterations, direct.summary.iterations, mg.summary.linear_iterations,
                mg.load_N / direct.load_N - 1.0);
    EXPECT_NEAR(mg.load_N / direct.load_N, 1.0, 1e-7);
    EXPECT_NEAR(mg.cavitated_fraction, direct.cavitated_fraction, 1e-12);
  }
}

// A multigrid solve stopped before its tolerance is reported, never returned as an answer (PFMG
// and BoomerAMG alike).
TEST(MultigridPressure, NonConvergenceIsReportedWithItsResidual) {
  for (const bool structured : {true, false}) {
    ReynoldsOptions o = with(PressureSolver::multigrid, 1e-14, structured);
    o.multigrid_max_iterations = 1;
    const ReynoldsSolution s = solve_reynolds(textured(64), o);
    EXPECT_EQ(s.summary.linear_solver, structured ? "pfmg-pcg" : "boomeramg-pcg");
    EXPECT_FALSE(s.summary.converged);
    EXPECT_EQ(s.summary.linear_iterations, 1);
    EXPECT_GT(s.summary.linear_residual, 1e-14);
    EXPECT_EQ(s.summary.residual, s.summary.linear_residual);
    EXPECT_NE(s.summary.message.find("relative residual"), std::string::npos) << s.summary.message;
  }
}

// automatic: CHOLMOD below multigrid_min_unknowns, multigrid from there on (PFMG on this box).
TEST(MultigridPressure, AutomaticChoosesByGridSize) {
  const ReynoldsProblem pr = textured(32);  // 31 × 32 unknowns
  EXPECT_EQ(solve_reynolds(pr).summary.linear_solver, "cholmod");
  ReynoldsOptions o;
  o.multigrid_min_unknowns = 31 * 32;
  EXPECT_EQ(solve_reynolds(pr, o).summary.linear_solver, "pfmg-pcg");
  o.multigrid_min_unknowns = 31 * 32 + 1;
  EXPECT_EQ(solve_reynolds(pr, o).summary.linear_solver, "cholmod");
}

TEST(MultigridPressure, RejectsBadOptions) {
  ReynoldsOptions o;
  o.multigrid_tolerance = 0;
  EXPECT_THROW(ReynoldsSolver{o}, std::invalid_argument);
  o = {};
  o.multigrid_max_iterations = 0;
  EXPECT_THROW(ReynoldsSolver{o}, std::invalid_argument);
}

}  // namespace
}  // namespace tribo::lubrication
