// contact/fft.h: the real 2-D transform against the discrete Fourier sum it defines, on a grid the
// shipped FFTW wisdom covers (its plan built from the wisdom) and on one it does not (FFTW's
// estimated plan), odd and even lengths; and the wisdom compiled into the library is FFTW's.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <utility>

#include "contact/fft.h"

namespace tribo::contact {
namespace {

// The wisdom text CMake compiled in is one FFTW 3.3.10 reads (fftw_import_wisdom_from_string
// returned non-zero); an empty or mangled string is rejected.
TEST(ShippedFftwWisdom, IsImportedByThisFftw) { EXPECT_TRUE(shipped_fftw_wisdom_loaded()); }

// spectrum[j (nx/2 + 1) + k] = Σ f(i, l) exp(−2πi (k i/nx + j l/ny)) (fft.h), checked at every
// bin of a few columns by the direct sum; the round trip returns nx ny f. Tolerance 1e-12 of Σ|f|:
// the direct sums' and the FFT's round-off are both ~1e-15 of it on these sizes.
class RealFft2dSums : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(RealFft2dSums, ForwardIsTheDiscreteFourierSumAndInverseUndoesIt) {
  const auto [nx, ny] = GetParam();
  RealFft2d fft(nx, ny, 1);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::ArrayXXd f(nx, ny);
  for (Eigen::Index m = 0; m < f.size(); ++m) f(m) = uniform(rng);
  fft.real() = f;
  fft.forward();
  const double scale = f.abs().sum();
  const int nxh = nx / 2 + 1;
  for (const int k : {0, 1, nxh / 2, nxh - 1}) {
    for (int j = 0; j < ny; ++j) {
      std::complex<double> sum = 0.0;
      for (int l = 0; l < ny; ++l)
        for (int i = 0; i < nx; ++i)
          sum += f(i, l) * std::polar(1.0, -2.0 * std::numbers::pi * (static_cast<double>(k * i) / nx + static_cast<double>(j * l) / ny));
      EXPECT_LE(std::abs(fft.spectrum()[j * nxh + k] - sum), 1e-12 * scale) << "bin k = " << k << ", j = " << j;
    }
  }
  fft.inverse();
  EXPECT_LE((fft.real() - static_cast<double>(nx * ny) * f).abs().maxCoeff(), 1e-12 * nx * ny);
}

// 64² is in the shipped wisdom, 63 × 40 is not.
INSTANTIATE_TEST_SUITE_P(WisdomAndEstimate, RealFft2dSums, ::testing::Values(std::pair{64, 64}, std::pair{63, 40}));

}  // namespace
}  // namespace tribo::contact
