// Surfaces: synthesis against the requested PSD, seeding, statistics and file round trips.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

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

TEST(GaussianSurface, RmsHeightIsExactAndMeanIsZero) {
  const auto p = self_affine(128);
  const Eigen::ArrayXXd h = gaussian_surface(p);
  const SurfaceStatistics s = surface_statistics(h, p.size_m, p.size_m);
  EXPECT_NEAR(s.rq_m, 1e-6, 1e-6 * 1e-12);  // scaled to the target exactly
  EXPECT_NEAR(s.mean_m, 0.0, 1e-6 * 1e-12);
  // A Gaussian field has Ra = √(2/π) Rq; 128² points with ~ (128/4)² independent long waves
  // leave a few per cent of sampling scatter.
  EXPECT_NEAR(s.ra_m / s.rq_m, std::sqrt(2.0 / std::numbers::pi), 0.05);
}

TEST(GaussianSurface, RmsSlopeTargetIsExact) {
  auto p = self_affine(96);
  p.rms_height_m = 0.0;
  p.rms_slope = 0.05;
  const SurfaceStatistics s = surface_statistics(gaussian_surface(p), p.size_m, p.size_m);
  EXPECT_NEAR(s.rms_slope, 0.05, 0.05 * 1e-12);
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
  // Relative to the requested shape, normalised by Rq² = ∫ C d²q: every bin within its
  // 4-sigma sampling band 4/√m (a bin mean of m independent exponential |h̃|² values).
  double norm = 0.0;
  const double dq = 2 * std::numbers::pi / p.size_m;
  for (Eigen::Index j = 0; j < p.grid; ++j) {
    for (Eigen::Index k = 0; k < p.grid; ++k) {
      const double qx = dq * static_cast<double>(k <= p.grid / 2 ? k : k - p.grid);
      const double qy = dq * static_cast<double>(j <= p.grid / 2 ? j : j - p.grid);
      norm += psd_shape(p, qx, qy) * dq * dq;
    }
  }
  const double c0 = p.rms_height_m * p.rms_height_m / norm;
  int checked = 0;
  for (std::size_t k = 0; k < psd.q_per_m.size(); ++k) {
    const double expected = c0 * psd_shape(p, psd.q_per_m[k], 0.0);
    if (psd.q_per_m[k] > 0.95 * q_s) {
      if (psd.q_per_m[k] > 1.05 * q_s) {
        EXPECT_LT(psd.psd_m4[k], 1e-20 * c0) << "q = " << psd.q_per_m[k];
      }
      continue;
    }
    if (std::abs(psd.q_per_m[k] - q_r) < dq) continue;  // bin straddles the roll-off kink
    if (psd.modes[k] < 16) continue;                     // too few modes for a Gaussian band
    EXPECT_NEAR(psd.psd_m4[k] / expected, 1.0, 4.0 / std::sqrt(psd.modes[k])) << "q = " << psd.q_per_m[k];
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

TEST(GaussianSurface, OddGridHasTheRequestedRms) {
  auto p = self_affine(63);
  const SurfaceStatistics s = surface_statistics(gaussian_surface(p), p.size_m, p.size_m);
  EXPECT_NEAR(s.rq_m, p.rms_height_m, 1e-12 * p.rms_height_m);
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
