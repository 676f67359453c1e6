// The quick withheld-effect selftest (issue 6): at least 90 % of withheld effects identified,
// every control answers "none", and the held-out gap of each identified effect shrinks by ≥ 50 %.
#include <gtest/gtest.h>

#include "gap/selftest.h"

namespace tribo::gap {
namespace {

TEST(Selftest, QuickSetIdentifiesWithheldEffectsAndControlsAnswerNone) {
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 100;
  const SelftestResult r = run_selftest(selftest_cases(true, 1), SyntheticOptions{}, o, nullptr);
  for (const auto& row : r.rows) std::printf("%-24s -> %-24s %.4f -> %.4f\n", row.c.true_effect.c_str(), row.verdict.c_str(), row.heldout_gap_before, row.heldout_gap_after);
  EXPECT_GE(r.identified_fraction, 0.9);
  EXPECT_EQ(r.controls_none_fraction, 1.0);
  for (const auto& [effect, shrink] : r.mean_shrink) EXPECT_GE(shrink, 0.5) << effect;
}

}  // namespace
}  // namespace tribo::gap
