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
