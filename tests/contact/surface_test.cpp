// Surfaces: synthesis against the requested PSD, seeding, statistics and file round trips.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <utility>

#include "contact/fft.h"
#include "contact/profile.h"
#include "contact/surface.h"
#include "contact/surface_io.h"

namespace tribo::contact {
namespace {

GaussianSurfaceParams self_affine(Eigen::Index n) {
  GaussianSurfaceParams p;
  p.grid = n;
  p.size_m = 1e-3;
  p.hurst = 0.8;
  p.rms_height_m = 1e-6;
  p.rolloff_wavelength_m = p.size_m / 4.0;
  p.cutoff_wavelength_m = p.size_m / 64.0;
  p.seed = 7;
  return p;
}

// Least-squares slope of log C against log q over bins with q in [q_lo, q_hi].
double log_log_slope(const RadialPsd& psd, double q_lo, double q_hi) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int m = 0;
  for (std::size_t k = 0; k < psd.q_per_m.size(); ++k) {
    if (psd.q_per_m[k] < q_lo || psd.q_per_m[k] > q_hi) continue;
    const double x = std::log(psd.q_per_m[k]), y = std::log(psd.psd_m4[k]);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++m;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

// Closed-form moments of the requested self-affine spectrum (the Persson 2006 / Jacobs, Junge &
// Pastewka 2017 form, written out here independently of psd_shape): C(q) = C0 for q < q_r,
// C0 (q/q_r)^{−2(1+H)} for q_r ≤ q ≤ q_s, 0 above. For an isotropic C, ∫ q^{2k} C d²q =
// 2π ∫ q^{2k+1} C dq, so (Parseval) Rq² = 2π C0 m(0) and h'_rms² = 2π C0 m(1) with
//   m(k) = q_r^{2k+2}/(2k+2) + q_r^{2+2H} (q_s^{2k−2H} − q_r^{2k−2H}) / (2k − 2H)   (2k ≠ 2H).
double spectral_moment(double q_r, double q_s, double hurst, int k) {
  const double e = 2.0 * k - 2.0 * hurst;
  return std::pow(q_r, 2.0 * k + 2.0) / (2.0 * k + 2.0) +
         std::pow(q_r, 2.0 + 2.0 * hurst) * (std::pow(q_s, e) - std::pow(q_r, e)) / e;
}

// The rms slope per unit rms height that the requested spectrum implies for periodic forward
// differences of step Δ: a mode q has |e^{iq_xΔ} − 1|²/Δ² = q_x² sinc²(q_xΔ/2) ≈ q_x² − q_x⁴Δ²/12,
// and the angular mean of q_x⁴ + q_y⁴ is (3/4) q⁴, so h'_fd² = 2π C0 (m(1) − (Δ²/16) m(2)); the next
// term, (2/45)(q_sΔ/2)⁴ ≈ 1e-3 at q_sΔ = π/4, is below the sampling scatter.
double spectral_slope_per_rq(const GaussianSurfaceParams& p) {
  const double two_pi = 2.0 * std::numbers::pi, dx = p.size_m / static_cast<double>(p.grid);
  const double q_r = two_pi / p.rolloff_wavelength_m, q_s = two_pi / p.cutoff_wavelength_m;
  const double m0 = spectral_moment(q_r, q_s, p.hurst, 0), m1 = spectral_moment(q_r, q_s, p.hurst, 1),
               m2 = spectral_moment(q_r, q_s, p.hurst, 2);
  return std::sqrt((m1 - dx * dx / 16.0 * m2) / m0);
}

// A self-affine spectrum with a wide plateau (q_r = 8 Δq, so Rq² is averaged over ~200
// independent long-wave amplitudes) and a cut-off resolved by 8 points per wavelength.
GaussianSurfaceParams plateau_self_affine(Eigen::Index n, std::uint64_t seed) {
  GaussianSurfaceParams p;
  p.grid = n;
  p.size_m = 1e-3;
  p.hurst = 0.8;
  p.rms_height_m = 1e-6;
  p.rolloff_wavelength_m = p.size_m / 8.0;
  p.cutoff_wavelength_m = p.size_m / 32.0;
  p.seed = seed;
  return p;
}

// Rq fixed by the generator, the rms slope then follows from the spectrum (Parseval): h'_fd/Rq
// = 7.04e4 /m here. Sampling: h'²/Rq² is a ratio of sums of independent exponential mode powers,
// Rq² dominated by the ~200 plateau amplitudes; over seeds 1–20 h'/Rq scatters by 1.4 % (sd)
// about 0.997 of the closed form. 5 % is 3.5 standard deviations and still catches a lost plateau
// (+30 %), a wrong spectral exponent or a slope estimator off by a grid factor.
TEST(GaussianSurface, RmsSlopeFollowsFromTheSpectrumsMoments) {
  const auto p = plateau_self_affine(256, 7);
  const SurfaceStatistics s = surface_statistics(gaussian_surface(p), p.size_m, p.size_m);
  std::printf("  h'/Rq = %.5g per m, spectrum %.5g per m\n", s.rms_slope / s.rq_m, spectral_slope_per_rq(p));
  EXPECT_NEAR(s.rms_slope / s.rq_m / spectral_slope_per_rq(p), 1.0, 0.05);
  EXPECT_NEAR(s.mean_m, 0.0, 1e-12 * s.rq_m);
}

// The same relation the other way round on an odd grid: ask for the rms slope, get the rms
// height the spectrum implies (same 5 % band, same reason).
TEST(GaussianSurface, RmsHeightFollowsFromTheSpectrumsMomentsOnAnOddGrid) {
  auto p = plateau_self_affine(255, 11);
  p.rms_height_m = 0.0;
  p.rms_slope = 0.05;
  const SurfaceStatistics s = surface_statistics(gaussian_surface(p), p.size_m, p.size_m);
  EXPECT_NEAR(s.rq_m * spectral_slope_per_rq(p) / 0.05, 1.0, 0.05);
}

// A Gaussian random field has Gaussian heights: skewness 0, kurtosis 3, Ra/Rq = √(2/π) = 0.7979.
// The estimators scatter because neighbouring heights are correlated (Isserlis: var ≈ (24/N)Σρ⁴
// for the kurtosis); over seeds 1–20 one surface gives sd 0.08 (skewness), 0.12 (kurtosis),
// 0.005 (Ra/Rq). Eight seeds are pooled (sd 0.03, 0.04, 0.002) and the bands are ≈ 5 sd: a
// non-Gaussian generator or a wrong moment normalisation (kurtosis of a sinusoid is 1.5, of a
// Laplace field 6) fails.
TEST(GaussianSurface, HeightsAreGaussian) {
  double skew = 0.0, kurt = 0.0, ra_rq = 0.0;
  const int seeds = 8;
  for (int seed = 1; seed <= seeds; ++seed) {
    const auto p = plateau_self_affine(256, static_cast<std::uint64_t>(seed));
    const SurfaceStatistics s = surface_statistics(gaussian_surface(p), p.size_m, p.size_m);
    skew += s.skewness / seeds;
    kurt += s.kurtosis / seeds;
    ra_rq += s.ra_m / s.rq_m / seeds;
  }
  std::printf("  pooled skewness %.3f, kurtosis %.3f, Ra/Rq %.4f\n", skew, kurt, ra_rq);
  EXPECT_NEAR(skew, 0.0, 0.15);
  EXPECT_NEAR(kurt, 3.0, 0.2);
  EXPECT_NEAR(ra_rq, std::sqrt(2.0 / std::numbers::pi), 0.01);
}

// The radially averaged PSD follows C ∝ q^{−2(1+H)} between roll-off and cut-off (Persson 2006),
// is flat below the roll-off and empty above the cut-off. Sampling scatter of a bin average of
// m modes is 1/√m; the fitted exponent over ~20 bins is good to ±0.1.
TEST(GaussianSurface, RadialPsdMatchesRequestedSelfAffineSpectrum) {
  const auto p = self_affine(256);
  const Eigen::ArrayXXd h = gaussian_surface(p);
  const RadialPsd psd = radial_psd(h, p.size_m, p.size_m);
  const double q_r = 2 * std::numbers::pi / p.rolloff_wavelength_m, q_s = 2 * std::numbers::pi / p.cutoff_wavelength_m;
  EXPECT_NEAR(log_log_slope(psd, 1.2 * q_r, 0.9 * q_s), -2.0 * (1.0 + p.hurst), 0.1);
  // Against the closed-form spectrum (not psd_shape): C0 from Parseval, Rq² = 2π C0 m(0) with the
  // analytic moment above; every bin within its 4-sigma sampling band 4/√m (a bin mean of m
  // independent exponential |h̃|² values) plus 3 % for the lattice sum against the integral (0.75 %
  // here).
  const double dq = 2 * std::numbers::pi / p.size_m;
  const double c0 = p.rms_height_m * p.rms_height_m / (2 * std::numbers::pi * spectral_moment(q_r, q_s, p.hurst, 0));
  auto requested = [&](double q) { return q < q_r ? c0 : c0 * std::pow(q / q_r, -2.0 * (1.0 + p.hurst)); };
  int checked = 0;
  for (std::size_t k = 0; k < psd.q_per_m.size(); ++k) {
    const double expected = requested(psd.q_per_m[k]);
    if (psd.q_per_m[k] > 0.95 * q_s) {
      if (psd.q_per_m[k] > 1.05 * q_s) {
        EXPECT_LT(psd.psd_m4[k], 1e-20 * c0) << "q = " << psd.q_per_m[k];
      }
      continue;
    }
    if (std::abs(psd.q_per_m[k] - q_r) < dq) continue;  // bin straddles the roll-off kink
    if (psd.modes[k] < 16) continue;                     // too few modes for a Gaussian band
    EXPECT_NEAR(psd.psd_m4[k] / expected, 1.0, 0.03 + 4.0 / std::sqrt(psd.modes[k])) << "q = " << psd.q_per_m[k];
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST(GaussianSurface, AnisotropicGaussianAcfHasRequestedCorrelationLengths) {
  GaussianSurfaceParams p;
  p.kind = SpectrumKind::gaussian_acf;
  p.grid = 256;
  p.size_m = 1e-3;
  const double dx = p.size_m / p.grid;
  p.correlation_length_m = 16 * dx;        // along the lay
  p.correlation_length_across_m = 4 * dx;  // across it
  p.rms_height_m = 1e-6;
  const Eigen::ArrayXXd h = gaussian_surface(p);
  auto acf = [&](int di, int dj) {
    double s = 0;
    for (Eigen::Index j = 0; j < h.cols(); ++j)
      for (Eigen::Index i = 0; i < h.rows(); ++i) s += h(i, j) * h((i + di) % h.rows(), (j + dj) % h.cols());
    return s / static_cast<double>(h.size()) / (p.rms_height_m * p.rms_height_m);
  };
  // ACF(x, y) = exp(−x²/ℓ_x² − y²/ℓ_y²) is e^{-1} at a lag of ℓ along either axis. Scatter of the
  // estimate: var ≈ Σ ρ² / N ≈ (π/2) ℓ_x ℓ_y / (Δx² N) ≈ 1.5e-3, σ ≈ 0.04; 4σ = 0.16.
  EXPECT_NEAR(acf(16, 0), std::exp(-1.0), 0.16);
  EXPECT_NEAR(acf(0, 4), std::exp(-1.0), 0.16);
  EXPECT_NEAR(acf(0, 16), 0.0, 0.16);  // across the lay a lag of ℓ_x is 4 ℓ_y: e^{-16}
}

// A lay (peklenik_gamma = γ): C(q_x, q_y) = C_iso(√(γ q_x² + q_y²/γ)). Substituting q_x = u/√γ,
// q_y = √γ v turns ∫ q_x² C d²q into γ^{-1} ∫ u² C_iso d²w and ∫ q_y² C d²q into γ ∫ v² C_iso d²w,
// equal by isotropy: the rms slope along x is 1/γ of that across, whatever H and the wavelengths.
// Measured from the generated surface's spectral moments Σ q_x²|ĥ|² and Σ q_y²|ĥ|² (exact
// derivatives, not differences), with the stretched band inside the grid (q_s √γ = 64 Δq < 256 Δq).
// Each moment sums exponential mode powers (the lattice itself is 0.07 % off the integral's ratio):
// one surface scatters by 2.1 % (sd, simulated over the 1660 modes of the band), so eight seeds are
// pooled (0.75 %) and the 3 % band (4 sd) still tells γ = 4 from 3.6 or 4.4. The stretch itself:
// C at (q_x, q_y) is the isotropic C at (√γ q_x, q_y/√γ) — features longer along x, not across.
TEST(GaussianSurface, ALaysSlopesAlongAndAcrossAreInTheRatioOfPeklenikGamma) {
  for (const double gamma : {4.0, 0.25}) {
    double mx = 0.0, my = 0.0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
      GaussianSurfaceParams p = plateau_self_affine(512, seed);
      p.peklenik_gamma = gamma;
      const Eigen::ArrayXXd h = gaussian_surface(p);
      RealFft2d fft(p.grid, p.grid, 1);
      fft.forward(h.data());
      const std::complex<double>* c = fft.spectrum();
      const double dq = 2.0 * std::numbers::pi / p.size_m;
      for (Eigen::Index j = 0; j < p.grid; ++j)
        for (Eigen::Index k = 0; k < fft.nx_half(); ++k) {
          const double w = (k == 0 || 2 * k == p.grid) ? 1.0 : 2.0;  // the conjugate half r2c leaves out
          const double qx = dq * static_cast<double>(k), qy = dq * static_cast<double>(signed_frequency(j, p.grid));
          const double power = std::norm(c[j * fft.nx_half() + k]);
          mx += w * qx * qx * power;
          my += w * qy * qy * power;
        }
    }
    EXPECT_NEAR(std::sqrt(mx / my) * gamma, 1.0, 0.03) << "gamma " << gamma;
  }
  const GaussianSurfaceParams iso = plateau_self_affine(128, 3);
  GaussianSurfaceParams lay = iso;
  lay.peklenik_gamma = 4.0;
  const double q_s = 2.0 * std::numbers::pi / iso.cutoff_wavelength_m;
  for (const auto& [qx, qy] : {std::pair{0.1, 0.3}, std::pair{0.4, 0.05}, std::pair{0.2, 0.8}})
    EXPECT_NEAR(psd_shape(lay, qx * q_s, qy * q_s), psd_shape(iso, 2.0 * qx * q_s, qy * q_s / 2.0),
                1e-12 * psd_shape(iso, 2.0 * qx * q_s, qy * q_s / 2.0))
        << qx << ", " << qy;
}

TEST(GaussianSurface, SameSeedSameSurfaceWhateverTheThreadCount) {
  const auto p = self_affine(64);
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const Eigen::ArrayXXd one = gaussian_surface(p);
  omp_set_num_threads(2);
  const Eigen::ArrayXXd two = gaussian_surface(p);
  omp_set_num_threads(before);
  EXPECT_TRUE((one == two).all());
  auto other = p;
  other.seed = 8;
  EXPECT_GT((gaussian_surface(other) - one).abs().maxCoeff(), 0.1 * p.rms_height_m);
}

// A single cosine h = A cos(2π k x / L) has Rq = A/√2, Ra = 2A/π, rms slope (2π k A / L)/√2
// (forward differences: times sin(π k/n)/(π k/n)), and mean curvature ½h'' with rms
// (2π k/L)² A/(2√2) (5-point stencil: times sinc²(π k/n)).
TEST(SurfaceStatistics, CosineHasClosedFormStatistics) {
  const Eigen::Index n = 256;
  const double L = 1e-3, A = 2e-6;
  const int k = 2;
  Eigen::ArrayXXd h(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) h.row(i).setConstant(A * std::cos(2 * std::numbers::pi * k * i / double(n)));
  const SurfaceStatistics s = surface_statistics(h, L, 3 * L / n);
  const double x = std::numbers::pi * k / n, q = 2 * std::numbers::pi * k / L;
  EXPECT_NEAR(s.rq_m, A / std::sqrt(2.0), 1e-12 * A);
  EXPECT_NEAR(s.ra_m, 2 * A / std::numbers::pi, 1e-3 * A);  // 128 samples per period of |cos|: O(1e-4) quadrature
  EXPECT_NEAR(s.rms_slope, q * A / std::sqrt(2.0) * std::sin(x) / x, 1e-9 * q * A);
  EXPECT_NEAR(s.rms_curvature_per_m, q * q * A / (2 * std::sqrt(2.0)) * std::pow(std::sin(x) / x, 2), 1e-9 * q * q * A);
}

// An oblique cosine h = A cos(2π(k i/n_x + l j/n_y)) on a rectangle (n_x ≠ n_y, L_x ≠ L_y): Rq =
// A/√2 and, per axis, the forward difference of a mode is exact: ⟨(Δh/Δx)²⟩ = (A²/2)(2 sin(πk/n_x)/Δx)²,
// likewise in y. Both are exact on the periodic grid (1e-12 for the summation).
TEST(SurfaceStatistics, ObliqueCosineOnARectangleHasExactRmsAndSlope) {
  const Eigen::Index nx = 96, ny = 60;
  const double lx = 1e-3, ly = 0.4e-3, A = 1e-6;
  const int k = 3, l = 2;
  Eigen::ArrayXXd h(nx, ny);
  for (Eigen::Index j = 0; j < ny; ++j)
    for (Eigen::Index i = 0; i < nx; ++i)
      h(i, j) = A * std::cos(2 * std::numbers::pi * (k * double(i) / double(nx) + l * double(j) / double(ny)));
  const SurfaceStatistics s = surface_statistics(h, lx, ly);
  const double dx = lx / nx, dy = ly / ny;
  const double gx = 2 * std::sin(std::numbers::pi * k / nx) / dx, gy = 2 * std::sin(std::numbers::pi * l / ny) / dy;
  EXPECT_NEAR(s.rq_m, A / std::sqrt(2.0), 1e-12 * A);
  EXPECT_NEAR(s.rms_slope, A / std::sqrt(2.0) * std::hypot(gx, gy), 1e-12 * A * std::hypot(gx, gy));
  EXPECT_NEAR(s.kurtosis, 1.5, 1e-12);  // a sinusoid's kurtosis: ⟨cos⁴⟩/⟨cos²⟩² = (3/8)/(1/4)
}

// A sum of modes below the coarse Nyquist wavenumber is its own band-limited interpolant: the
// refined field is the closed form on the fine grid, to round-off (1e-12 of the amplitude). An
// even and an odd, rectangular grid; the even one carries a Nyquist cosine along x, which refines
// to cos(q_N x) (its real, even-split interpretation).
TEST(FourierRefine, BandLimitedModesRefineToTheirClosedForm) {
  for (const auto& [nx, ny] : {std::pair<Eigen::Index, Eigen::Index>{16, 12}, {15, 9}}) {
    const double lx = 2e-4, ly = 1.5e-4;
    const auto field = [&](Eigen::Index mx, Eigen::Index my) {
      Eigen::ArrayXXd h(mx, my);
      for (Eigen::Index i = 0; i < mx; ++i)
        for (Eigen::Index j = 0; j < my; ++j) {
          const double x = lx * static_cast<double>(i) / static_cast<double>(mx), y = ly * static_cast<double>(j) / static_cast<double>(my);
          h(i, j) = 1e-6 * std::cos(2 * std::numbers::pi * (3 * x / lx + 2 * y / ly) + 0.4) + 5e-7 * std::sin(2 * std::numbers::pi * 4 * y / ly);
          if (nx % 2 == 0) h(i, j) += 2e-7 * std::cos(std::numbers::pi * static_cast<double>(nx) * x / lx);
        }
      return h;
    };
    for (int factor : {2, 3}) {
      const Eigen::ArrayXXd refined = fourier_refine(field(nx, ny), factor);
      ASSERT_EQ(refined.rows(), factor * nx);
      ASSERT_EQ(refined.cols(), factor * ny);
      EXPECT_LT((refined - field(factor * nx, factor * ny)).abs().maxCoeff(), 1e-18) << nx << "x" << ny << ", factor " << factor;
    }
  }
}

// Any field, band-limited or not, keeps its values at the coarse nodes, its mean and its Rq
// (Parseval: the coefficients are kept) when refined.
TEST(FourierRefine, RefinedSurfaceKeepsTheCoarseNodesAndRq) {
  GaussianSurfaceParams p;
  p.grid = 33;
  p.size_m = 1e-4;
  p.rms_height_m = 4e-7;
  const Eigen::ArrayXXd z = gaussian_surface(p);
  const Eigen::ArrayXXd f = fourier_refine(z, 2);
  double worst = 0;
  for (Eigen::Index i = 0; i < z.rows(); ++i)
    for (Eigen::Index j = 0; j < z.cols(); ++j) worst = std::max(worst, std::abs(f(2 * i, 2 * j) - z(i, j)));
  EXPECT_LT(worst, 1e-12 * p.rms_height_m);  // round-off of two FFTs
  EXPECT_NEAR(std::sqrt((f - f.mean()).square().mean()), p.rms_height_m, 1e-12 * p.rms_height_m);
  EXPECT_THROW(fourier_refine(z, 0), std::invalid_argument);
}

TEST(SurfaceStatistics, HistogramIsANormalisedDensity) {
  const auto p = self_affine(64);
  const HeightHistogram hist = height_histogram(gaussian_surface(p), 20);
  const double width = hist.bin_centre_m[1] - hist.bin_centre_m[0];
  double total = 0.0;
  for (double d : hist.density_per_m) total += d * width;
  EXPECT_NEAR(total, 1.0, 1e-12);
}

class SurfaceFiles : public ::testing::Test {
 protected:
  std::filesystem::path dir_ = std::filesystem::temp_directory_path() /
                               ("tribo_surface_io_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  void SetUp() override { std::filesystem::create_directories(dir_); }
  void TearDown() override { std::filesystem::remove_all(dir_); }
};

TEST_F(SurfaceFiles, NpyRoundTripIsBitExactOnARectangularGrid) {
  Eigen::ArrayXXd h = Eigen::ArrayXXd::Random(5, 7) * 1e-6;
  write_npy(dir_ / "h.npy", h);
  const Eigen::ArrayXXd back = read_npy(dir_ / "h.npy");
  ASSERT_EQ(back.rows(), 5);
  ASSERT_EQ(back.cols(), 7);
  EXPECT_TRUE((back == h).all());
}

TEST_F(SurfaceFiles, NpyInCOrderFloat32IsReadRowByRow) {
  // numpy: np.array([[1, 2, 3], [4, 5, 6]], dtype='<f4') saved in C order.
  std::string header = "{'descr': '<f4', 'fortran_order': False, 'shape': (2, 3), }";
  while ((10 + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::ofstream out(dir_ / "c.npy", std::ios::binary);
  out.write("\x93NUMPY\x01\x00", 8);
  const char len[2] = {static_cast<char>(header.size()), 0};
  out.write(len, 2);
  out << header;
  for (float v : {1.f, 2.f, 3.f, 4.f, 5.f, 6.f}) out.write(reinterpret_cast<const char*>(&v), 4);
  out.close();
  const Eigen::ArrayXXd h = read_npy(dir_ / "c.npy");
  ASSERT_EQ(h.rows(), 2);
  EXPECT_EQ(h(0, 2), 3.0);
  EXPECT_EQ(h(1, 0), 4.0);
}

TEST_F(SurfaceFiles, AsciiMatrixAndXyzGiveTheSameHeights) {
  {
    std::ofstream m(dir_ / "m.txt");
    m << "# heights in um\n1 2 3\n4, 5, 6\n";
    std::ofstream x(dir_ / "s.xyz");
    // shuffled lines, spacing 0.5 in x and 2 in y
    x << "0.5 4 6\n0 0 1\n0.5 0 4\n0 2 2\n0.5 2 5\n0 4 3\n";
  }
  const Topography m = read_topography(dir_ / "m.txt", 1e-6);
  const Topography x = read_topography(dir_ / "s.xyz", 1e-6);
  ASSERT_EQ(m.heights_m.rows(), 2);
  ASSERT_EQ(m.heights_m.cols(), 3);
  EXPECT_TRUE(m.heights_m.isApprox(x.heights_m, 1e-15));
  EXPECT_DOUBLE_EQ(x.lx_m, 1.0);
  EXPECT_DOUBLE_EQ(x.ly_m, 6.0);
  EXPECT_EQ(m.lx_m, 0.0);
}

TEST_F(SurfaceFiles, BadFilesAreRejectedWithTheFileName) {
  {
    std::ofstream(dir_ / "ragged.txt") << "1 2 3\n4 5\n";
    std::ofstream(dir_ / "nan.txt") << "1 nan\n2 3\n";
    std::ofstream(dir_ / "word.txt") << "1 x\n";
    std::ofstream(dir_ / "holes.xyz") << "0 0 1\n1 0 1\n0 1 1\n";
    std::ofstream(dir_ / "fake.npy") << "not numpy";
  }
  for (const char* name : {"ragged.txt", "nan.txt", "word.txt", "holes.xyz", "fake.npy", "missing.npy"}) {
    try {
      read_topography(dir_ / name);
      ADD_FAILURE() << name << " was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

// The interferometer export's header (ContactEngineering/SurfaceTopography's matrix-2.txt has
// this form: phase in rad, a conversion factor to metres, a pixel size): the reader must take
// the size, pixel and unit from it, refuse a header that disagrees with the data, and refuse a
// second scaling on top.
TEST_F(SurfaceFiles, InterferometerHeaderSetsPixelSizeAndHeightUnit) {
  {
    std::ofstream(dir_ / "phase.txt") << "h=2 w=3\npixel size=3.69862e-007 m\ndata unit=rad\n"
                                         "height conversion factor (-> m)=6.30079e-008\n1 2 3\n-1 0 4\n";
    std::ofstream(dir_ / "short.txt") << "h=3 w=3\npixel size=1 um\n1 2 3\n4 5 6\n";
  }
  const Topography t = read_topography(dir_ / "phase.txt");
  ASSERT_EQ(t.heights_m.rows(), 2);
  ASSERT_EQ(t.heights_m.cols(), 3);
  EXPECT_DOUBLE_EQ(t.heights_m(1, 2), 4 * 6.30079e-8);
  EXPECT_DOUBLE_EQ(t.lx_m, 2 * 3.69862e-7);
  EXPECT_DOUBLE_EQ(t.ly_m, 3 * 3.69862e-7);
  EXPECT_THROW(read_topography(dir_ / "phase.txt", 1e-6), std::invalid_argument);
  EXPECT_THROW(read_topography(dir_ / "short.txt"), std::invalid_argument);
}

// Measured maps against the statistics another project publishes for them
// (tests/contact/data/topography/SOURCE.md; ContactEngineering/SurfaceTopography, MIT).
const std::filesystem::path kTopographyData = std::filesystem::path(TRIBO_CONTACT_TEST_DATA) / "topography";

// Root mean square of one-sided differences over a non-periodic map (a measured map does not
// wrap around, so the periodic estimator of surface_statistics would add the edge jump).
double open_map_rms_gradient(const Eigen::ArrayXXd& h, double dx, double dy) {
  const Eigen::Index nx = h.rows(), ny = h.cols();
  const double sx = (h.bottomRows(nx - 1) - h.topRows(nx - 1)).square().mean() / (dx * dx);
  const double sy = (h.rightCols(ny - 1) - h.leftCols(ny - 1)).square().mean() / (dy * dy);
  return std::sqrt(sx + sy);
}

// AFM map (Gwyddion ASCII: "# Width: 10.00 µm", "# Value units: m"): 256 × 256 over 10 µm. The
// published rms height (mean removed, no tilt removal) is of the same 5-digit numbers, so only
// summation order separates the two: 1e-10. The published one-sided rms gradient 0.19232 has 5
// digits: ±5e-5. A reader that ignored the header's size or unit misses both by orders.
TEST(MeasuredTopography, AfmMapHasThePublishedRmsHeightAndGradient) {
  const Topography t = read_topography(kTopographyData / "matrix-3.txt");
  ASSERT_EQ(t.heights_m.rows(), 256);
  ASSERT_EQ(t.heights_m.cols(), 256);
  EXPECT_DOUBLE_EQ(t.lx_m, 10e-6);
  EXPECT_DOUBLE_EQ(t.ly_m, 10e-6);
  const SurfaceStatistics s = surface_statistics(t.heights_m, t.lx_m, t.ly_m);
  EXPECT_NEAR(s.rq_m / 3.5222918750198742e-8, 1.0, 1e-10);
  EXPECT_NEAR(open_map_rms_gradient(t.heights_m, t.lx_m / 256, t.ly_m / 256), 0.19232, 5e-5);
}

// Dektak stylus line (header: Length 1500 µm, heights "Raw Micrometer"; 9600 samples). The
// instrument reports Rq = 0.01143 µm and Ra = 0.00525 µm between its cursors at 468 and 733 µm,
// with the profile levelled there (a least-squares line removed — without it Rq is 0.84 µm).
// Tolerance 0.5 %: the published 4 digits (0.05 %, 0.1 %) and where the cursors fall between
// samples (shifting the window by a few samples moves Rq by ≈ 0.15 %).
TEST(MeasuredTopography, StylusProfileHasTheInstrumentsRqBetweenItsCursors) {
  const Topography t = read_topography(kTopographyData / "dektak-1.csv");
  ASSERT_EQ(t.heights_m.rows(), 9600);
  ASSERT_EQ(t.heights_m.cols(), 1);
  EXPECT_DOUBLE_EQ(t.lx_m, 1500e-6);
  const double dx = t.lx_m / 9600;
  const auto first = static_cast<Eigen::Index>(std::ceil(468e-6 / dx)), last = static_cast<Eigen::Index>(std::floor(733e-6 / dx));
  const Eigen::Index n = last - first + 1;
  const Eigen::ArrayXXd levelled = level_profile(t.heights_m.col(0).segment(first, n));
  const SurfaceStatistics s = surface_statistics(levelled, static_cast<double>(n) * dx, dx);
  EXPECT_NEAR(s.rq_m / 0.01143e-6, 1.0, 0.005);
  EXPECT_NEAR(s.ra_m / 0.00525e-6, 1.0, 0.005);
}

TEST(GaussianSurface, BadParametersNameTheParameter) {
  auto expect_error = [](GaussianSurfaceParams p, const std::string& word) {
    try {
      gaussian_surface(p);
      ADD_FAILURE() << "accepted bad " << word;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  auto p = self_affine(32);
  auto q = p;
  q.size_m = -1;
  expect_error(q, "size_m");
  q = p;
  q.size_m = std::nan("");
  expect_error(q, "size_m");
  q = p;
  q.hurst = 1.5;
  expect_error(q, "hurst");
  q = p;
  q.rms_slope = 0.1;
  expect_error(q, "exactly one");
  q = p;
  q.grid = 0;
  expect_error(q, "grid");
  q = p;
  q.cutoff_wavelength_m = 2 * q.rolloff_wavelength_m;
  expect_error(q, "cutoff_wavelength_m");
}

}  // namespace
}  // namespace tribo::contact
