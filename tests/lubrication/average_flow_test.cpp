// Average flow model in the Reynolds solver (lubrication/reynolds.h, Patir & Cheng 1978): the
// per-node pressure flow factors φx, φy and the Couette film t, against the plain solve, the
// Appendix III squeeze film and a closed-form inclined pad; mass balance and input checks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "lubrication/geometry.h"
#include "lubrication/reference/squeeze_film.h"
#include "lubrication/reynolds.h"
#include "tests/lubrication/observed_order.h"
#include "tests/lubrication/fixture.h"

namespace tribo::lubrication {
namespace {

using fixture::kEta, fixture::kRadius, fixture::kGap, fixture::kRate;

// A wavy, inclined gap sliding at U with ambient edges: it has diverging zones, so with
// Cavitation::mass_conserving the film ruptures and reforms (the Newton path is exercised).
ReynoldsProblem wavy_pad(int nx, int ny, Cavitation cavitation) {
  ReynoldsProblem pr;
  const double lx = 2e-3, ly = 1e-3;
  pr.grid = contact::Grid{nx, ny, lx / (nx - 1), ly / (ny - 1)};
  pr.gap_m = pr.grid.field();
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = i * pr.grid.dx_m / lx, y = j * pr.grid.dy_m / ly;
      pr.gap_m(i, j) =
          kGap * (1.0 + 0.8 * (1.0 - x) + 0.5 * std::cos(6 * std::numbers::pi * x) + 0.2 * std::sin(2 * std::numbers::pi * y));
    }
  pr.viscosity_Pa_s = kEta;
  pr.sliding_speed_m_per_s = 0.5;
  pr.cavitation = cavitation;
  return pr;
}

// φx = φy = 1 and t = h written out: the average flow faces reduce algebraically to the plain
// faces ((h_P⁻² + h_N⁻²)/(h_P⁻³ + h_N⁻³) = (h_P/h_P³ + h_N/h_N³)/(h_P⁻³ + h_N⁻³)), so the solutions
// agree to rounding: 1e-13 relative in load and peak pressure (observed ≈ 1e-15).
class AverageFlowIdentity : public ::testing::TestWithParam<std::tuple<Cavitation, int>> {};

TEST_P(AverageFlowIdentity, UnitFactorsAndGapFilmReproduceThePlainSolve) {
  const auto [cavitation, nx] = GetParam();
  const ReynoldsProblem plain = wavy_pad(nx, nx / 2 + 1, cavitation);
  ReynoldsProblem average = plain;
  average.pressure_flow_factor_x = plain.grid.field(1.0);
  average.pressure_flow_factor_y = plain.grid.field(1.0);
  average.couette_film_m = plain.gap_m;
  const ReynoldsSolution a = solve_reynolds(plain), b = solve_reynolds(average);
  ASSERT_TRUE(a.summary.converged) << a.summary.message;
  ASSERT_TRUE(b.summary.converged) << b.summary.message;
  if (cavitation == Cavitation::mass_conserving) {
    EXPECT_GT(a.cavitated_fraction, 0.05);
  }
  std::printf("  nx = %d: load %.6e N, relative differences load %.1e, max pressure %.1e\n", nx, a.load_N,
              std::abs(b.load_N / a.load_N - 1.0), std::abs(b.max_pressure_Pa / a.max_pressure_Pa - 1.0));
  EXPECT_NEAR(b.load_N, a.load_N, 1e-13 * std::abs(a.load_N));
  EXPECT_NEAR(b.max_pressure_Pa, a.max_pressure_Pa, 1e-13 * a.max_pressure_Pa);
  EXPECT_NEAR(b.cavitated_fraction, a.cavitated_fraction, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(CavitationAndGridParity, AverageFlowIdentity,
                         ::testing::Combine(::testing::Values(Cavitation::none, Cavitation::mass_conserving),
                                            ::testing::Values(64, 65)),
                         [](const auto& info) {
                           return std::string(std::get<0>(info.param) == Cavitation::none ? "full_film" : "jfo") +
                                  "_nx" + std::to_string(std::get<1>(info.param));
                         });

// The same identity through the disc's cut-cell rim links (φ interpolated to the rim like h),
// with a non-uniform gap so the rim faces differ from the interior ones: 1e-13.
TEST(AverageFlowIdentityDisc, UnitFactorsThroughTheRimLinks) {
  for (int n : {40, 41}) {
    ReynoldsProblem plain = parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.2, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) plain.gap_m(i, j) = kGap * (1.0 + 0.3 * i / (n - 1.0) + 0.1 * j / (n - 1.0));
    ReynoldsProblem average = plain;
    average.pressure_flow_factor_x = plain.grid.field(1.0);
    average.pressure_flow_factor_y = plain.grid.field(1.0);
    average.couette_film_m = plain.gap_m;
    const ReynoldsSolution a = solve_reynolds(plain), b = solve_reynolds(average);
    EXPECT_NEAR(b.load_N, a.load_N, 1e-13 * std::abs(a.load_N)) << "n = " << n;
    EXPECT_NEAR(b.max_pressure_Pa, a.max_pressure_Pa, 1e-13 * std::abs(a.max_pressure_Pa)) << "n = " << n;
  }
}

// Uniform φ on the squeeze film between parallel discs: ∇·(φh³/(12η)∇p) = ḣ gives
// p = p_AppIII/φ and N_f = −(3/2)πηR⁴ḣ/(φh³) (thesis (3.2.2) divided by φ). The rim is curved
// (cut cells), so the load converges at second order: observed order > 1.8 and the error at
// 163² < 5e-5 (the plain solver's own error there; φ only rescales the discrete system).
TEST(AverageFlowSqueezeFilm, UniformFactorDividesTheAppendixIIILoad) {
  const double phi = 0.62;
  const double load_ref = squeeze_film_load_N(kEta, kRadius, kGap, kRate) / phi;
  std::vector<double> dx, err;
  for (int n : {23, 43, 83, 163}) {
    ReynoldsProblem pr = parallel_discs_problem(kRadius, kGap, kRate, kEta, 0.0, n);
    pr.pressure_flow_factor_x = pr.grid.field(phi);
    pr.pressure_flow_factor_y = pr.grid.field(phi);
    const ReynoldsSolution s = solve_reynolds(pr);
    ASSERT_TRUE(s.summary.converged) << s.summary.message;
    dx.push_back(pr.grid.dx_m);
    err.push_back(std::abs(s.load_N / load_ref - 1.0));
    std::printf("  n = %3d  load %.8f N (reference %.8f N)  error %.2e\n", n, s.load_N, load_ref, err.back());
  }
  const double order = observed_order(dx, err);
  std::printf("  observed order %.2f\n", order);
  EXPECT_GT(order, 1.8);
  EXPECT_LT(err.back(), 5e-5);
}

// Inclined pad, infinitely wide (ny = 3, periodic y), h = h₀(1 + K(1 − x/L)), sliding at U,
// p(0) = p(L) = 0, with uniform φx and the Couette film t = βh + c (constant β, offset c).
// Derivation: the flux q̄ = −φh³/(12η) p' + (U/2)t is constant, so
//     p' = (12η/(φh³)) ((U/2)(βh + c) − q̄),   and ∫₀ᴸ p' dx = 0 fixes
//     q̄ = (U/2)(β I₂/I₃ + c),   I_n = ∫₀ᴸ dx/hⁿ,   I₂/I₃ = 2h₀(1 + K)/(2 + K),
// whence p' = (6ηUβ/φ)(1/h² − (I₂/I₃)/h³): the offset c moves the flux, not the pressure, and
//     W/B = (β/φ) 6ηUL²/(K²h₀²) [ln(1 + K) − 2K/(2 + K)]
// (the plain pad of Hamrock, Schmid & Jacobson §8.4 times β/φ). φy plays no part in a film
// uniform across y. Second-order convergence as the plain pad: load error < 1e-5 at 401 nodes,
// observed order 2 ± 0.1; the face flux (x_face_flow_m2_per_s) is the same on every face to
// 1e-12 and within 1e-5 of q̄.
TEST(AverageFlowInclinedPad, MatchesTheClosedFormWithFactorAndFilmOffset) {
  const double length = 5e-3, h0 = 2e-6, k = 1.5, u = 1.0;
  const double phi = 0.7, beta = 0.9, c = 0.4 * h0;
  const double load_ref = beta / phi * 6.0 * kEta * u * length * length / (k * k * h0 * h0) *
                          (std::log1p(k) - 2.0 * k / (2.0 + k));
  const double q_ref = 0.5 * u * (beta * 2.0 * h0 * (1.0 + k) / (2.0 + k) + c);
  std::vector<double> dx, err;
  double q_err = 0;
  for (int nx : {51, 101, 201, 401}) {
    ReynoldsProblem pr;
    pr.grid = contact::Grid{nx, 3, length / (nx - 1), 1e-4 / 3};
    pr.gap_m = pr.grid.field();
    pr.couette_film_m = pr.grid.field();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < nx; ++i) {
        const double h = h0 * (1.0 + k * (1.0 - i * pr.grid.dx_m / length));
        pr.gap_m(i, j) = h;
        pr.couette_film_m(i, j) = beta * h + c;
      }
    pr.pressure_flow_factor_x = pr.grid.field(phi);
    pr.pressure_flow_factor_y = pr.grid.field(0.3);
    pr.viscosity_Pa_s = kEta;
    pr.boundary_y = BoundaryY::periodic;
    pr.sliding_speed_m_per_s = u;
    const ReynoldsSolution s = solve_reynolds(pr);
    ASSERT_TRUE(s.summary.converged) << s.summary.message;
    dx.push_back(pr.grid.dx_m);
    err.push_back(std::abs(s.load_N / (pr.grid.ny * pr.grid.dy_m) / load_ref - 1.0));
    const Eigen::ArrayXXd q = x_face_flow_m2_per_s(pr, s);
    for (double qf : q.reshaped()) EXPECT_NEAR(qf, q(0), 1e-12 * q_ref);
    q_err = std::abs(q(0) / q_ref - 1.0);
  }
  const double order = observed_order(dx, err);
  std::printf("  inclined pad with phi_x %.2f, t = %.1f h + %.1f h0: load error %.2e at nx = 401 (order %.2f), "
              "flux error %.2e\n", phi, beta, c / h0, err.back(), order, q_err);
  EXPECT_LT(err.back(), 1e-5);
  EXPECT_NEAR(order, 2.0, 0.1);
  EXPECT_LT(q_err, 1e-5);
}

// Mass conservation with non-uniform φx, φy and t, through rupture and reformation: every cell
// balances its face fluxes (the conservative form is kept) to the Newton tolerance, 1e-8 of the
// Couette flux scale U t̄ dy / 2 (observed ≈ 1e-14), and the film's net outflow equals −storage.
TEST(AverageFlowConservation, CellsBalanceWithVariableFactorsAndCavitation) {
  ReynoldsProblem pr = wavy_pad(81, 41, Cavitation::mass_conserving);
  pr.gap_rate_m_per_s = pr.grid.field(-2e-7);
  pr.pressure_flow_factor_x = pr.grid.field();
  pr.pressure_flow_factor_y = pr.grid.field();
  pr.couette_film_m = pr.grid.field();
  for (Eigen::Index n = 0; n < pr.grid.size(); ++n) {
    const double s = std::sin(0.37 * static_cast<double>(n));
    pr.pressure_flow_factor_x(n) = 0.8 + 0.3 * s;
    pr.pressure_flow_factor_y(n) = 0.6 - 0.2 * s;
    pr.couette_film_m(n) = pr.gap_m(n) * (1.0 + 0.1 * s);
  }
  const ReynoldsSolution s = solve_reynolds(pr);
  ASSERT_TRUE(s.summary.converged) << s.summary.message;
  EXPECT_GT(s.cavitated_fraction, 0.05);
  const FilmFlow f = film_flow(pr, s);
  const double scale = 0.5 * pr.sliding_speed_m_per_s * kGap * pr.grid.dy_m;
  std::printf("  cavitated %.2f, max cell imbalance %.1e of the Couette cell flux\n", s.cavitated_fraction,
              f.max_cell_imbalance_m3_per_s / scale);
  EXPECT_LT(f.max_cell_imbalance_m3_per_s, 1e-8 * scale);
  EXPECT_NEAR(f.net_outflow_m3_per_s + f.squeeze_storage_m3_per_s, 0.0, 1e-8 * scale * pr.grid.nx);
}

// Bad average-flow fields are rejected naming the field and the node.
TEST(AverageFlowInput, RejectsBadFieldsNamingFieldAndNode) {
  auto expect_message = [](const ReynoldsProblem& pr, const std::string& needle) {
    try {
      validate(pr);
      ADD_FAILURE() << "no exception for " << needle;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const ReynoldsProblem good = wavy_pad(11, 5, Cavitation::none);
  ReynoldsProblem p = good;
  p.pressure_flow_factor_x = Eigen::ArrayXXd::Ones(7, 1);
  expect_message(p, "pressure_flow_factor_x must be empty or have one value per node");
  p = good;
  p.pressure_flow_factor_y = good.grid.field(1.0);
  p.pressure_flow_factor_y(13) = 0.0;
  expect_message(p, "pressure_flow_factor_y must be finite and > 0 everywhere; node (i=2, j=1)");
  p = good;
  p.pressure_flow_factor_x = good.grid.field(1.0);
  p.pressure_flow_factor_x(4) = std::numeric_limits<double>::quiet_NaN();
  expect_message(p, "pressure_flow_factor_x must be finite and > 0 everywhere; node (i=4, j=0)");
  p = good;
  p.couette_film_m = good.gap_m;
  p.couette_film_m(25) = -1e-9;
  expect_message(p, "couette_film_m must be finite and >= 0 everywhere; node (i=3, j=2)");
  p = good;
  p.couette_film_m = good.grid.field(0.0);
  EXPECT_NO_THROW(validate(p));  // t = 0 is allowed: no Couette transport
}

}  // namespace
}  // namespace tribo::lubrication
