// Homogenised rough films: Patir–Cheng flow factors and rugosity lift, averaged over
// realisations of a Gaussian rough surface (contact/surface.h).
//
// Average flow model (Patir & Cheng, J. Lubr. Technol. 100, 1978, 12–17; 101, 1979, 220–230):
// the mean flow per unit width between a rough surface (composite rms σ, stationary) and a
// smooth one, nominal separation h between mean planes, local film h_T = max(h + δ, 0), is
//
//     q̄_x = −φ_x h³/(12η) ∂p̄/∂x + (U/2) h̄_T − (U/2) σ Φ_s ,     q̄_y = −φ_y h³/(12η) ∂p̄/∂y,
//
// with U the speed of the smooth surface (U₁ = 0, U₂ = U in Patir–Cheng's φ_s = V_r1Φ_s − V_r2Φ_s).
// Cells: the surface is periodic, n × n on a side L; the Reynolds cell has n + 1 nodes along the
// flow (the surface wraps, x = L ≡ 0), is periodic across it, and
//   φ_x:  p = Δp at x = 0, p = 0 at x = L, U = 0:     φ_x = q̄_x / (h³ Δp / (12η L));
//   φ_y:  the same on the transposed surface;
//   Φ_s:  p = 0 at both ends, U ≠ 0:                 Φ_s = (U h̄_T/2 − q̄_x) / (U σ/2).
// Where the surfaces touch (h + δ ≤ 0) the film is floored at `contact_gap_fraction`·σ, which
// passes a flow of order (that fraction)³ — negligible, as in Patir–Cheng's h_T = 0.
//
// Shear-stress factors (Patir & Cheng, J. Lubr. Technol. 101, 1979, 220–230). In the local film
// the velocity is u(z) = U z/h_T + (p'/2η)(z² − z h_T) between the stationary rough wall (z = 0)
// and the smooth wall moving at U (z = h_T); the viscous shear stress τ = η ∂u/∂z on the
// stationary wall is ηU/h_T − (h_T/2)p', on the moving wall ηU/h_T + (h_T/2)p'. Its mean over
// the cell area, contact nodes excluded (there the surfaces carry boundary friction, not fluid
// shear; they count as zero over the full area N), is written
//
//     τ̄_stationary = (ηU/h)(φf − φfs) − φfp (h/2) ∂p̄/∂x,
//     τ̄_moving     = (ηU/h)(φf + φfs) + φfp (h/2) ∂p̄/∂x,          (sign convention of this code)
//
//   φf  = (1/N) Σ_non-contact h/h_T                                  (Couette part, any cell)
//   φfs = (h/ηU) (1/N) Σ_non-contact (h_T/2) ∂p/∂x, shear cell (U ≠ 0, p = 0 at both ends):
//         the shear-induced pressure's part; ≥ 0 (in 1-D, Cauchy–Schwarz), → 0 for a smooth film
//   φfp = (1/N) Σ_non-contact (h_T/2) ∂p/∂x / ((h/2) ∂p̄/∂x), pressure cell (Δp along x, U = 0)
// with ∂p/∂x at a node from its mean x-face flow q̄ by the local 1-D relation
// q̄ = −h_T³p'/(12η) + (U/2)h_T. φf, φfs → 1, 0 and φfp → 1 as h/σ → ∞; for a Gaussian isotropic
// field the small-roughness rates are φf = 1 + (σ/h)², φfs = 1.5(σ/h)², φfp = 1 − 1.5(σ/h)².
// The friction of a flat (smooth) pin sliding over the rough stationary surface in steady
// sliding with no mean pressure gradient is τ̄ = (ηU/h)·couette_shear_factor, where
// couette_shear_factor = φf − φfs is measured directly as the mean stationary-wall shear of the
// shear cell times h/(ηU) (per realisation, so its error bar is its own).
//
// Rugosity lift: the same rough gap, p = 0 at both ends, sliding at U, with mass-conserving
// cavitation: the mean film pressure p̄ = load / area. p̄ is exactly proportional to ηU (the
// complementarity problem is homogeneous), so the table reports p̄ and p̄/(ηU) (1/m).
// A rough surface moving past a smooth stationary one gives the mirror-image steady problem
// (∂h/∂t = −U ∂h/∂x), with the same mean lift.
//
// Error bars: the mean over realisations ± its standard error s/√n (n = realisations).
#pragma once

#include "contact/surface.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace tribo::lubrication {

struct HomogenisationOptions {
  // The composite rough surface; rms_height_m is σ. Correlation lengths set γ = ℓ_x/ℓ_y
  // (Patir–Cheng's ratio of the lengths at which the autocorrelation falls to 0.5).
  contact::GaussianSurfaceParams surface;
  std::vector<double> gap_ratios{0.5, 1, 1.5, 2, 3, 4, 6};  // h/σ
  int realisations = 8;
  std::uint64_t first_seed = 1;            // realisation k uses seed first_seed + k
  double viscosity_Pa_s = 0.021;
  double sliding_speed_m_per_s = 0.1;      // for Φ_s and lift
  double pressure_drop_Pa = 1e5;           // for φ_x, φ_y (the answer does not depend on it)
  double contact_gap_fraction = 1e-3;      // film floor at contact, × σ
  int threads = 0;                         // OpenMP threads; 0 = default
  // The one realisation's heights (surface.grid² nodes over surface.size_m, σ = surface.rms_height_m),
  // used as they are instead of a surface generated from `surface`: a measured map, or the caller's
  // own realisation (homogenise/ passes the one its BEM solved). Requires realisations = 1.
  std::optional<Eigen::ArrayXXd> heights_m;
};

// Throws std::invalid_argument naming the bad field.
void validate(const HomogenisationOptions& options);

struct Estimate {
  double mean = 0, standard_error = 0;
};
// Mean and its standard error s/√n of the values (NaN, NaN when there are none; error 0 for one).
Estimate estimate(const std::vector<double>& values);

struct FlowFactorRow {
  double h_over_sigma = 0;
  Estimate phi_x, phi_y, phi_s;
  Estimate phi_f, phi_fs, phi_fp;   // shear-stress factors (see above; stationary rough wall)
  Estimate couette_shear_factor;    // τ̄ h/(ηU) on the stationary wall at ∂p̄/∂x = 0: φf − φfs
  Estimate mean_film_over_sigma;  // h̄_T/σ
  Estimate contact_fraction;      // share of nodes where the surfaces touch
  int unconverged = 0;            // realisations whose solve did not converge (excluded)
};

struct LiftRow {
  double h_over_sigma = 0;
  Estimate mean_pressure_Pa;         // with cavitation
  Estimate mean_pressure_per_eta_u;  // p̄/(ηU), 1/m
  Estimate mean_pressure_full_film_Pa;  // without cavitation (≈ 0 for a statistically symmetric gap)
  Estimate cavitated_fraction;
  Estimate newton_iterations;
  int unconverged = 0;
};

std::vector<FlowFactorRow> flow_factors(const HomogenisationOptions& options);
std::vector<LiftRow> rugosity_lift(const HomogenisationOptions& options);

// Patir & Cheng's fits (1978 Table 1, 1979 Table 1) for the tabulated γ ∈ {1/9, 1/6, 1/3, 1, 3,
// 6, 9} (matched to 1e-6); NaN for other γ or outside the fitted range (φ_x: H ≥ 0.5; Φ_s: H > 0.5).
//   φ_x = 1 − C e^{−rH} (γ ≤ 1),   φ_x = 1 + C H^{−r} (γ > 1);   φ_y(H, γ) = φ_x(H, 1/γ);
//   Φ_s = A₁ H^{α₁} e^{−α₂H + α₃H²} (H ≤ 5),   A₂ e^{−0.25H} (H > 5).
double patir_cheng_phi_x(double h_over_sigma, double gamma);
double patir_cheng_phi_y(double h_over_sigma, double gamma);
double patir_cheng_shear_factor(double h_over_sigma, double gamma);

// Patir & Cheng's (1979) closed form of φf for their polynomial approximation of the Gaussian
// height density, f(δ) = (35/(96σ))(1 − δ²/(9σ²))³ on |δ| ≤ 3σ, contact (h_T < ε* · 3σ) excluded:
// with z = H/3 and ε* = contact_gap_fraction/3 (the floor in units of 3σ),
//   H ≤ 3: φf = (35/32) z {(1 − z²)³ ln((z + 1)/ε*) + (1/60)[−55 + z(132 + z(345 + z(−160 + z(−405 + z(60 + 147z)))))]}
//   H > 3: φf = (35/32) z {(1 − z²)³ ln((z + 1)/(z − 1)) + (z/15)[66 + z²(30z² − 80)]}
// — the integral (35/32)∫(1 − u²)³ z/(z − u) du over u < min(1, z − ε*), exact for H > 3 and to
// O(ε*) below. For the exact Gaussian density it differs by up to 7 % near H = 2 (see the tests).
// NaN for H ≤ 0 or a fraction ≤ 0.
double patir_cheng_phi_f(double h_over_sigma, double contact_gap_fraction);

}  // namespace tribo::lubrication
