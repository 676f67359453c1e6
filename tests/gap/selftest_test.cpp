// The quick withheld-effect selftest (issues 6, 15 and 35) in CI: one test per case, so that CTest
// spreads the full diagnoses over the cores beside the other tests. Each case is a whole diagnosis
// with every default candidate (2–3 min on 2 cores), so CI runs the two of the quick set's cases
// that no dedicated test covers: the first generator's (the rig's own simulator) slip transient —
// named, the gap shrinking by ≥ 50 % on the held-out blocks and on a test block at speeds neither
// the fits nor the verdict saw (gap/test_block.h) — and the independent generator's (gap/independent/:
// another integrator, a measuring chain with filter, drift, coloured noise and quantisation, rig
// constants a few per cent off) Kato-ageing case, read as a static friction on the junction locus
// (with or without the hardening that implies it). Left to other tests: viscous friction
// (Diagnosis.TracesOnlyNameViscousFrictionDeterministically, ViscousPipeline.*), the rate-dependent
// static friction and its hardening (RateHardening.*), the controls (ForeignControl: a control from
// a simulator written outside the project, with every default — harder than either generator's;
// Diagnosis.StaticPointsOnlyCalibrateMuSAndAnswerNone), and the lift, whose quick case holds a fifth
// of a noise floor — a coin, not a check. The whole quick set is `tribo gap selftest --quick`.
// These are the development set's cases (what the diagnosis was tuned on): the validation set's
// figures are in the README.
#include <gtest/gtest.h>

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

#include "gap/selftest.h"

namespace tribo::gap {

// How GoogleTest shows a case (CTest lists it beside the test's name): found by argument-dependent lookup, so in SelftestCase's namespace.
void PrintTo(const SelftestCase& c, std::ostream* os) { *os << c.generator << " generator, " << c.true_effect << ", seed " << c.seed; }

namespace {

class QuickSelftest : public ::testing::TestWithParam<SelftestCase> {};

TEST_P(QuickSelftest, NamesTheWithheldEffectAndShrinksTheGap) {
  const SelftestCase& sc = GetParam();
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 100;
  const SelftestResult r = run_selftest({sc}, SyntheticOptions{}, o, nullptr);
  ASSERT_EQ(r.rows.size(), 1u);
  const SelftestRow& row = r.rows.front();
  std::printf("%-12s %-24s -> %-24s %.4f -> %.4f  confidence %.2f  test block %.4f -> %.4f  %.0f s\n", row.c.generator.c_str(),
              row.c.true_effect.c_str(), row.verdict.c_str(), row.heldout_gap_before, row.heldout_gap_after, row.confidence,
              row.test_gap_before, row.test_gap_after, row.wall_s);
  if (sc.generator != kRigGenerator && sc.true_effect == "rate_dependent_static") {
    // Kato's stick-time ageing is neither catalogue form: it is read right as a static friction
    // that grows with the stick time, the junction locus — alone, or with the hardening that
    // implies it when the held-out data decide for its extra parameter (since the fits weigh by
    // the likelihood, 2026-11-27: 51 ± 4 against 43 ± 5 nats on seed 301; the selftest itself
    // still counts only the locus as right).
    EXPECT_TRUE(row.verdict == "rate_dependent_static" || row.verdict == "strain_rate_hardening") << "read as " << row.verdict;
  } else {
    EXPECT_TRUE(row.correct) << sc.true_effect << " read as " << row.verdict << " at confidence " << row.confidence;
  }
  if (sc.generator != kRigGenerator) return;
  // Half the gap closed where the effect is named (2026-11-26: held-out 68–99 % over the quick set;
  // test block of the slip transient 99 %).
  EXPECT_GE(1.0 - row.heldout_gap_after / row.heldout_gap_before, 0.5);
  EXPECT_GE(1.0 - row.test_gap_after / row.test_gap_before, 0.5);
}

std::string case_name(const ::testing::TestParamInfo<SelftestCase>& info) {
  return info.param.generator + "_" + info.param.true_effect + "_seed" + std::to_string(info.param.seed);
}

// The quick set's cases that no dedicated test covers (the header says which cover the others).
std::vector<SelftestCase> cases_no_other_test_covers() {
  std::vector<SelftestCase> kept;
  for (const SelftestCase& c : selftest_cases(true, 1))
    if (c.generator == kRigGenerator ? c.true_effect == "slip_transient" : c.true_effect != "none") kept.push_back(c);
  return kept;
}

INSTANTIATE_TEST_SUITE_P(Development, QuickSelftest, ::testing::ValuesIn(cases_no_other_test_covers()), case_name);

}  // namespace
}  // namespace tribo::gap
