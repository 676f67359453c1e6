// Mass-conserving cavitation (JFO complementarity, Fischer–Burmeister–Newton) in
// lubrication/reynolds.h, against a closed-form JFO solution and conservation laws.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "lubrication/reynolds.h"
#include "tests/lubrication/fixture.h"

namespace tribo::lubrication {
namespace {

using fixture::kEta;

// Four-step bearing, infinitely wide (periodic y, ny = 3), U > 0, p = 0 at both ends:
//   A [0, a): h_A (wide inlet)      B [a, b): h_B < h_A (Rayleigh step: pressure builds)
//   C [b, c): h_C > h_B (pocket: the film ruptures at b)   D [c, L]: h_D < h_C (reformation)
// JFO closed form (derived here; the construction of Giacopini et al. 2010, §4): steady 1-D
// mass conservation makes the flow q the same at every x. A–B is full film with p(0) = p(b) = 0:
//   p_a = 6ηU(h_A − h_B)/(h_A³/ℓ_A + h_B³/ℓ_B),   q = U h_B/2 + h_B³ p_a/(12η ℓ_B).
// C is cavitated from b to the reformation front r with ϑ = 2q/(U h_C); from r the film is full,
// with p' = 6ηU/h² − 12ηq/h³ in C and D, and p(L) = 0 fixes r = c + ℓ_D p'_D/p'_C.
struct FourStep {
  double la, lb, lc, ld, ha, hb, hc, hd, u;
  double length() const { return la + lb + lc + ld; }
  double pa() const { return 6 * kEta * u * (ha - hb) / (ha * ha * ha / la + hb * hb * hb / lb); }
  double q() const { return 0.5 * u * hb + hb * hb * hb * pa() / (12 * kEta * lb); }
  double slope(double h) const { return 6 * kEta * u / (h * h) - 12 * kEta * q() / (h * h * h); }
  double theta_c() const { return 2 * q() / (u * hc); }
  double front() const { return la + lb + lc + ld * slope(hd) / slope(hc); }
  double pc() const { return slope(hc) * (la + lb + lc - front()); }
};

// Steps placed on face midpoints of a grid with nx nodes over L.
ReynoldsProblem four_step_problem(int nx, FourStep& s) {
  ReynoldsProblem pr;
  const double length = 1e-3;
  pr.grid = contact::Grid{nx, 3, length / (nx - 1), 1e-5};
  const double dx = pr.grid.dx_m;
  auto snap = [&](double x) { return (std::round(x / dx - 0.5) + 0.5) * dx; };
  const double a = snap(0.3 * length), b = snap(0.5 * length), c = snap(0.9 * length);
  s = FourStep{a, b - a, c - b, length - c, 2e-6, 1e-6, 3e-6, 1e-6, 0.5};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = i * dx;
      pr.gap_m(i, j) = x < a ? s.ha : x < b ? s.hb : x < c ? s.hc : s.hd;
    }
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = s.u;
  pr.boundary_y = BoundaryY::periodic;
  pr.cavitation = Cavitation::mass_conserving;
  return pr;
}

struct FourStepResult {
  FourStep ref;
  ReynoldsProblem problem;
  ReynoldsSolution solution;
  double flow_per_width, theta_min, front_m, second_peak_Pa;
};

FourStepResult solve_four_step(int nx, Complementarity complementarity = Complementarity::minimum) {
  FourStepResult r{};
  r.problem = four_step_problem(nx, r.ref);
  ReynoldsOptions options;
  options.complementarity = complementarity;
  r.solution = solve_reynolds(r.problem, options);
  const contact::Grid& g = r.problem.grid;
  r.theta_min = 1.0;
  int last_cavitated = -1;
  for (int i = 0; i < nx; ++i) {
    if (r.solution.fill_fraction(i, 1) < 1.0 - 1e-9) {
      last_cavitated = i;
      r.theta_min = std::min(r.theta_min, r.solution.fill_fraction(i, 1));
    }
    if (i * g.dx_m > r.ref.la + r.ref.lb) r.second_peak_Pa = std::max(r.second_peak_Pa, r.solution.pressure_Pa(i, 1));
  }
  r.front_m = (last_cavitated + 0.5) * g.dx_m;  // the front lies between the last cavitated node and the next
  r.flow_per_width = film_flow(r.problem, r.solution).inflow_x0_m3_per_s / (g.ny * g.dy_m);
  return r;
}

// The JFO closed form above, at nx = 401: the free boundaries (rupture at b, reformation at r)
// are captured at node resolution, so the errors are first order in dx (the observed order of
// the flow error over nx = 101 → 1601 is printed and must be 1 ± 0.3). At nx = 401 (dx = L/400)
// the flow q and the cavitated fill ϑ = 2q/(U h_C) are within 1e-3, the reformation front
// within 2 dx, and both pressure peaks within 1 %. Both NCP functions reach the same solution.
class JfoCavitation : public ::testing::TestWithParam<Complementarity> {};

TEST_P(JfoCavitation, FourStepBearingMatchesClosedForm) {
  const FourStepResult r = solve_four_step(401, GetParam());
  ASSERT_TRUE(r.solution.summary.converged) << r.solution.summary.message;
  std::printf("  Newton iterations %d, residual %.1e\n", r.solution.summary.iterations, r.solution.summary.residual);
  EXPECT_NEAR(r.flow_per_width / r.ref.q(), 1.0, 1e-3);
  EXPECT_NEAR(r.theta_min / r.ref.theta_c(), 1.0, 1e-3);
  EXPECT_NEAR(r.front_m, r.ref.front(), 2.0 * r.problem.grid.dx_m);
  EXPECT_NEAR(r.solution.max_pressure_Pa / r.ref.pa(), 1.0, 1e-2);
  EXPECT_NEAR(r.second_peak_Pa / r.ref.pc(), 1.0, 1e-2);
  std::vector<double> err;
  for (int nx : {101, 401, 1601}) {
    const FourStepResult f = solve_four_step(nx, GetParam());
    err.push_back(std::abs(f.flow_per_width / f.ref.q() - 1.0));
  }
  const double order = std::log(err[0] / err[2]) / std::log(16.0);
  std::printf("  flow error %.2e, %.2e, %.2e at nx = 101, 401, 1601: observed order %.2f\n", err[0], err[1], err[2],
              order);
  EXPECT_NEAR(order, 1.0, 0.3);
}

// Mass conservation through rupture and reformation: what enters at x = 0 leaves at x = L
// (Newton residual 1e-10 of the flux scale → 1e-8 relative), and every cell balances to 1e-8 of
// the through-flow. The half-Sommerfeld answer (the linear solution with p < 0 clipped to 0) on
// the same bearing violates the cell balance near the clipped zone by more than 5 % of the
// through-flow. p ≥ 0 holds at every node (to 1e-9 of the peak).
TEST_P(JfoCavitation, ConservesMassThroughRuptureAndReformation) {
  const FourStepResult r = solve_four_step(401, GetParam());
  const FilmFlow f = film_flow(r.problem, r.solution);
  EXPECT_NEAR(f.outflow_xL_m3_per_s / f.inflow_x0_m3_per_s, 1.0, 1e-8);
  EXPECT_LT(f.max_cell_imbalance_m3_per_s, 1e-8 * f.inflow_x0_m3_per_s);
  EXPECT_GT(r.solution.cavitated_fraction, 0.1);
  for (double p : r.solution.pressure_Pa.reshaped()) EXPECT_GE(p, -1e-9 * r.solution.max_pressure_Pa);

  ReynoldsProblem full = r.problem;
  full.cavitation = Cavitation::none;
  ReynoldsSolution half_sommerfeld = solve_reynolds(full);
  for (double& p : half_sommerfeld.pressure_Pa.reshaped()) p = std::max(p, 0.0);
  const FilmFlow hs = film_flow(full, half_sommerfeld);
  std::printf("  largest cell imbalance / through-flow: JFO %.1e, half-Sommerfeld %.1e\n",
              f.max_cell_imbalance_m3_per_s / f.inflow_x0_m3_per_s, hs.max_cell_imbalance_m3_per_s / hs.inflow_x0_m3_per_s);
  EXPECT_GT(hs.max_cell_imbalance_m3_per_s, 0.05 * hs.inflow_x0_m3_per_s);
}

INSTANTIATE_TEST_SUITE_P(NcpFunctions, JfoCavitation,
                         ::testing::Values(Complementarity::minimum, Complementarity::fischer_burmeister),
                         [](const auto& info) {
                           return info.param == Complementarity::minimum ? "minimum" : "fischer_burmeister";
                         });

// Infinitely long journal bearing, flooded at the widest gap (θ = 0 and 2π at ambient), gap
// h = c(1 + ε cos θ), journal surface speed U, x = Rθ. For a rupture boundary the JFO conditions
// are p = ∂p/∂x = 0 — the Swift–Stieber (Reynolds) condition — so with h_c = h(θ_c):
//   h³ dp/dθ = 6ηUR (h − h_c),   p(0) = 0,   p(θ_c) = 0,
// and the cavitated zone θ_c < θ < 2π carries the Couette flow with ϑ = h_c/h (Dowson & Taylor,
// Annu. Rev. Fluid Mech. 11, 1979). The reference is this ODE integrated by Simpson's rule (10⁴
// intervals) with θ_c from bisection. The rupture is captured to a node (2 nodes allowed); the
// peak pressure and the load per unit length are second-order quantities of the full-film part
// (observed 4e-5 at 801 nodes): 1e-3.
TEST(JfoCavitationJournal, LongBearingMatchesSwiftStieber) {
  const double c = 10e-6, eps = 0.6, radius = 10e-3, u = 2.0;
  auto gap = [&](double th) { return c * (1.0 + eps * std::cos(th)); };
  auto pressure = [&](double th_end, double th_c) {  // p(θ_end) for a trial rupture angle
    const int m = 10000;
    const double d = th_end / m, hc = gap(th_c);
    double sum = 0;
    for (int k = 0; k <= m; ++k) {
      const double th = k * d, h = gap(th);
      sum += (k == 0 || k == m ? 1.0 : (k % 2 ? 4.0 : 2.0)) * (h - hc) / (h * h * h);
    }
    return 6 * kEta * u * radius * sum * d / 3.0;
  };
  double lo = std::numbers::pi + 1e-6, hi = 2 * std::numbers::pi - 1e-6;  // p(θ_c; θ_c) changes sign
  for (int k = 0; k < 60; ++k) {
    const double mid = 0.5 * (lo + hi);
    (pressure(mid, mid) > 0 ? lo : hi) = mid;
  }
  const double theta_c = 0.5 * (lo + hi);
  double peak = 0, load_per_length = 0;
  const int m = 2000;
  for (int k = 1; k < m; ++k) {  // trapezoid on θ ∈ [0, θ_c] (p vanishes at both ends)
    const double p = pressure(k * theta_c / m, theta_c);
    peak = std::max(peak, p);
    load_per_length += p * radius * theta_c / m;
  }

  const int nx = 801;
  ReynoldsProblem pr;
  pr.grid = contact::Grid{nx, 3, 2 * std::numbers::pi * radius / (nx - 1), 1e-5};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < nx; ++i) pr.gap_m(i, j) = gap(i * pr.grid.dx_m / radius);
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = u;
  pr.boundary_y = BoundaryY::periodic;
  pr.cavitation = Cavitation::mass_conserving;
  const ReynoldsSolution s = solve_reynolds(pr);
  ASSERT_TRUE(s.summary.converged) << s.summary.message;
  int first_cavitated = -1;
  for (int i = 0; i < nx && first_cavitated < 0; ++i)
    if (s.fill_fraction(i, 1) < 1.0 - 1e-9) first_cavitated = i;
  const double theta_rupture = (first_cavitated - 0.5) * pr.grid.dx_m / radius;
  const double width = pr.grid.ny * pr.grid.dy_m;
  std::printf("  rupture %.4f rad (Swift-Stieber %.4f), peak %.4e Pa (%.4e), load %.4e N/m (%.4e), %d Newton\n",
              theta_rupture, theta_c, s.max_pressure_Pa, peak, s.load_N / width, load_per_length,
              s.summary.iterations);
  EXPECT_NEAR(theta_rupture, theta_c, 2.0 * pr.grid.dx_m / radius);
  EXPECT_NEAR(s.max_pressure_Pa / peak, 1.0, 1e-3);
  EXPECT_NEAR(s.load_N / width / load_per_length, 1.0, 1e-3);
  // In the cavitated zone the film carries the rupture flow: ϑ h = h_c (to the upwind scheme's
  // O(dx) smearing, 1 %).
  const int probe = (first_cavitated + nx) / 2;
  EXPECT_NEAR(s.fill_fraction(probe, 1) * pr.gap_m(probe, 1) / gap(theta_c), 1.0, 1e-2);
}

// Outcomes are data: a Newton budget too small to converge is reported (converged = false with
// the reason), not thrown and not silently returned as an answer.
TEST(JfoCavitationOutcome, IterationLimitIsReported) {
  FourStep ref{};
  const ReynoldsProblem pr = four_step_problem(201, ref);
  ReynoldsOptions options;
  options.max_newton_iterations = 1;
  const ReynoldsSolution s = solve_reynolds(pr, options);
  EXPECT_FALSE(s.summary.converged);
  EXPECT_EQ(s.summary.iterations, 1);
  EXPECT_GT(s.summary.residual, options.newton_tolerance);
  EXPECT_NE(s.summary.message.find("iteration limit"), std::string::npos) << s.summary.message;
}

// Symbolic analyses are reused across cavitating solves with the same pattern: one CHOLMOD
// (full-film start) and one UMFPACK analysis for three speeds of the same sign; the loads scale
// exactly with U (homogeneity, to the Newton tolerance).
TEST(JfoCavitationOutcome, SymbolicAnalysesReusedAcrossSolves) {
  FourStep ref{};
  ReynoldsProblem pr = four_step_problem(201, ref);
  ReynoldsSolver solver;
  const double w1 = solver.solve(pr).load_N;
  pr.sliding_speed_m_per_s *= 2.0;
  const double w2 = solver.solve(pr).load_N;
  pr.sliding_speed_m_per_s *= 2.0;
  solver.solve(pr);
  EXPECT_EQ(solver.symbolic_analyses(), 2);
  EXPECT_NEAR(w2 / w1, 2.0, 2e-8);
}

// A rough gap mirror-symmetric about the middle of the film, h(x, y) = h(L − x, y):
// without cavitation p(x) = −p(L − x) (the mirror of a solution solves the problem with U
// reversed, i.e. −p), so the net lift vanishes to rounding (1e-9 of ∫|p|). With cavitation the
// sub-ambient half is cut off and the lift is positive, at least 20 % of ∫|p| of the full film.
ReynoldsProblem symmetric_rough_gap(Cavitation cavitation) {
  const int nx = 81, ny = 40;
  ReynoldsProblem pr;
  pr.grid = contact::Grid{nx, ny, 1e-3 / (nx - 1), 1e-3 / ny};
  pr.gap_m = pr.grid.field();
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::ArrayXXd z = pr.grid.field();
  for (double& v : z.reshaped()) v = noise(rng);
  const double mean_gap = 1e-6, sigma = 0.3e-6;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      // three-point smoothing along x gives the asperities a slope the wedge terms can feel
      auto zz = [&](int ii) { return z(std::clamp(ii, 0, nx - 1), j); };
      const double a = (zz(i - 1) + 2 * zz(i) + zz(i + 1)) / 4, b = (zz(nx - i - 2) + 2 * zz(nx - 1 - i) + zz(nx - i)) / 4;
      pr.gap_m(i, j) = mean_gap + sigma * 0.5 * (a + b);
    }
  for (double& h : pr.gap_m.reshaped()) h = std::max(h, 0.05 * mean_gap);
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = 0.1;
  pr.boundary_y = BoundaryY::periodic;
  pr.cavitation = cavitation;
  return pr;
}

TEST(RugosityLift, SymmetricRoughGapLiftsOnlyWithCavitation) {
  const ReynoldsSolution full = solve_reynolds(symmetric_rough_gap(Cavitation::none));
  const ReynoldsProblem cav_problem = symmetric_rough_gap(Cavitation::mass_conserving);
  const ReynoldsSolution cav = solve_reynolds(cav_problem);
  ASSERT_TRUE(cav.summary.converged) << cav.summary.message;
  double abs_integral = 0;
  for (double p : full.pressure_Pa.reshaped()) abs_integral += std::abs(p) * cav_problem.grid.dx_m * cav_problem.grid.dy_m;
  std::printf("  lift: full film %.3e N, JFO %.3e N, integral |p| %.3e N, cavitated %.1f %%\n", full.load_N, cav.load_N,
              abs_integral, 100 * cav.cavitated_fraction);
  EXPECT_NEAR(full.load_N, 0.0, 1e-9 * abs_integral);
  EXPECT_GT(cav.load_N, 0.2 * abs_integral);
  for (double p : cav.pressure_Pa.reshaped()) EXPECT_GE(p, -1e-9 * cav.max_pressure_Pa);
}

// Complementarity is homogeneous: p → λp with ϑ unchanged solves the problem with ηU → ληU.
// So the lift with cavitation is linear in ηU (checked to the Newton tolerance, 1e-8).
TEST(RugosityLift, LiftIsLinearInViscosityTimesSpeed) {
  ReynoldsProblem pr = symmetric_rough_gap(Cavitation::mass_conserving);
  const double w1 = solve_reynolds(pr).load_N;
  pr.sliding_speed_m_per_s *= 3.0;
  pr.viscosity_Pa_s *= 0.5;
  EXPECT_NEAR(solve_reynolds(pr).load_N / w1, 1.5, 1.5e-8);
}

}  // namespace
}  // namespace tribo::lubrication
