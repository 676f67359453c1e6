// The calibration stage's start read off the data (gap/calibration.h): which measured levels make
// μs and μk, in which order of preference, and the clamps.
#include <gtest/gtest.h>

#include <cmath>

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

// The ageing law's healing Δμ_peak = b ln(1 + t_h V/D_c) (Marone 1998) written exactly for holds
// of 1 … 100 s at V = 8.6 µm/s, b = 0.014, D_c = 5 µm: the read-off finds them to its grid (20
// per decade: D_c within 10^(1/40) = 6 %, and b, fitted at that D_c, within 2 %); a held-out peak
// does not enter; fewer than two peaks, or peaks that fall with the hold, give NaN.
TEST(Calibration, HealingIsReadOffTheReSlidePeaksOfASlideHoldSlideTest) {
  const double b = 0.014, dc = 5e-6, v = 8.6e-6;
  std::vector<Item> items{level("steady_mu", 0.63)};
  for (double t : {1.0, 3.0, 10.0, 30.0, 100.0}) {
    Item p = level("peak_after_hold", b * std::log1p(t * v / dc));
    p.hold_s = t, p.v_m_per_s = v;
    items.push_back(p);
  }
  std::vector<bool> use(items.size(), true);
  Healing h = healing_from_data(items, use);
  EXPECT_NEAR(h.b, b, 0.02 * b);
  EXPECT_NEAR(std::log10(h.decay_distance_m), std::log10(dc), 0.5 / 20);
  items[5].measured = 1.0;  // a wild peak, held out: not read
  use[5] = false;
  h = healing_from_data(items, use);
  EXPECT_NEAR(h.b, b, 0.02 * b);
  use.assign(items.size(), false);
  use[1] = true;  // one peak: nothing to read
  EXPECT_TRUE(std::isnan(healing_from_data(items, use).b));
  for (Item& it : items) it.measured = it.observable == "peak_after_hold" ? 0.05 - 0.01 * std::log(it.hold_s + 1.0) : it.measured;
  use.assign(items.size(), true);
  EXPECT_TRUE(std::isnan(healing_from_data(items, use).decay_distance_m));  // no growth with the hold
}

}  // namespace
}  // namespace tribo::gap
