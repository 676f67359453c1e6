// Reynolds solver (lubrication/reynolds.h) without cavitation, against closed forms:
// squeeze film between parallel discs (thesis Appendix III), plane Couette and Poiseuille
// channel flow, the inclined-pad bearing and the Rayleigh step; plus input validation and
// reuse of the symbolic factorisation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "lubrication/geometry.h"
#include "lubrication/reference/squeeze_film.h"
#include "lubrication/reynolds.h"
#include "tests/lubrication/observed_order.h"
#include "tests/lubrication/fixture.h"

namespace tribo::lubrication {
namespace {

using fixture::kEta, fixture::kRadius, fixture::kGap, fixture::kRate;

// A film that is uniform across y (ny = 3, periodic): the infinitely wide bearing.
ReynoldsProblem channel(int nx, double length_m, double width_m) {
  ReynoldsProblem pr;
  pr.grid = contact::Grid{nx, 3, length_m / (nx - 1), width_m / 3};
  pr.gap_m = pr.grid.field(kGap);
  pr.viscosity_Pa_s = kEta;
  pr.boundary_y = BoundaryY::periodic;
  return pr;
}

// Appendix III: p(ρ) = 3η(ρ² − R²)ḣ/h³ and N_f = −(3/2)πηR⁴ḣ/h³ (3.2.2). The rim is curved,
// so this exercises the cut-cell (Gibou) boundary; the grid spacing halves four times.
// Expected: pressure max-norm error falls as dx² (order 2 ± 0.2); the load error at least as fast.
TEST(SqueezeFilmDiscs, ConvergesToAppendixIIIAtSecondOrder) {
  const double load_ref = squeeze_film_load_N(kEta, kRadius, kGap, kRate);
  std::vector<double> dx, load_err, p_err;
  // The discretisation's order, on the reference (direct) solve at every grid: the multigrid path's
  // agreement with it is multigrid_test.cpp's (and 323² would start Open MPI, tests labelled `mpi`).
  ReynoldsOptions direct;
  direct.pressure_solver = PressureSolver::direct;
  for (int n : {23, 43, 83, 163, 323}) {  // n − 3 = 20 · 2^k: dx halves exactly
    const ReynoldsProblem pr = parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.0, n);
    const ReynoldsSolution s = solve_reynolds(pr, direct);
    ASSERT_TRUE(s.summary.converged) << s.summary.message;
    double e = 0;
    const double p0 = squeeze_film_pressure_Pa(kEta, kRadius, kGap, kRate, 0.0);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (!s.wetted(i, j)) continue;
        const double r = std::hypot(i * pr.grid.dx_m - pr.disc->centre_x_m, j * pr.grid.dy_m - pr.disc->centre_y_m);
        e = std::max(e, std::abs(s.pressure_Pa(i, j) - squeeze_film_pressure_Pa(kEta, kRadius, kGap, kRate, r)) / p0);
      }
    dx.push_back(pr.grid.dx_m);
    load_err.push_back(std::abs(s.load_N / load_ref - 1.0));
    p_err.push_back(e);
    std::printf("  n = %3d  dx = %.3e m  load = %.8f N (ref %.8f)  load error %.2e  max p error %.2e\n", n,
                pr.grid.dx_m, s.load_N, load_ref, load_err.back(), e);
  }
  const double p_order = observed_order(dx, p_err), load_order = observed_order(dx, load_err);
  std::printf("  observed order: pressure %.2f, load %.2f\n", p_order, load_order);
  EXPECT_NEAR(p_order, 2.0, 0.2);
  EXPECT_GT(load_order, 1.8);
  EXPECT_LT(load_err.back(), 2e-6);  // finest grid: 20 µN of 51 N
}

// Squeeze-out under constant load (Appendix III): integrating ḣ = −W / C(h), with C(h) the load
// per unit closing speed computed by the solver at each node of the quadrature (t = ∫ dh/ḣ by
// Simpson's rule in ln h, 20 panels from h₀ = 2 µm to h₁ = 1 µm), reproduces
// t = (3πηR⁴/4W)(1/h₁² − 1/h₀²). The solver's load is within 2e-5 of (3.2.2) on 83² (see the
// convergence test) and the quadrature of the smooth integrand (∝ h²) adds < 1e-7: 1e-4.
TEST(SqueezeFilmDiscs, SqueezeOutTimeUnderConstantLoad) {
  const double load = 93.86, h0 = 2e-6, h1 = 1e-6;
  ReynoldsSolver solver;
  // d(ln h)/dt = ḣ/h = −W/(C(h) h); C from a solve at unit closing speed.
  auto dlnh_dt = [&](double lnh) {
    const double h = std::exp(lnh);
    const double c = solver.solve(parallel_discs_problem(kRadius, h, -1.0, kEta, 0.0, 83)).load_N;
    return -load / (c * h);
  };
  // Integrate t(ln h): dt/d(ln h) = 1 / (d ln h / dt), from ln h₀ to ln h₁.
  const int steps = 20;
  const double a = std::log(h0), b = std::log(h1), d = (b - a) / steps;
  double t = 0;
  for (int k = 0; k < steps; ++k) {
    const double x = a + k * d;
    t += d / 6.0 * (1.0 / dlnh_dt(x) + 4.0 / dlnh_dt(x + 0.5 * d) + 1.0 / dlnh_dt(x + d));
  }
  const double t_ref = squeeze_out_time_s(kEta, kRadius, load, h0, h1);
  std::printf("  squeeze-out 2 -> 1 um under %.2f N: %.6f s (closed form %.6f s)\n", load, t, t_ref);
  EXPECT_NEAR(t / t_ref, 1.0, 1e-4);
  EXPECT_EQ(solver.symbolic_analyses(), 1);
}

// Sliding does not change the squeeze load of parallel discs (thesis, after (3.2.2)): with
// uniform h the Couette term (U/2)∂h/∂x vanishes identically.
TEST(SqueezeFilmDiscs, LoadIndependentOfSliding) {
  const ReynoldsProblem still = parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.0, 63);
  const ReynoldsProblem sliding = parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.3, 63);
  EXPECT_NEAR(solve_reynolds(sliding).load_N, solve_reynolds(still).load_N, 1e-12 * solve_reynolds(still).load_N);
}

// Plane Couette flow: parallel plates, equal end pressures, sliding at U: p ≡ 0 and the flow per
// unit width is U h/2. Both hold to rounding (the scheme is exact for uniform h).
TEST(ChannelFlow, PlaneCouette) {
  ReynoldsProblem pr = channel(41, 1e-3, 1e-4);
  pr.sliding_speed_m_per_s = 0.2;
  const ReynoldsSolution s = solve_reynolds(pr);
  for (double p : s.pressure_Pa.reshaped()) EXPECT_NEAR(p, 0.0, 1e-9);
  const FilmFlow f = film_flow(pr, s);
  const double width = pr.grid.ny * pr.grid.dy_m;
  EXPECT_NEAR(f.inflow_x0_m3_per_s / width, 0.5 * 0.2 * kGap, 1e-12 * 0.5 * 0.2 * kGap);
  EXPECT_NEAR(f.outflow_xL_m3_per_s, f.inflow_x0_m3_per_s, 1e-12 * f.inflow_x0_m3_per_s);
}

// Plane Poiseuille flow: pressure drop Δp over L between fixed plates: linear p and flow per
// unit width h³Δp/(12ηL); exact for uniform h, so 1e-10 relative.
TEST(ChannelFlow, PlanePoiseuille) {
  ReynoldsProblem pr = channel(31, 2e-3, 1e-4);
  pr.inlet_pressure_Pa = 3e5;
  const ReynoldsSolution s = solve_reynolds(pr);
  for (int i = 0; i < pr.grid.nx; ++i) {
    const double x = i * pr.grid.dx_m;
    EXPECT_NEAR(s.pressure_Pa(i, 1), 3e5 * (1.0 - x / 2e-3), 1e-10 * 3e5);
  }
  const double q_ref = kGap * kGap * kGap * 3e5 / (12.0 * kEta * 2e-3);
  const FilmFlow f = film_flow(pr, s);
  EXPECT_NEAR(f.inflow_x0_m3_per_s / (pr.grid.ny * pr.grid.dy_m), q_ref, 1e-10 * q_ref);
}

// Piezoviscous Poiseuille channel, Barus η = η₀e^{ψp}: the reduced pressure q = (1 − e^{−ψp})/ψ
// is linear, so p(x) = −ln(1 − (1 − e^{−ψp_in})(1 − x/L))/ψ and the flow per unit width is
// h³(1 − e^{−ψp_in})/(12η₀Lψ) — exact for uniform h, so 1e-10. With ψp_in = 2 the flow is
// (1 − e⁻²)/2 = 43 % of the isoviscous one.
TEST(ChannelFlow, PiezoviscousPoiseuille) {
  ReynoldsProblem pr = channel(31, 2e-3, 1e-4);
  const double psi = 2e-8, p_in = 1e8;
  pr.inlet_pressure_Pa = p_in;
  pr.pressure_viscosity_per_Pa = psi;
  const ReynoldsSolution s = solve_reynolds(pr);
  ASSERT_TRUE(s.summary.converged) << s.summary.message;
  const double a = -std::expm1(-psi * p_in);
  for (int i = 0; i < pr.grid.nx; ++i) {
    const double x = i * pr.grid.dx_m;
    EXPECT_NEAR(s.pressure_Pa(i, 1), -std::log1p(-a * (1.0 - x / 2e-3)) / psi, 1e-10 * p_in);
  }
  const double q_ref = kGap * kGap * kGap * a / (12.0 * kEta * 2e-3 * psi);
  EXPECT_NEAR(film_flow(pr, s).inflow_x0_m3_per_s / (pr.grid.ny * pr.grid.dy_m), q_ref, 1e-10 * q_ref);
}

// Where the isoviscous reduced pressure reaches 1/ψ Barus' law has no finite pressure: reported
// as non-convergence with the reason, not returned as a number.
TEST(ChannelFlow, PiezoviscousBlowUpIsReported) {
  ReynoldsProblem pr = channel(101, 5e-3, 1e-4);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < pr.grid.nx; ++i) pr.gap_m(i, j) = 2e-7 * (1.0 + 1.5 * (1.0 - i / 100.0));
  pr.sliding_speed_m_per_s = 1.0;
  pr.pressure_viscosity_per_Pa = 2e-8;  // isoviscous peak here ≈ 6.8e8 Pa > 1/ψ = 5e7 Pa
  const ReynoldsSolution s = solve_reynolds(pr);
  EXPECT_FALSE(s.summary.converged);
  EXPECT_NE(s.summary.message.find("blow-up"), std::string::npos) << s.summary.message;
}

// Inclined pad (infinitely wide), h = h₀(1 + K(1 − x/L)), sliding at U towards the narrow end:
// W/B = 6ηUL²/(K²h₀²) [ln(1 + K) − 2K/(2 + K)] (Hamrock, Schmid & Jacobson, Fundamentals of
// Fluid Film Lubrication, 2nd ed., §8.4). The gap varies smoothly: second-order convergence,
// so 401 nodes give the load to 1e-5 and the observed order is 2 ± 0.1.
TEST(InclinedPad, LoadMatchesClosedForm) {
  const double length = 5e-3, h0 = 2e-6, k = 1.5, u = 1.0;
  const double load_ref = 6.0 * kEta * u * length * length / (k * k * h0 * h0) * (std::log1p(k) - 2.0 * k / (2.0 + k));
  std::vector<double> dx, err;
  for (int nx : {51, 101, 201, 401}) {
    ReynoldsProblem pr = channel(nx, length, 1e-4);
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < nx; ++i) pr.gap_m(i, j) = h0 * (1.0 + k * (1.0 - i * pr.grid.dx_m / length));
    pr.sliding_speed_m_per_s = u;
    const ReynoldsSolution s = solve_reynolds(pr);
    dx.push_back(pr.grid.dx_m);
    err.push_back(std::abs(s.load_N / (pr.grid.ny * pr.grid.dy_m) / load_ref - 1.0));
  }
  std::printf("  inclined pad: load error %.2e at nx = 401, observed order %.2f\n", err.back(), observed_order(dx, err));
  EXPECT_LT(err.back(), 1e-5);
  EXPECT_NEAR(observed_order(dx, err), 2.0, 0.1);
}

// Rayleigh step: gap h₁ over [0, a], h₂ < h₁ over [a, L]; the peak pressure at the step is
// p_a = 6ηU(h₁ − h₂)/(h₁³/a + h₂³/(L − a)). With the step on a face midpoint the face integral
// of the scheme is exact, so the discrete peak equals the closed form to rounding (1e-10).
TEST(RayleighStep, PeakPressureExact) {
  const int nx = 81;
  const double length = 4e-3, h1 = 2e-6, h2 = 1e-6, u = 0.5;
  ReynoldsProblem pr = channel(nx, length, 1e-4);
  const int step_face = 50;  // step between nodes 49 and 50, at a = 49.5 dx
  const double a = (step_face - 0.5) * pr.grid.dx_m;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < nx; ++i) pr.gap_m(i, j) = i < step_face ? h1 : h2;
  pr.sliding_speed_m_per_s = u;
  const ReynoldsSolution s = solve_reynolds(pr);
  const double pa = 6.0 * kEta * u * (h1 - h2) / (h1 * h1 * h1 / a + h2 * h2 * h2 / (length - a));
  // The peak lies between the two nodes either side of the step: linear profiles on each side.
  const double p49 = s.pressure_Pa(49, 1), p50 = s.pressure_Pa(50, 1);
  EXPECT_NEAR(p49, pa * 49.0 / 49.5, 1e-10 * pa);
  EXPECT_NEAR(p50, pa * (nx - 1 - 50) / (nx - 1 - 49.5), 1e-10 * pa);
}

// Bad inputs are rejected with std::invalid_argument naming the input.
TEST(ReynoldsInput, RejectsBadInputWithClearMessage) {
  auto expect_message = [](ReynoldsProblem pr, const std::string& needle) {
    try {
      solve_reynolds(pr);
      ADD_FAILURE() << "no exception for " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const ReynoldsProblem good = channel(11, 1e-3, 1e-4);
  ReynoldsProblem p = good;
  p.gap_m(7) = 0.0;
  expect_message(p, "gap_m must be finite and > 0");
  p = good;
  p.gap_m(7) = -1e-6;
  expect_message(p, "node (i=7, j=0)");
  p = good;
  p.gap_m(3) = std::numeric_limits<double>::quiet_NaN();
  expect_message(p, "gap_m");
  p = good;
  p.viscosity_Pa_s = 0.0;
  expect_message(p, "viscosity_Pa_s");
  p = good;
  p.viscosity_Pa_s = -0.02;
  expect_message(p, "viscosity_Pa_s");
  p = good;
  p.sliding_speed_m_per_s = std::numeric_limits<double>::quiet_NaN();
  expect_message(p, "sliding_speed_m_per_s");
  p = good;
  p.pressure_viscosity_per_Pa = -1e-8;
  expect_message(p, "pressure_viscosity_per_Pa");
  p = good;
  p.grid.ny = 2;
  p.gap_m = p.grid.field(kGap);
  expect_message(p, "at least 3 nodes");
  EXPECT_THROW(parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.0, 2), std::invalid_argument);
  EXPECT_THROW(solve_reynolds(parallel_discs_problem(kRadius, -kGap, kRate, kEta, 0.0, 21)), std::invalid_argument);
}

// Repeated solves on one grid reuse CHOLMOD's symbolic analysis: one analysis for three gaps;
// a new grid needs a new one. Loads scale as 1/h³ (3.2.2), to discretisation-independent 1e-12.
TEST(ReynoldsSolverReuse, SymbolicAnalysisReusedWhilePatternHolds) {
  ReynoldsSolver solver;
  const double w1 = solver.solve(parallel_discs_problem(kRadius, 1e-6, kRate, kEta, 0.0, 41)).load_N;
  const double w2 = solver.solve(parallel_discs_problem(kRadius, 2e-6, kRate, kEta, 0.0, 41)).load_N;
  solver.solve(parallel_discs_problem(kRadius, 3e-6, kRate, kEta, 0.0, 41));
  EXPECT_EQ(solver.symbolic_analyses(), 1);
  EXPECT_NEAR(w1 / w2, 8.0, 8e-12);
  solver.solve(parallel_discs_problem(kRadius, 1e-6, kRate, kEta, 0.0, 43));
  EXPECT_EQ(solver.symbolic_analyses(), 2);
}

}  // namespace
}  // namespace tribo::lubrication
