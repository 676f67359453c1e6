// The data acquisition's anti-alias filter (gap/recorder.h, experiment.toml [recorder]): the
// filter against the Butterworth low-pass it realises, and the bundle keys. What reading a
// simulation through it does to a calibration is recorder_calibration_test.cpp's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/recorder.h"

namespace tribo::gap {
namespace {

namespace fs = std::filesystem;

// The recorder of the independent generator: 4th order at 200 Hz, read at a 0.25-ms step (a
// quarter of its 1-kHz record, compare.cpp's kRecorderSubsteps).
const AntiAliasFilter kFourthOrder{4, 200.0};
constexpr double kStep_s = 2.5e-4;

// |H(f)|² = 1 / (1 + (f/f_c)^{2N}) of the analog Butterworth (Butterworth 1930), realised by the
// bilinear transform with f_c pre-warped: 1 / (1 + (tan(π f h) / tan(π f_c h))^{2N}) — exact at
// f_c (−3 dB) and at DC. At 2 f_c that is 0.0565 against the analog 0.0624 (the warped frequency
// axis, raised to the 8th power); asserted to 1e-4 relative (single-precision coefficients).
TEST(AntiAliasFilter, MagnitudeIsThePrewarpedBilinearButterworths) {
  const auto bilinear = [](double f) {
    const double ratio = std::tan(M_PI * f * kStep_s) / std::tan(M_PI * 200.0 * kStep_s);
    return 1.0 / std::sqrt(1.0 + std::pow(ratio, 8));
  };
  EXPECT_NEAR(gain_at(kFourthOrder, 200.0, kStep_s), 1.0 / std::sqrt(2.0), 1e-4);
  for (double f : {50.0, 100.0, 400.0, 800.0}) EXPECT_NEAR(gain_at(kFourthOrder, f, kStep_s) / bilinear(f), 1.0, 1e-4) << f << " Hz";
  EXPECT_NEAR(gain_at(kFourthOrder, 0.0, kStep_s), 1.0, 1e-12);  // DC gain exactly 1
}

// A sinusoid at 150 Hz settles to the amplitude gain_at() gives: low_pass() runs the sections
// gain_at() evaluates. Read over the last ten periods, 1e-3 of the amplitude (the sampled peak
// lies within 1 − cos(π · 150 · h) = 0.3 % of the true one, which the max over ten periods mostly finds).
TEST(AntiAliasFilter, SteadySinusoidHasTheDesignedAmplitude) {
  const double f = 150.0;
  std::vector<double> u;
  for (int i = 0; i < 4000; ++i) u.push_back(std::sin(2.0 * M_PI * f * i * kStep_s));
  const std::vector<double> y = low_pass(kFourthOrder, u, kStep_s);
  double peak = 0.0;
  for (std::size_t i = y.size() - static_cast<std::size_t>(10.0 / (f * kStep_s)); i < y.size(); ++i) peak = std::max(peak, std::abs(y[i]));
  EXPECT_NEAR(peak, gain_at(kFourthOrder, f, kStep_s), 3e-3);
}

// Started from the steady state of the first value: a constant passes unchanged; a unit step
// overshoots by about the analog 4th-order Butterworth's 10.8 % (Zverev, Handbook of Filter
// Synthesis, 1967) — 11.1 % realised at f_c h = 0.05, whose warped axis sharpens the knee; asserted
// within 0.5 points of the analog value.
TEST(AntiAliasFilter, ConstantPassesAndAStepOvershootsByButterworthsTenPointEightPercent) {
  const std::vector<double> constant(500, 0.37);
  for (double y : low_pass(kFourthOrder, constant, kStep_s)) ASSERT_DOUBLE_EQ(y, 0.37);
  std::vector<double> step(4000, 1.0);
  step[0] = 0.0;
  const std::vector<double> y = low_pass(kFourthOrder, step, kStep_s);
  EXPECT_NEAR(*std::max_element(y.begin(), y.end()) - 1.0, 0.108, 0.005);
  EXPECT_NEAR(y.back(), 1.0, 1e-9);
}

TEST(AntiAliasFilter, CutOffAtOrAboveTheStepsNyquistFrequencyIsRejected) {
  EXPECT_THROW(low_pass({4, 2000.0}, {0.0, 1.0}, kStep_s), std::invalid_argument);
  EXPECT_THROW(gain_at({4, 5000.0}, 10.0, kStep_s), std::invalid_argument);
}

// [recorder] in experiment.toml: both keys, in range, pin_on_disc only; a bad one names the file,
// the line and the key.
void write_toml(const fs::path& dir, const std::string& text) {
  fs::remove_all(dir);
  fs::create_directories(dir / "traces");
  std::ofstream(dir / "experiment.toml") << text;
  std::ofstream(dir / "static_friction.csv") << "phi_dot_per_s,mu_s\n1.0,0.3\n";
}

std::string read_error(const fs::path& dir) {
  try {
    read_bundle(dir);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(RecorderKeys, AreReadAndEveryBadOneIsNamedWithItsLine) {
  const fs::path dir = fs::temp_directory_path() / "tribo_gap_recorder_keys";
  write_toml(dir, "[rig]\nkind = \"pin_on_disc\"\n\n[recorder]\nanti_alias_order = 4\nanti_alias_cutoff_Hz = 200.0\n");
  const ExperimentBundle b = read_bundle(dir);
  EXPECT_EQ(b.anti_alias.order, 4);
  EXPECT_DOUBLE_EQ(b.anti_alias.cutoff_Hz, 200.0);

  write_toml(dir, "[recorder]\nanti_alias_order = 4\n");
  EXPECT_NE(read_error(dir).find("experiment.toml:1: [recorder] needs both anti_alias_order and anti_alias_cutoff_Hz"), std::string::npos)
      << read_error(dir);
  write_toml(dir, "[recorder]\nanti_alias_order = 2.5\nanti_alias_cutoff_Hz = 200.0\n");
  EXPECT_NE(read_error(dir).find(":2: [recorder] anti_alias_order must be an integer from 1 to 8"), std::string::npos) << read_error(dir);
  write_toml(dir, "[recorder]\nanti_alias_order = 4\nanti_alias_cutoff_Hz = -1\n");
  EXPECT_NE(read_error(dir).find(":3: [recorder] anti_alias_cutoff_Hz must be a positive number"), std::string::npos) << read_error(dir);
  write_toml(dir, "[rig]\nkind = \"velocity_step\"\n[recorder]\nanti_alias_order = 4\nanti_alias_cutoff_Hz = 200.0\n");
  EXPECT_NE(read_error(dir).find(":3: [recorder] is read for kind = \"pin_on_disc\" only"), std::string::npos) << read_error(dir);
  write_toml(dir, "[recorder]\nanti_alias_order = 4\nanti_alias_cutoff_Hz = 200.0\nrate_Hz = 1000\n");
  EXPECT_NE(read_error(dir).find(":4: unknown key [recorder] rate_Hz"), std::string::npos) << read_error(dir);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace tribo::gap
