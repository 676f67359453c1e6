// Homogenised rough films (lubrication/flow_factors.h): Patir–Cheng flow factors against the
// small-roughness limit, the published fits and the anisotropy direction; rugosity lift sign.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>
#include <cstdio>

#include "lubrication/flow_factors.h"
#include "tests/contact/fixture.h"

namespace tribo::lubrication {
namespace {

HomogenisationOptions cell(int grid, double gamma, std::vector<double> ratios, int realisations) {
  HomogenisationOptions o;
  o.surface.kind = contact::SpectrumKind::gaussian_acf;
  o.surface.grid = grid;
  o.surface.size_m = 1e-3;
  o.surface.rms_height_m = 0.5e-6;
  o.surface.correlation_length_m = 1e-3 / 16 * std::sqrt(gamma);  // ℓ_x ℓ_y fixed, ℓ_x/ℓ_y = γ
  o.surface.correlation_length_across_m = 1e-3 / 16 / std::sqrt(gamma);
  o.gap_ratios = std::move(ratios);
  o.realisations = realisations;
  return o;
}

// Small roughness (h/σ = H ≫ 1): second-order perturbation of the conductance h³ for a Gaussian
// field with Gaussian ACF (Tripp, J. Lubr. Technol. 105, 1983) gives
//     φ_x = 1 + (3/H²)(1 − 3/(1 + γ)),   φ_y = 1 + (3/H²)(1 − 3γ/(1 + γ)),
// (γ = ℓ_x/ℓ_y): 1 − 1.5/H² isotropic, above 1 along the lay, below across it. The flow
// factors tend to 1 as H → ∞ at this rate. At H = 20 the O(H⁻⁴) terms are ~1 % of the
// deviation; the tolerance is three standard errors across the 8 realisations (sampling) plus
// 10 % of the coefficient (grid: ℓ_y ≈ 4.6 dx for γ = 3).
TEST(FlowFactors, TendToOneAtTheSmallRoughnessRate) {
  for (double gamma : {1.0, 3.0}) {
    const auto rows = flow_factors(cell(128, gamma, {20.0}, 8));
    const double h2 = 400.0;
    const double ref_x = 3.0 * (1.0 - 3.0 / (1.0 + gamma)), ref_y = 3.0 * (1.0 - 3.0 * gamma / (1.0 + gamma));
    std::printf("  gamma %.0f: H^2(phi_x - 1) = %.3f +- %.3f (theory %.3f), H^2(phi_y - 1) = %.3f +- %.3f (theory %.3f)\n",
                gamma, h2 * (rows[0].phi_x.mean - 1.0), h2 * rows[0].phi_x.standard_error, ref_x,
                h2 * (rows[0].phi_y.mean - 1.0), h2 * rows[0].phi_y.standard_error, ref_y);
    EXPECT_NEAR(h2 * (rows[0].phi_x.mean - 1.0), ref_x, 3 * h2 * rows[0].phi_x.standard_error + 0.1 * std::abs(ref_x));
    EXPECT_NEAR(h2 * (rows[0].phi_y.mean - 1.0), ref_y, 3 * h2 * rows[0].phi_y.standard_error + 0.1 * std::abs(ref_y));
    EXPECT_EQ(rows[0].unconverged, 0);
  }
}

// Against Patir & Cheng's fit for isotropic roughness (γ = 1), φ_x = 1 − 0.90 e^{−0.56H} (J. Lubr.
// Technol. 100, 1978, Table 1, H > 0.5), where the roughness effect 1 − φ is large (0.29 at H = 2,
// 0.17 at H = 3), compared as that effect: for isotropic roughness φ_x and φ_y estimate the same
// factor, so their mean φ̄ is used. The band is three standard errors of φ̄ over 8 realisations
// plus 30 % of Patir–Cheng's effect for the difference in surface model and grid (their fits
// come from few coarse realisations; ours land at 0.7–0.75 of their effect here, a systematic
// shortfall this band admits and does not hide: see the printout). Unlike the former ±0.05
// absolute band at H = 6 — wider than the effect 0.03 it checked — this fails for a roughness
// effect lost, doubled or of the wrong sign, and for a film floored at σ instead of 1e-3 σ
// (effect 0.11 at H = 2), which the former test passed. Φ_s (Patir & Cheng 1979) at H = 3 likewise: within
// 3 SE + 15 % of the fit's 0.55.
TEST(FlowFactors, RoughnessEffectAgreesWithPatirChengIsotropicFit) {
  const auto rows = flow_factors(cell(96, 1.0, {2.0, 3.0}, 8));
  for (const auto& r : rows) {
    const double pc_effect = 1.0 - patir_cheng_phi_x(r.h_over_sigma, 1.0);
    const double effect = 1.0 - 0.5 * (r.phi_x.mean + r.phi_y.mean);
    const double se = 0.5 * std::hypot(r.phi_x.standard_error, r.phi_y.standard_error);
    std::printf("  H = %.0f: 1 - phi %.4f +- %.4f (PC %.4f, ratio %.2f); Phi_s %.4f +- %.4f (PC %.4f)\n", r.h_over_sigma,
                effect, se, pc_effect, effect / pc_effect, r.phi_s.mean, r.phi_s.standard_error,
                patir_cheng_shear_factor(r.h_over_sigma, 1.0));
    EXPECT_NEAR(effect, pc_effect, 3 * se + 0.3 * pc_effect) << "H = " << r.h_over_sigma;
    EXPECT_EQ(r.unconverged, 0);
  }
  const double pc_shear = patir_cheng_shear_factor(3.0, 1.0);
  EXPECT_NEAR(rows[1].phi_s.mean, pc_shear, 3 * rows[1].phi_s.standard_error + 0.15 * pc_shear);
}

// Anisotropy (Patir–Cheng 1978, Fig. 6): ridges along the flow (γ = 3) pass more pressure flow
// than a smooth film, ridges across it (the transposed direction) much less. At H = 2 the fits
// give φ_x = 1.08 and φ_y = 0.49; the computed factors must lie on the same sides of 1 and agree
// with the fits within three standard errors of the mean over 64 realisations plus 3 % of the
// value (the fits' own scatter about Patir and Cheng's simulations) — narrower than φ_x's excess
// of 0.08 over a smooth film, so a factor that lost the lay would fail (with 4 realisations, as
// before, one standard error was 0.053: the test could not tell φ_x from 1).
TEST(FlowFactors, AnisotropicRoughnessFavoursFlowAlongTheLay) {
  const auto rows = flow_factors(cell(96, 3.0, {2.0}, 64));
  const double pc_x = patir_cheng_phi_x(2.0, 3.0), pc_y = patir_cheng_phi_y(2.0, 3.0);
  const auto& fx = rows[0].phi_x;
  const auto& fy = rows[0].phi_y;
  std::printf("  gamma 3, H = 2: phi_x %.3f +- %.3f (PC %.3f), phi_y %.3f +- %.3f (PC %.3f)\n", fx.mean, fx.standard_error, pc_x, fy.mean,
              fy.standard_error, pc_y);
  EXPECT_GT(fx.mean, 1.0);
  EXPECT_LT(fy.mean, 1.0);
  EXPECT_NEAR(fx.mean, pc_x, 3.0 * fx.standard_error + 0.03 * pc_x);
  EXPECT_NEAR(fy.mean, pc_y, 3.0 * fy.standard_error + 0.03 * pc_y);
  EXPECT_LT(3.0 * fx.standard_error + 0.03 * pc_x, pc_x - 1.0);  // the band is narrower than the effect
}

// The published fits checked by what they must satisfy rather than by retyping their constants
// (Patir & Cheng 1978 Table 1, 1979 Table 1 — the code's table): the shear-flow factor's two
// branches were fitted to join at H = 5 — a₁ 5^α₁ e^{−5α₂ + 25α₃} = A₂ e^{−1.25} — to 0.08 % in every
// row of the published table (a mistyped constant of the six breaks it by more); the pressure-flow
// factor rises with γ (transverse lay, γ < 1, obstructs the flow, longitudinal lay, γ > 1, channels
// it; a swapped row or constant breaks the order) and tends to 1 in thick films; φ_y(γ) = φ_x(1/γ);
// outside the tabulated γ or the fitted range the fits answer NaN.
TEST(FlowFactors, PatirChengFitsJoinTheirBranchesAndOrderByLay) {
  const std::vector<double> gammas{1.0 / 9, 1.0 / 6, 1.0 / 3, 1.0, 3.0, 6.0, 9.0};
  for (double g : gammas) {
    EXPECT_NEAR(patir_cheng_shear_factor(5.0 + 1e-12, g) / patir_cheng_shear_factor(5.0, g), 1.0, 1e-3) << "γ = " << g;
    EXPECT_NEAR(patir_cheng_phi_x(100.0, g), 1.0, 1e-2) << "γ = " << g;
    EXPECT_DOUBLE_EQ(patir_cheng_phi_y(2.0, g), patir_cheng_phi_x(2.0, 1.0 / g));
  }
  for (double h : {0.5, 1.0, 2.0, 3.0, 6.0})
    for (std::size_t k = 1; k < gammas.size(); ++k)
      EXPECT_GT(patir_cheng_phi_x(h, gammas[k]), patir_cheng_phi_x(h, gammas[k - 1])) << "H = " << h << ", γ = " << gammas[k];
  EXPECT_TRUE(std::isnan(patir_cheng_phi_x(2.0, 2.0)));
  EXPECT_TRUE(std::isnan(patir_cheng_phi_x(0.2, 1.0)));
}

// Rugosity lift on nominally parallel rough surfaces (DESIGN §3; thesis §5.2): with cavitation
// the mean film pressure is positive, more than 3 standard errors above zero over 6
// realisations at H = 3. Contact spots are floored at 0.1 σ here: a thinner floor lets the rare
// touching nodes dominate the mean with pressures that the solids, not the film, would carry.
// Reynolds' equation with JFO cavitation at zero cavity pressure is homogeneous in ηU (p and the
// cavity both scale with the Couette forcing), so a second, independent solve at 3U must give
// exactly 3 p̄ — to the Newton tolerance, 1e-6 relative here.
TEST(RugosityLift, RoughParallelSurfacesLiftWithCavitationInProportionToSpeed) {
  HomogenisationOptions o = cell(48, 1.0, {3.0}, 6);
  o.contact_gap_fraction = 0.1;
  const LiftRow r = rugosity_lift(o)[0];
  std::printf("  H = 3: mean pressure %.3e +- %.1e Pa (full film %.2e +- %.1e), cavitated %.2f, Newton %.1f\n",
              r.mean_pressure_Pa.mean, r.mean_pressure_Pa.standard_error, r.mean_pressure_full_film_Pa.mean,
              r.mean_pressure_full_film_Pa.standard_error, r.cavitated_fraction.mean, r.newton_iterations.mean);
  EXPECT_EQ(r.unconverged, 0);
  EXPECT_GT(r.mean_pressure_Pa.mean, 3.0 * r.mean_pressure_Pa.standard_error);
  o.sliding_speed_m_per_s *= 3.0;
  const LiftRow fast = rugosity_lift(o)[0];
  EXPECT_NEAR(fast.mean_pressure_Pa.mean / r.mean_pressure_Pa.mean, 3.0, 3e-6);
  EXPECT_NEAR(fast.cavitated_fraction.mean, r.cavitated_fraction.mean, 1e-6);
}

// The thesis preset's rough cells (examples/thesis-steel.toml: 128², self-affine H 0.8 between
// 62.5 and 15.6 µm, seed 1, lift floor 0.1σ) at its closest separation, h/σ = 0.25, where the
// cavitating lift cell needed 62 Newton steps and the limit of 60 dropped it (issue 37): every
// flow, Couette and lift cell converges.
TEST(RugosityLift, ThesisPresetCellsConvergeAtTheClosestSeparation) {
  HomogenisationOptions o;
  o.surface = contact::fixture::thesis_steel_surface();
  o.gap_ratios = {0.25};
  o.realisations = 1;
  o.contact_gap_fraction = 0.1;
  EXPECT_EQ(rugosity_lift(o)[0].unconverged, 0);
  o.contact_gap_fraction = 1e-3;  // the flow cells' floor
  EXPECT_EQ(flow_factors(o)[0].unconverged, 0);
}

}  // namespace
}  // namespace tribo::lubrication
