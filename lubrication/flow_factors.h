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
};

// Throws std::invalid_argument naming the bad field.
void validate(const HomogenisationOptions& options);

struct Estimate {
  double mean = 0, standard_error = 0;
};

struct FlowFactorRow {
  double h_over_sigma = 0;
  Estimate phi_x, phi_y, phi_s;
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

}  // namespace tribo::lubrication
