// The quick withheld-effect selftest (issues 6, 15 and 35), one test per case so that CTest spreads
// the eight full diagnoses over the cores beside the other tests. First generator (the rig's own
// simulator): every withheld effect named — the quick set's four are the ≥ 90 % of issue 6, with
// no miss allowed but a coin's (confidence under one half, the truth among the effects the report
// says the data do not tell apart) — with the gap shrinking by ≥ 50 % on the held-out blocks and on a test block at
// speeds neither the fits nor the verdict saw (gap/test_block.h); every control answers "none".
// Independent generator (gap/independent/: another integrator, a measuring chain with filter,
// drift, coloured noise and quantisation, rig constants a few per cent off): its control answers
// "none" and its Kato-ageing case is read as a static friction on the junction locus (with or
// without the hardening that implies it). These are the development
// set's cases (what the diagnosis was tuned on): the validation set's figures are in the README.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <string>

#include "gap/selftest.h"

namespace tribo::gap {

// How GoogleTest shows a case (CTest lists it beside the test's name): found by argument-dependent lookup, so in SelftestCase's namespace.
void PrintTo(const SelftestCase& c, std::ostream* os) { *os << c.generator << " generator, " << c.true_effect << ", seed " << c.seed; }

namespace {

class QuickSelftest : public ::testing::TestWithParam<SelftestCase> {};

TEST_P(QuickSelftest, NamesTheWithheldEffectOrNoneAndShrinksTheGap) {
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
  } else if (!row.correct && row.confidence < 0.5 &&
             std::count(row.indistinguishable_from.begin(), row.indistinguishable_from.end(), sc.true_effect)) {
    // Wrong only as a coin is: at a confidence under one half, with the report saying the held-out
    // data do not tell the verdict from the truth. The lift of seed 3 is such a case since the slow
    // runs are simulated for whole cycles (2026-11-27): a held-out gap of 0.0047, a fifth of the
    // noise floor, closed about equally by thermal thinning, lift, squeeze film and slip transient.
    std::printf("  %s, indistinguishable from %s at confidence %.2f\n", row.verdict.c_str(), sc.true_effect.c_str(), row.confidence);
    return;
  } else {
    EXPECT_TRUE(row.correct) << sc.true_effect << " read as " << row.verdict << " at confidence " << row.confidence;
  }
  if (sc.true_effect == "none" || sc.generator != kRigGenerator) return;
  // Half the gap closed where the effect is named (2026-11-26: held-out 68–99 %; test block slip
  // 99 %, viscous 96 %, lift 68 %, rate-dependent μs 99 %).
  EXPECT_GE(1.0 - row.heldout_gap_after / row.heldout_gap_before, 0.5);
  EXPECT_GE(1.0 - row.test_gap_after / row.test_gap_before, 0.5);
}

std::string case_name(const ::testing::TestParamInfo<SelftestCase>& info) {
  return info.param.generator + "_" + info.param.true_effect + "_seed" + std::to_string(info.param.seed);
}

INSTANTIATE_TEST_SUITE_P(Development, QuickSelftest, ::testing::ValuesIn(selftest_cases(true, 1)), case_name);

}  // namespace
}  // namespace tribo::gap
