// Patir–Cheng shear-stress factors φf, φfs, φfp of the flow-factor cells
// (lubrication/flow_factors.h): the smooth limit at the small-roughness rate, φf against the
// Gaussian height integral and Patir–Cheng's closed form, and the 1-D (ridges across the flow)
// series solution. Small cells (64², 4 realisations) so the suite runs in about a second.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "contact/surface.h"
#include "lubrication/flow_factors.h"

namespace tribo::lubrication {
namespace {

HomogenisationOptions small_cells(std::vector<double> ratios, double gamma = 1.0) {
  HomogenisationOptions o;
  o.surface.kind = contact::SpectrumKind::gaussian_acf;
  o.surface.grid = 64;
  o.surface.size_m = 1e-3;
  o.surface.rms_height_m = 0.5e-6;
  o.surface.correlation_length_m = 1e-3 / 16;
  o.surface.correlation_length_across_m = 1e-3 / 16 / gamma;
  o.gap_ratios = std::move(ratios);
  o.realisations = 4;
  return o;
}

// Composite Simpson rule on [a, b] with an even number of panels.
template <class F>
double simpson(F f, double a, double b, int panels) {
  const double d = (b - a) / panels;
  double s = f(a) + f(b);
  for (int k = 1; k < panels; ++k) s += (k % 2 ? 4.0 : 2.0) * f(a + k * d);
  return s * d / 3.0;
}

// φf = E[h/h_T; h_T > floor] for Gaussian heights δ ~ N(0, σ²), h_T = h + δ (σ = 1):
// ∫_{floor − H}^{∞} H/(H + δ) e^{−δ²/2}/√(2π) dδ, by Simpson in w = ln(H + δ), which takes out the
// 1/h_T near the floor (4000 panels up to δ = 12: quadrature error < 1e-10).
double gaussian_phi_f(double h_over_sigma, double floor_fraction) {
  const double hh = h_over_sigma;
  auto integrand = [&](double w) {
    const double d = std::exp(w) - hh;
    return hh * std::exp(-0.5 * d * d) / std::sqrt(2.0 * std::numbers::pi);
  };
  return simpson(integrand, std::log(floor_fraction), std::log(hh + 12.0), 4000);
}

// Small roughness, H = h/σ ≫ 1, Gaussian isotropic field (perturbation in ε = 1/H, derived here):
// with h_T = h(1 + εζ), ⟨ζ²⟩ = 1,
//   φf  = ⟨1/(1 + εζ)⟩ = 1 + ε² + 3ε⁴ + …;
//   shear cell:    ∇²p₁ = (6ηU/h²) ∂ζ/∂x ⇒ ⟨ζ ∂p₁/∂x⟩ = (6ηU/h²)⟨k_x²/k²⟩ ⇒ φfs = 3ε²⟨k_x²/k²⟩ = 1.5ε²;
//   pressure cell: ∇²p₁ = 3G ∂ζ/∂x (mean gradient −G) ⇒ φfp = 1 − 3ε²⟨k_x²/k²⟩ = 1 − 1.5ε²,
// (1-D ridges across the flow: ⟨k_x²/k²⟩ = 1, φfs = 3ε², φfp = 1 − 3ε²). At H = 10 every
// deviation from (1, 0, 1) is O(ε²) = 0.01 with a coefficient ≤ 1.5 here and ≤ 3 for any lay:
// |φ − limit| < 3ε² = 0.03 is the limit test. The coefficients H²(φ − limit) are checked within
// three standard errors (4 realisations) plus 12 % (O(ε²) = 1 % from the next order, the
// Dirichlet ends of the cell, and the grid: ℓ = 4 dx resolves the slopes that p₁ responds to to
// some per cent).
TEST(ShearFactors, TendToTheSmoothLimitsAtTheSmallRoughnessRate) {
  const double big = 10.0, e2 = 1.0 / (big * big);
  const auto rows = flow_factors(small_cells({big}));
  const FlowFactorRow& r = rows[0];
  ASSERT_EQ(r.unconverged, 0);
  std::printf("  H = 10: phi_f %.5f +- %.5f, phi_fs %.5f +- %.5f, phi_fp %.5f +- %.5f, couette %.5f\n", r.phi_f.mean,
              r.phi_f.standard_error, r.phi_fs.mean, r.phi_fs.standard_error, r.phi_fp.mean, r.phi_fp.standard_error,
              r.couette_shear_factor.mean);
  std::printf("  H^2 (phi_f - 1) = %.3f (theory %.3f), H^2 phi_fs = %.3f (1.5), H^2 (1 - phi_fp) = %.3f (1.5)\n",
              (r.phi_f.mean - 1) / e2, 1 + 3 * e2, r.phi_fs.mean / e2, (1 - r.phi_fp.mean) / e2);
  EXPECT_LT(std::abs(r.phi_f.mean - 1.0), 3 * e2);
  EXPECT_LT(std::abs(r.phi_fs.mean), 3 * e2);
  EXPECT_LT(std::abs(r.phi_fp.mean - 1.0), 3 * e2);
  EXPECT_NEAR((r.phi_f.mean - 1.0) / e2, 1.0 + 3.0 * e2, 3 * r.phi_f.standard_error / e2 + 0.12);
  EXPECT_NEAR(r.phi_fs.mean / e2, 1.5, 3 * r.phi_fs.standard_error / e2 + 0.12 * 1.5);
  EXPECT_NEAR((1.0 - r.phi_fp.mean) / e2, 1.5, 3 * r.phi_fp.standard_error / e2 + 0.12 * 1.5);
  // The combined factor is the same shear measured at once: φf − φfs per realisation.
  EXPECT_NEAR(r.couette_shear_factor.mean, r.phi_f.mean - r.phi_fs.mean, 1e-12);
}

// φf is a height statistic: ⟨h/h_T⟩ over the non-contact nodes times their area share, for the
// Gaussian heights of the cells = the integral over the Gaussian density above the floor
// (quadrature above). The sampled heights have exactly zero mean and rms σ; the rest of the
// density is sampled (4 × 64² nodes, ≈ 4 × 16² correlation areas): tolerance three standard
// errors across the realisations plus 1 %. Patir–Cheng's closed form belongs to their
// polynomial density and is printed for comparison (it is up to 7 % off the Gaussian near H = 2).
TEST(ShearFactors, CouettePartMatchesTheGaussianHeightIntegral) {
  HomogenisationOptions o = small_cells({1.0, 1.5, 2.0, 3.0});
  o.contact_gap_fraction = 0.01;
  const auto rows = flow_factors(o);
  for (const FlowFactorRow& r : rows) {
    const double ref = gaussian_phi_f(r.h_over_sigma, o.contact_gap_fraction);
    std::printf("  H = %.1f: phi_f %.4f +- %.4f, Gaussian integral %.4f, Patir-Cheng polynomial %.4f; contact %.3f\n",
                r.h_over_sigma, r.phi_f.mean, r.phi_f.standard_error, ref,
                patir_cheng_phi_f(r.h_over_sigma, o.contact_gap_fraction), r.contact_fraction.mean);
    EXPECT_NEAR(r.phi_f.mean, ref, 3 * r.phi_f.standard_error + 0.01 * ref) << "H = " << r.h_over_sigma;
  }
}

// Patir–Cheng's closed form against the integral it comes from,
// (35/32)∫(1 − u²)³ z/(z − u) du over −1 < u < min(1, z − ε*) (z = H/3, ε* = floor/3σ), by
// Simpson in w = ln(z − u): exact (1e-10) for H > 3, where no contact cut enters; for H ≤ 3 the
// closed form drops O(ε*) terms of the polynomial part: within 2ε* (ε* = 1/300, their value).
// Continuity at H = 3 (both branches give 7/6) to 1e-12.
TEST(ShearFactors, PatirChengClosedFormIsThePolynomialDensityIntegral) {
  const double fraction = 0.01, eps = fraction / 3.0;
  for (double hh : {0.5, 1.0, 1.5, 2.0, 2.5, 3.5, 4.0, 6.0, 10.0}) {
    const double z = hh / 3.0, upper = std::min(1.0, z - eps);
    auto integrand = [&](double w) {
      const double u = z - std::exp(w), a = 1.0 - u * u;
      return 35.0 / 32.0 * a * a * a * z;
    };
    const double ref = simpson(integrand, std::log(z - upper), std::log(z + 1.0), 20000);
    const double pc = patir_cheng_phi_f(hh, fraction);
    EXPECT_NEAR(pc, ref, (hh > 3.0 ? 1e-10 : 2.0 * eps) * ref) << "H = " << hh;
  }
  EXPECT_NEAR(patir_cheng_phi_f(3.0, fraction), 7.0 / 6.0, 1e-12);
  EXPECT_NEAR(patir_cheng_phi_f(3.0 + 1e-9, fraction), 7.0 / 6.0, 1e-8);
}

// Ridges across the flow (ℓ_y ≫ L: the field varies along x only), where each row is the 1-D
// bearing and the factors have the series closed forms (derived here): the x-flow q is the
// same at every face, q = −h_T³p'/(12η) + (U/2)h_T, so with ⟨·⟩ the mean over a period,
//   pressure cell:  q = Δp/(12ηL⟨h_T⁻³⟩),  φx = 1/(h³⟨h_T⁻³⟩),  φfp = ⟨h_T⁻²⟩'/(h⟨h_T⁻³⟩),
//   shear cell:     q = (U/2)⟨h_T⁻²⟩/⟨h_T⁻³⟩,  φfs = 3h⟨1/h_T − (q·2/U)/h_T²⟩',
// where ⟨·⟩' sums over the non-contact nodes only (divided by all N). The trapezoid faces make
// ⟨h_T⁻³⟩ the plain node mean on a periodic row, so the discrete factors equal these means of
// the generated heights to rounding: 1e-9.
TEST(ShearFactors, RidgesAcrossTheFlowFollowTheSeriesSolution) {
  HomogenisationOptions o = small_cells({2.0, 4.0});
  o.surface.correlation_length_across_m = 1e3;  // every q_y ≠ 0 mode is filtered out
  o.realisations = 2;
  const auto rows = flow_factors(o);
  const double sigma = o.surface.rms_height_m, floor_m = o.contact_gap_fraction * sigma;
  for (const FlowFactorRow& r : rows) {
    std::vector<double> fx, ffp, ffs;
    for (int k = 0; k < o.realisations; ++k) {
      contact::GaussianSurfaceParams p = o.surface;
      p.seed = o.first_seed + static_cast<std::uint64_t>(k);
      const Eigen::ArrayXXd z = contact::gaussian_surface(p);
      const double h = r.h_over_sigma * sigma;
      double m2 = 0, m3 = 0, m2_nc = 0, m1_nc = 0;
      for (Eigen::Index i = 0; i < z.size(); ++i) {
        const double ht = std::max(h + z(i), floor_m);
        m2 += 1.0 / (ht * ht);
        m3 += 1.0 / (ht * ht * ht);
        if (ht > floor_m) {
          m1_nc += 1.0 / ht;
          m2_nc += 1.0 / (ht * ht);
        }
      }
      const double n = static_cast<double>(z.size());
      m2 /= n, m3 /= n, m2_nc /= n, m1_nc /= n;
      fx.push_back(1.0 / (h * h * h * m3));
      ffp.push_back(m2_nc / (h * m3));
      ffs.push_back(3.0 * h * (m1_nc - (m2 / m3) * m2_nc));
    }
    auto mean = [](const std::vector<double>& v) { return (v[0] + v[1]) / 2.0; };
    std::printf("  H = %.0f: phi_x %.6f (series %.6f), phi_fp %.6f (%.6f), phi_fs %.6f (%.6f)\n", r.h_over_sigma,
                r.phi_x.mean, mean(fx), r.phi_fp.mean, mean(ffp), r.phi_fs.mean, mean(ffs));
    EXPECT_NEAR(r.phi_x.mean, mean(fx), 1e-9 * mean(fx));
    EXPECT_NEAR(r.phi_fp.mean, mean(ffp), 1e-9 * mean(ffp));
    EXPECT_NEAR(r.phi_fs.mean, mean(ffs), 1e-9 * std::abs(mean(ffs)) + 1e-12);
    EXPECT_GT(r.phi_fs.mean, 0.0);  // the shear-induced pressure lowers the stationary-wall shear
  }
}

}  // namespace
}  // namespace tribo::lubrication
