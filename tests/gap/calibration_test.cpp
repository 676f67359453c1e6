// The calibration stage's start read off the data (gap/calibration.h): which measured levels make
// μs and μk, in which order of preference, and the clamps.
#include <gtest/gtest.h>

#include "gap/calibration.h"

namespace tribo::gap {
namespace {

Item level(const std::string& observable, double measured) {
  Item it;
  it.observable = observable;
  it.measured = measured;
  return it;
}

const FrictionLevels kFallback{0.3, 0.2};

TEST(Calibration, StickSlipGivesMuSAtThePeaksAndMuKMidwayToTheTroughs) {
  // Coulomb stick-slip: the force swings symmetrically about μk W between μs W and 2μk − μs.
  const FrictionLevels l = friction_levels_from_data(
      {level("mu_peak", 0.48), level("mu_peak", 0.52), level("mu_trough", 0.30), level("steady_mu", 0.9)}, kFallback);
  EXPECT_DOUBLE_EQ(l.mu_s, 0.5);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.4);  // the peaks and troughs win over a steady level
}

TEST(Calibration, SteadySlidingAndStaticPointsFillInWhatStickSlipDoesNotGive) {
  FrictionLevels l = friction_levels_from_data({level("mu_s_vs_load_rate", 0.6), level("steady_mu", 0.4)}, kFallback);
  EXPECT_DOUBLE_EQ(l.mu_s, 0.6);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.4);
  l = friction_levels_from_data({level("steady_mu", 0.25)}, kFallback);  // no static level: μs = μk
  EXPECT_DOUBLE_EQ(l.mu_s, 0.25);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.25);
  l = friction_levels_from_data({level("mean_mu", 0.35), level("period_s", 2.0)}, kFallback);
  EXPECT_DOUBLE_EQ(l.mu_s, 0.35);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.35);
  l = friction_levels_from_data({level("period_s", 2.0)}, kFallback);  // no friction level at all
  EXPECT_DOUBLE_EQ(l.mu_s, 0.3);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.2);
}

TEST(Calibration, LevelsAreClampedInsideTheBaselineFitsBounds) {
  FrictionLevels l = friction_levels_from_data({level("mu_peak", 2.0), level("mu_trough", -3.0)}, kFallback);
  EXPECT_DOUBLE_EQ(l.mu_s, 1.49);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.05 * 1.49);  // midway is −0.5: μk ≥ 0.05 μs
  l = friction_levels_from_data({level("mu_s_vs_load_rate", 0.2), level("steady_mu", 0.5)}, kFallback);
  EXPECT_DOUBLE_EQ(l.mu_k, 0.2);  // μk ≤ μs
}

}  // namespace
}  // namespace tribo::gap
