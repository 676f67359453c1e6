// The EHL point contact (lubrication/ehl_point.h), the checks fast enough for the sanitizer build:
// the dry Hertz pressure at a high load, the load balance, bad input and a reported
// non-convergence. The film against the published fits and its grid convergence are in
// ehl_point_slow_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "lubrication/ehl_traction.h"
#include "lubrication/reference/ehl_point_film.h"
#include "tests/lubrication/ball_on_disc.h"

namespace tribo::lubrication {
namespace {

using namespace ball_on_disc;

// At 20 N (p_H = 0.83 GPa, Moes M ≈ 100) the film is thin against the deflection and the pressure
// is the dry contact's: Hertz's semi-ellipsoid across the flow through the centre, to 4 % of p_H
// within 0.7 a (31² nodes put 6 of them there; the film departs from Hertz at the inlet and the
// outlet's constriction, along x).
TEST(EhlPoint, HighLoadPressureIsHertzianAcrossTheFlow) {
  const double load = 20.0;
  const EhlPointResult r = solve_ehl_point(ball_contact(load, 0.5), ball_oil(), ball_grid(31));
  ASSERT_TRUE(r.converged) << r.message;
  EXPECT_NEAR(r.hertz_pressure_Pa, reference::hertz_point_peak_pressure_Pa(load, kBallRadius_m, kBallModulus_Pa), 1e-12 * r.hertz_pressure_Pa);
  EXPECT_NEAR(r.load_balance_error, 0.0, 1e-9);
  const std::size_t nx = r.x_m.size();
  std::size_t centre = 0;  // the column nearest x = 0
  for (std::size_t i = 0; i < nx; ++i)
    if (std::abs(r.x_m[i]) < std::abs(r.x_m[centre])) centre = i;
  ASSERT_LT(std::abs(r.x_m[centre]) / r.hertz_radius_m, 0.1);
  int inside = 0;
  for (std::size_t j = 0; j < r.y_m.size(); ++j) {
    const double y = r.y_m[j] / r.hertz_radius_m, x = r.x_m[centre] / r.hertz_radius_m;
    if (std::abs(y) > 0.7) continue;
    ++inside;
    EXPECT_NEAR(r.pressure_Pa[centre + nx * j] / r.hertz_pressure_Pa, std::sqrt(1.0 - x * x - y * y), 0.04) << "y/a = " << y;
  }
  EXPECT_GE(inside, 6);
  // The horseshoe: the minimum film lies below the central one.
  EXPECT_LT(r.minimum_film_m, r.central_film_m);
}

// The traction of a point film is the Eyring stress τ0 asinh(η(p) Δu/(τ0 h)) over each pressurised
// node's Δx Δy cell (Johnson & Tevaarwerk 1977's model): on a hand-made film of uniform p and h over
// 3 × 3 of 5 × 5 nodes the force is 9 of those cells' worth, to round-off; the cavitated rim
// carries none, and the sign follows the sliding.
TEST(EhlPoint, TractionIsTheEyringStressOverThePressurisedCells) {
  EhlPointResult film;
  const double dx = 2e-5, dy = 3e-5, p0 = 5e8, h0 = 2e-7;
  for (int i = 0; i < 5; ++i) film.x_m.push_back(i * dx), film.y_m.push_back(i * dy);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const bool inner = i > 0 && i < 4 && j > 0 && j < 4;
      film.pressure_Pa.push_back(inner ? p0 : 0.0);
      film.film_m.push_back(h0);
    }
  const double du = 0.1, tau0 = 5e6, load = 10.0;
  const double eta = ball_oil().viscosity_Pa_s * viscosity_ratio(ball_oil(), p0).ratio;
  const double tau = tau0 * std::asinh(eta * du / (tau0 * h0));
  const EhlPointTraction t = ehl_point_traction(film, ball_oil(), du, tau0, load);
  EXPECT_NEAR(t.force_N, 9.0 * tau * dx * dy, 1e-12 * t.force_N);
  EXPECT_NEAR(t.friction_coefficient, t.force_N / load, 1e-15);
  EXPECT_NEAR(t.max_shear_stress_Pa, tau, 1e-9 * tau);
  EXPECT_NEAR(ehl_point_traction(film, ball_oil(), -du, tau0, load).force_N, -t.force_N, 1e-12 * t.force_N);
  // The solver leaves the cavitated zone at 0 only to round-off: ±1e-11 Pa there must not make
  // those nodes shear (their film would add 16 cells' worth of τ).
  for (std::size_t k = 0; k < film.pressure_Pa.size(); ++k)
    if (film.pressure_Pa[k] == 0.0) film.pressure_Pa[k] = k % 2 ? 1e-11 : -1e-11;
  EXPECT_EQ(ehl_point_traction(film, ball_oil(), du, tau0, load).force_N, t.force_N);
  film.film_m.pop_back();
  EXPECT_THROW(ehl_point_traction(film, ball_oil(), du, tau0, load), std::invalid_argument);
}

// Two solves of the same discrete problem, each to ‖F‖∞ ≤ 1e-9 (≈ 1e-9 relative on the pressures):
// the central and minimum films and the peak pressure agree to 1e-7.
void expect_same_solution(const EhlPointResult& a, const EhlPointResult& b) {
  EXPECT_NEAR(a.central_film_m / b.central_film_m, 1.0, 1e-7);
  EXPECT_NEAR(a.minimum_film_m / b.minimum_film_m, 1.0, 1e-7);
  EXPECT_NEAR(a.max_pressure_Pa / b.max_pressure_Pa, 1.0, 1e-7);
}

// The two linear solvers of the Newton step solve the same discrete problem: Newton–Krylov applies
// the elastic kernel by FFT (contact/'s zero-padded half-space, E* = π/2 to match the scaling) where
// the dense LU multiplies the assembled kernel. From the same start (no coarser-grid start) both
// converge to ‖F‖∞ ≤ 1e-9 (set here; the default is 1e-7), which bounds the difference of the
// answers (≈ 1e-9 relative on the pressures): the films and the peak pressure to 1e-7. GMRES solves each step only as exactly as
// Newton's progress can use (1e-2 … 1e-6), which may cost a Newton step or two more, not fewer.
// A kernel off by a factor or a transposed offset fails this by orders. 25² is odd (a node on the
// centre line), 26² even.
class EhlPointLinearSolvers : public ::testing::TestWithParam<int> {};

TEST_P(EhlPointLinearSolvers, NewtonKrylovMatchesTheDenseLu) {
  EhlPointOptions dense = ball_grid(GetParam());
  dense.tolerance = 1e-9;
  EhlPointOptions krylov = dense;
  dense.linear_solver = EhlPointLinearSolver::dense_lu;
  krylov.linear_solver = EhlPointLinearSolver::newton_krylov;
  krylov.start_from_coarser_grid = false;
  const EhlPointResult d = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), dense);
  const EhlPointResult k = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), krylov);
  ASSERT_TRUE(d.converged) << d.message;
  ASSERT_TRUE(k.converged) << k.message;
  EXPECT_EQ(d.linear_solver, "dense LU");
  EXPECT_EQ(k.linear_solver, "GMRES, sparse LU preconditioner");
  EXPECT_EQ(d.krylov_iterations, 0);
  EXPECT_GT(k.krylov_iterations, k.iterations);  // more than one GMRES iteration a step: the preconditioner is not exact
  expect_same_solution(k, d);
  EXPECT_GE(k.iterations, d.iterations);
  EXPECT_LE(k.iterations, d.iterations + 2);
}

// Started from a coarser grid (the default), Newton–Krylov solves the same discrete problem: the
// coarser solve (dense, on 16² or 17²) is only a start, interpolated by cubics, while a second
// thread analyses the preconditioner's pattern from the Jacobian at the Hertz start. Same answer as
// the dense LU from the Hertz start, to the bound above (1e-7, both to ‖F‖∞ ≤ 1e-9), and no more
// Newton steps on the grid itself than from the Hertz start: a start is worth no less than
// Hertz's. (The analysis is kept only where its pattern's size is the factorised matrix's, else
// redone; an interpolation that misplaced the coarse pressures would cost the steps.)
TEST_P(EhlPointLinearSolvers, NewtonKrylovFromACoarserGridMatchesTheDenseLu) {
  EhlPointOptions dense = ball_grid(GetParam() + 6);
  dense.tolerance = 1e-9;
  EhlPointOptions nested = dense, cold = dense;
  dense.linear_solver = EhlPointLinearSolver::dense_lu;
  nested.linear_solver = cold.linear_solver = EhlPointLinearSolver::newton_krylov;
  cold.start_from_coarser_grid = false;
  const EhlPointResult d = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), dense);
  const EhlPointResult n = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), nested);
  const EhlPointResult c = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), cold);
  ASSERT_TRUE(d.converged) << d.message;
  ASSERT_TRUE(n.converged) << n.message;
  ASSERT_TRUE(c.converged) << c.message;
  expect_same_solution(n, d);
  EXPECT_LE(n.iterations, c.iterations);
}

INSTANTIATE_TEST_SUITE_P(OddAndEvenGrids, EhlPointLinearSolvers, ::testing::Values(25, 26));

// The smooth contact entrained along x is symmetric in y, so the default solves the half Y ≥ 0 (a
// node and its mirror image share an unknown; the load counts it twice, the kernel's column holds
// both cells). The same discrete problem as on the full grid: both to ‖F‖∞ ≤ 1e-9, the films and
// the peak pressure to 1e-7 (as above) and every nodal pressure to 1e-7 p_H — by the dense LU
// (21²), and by Newton–Krylov started from coarser grids on an odd grid (25², a row of nodes on
// the centre line, its own mirror) and an even one (26²). (A load row that forgot the mirror's
// weight left 21² and 25² unconverged at ‖F‖∞ ≈ 5e-5 after the whole continuation.)
class EhlPointHalfDomain : public ::testing::TestWithParam<int> {};

TEST_P(EhlPointHalfDomain, MirrorSymmetricHalfSolvesTheFullGridsProblem) {
  EhlPointOptions half = ball_grid(GetParam());
  half.tolerance = 1e-9;
  EhlPointOptions full = half;
  full.symmetric_in_y = false;
  const EhlPointResult h = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), half);
  const EhlPointResult f = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), full);
  ASSERT_TRUE(h.converged) << h.message;
  ASSERT_TRUE(f.converged) << f.message;
  EXPECT_EQ(h.linear_solver, f.linear_solver);
  expect_same_solution(h, f);
  double largest = 0.0;
  for (std::size_t k = 0; k < f.pressure_Pa.size(); ++k) largest = std::max(largest, std::abs(h.pressure_Pa[k] - f.pressure_Pa[k]));
  EXPECT_LE(largest, 1e-7 * f.hertz_pressure_Pa);
}

INSTANTIATE_TEST_SUITE_P(OddAndEvenGrids, EhlPointHalfDomain, ::testing::Values(21, 25, 26));

// The two NCP functions (complementarity.h) state the same cavitation conditions, so they pose the
// same discrete problem: from the same start both converge to ‖F‖∞ ≤ 1e-9 (set here), and the films and the
// peak pressure agree to 1e-7 (as the linear solvers above). The minimum function's Newton step is
// a primal–dual active-set step, quadratic once the cavitated set has settled; Fischer–Burmeister
// rounds the corner where P and the Reynolds residual are both small — at the cavitation front —
// and converges only linearly there: the reason for the default (31² at 10 N: 6 steps against 15).
TEST(EhlPoint, MinimumAndFischerBurmeisterSolveTheSameCavitationProblem) {
  EhlPointOptions minimum = ball_grid(31);
  minimum.tolerance = 1e-9;
  EhlPointOptions fischer = minimum;
  fischer.complementarity = Complementarity::fischer_burmeister;
  const EhlPointResult m = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), minimum);
  const EhlPointResult f = solve_ehl_point(ball_contact(10.0, 0.5), ball_oil(), fischer);
  ASSERT_TRUE(m.converged) << m.message;
  ASSERT_TRUE(f.converged) << f.message;
  expect_same_solution(m, f);
  EXPECT_LT(m.iterations, f.iterations);
}

// At 100 N (p_H 1.4 GPa, Moes M ≈ 540) 25² nodes do not resolve the contact: from the Hertz start
// Newton drives the film to zero at a node, the step limit halves at every step and ‖F‖ stands
// still. The solve says so and gives up early, not after its 30 steps (without the continuation,
// which stalls the same way at every λ on this grid).
TEST(EhlPoint, StalledSolveEndsEarlyAndSaysWhy) {
  EhlPointOptions o = ball_grid(25);
  o.max_continuation_steps = 0;
  const EhlPointResult r = solve_ehl_point(ball_contact(100.0, 0.5), ball_oil(), o);
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("stalled"), std::string::npos) << r.message;
  EXPECT_LT(r.iterations, o.max_newton_iterations / 2) << r.message;
}

TEST(EhlPoint, BadInputIsRejectedAndNonConvergenceIsReported) {
  EXPECT_THROW(solve_ehl_point(ball_contact(-1.0, 0.5), ball_oil(), ball_grid(21)), std::invalid_argument);
  EhlPointOptions narrow = ball_grid(21);
  narrow.side_over_radius = 0.8;  // the Hertz circle does not fit
  EXPECT_THROW(solve_ehl_point(ball_contact(2.0, 0.5), ball_oil(), narrow), std::invalid_argument);
  EXPECT_THROW(solve_ehl_point(ball_contact(2.0, 0.5), ball_oil(), ball_grid(9)), std::invalid_argument);
  EhlPointOptions far_reach = ball_grid(21);
  far_reach.preconditioner_reach = 17;
  EXPECT_THROW(solve_ehl_point(ball_contact(2.0, 0.5), ball_oil(), far_reach), std::invalid_argument);
  EhlPointOptions starved = ball_grid(21);
  starved.max_newton_iterations = 1;
  starved.max_continuation_steps = 0;
  const EhlPointResult r = solve_ehl_point(ball_contact(2.0, 0.5), ball_oil(), starved);
  EXPECT_FALSE(r.converged);
  EXPECT_GT(r.residual, starved.tolerance);
  EXPECT_NE(r.message.find("not converged"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace tribo::lubrication
