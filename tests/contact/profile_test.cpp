// A measured profile's levelling and Gaussian filter (contact/profile.h) against ISO 16610-21's
// transmission and against a measured trace.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "contact/profile.h"

namespace tribo::contact {
namespace {

Eigen::ArrayXd sinusoid(Eigen::Index n, double spacing_m, double wavelength_m, double amplitude_m) {
  const Eigen::ArrayXd x = Eigen::ArrayXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) * spacing_m);
  return amplitude_m * (2.0 * std::numbers::pi * x / wavelength_m).cos();
}

// ISO 16610-21: a sinusoid's amplitude passes as exp(−π (α λc / λ)²) — 1/2 at the cut-off. Sampled
// at 100 points a cut-off the filter's discrete sum differs from the integral by far less than
// 1e-6 (the Gaussian's spectrum is then down by e^{-π·2500·α²}); the truncation at ±λc costs
// 6.5e-7 of the window. Tolerance 1e-5 of the amplitude, on a sinusoid whose amplitude is read off
// the middle of the filtered profile at a crest.
TEST(GaussianProfileFilter, SinusoidPassesWithIsoTransmission) {
  const double spacing = 1e-7, cutoff = 1e-5;
  EXPECT_NEAR(gaussian_filter_transmission(cutoff, cutoff), 0.5, 1e-15);
  for (const double wavelength : {0.5 * cutoff, cutoff, 2.0 * cutoff, 8.0 * cutoff}) {
    const Eigen::Index per = static_cast<Eigen::Index>(std::lround(wavelength / spacing));
    const Eigen::ArrayXd z = sinusoid(40 * per + 1, spacing, wavelength, 1.0);
    const FilteredProfile f = gaussian_profile_filter(z, spacing, cutoff);
    ASSERT_EQ(f.first, 100);
    ASSERT_EQ(f.height_m.size(), z.size() - 200);
    const Eigen::Index crest = 20 * per - f.first;  // input sample 20 wavelengths in: a crest
    EXPECT_NEAR(f.height_m(crest), gaussian_filter_transmission(wavelength, cutoff), 1e-5) << "lambda/lambda_c " << wavelength / cutoff;
  }
}

// A constant and a straight line are the filter's fixed points (the weights are symmetric and sum
// to one), and levelling takes out a line added to any profile: rounding only.
TEST(GaussianProfileFilter, LinesPassUnchangedAndLevellingRemovesThem) {
  const Eigen::Index n = 501;
  const Eigen::ArrayXd line = 3e-6 + 2e-4 * Eigen::ArrayXd::LinSpaced(n, 0.0, 1e-3);
  const FilteredProfile f = gaussian_profile_filter(line, 2e-6, 5e-5);
  EXPECT_LT((f.height_m - line.segment(f.first, f.height_m.size())).abs().maxCoeff(), 1e-18);
  EXPECT_LT(level_profile(line).abs().maxCoeff(), 1e-18);
  const Eigen::ArrayXd wave = sinusoid(n, 2e-6, 1e-4, 1e-8);
  EXPECT_LT((level_profile(wave + line) - level_profile(wave)).abs().maxCoeff(), 1e-20);
}

// ISO 16610-61's areal Gaussian filter is the profile filter along x times along y: the surface
// cos(2πx/λx) cos(2πy/λy) passes with T(λx) T(λy), T the profile transmission (λx = λc, λy = 2 λc:
// 0.5 × 0.8409), read at a crest in the middle of the map to 1e-5 (as the profile's, above), on a
// 20 × 30-sample cut-off grid with unequal spacings; the valid region starts a window's half width
// in along each direction.
TEST(GaussianArealFilter, WavySurfacePassesWithTheProductOfTheProfileTransmissions) {
  const double dx = 5e-7, dy = 1e-6 / 3.0, cutoff = 1e-5, lx = cutoff, ly = 2.0 * cutoff;
  const Eigen::Index nx = 241, ny = 361;
  Eigen::ArrayXXd z(nx, ny);
  for (Eigen::Index j = 0; j < ny; ++j)
    for (Eigen::Index i = 0; i < nx; ++i)
      z(i, j) = std::cos(2.0 * std::numbers::pi * static_cast<double>(i) * dx / lx) * std::cos(2.0 * std::numbers::pi * static_cast<double>(j) * dy / ly);
  const FilteredMap f = gaussian_areal_filter(z, dx, dy, cutoff);
  ASSERT_EQ(f.first_x, 20);
  ASSERT_EQ(f.first_y, 30);
  ASSERT_EQ(f.height_m.rows(), nx - 40);
  ASSERT_EQ(f.height_m.cols(), ny - 60);
  const Eigen::Index ci = 120 - f.first_x, cj = 180 - f.first_y;  // x = 6 λx, y = 3 λy: a crest
  EXPECT_NEAR(f.height_m(ci, cj), gaussian_filter_transmission(lx, cutoff) * gaussian_filter_transmission(ly, cutoff), 1e-5);
}

// Levelling a map takes out a plane added to it (rounding only) and leaves a zero-mean surface.
TEST(GaussianArealFilter, LevellingRemovesAPlane) {
  Eigen::ArrayXXd wave(40, 30), plane(40, 30);
  for (Eigen::Index j = 0; j < 30; ++j)
    for (Eigen::Index i = 0; i < 40; ++i) {
      wave(i, j) = 1e-8 * std::sin(0.3 * static_cast<double>(i)) * std::cos(0.2 * static_cast<double>(j));
      plane(i, j) = 2e-6 + 3e-8 * static_cast<double>(i) - 5e-8 * static_cast<double>(j);
    }
  EXPECT_LT(level_map(plane).abs().maxCoeff(), 1e-19);
  EXPECT_LT((level_map(wave + plane) - level_map(wave)).abs().maxCoeff(), 1e-20);
  EXPECT_LT(std::abs(level_map(wave).mean()), 1e-22);
  EXPECT_THROW(level_map(Eigen::ArrayXXd::Zero(1, 5)), std::invalid_argument);
}

TEST(GaussianProfileFilter, BadArgumentsNameTheReason) {
  const Eigen::ArrayXd z = Eigen::ArrayXd::Zero(100);
  auto expect_error = [&](double spacing, double cutoff, const std::string& word) {
    try {
      gaussian_profile_filter(z, spacing, cutoff);
      ADD_FAILURE() << "accepted " << word;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
    }
  };
  expect_error(0.0, 1e-5, "spacing");
  expect_error(1e-7, -1.0, "cut-off");
  expect_error(1e-7, 1e-5, "shorter than the filter's window");  // needs 201 samples
  EXPECT_THROW(level_profile(Eigen::ArrayXd::Zero(1)), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::contact
