// What the diagnosis reads off one trace (gap/trace_features.h), on records whose features are
// known in closed form.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "gap/trace_features.h"

namespace tribo::gap::trace {
namespace {

// A sawtooth of stick-slip: μ rises linearly from 0.2 to 0.3 over 0.8 s (stick) and falls back
// over 0.2 s (slip), period 1 s, sampled at 1 kHz for 20 s.
Signal sawtooth() {
  Signal s;
  for (int i = 0; i <= 20000; ++i) {
    const double t = 1e-3 * i, phase = t - std::floor(t);
    s.t.push_back(t);
    s.mu.push_back(phase < 0.8 ? 0.2 + 0.1 * phase / 0.8 : 0.3 - 0.1 * (phase - 0.8) / 0.2);
  }
  return s;
}

// The extrema are read on μ smoothed over ±2 sample spacings, which rounds the sawtooth's corners:
// at the peak by at most (0.125 + 0.5)/s × 2 ms / 2 ≈ 6e-4, at the trough likewise. The period and
// the rise are read between extrema located to the grid's spacing.
TEST(TraceFeatures, AStickSlipSawtoothReadsItsPeriodRiseAndExtrema) {
  const Signal s = sawtooth();
  double slip_step_s = 0.0;
  std::string regime;
  const Features f = analyse_constant_speed(s, 1e-3, slip_step_s, &regime);
  EXPECT_EQ(regime, "stick_slip");
  EXPECT_NEAR(f.at("period_s"), 1.0, 1e-3);
  EXPECT_NEAR(f.at("rise_time_s"), 0.8, 5e-3);
  EXPECT_NEAR(f.at("mu_peak"), 0.3, 1e-3);
  EXPECT_NEAR(f.at("mu_trough"), 0.2, 1e-3);
  // Over whole cycles the mean of a sawtooth is the mid-level.
  EXPECT_NEAR(f.at("mean_mu"), 0.25, 1e-3);
  // Δ of the slip drops: the fall's duration over kSlipDropPoints + 1.
  EXPECT_NEAR(slip_step_s, 0.2 / (kSlipDropPoints + 1), 2e-3);
}

// Friction that wanders by less than 5 % of its mean is steady sliding: no extrema are read.
TEST(TraceFeatures, AQuietRecordIsSteadySlidingWithItsMean) {
  Signal s;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (int i = 0; i <= 5000; ++i) {
    s.t.push_back(1e-3 * i);
    s.mu.push_back(0.25 + noise(rng));
  }
  double slip_step_s = 0.0;
  std::string regime;
  const Features f = analyse_constant_speed(s, 1e-3, slip_step_s, &regime);
  EXPECT_EQ(regime, "steady_sliding");
  EXPECT_EQ(f.count("mu_peak"), 0u);
  // The mean of ~2 500 samples of σ = 1e-3 (smoothed): within 1e-4 (five standard errors).
  EXPECT_NEAR(f.at("mean_mu"), 0.25, 1e-4);
}

// For white noise of standard deviation σ the median absolute second difference is 0.6745 √6 σ; a
// signal smooth at the sampling rate adds nothing measurable (a 1-Hz sine of amplitude 0.05 at
// 1 kHz: second differences of at most 2e-6).
TEST(TraceFeatures, HighPassNoiseIsTheWhiteNoiseUnderASmoothSignal) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> noise(0.0, 2e-3);
  std::vector<double> smooth, noisy;
  for (int i = 0; i < 20000; ++i) {
    const double y = 0.3 + 0.05 * std::sin(2.0 * std::numbers::pi * 1e-3 * i);
    smooth.push_back(y);
    noisy.push_back(y + noise(rng));
  }
  EXPECT_LT(high_pass_noise(smooth), 2e-6);
  // A median's scale estimate on 20 000 samples: 3 % (as tests/gap/noise_floor_test.cpp).
  EXPECT_NEAR(high_pass_noise(noisy), 2e-3, 0.03 * 2e-3);
}

// A slide-hold-slide-and-step drive record at 10 Hz with sensor noise and a three-sample glitch:
// the segments start where the drive changes, the glitch joins the segment it sits in, the hold
// reads exactly 0 and each slide its speed to the noise's standard error.
TEST(TraceFeatures, DriveSegmentsAreTheStepsAndTheHoldOfANoisyDriveRecord) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 1e-8);
  std::vector<double> t, v;
  for (int i = 0; i < 400; ++i) {
    const double ti = 0.1 * i;
    const double vi = ti < 10.0 ? 1e-5 : ti < 20.0 ? 0.0 : ti < 30.0 ? 1e-5 : 3e-5;
    const bool glitch = i >= 50 && i < 53;
    t.push_back(ti);
    v.push_back((glitch ? 2e-5 : vi) + noise(rng));
  }
  const DriveSegments d = drive_segments(t, v);
  ASSERT_EQ(d.start_s.size(), 4u);
  const double starts[] = {0.0, 10.0, 20.0, 30.0}, speeds[] = {1e-5, 0.0, 1e-5, 3e-5};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(d.start_s[k], starts[k], 1e-9) << k;
    EXPECT_NEAR(d.speed_m_per_s[k], speeds[k], 5e-9) << k;
  }
  EXPECT_EQ(d.speed_m_per_s[1], 0.0);
}

}  // namespace
}  // namespace tribo::gap::trace
