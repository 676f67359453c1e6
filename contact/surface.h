// Rough surfaces: periodic Gaussian random fields synthesised from a power spectral density
// (PSD), and their statistics.
//
// Conventions (SI): heights h(x, y) in m on an nx × ny periodic grid of side L_x × L_y
// (layout as in contact/fft.h: rows are x). Discrete Fourier coefficients
//   h̃(q) = (1 / (nx ny)) Σ h(x) exp(−i q·x),   so that Rq² = Σ_q |h̃(q)|²  (Parseval),
// and the two-sided 2-D PSD (Persson's C(q), m⁴) is
//   C(q) = |h̃(q)|² L_x L_y / (2π)²,   with   Rq² = ∫ C(q) d²q  (Δq² = (2π)²/(L_x L_y)).
// Spectra offered (q = |q|, q_r = 2π/λ_r roll-off, q_s = 2π/λ_s short-wavelength cut-off):
//   self-affine, Hurst H:  C ∝ 1 for q < q_r,  (q/q_r)^{−2(1+H)} for q_r ≤ q ≤ q_s,  0 for q > q_s
//   Gaussian ACF:          R(x, y) = Rq² exp(−x²/ℓ_x² − y²/ℓ_y²)  ⇒  C ∝ exp(−(q_x² ℓ_x² + q_y² ℓ_y²)/4)
// (anisotropic with ℓ_x along the lay, ℓ_y across it — the lapped and worn surfaces of thesis
// Appendix V are rougher across the directional marks).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace tribo::contact {

enum class SpectrumKind { self_affine, gaussian_acf };

// Parameters of a synthesised surface. Exactly one of rms_height_m and rms_slope must be > 0:
// the realised field is scaled so that its Rq (or its rms slope, by the same finite differences
// as surface_statistics) equals the target exactly.
struct GaussianSurfaceParams {
  Eigen::Index grid = 256;       // points per side, n (n × n grid)
  double size_m = 1e-3;          // side L of the periodic square
  SpectrumKind kind = SpectrumKind::self_affine;
  double rms_height_m = 1e-6;    // target Rq (0 when rms_slope is given)
  double rms_slope = 0.0;        // target rms gradient √⟨|∇h|²⟩ (0 when rms_height_m is given)
  std::uint64_t seed = 1;        // same seed, same surface, whatever the thread count
  // self-affine
  double hurst = 0.8;                  // H in (0, 1]
  double rolloff_wavelength_m = 0.0;   // λ_r; 0 → no plateau (λ_r = L)
  double cutoff_wavelength_m = 0.0;    // λ_s; 0 → none (Nyquist, 2 L/n)
  // Lay: the spectrum stretched so that features are γ times longer along x (the sliding
  // direction) than across — Peklenik's γ, the ratio of correlation lengths: C(q_x, q_y) is the
  // isotropic C at q' = √(γ q_x² + q_y²/γ), the wavelengths above holding along the geometric mean.
  // 1: isotropic; > 1 a longitudinal lay (streaks along the sliding), < 1 a transverse one. The rms
  // slope along x is then 1/γ of that across.
  double peklenik_gamma = 1.0;
  // Gaussian ACF
  double correlation_length_m = 0.0;         // ℓ_x (along the lay)
  double correlation_length_across_m = 0.0;  // ℓ_y; 0 → isotropic (ℓ_y = ℓ_x)
};

// Throws std::invalid_argument naming the first bad parameter.
void validate(const GaussianSurfaceParams& params);

// Relative PSD shape C(q)/C₀ of the requested spectrum at wavevector (q_x, q_y) in rad/m
// (dimensionless; 0 at q = 0 because the mean height is removed).
double psd_shape(const GaussianSurfaceParams& params, double qx_per_m, double qy_per_m);

// The surface: white Gaussian noise from a seeded generator, filtered by √C(q) in Fourier space
// (single-threaded FFT, so the bits do not depend on the thread count), mean removed, scaled to
// the requested rms height or rms slope.
Eigen::ArrayXXd gaussian_surface(const GaussianSurfaceParams& params);

struct SurfaceStatistics {
  double mean_m = 0;
  double rq_m = 0;                 // rms height about the mean
  double ra_m = 0;                 // arithmetic mean deviation (CLA)
  double rms_slope = 0;            // √⟨(∂h/∂x)² + (∂h/∂y)²⟩, periodic forward differences
  double rms_curvature_per_m = 0;  // rms of ½∇²h (mean curvature), periodic 5-point Laplacian
  double skewness = 0, kurtosis = 0;
  double min_m = 0, max_m = 0;
};

// Statistics of heights on a grid of side lx_m × ly_m (derivatives wrap around the edges).
SurfaceStatistics surface_statistics(const Eigen::ArrayXXd& heights_m, double lx_m, double ly_m);

// Radially averaged PSD: bins of width Δq = 2π / max(L_x, L_y) centred on multiples of Δq,
// from Δq up to the largest full circle in the spectrum.
struct RadialPsd {
  std::vector<double> q_per_m;  // bin centre
  std::vector<double> psd_m4;   // mean C(q) of the modes in the bin
  std::vector<int> modes;       // independent Fourier amplitudes averaged (conjugate pairs once)
};
RadialPsd radial_psd(const Eigen::ArrayXXd& heights_m, double lx_m, double ly_m);

// Height distribution as a probability density over `bins` equal bins spanning [min, max].
// The same periodic surface on a grid `factor` times finer in each direction: its trigonometric
// (band-limited) interpolant, whose Fourier coefficients are the coarse ones and zero above the
// coarse Nyquist wavenumber; a Nyquist bin of an even grid (a pure cosine there) is split evenly
// between ±q_N. The refined field equals the coarse one at the coarse nodes (every factor-th node),
// and its spectrum, Rq and mean are the coarse ones: it is the same continuous surface sampled
// more finely, so a solve on it measures the discretisation error of the coarse solve, not a new
// realisation. Works on odd and even, rectangular grids; factor 1 returns a copy. Throws
// std::invalid_argument for factor < 1 or an empty field.
Eigen::ArrayXXd fourier_refine(const Eigen::ArrayXXd& heights_m, int factor);

struct HeightHistogram {
  std::vector<double> bin_centre_m;
  std::vector<double> density_per_m;
};
HeightHistogram height_histogram(const Eigen::ArrayXXd& heights_m, int bins);

}  // namespace tribo::contact
