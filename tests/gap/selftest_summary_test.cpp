// Selftest bookkeeping (issue 15), without diagnosing anything: per-generator confusion matrices
// and shrink, the reliability table's bins, and the case lists of both generators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gap/selftest.h"

namespace tribo::gap {
namespace {

SelftestRow row(const std::string& truth, const std::string& verdict, double confidence, const char* generator, double before = 0.1,
                double after = 0.02) {
  SelftestRow r;
  r.c.true_effect = truth;
  r.c.generator = generator;
  r.verdict = verdict;
  r.confidence = confidence;
  r.heldout_gap_before = before, r.heldout_gap_after = after;
  r.correct = verdict == truth;
  return r;
}

TEST(SelftestSummary, ConfusionShrinkAndFractionsPerRowSet) {
  const std::vector<SelftestRow> rows{row("slip_transient", "slip_transient", 0.95, kIndependentGenerator, 0.1, 0.04),
                                      row("viscous_friction", "none", 0.6, kIndependentGenerator),
                                      row("none", "none", 1.0, kIndependentGenerator), row("none", "squeeze_film", 0.9, kIndependentGenerator)};
  const SelftestSummary s = summarise(rows);
  EXPECT_EQ(s.effect_cases, 2);
  EXPECT_EQ(s.controls, 2);
  EXPECT_DOUBLE_EQ(s.identified_fraction, 0.5);
  EXPECT_DOUBLE_EQ(s.controls_none_fraction, 0.5);
  EXPECT_EQ(s.confusion.at("none").at("squeeze_film"), 1);
  EXPECT_EQ(s.confusion.at("viscous_friction").at("none"), 1);
  EXPECT_NEAR(s.mean_shrink.at("slip_transient"), 0.6, 1e-12);  // 1 − 0.04/0.1
  EXPECT_FALSE(s.mean_shrink.count("viscous_friction"));       // shrink only of right verdicts
}

// A power analysis beside the score: effects whose calibrated baseline misses the held-out data
// by at least two noise floors are "visible"; the share named among them is reported apart.
TEST(SelftestSummary, EffectsAreSplitByTheSignalTheirDataHold) {
  std::vector<SelftestRow> rows{row("slip_transient", "slip_transient", 0.9, kRigGenerator, 0.06, 0.01),  // 3 floors, named
                                row("squeeze_film", "none", 0.6, kRigGenerator, 0.03, 0.03),                // 1.5 floors, missed
                                row("viscous_friction", "instrument", 0.6, kRigGenerator, 0.04, 0.02),       // 2 floors exactly, missed
                                row("none", "none", 1.0, kRigGenerator, 0.02, 0.02),                        // a control: not counted
                                row("instrument", "instrument", 0.9, kRigGenerator, 0.5, 0.01)};            // no floor (old journal)
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) rows[i].noise_floor = 0.02;
  EXPECT_NEAR(rows[0].signal_floors(), 3.0, 1e-12);
  EXPECT_TRUE(std::isnan(rows[4].signal_floors()));
  const SelftestSummary s = summarise(rows);
  EXPECT_EQ(s.effect_cases, 4);
  EXPECT_DOUBLE_EQ(s.identified_fraction, 0.5);
  EXPECT_EQ(s.visible_effect_cases, 2);  // 3 and 2 floors; 1.5 floors and the unknown one are not
  EXPECT_DOUBLE_EQ(s.visible_identified_fraction, 0.5);
  rows.erase(rows.begin(), rows.begin() + 3);
  EXPECT_TRUE(std::isnan(summarise(rows).visible_identified_fraction));  // none visible: not a score of 0
}

// Beside the score, not in it: the truth among the verdict and the earning candidates the held-out
// data cannot tell from it (a hardening named rate-dependent static with hardening beside it), and
// how many names those verdicts give; controls are not counted.
TEST(SelftestSummary, TruthBesideTheVerdictIsCountedApartWithTheNamesGiven) {
  std::vector<SelftestRow> rows{row("strain_rate_hardening", "rate_dependent_static", 0.5, kIndependentGenerator),
                                row("thermal_thinning", "hydrodynamic_lift", 0.3, kIndependentGenerator),
                                row("squeeze_film", "strain_rate_hardening", 0.1, kIndependentGenerator),
                                row("slip_transient", "slip_transient", 0.9, kIndependentGenerator),
                                row("none", "none", 0.9, kIndependentGenerator)};
  rows[0].indistinguishable_from = {"strain_rate_hardening"};
  rows[1].indistinguishable_from = {"squeeze_film", "slip_transient", "thermal_thinning"};
  rows[2].indistinguishable_from = {"rate_dependent_static"};
  rows[4].indistinguishable_from = {"squeeze_film"};
  const SelftestSummary s = summarise(rows);
  EXPECT_DOUBLE_EQ(s.identified_fraction, 0.25);
  EXPECT_DOUBLE_EQ(s.named_or_indistinguishable_fraction, 0.75);  // all but the squeeze film
  EXPECT_DOUBLE_EQ(s.mean_names_per_verdict, (2.0 + 4.0 + 2.0 + 1.0) / 4.0);
  EXPECT_TRUE(std::isnan(summarise({rows[4]}).named_or_indistinguishable_fraction));  // controls only
}

// What the verdict adds to the model (Verdict::adds) is counted beside the score, not in it: the
// hardened locus on a model without the locus brings the locus (Kato's ageing, a static friction
// growing with the time at rest, named the hardened locus counts there), a pair both its effects.
TEST(SelftestSummary, TheTruthAmongWhatTheVerdictAddsIsCountedApart) {
  std::vector<SelftestRow> rows{row("rate_dependent_static", "strain_rate_hardening", 0.1, kIndependentGenerator),
                                row("squeeze_film", "thermal_thinning+squeeze_film", 0.2, kIndependentGenerator),
                                row("viscous_friction", "thermal_thinning", 0.3, kIndependentGenerator),
                                row("none", "none", 0.7, kIndependentGenerator)};
  rows[0].verdict_adds = {"rate_dependent_static", "strain_rate_hardening"};
  rows[1].verdict_adds = {"thermal_thinning", "squeeze_film"};
  rows[2].verdict_adds = {"thermal_thinning"};
  const SelftestSummary s = summarise(rows);
  EXPECT_DOUBLE_EQ(s.identified_fraction, 0.0);  // the score counts the verdict alone
  EXPECT_EQ(s.truth_among_adds, 2);               // the locus the hardening brings, the film in the pair
  EXPECT_FALSE(rows[3].truth_added());            // a control's empty change holds no truth
}

// A proposed test run on the truth counts when its proposed separation reached two floors (the
// conclusion names only those), and for the truth when the truth's model came nearer its record.
TEST(SelftestSummary, ProposedTestsCountWhenTheyDecideAndForTheTruthWhenItCameNearer) {
  std::vector<SelftestRow> rows{row("squeeze_film", "rate_dependent_static", 0.4, kIndependentGenerator),
                                row("thermal_thinning", "hydrodynamic_lift", 0.2, kIndependentGenerator)};
  // Journalled before the verdict after the record: it is empty.
  rows[0].proposal_checks = {{"squeeze_film", "stiffer_spring", 5.2, 0.106, 0.086, true, ""},
                             {"strain_rate_hardening", "wider_speeds", 1.7, 0.1, 0.2, false, ""}};
  rows[1].proposal_checks = {{"thermal_thinning", "stiffer_spring", 4.6, 0.02, 0.03, false, ""}};
  const SelftestSummary s = summarise(rows);
  EXPECT_EQ(s.deciding_proposals, 2);  // the 1.7-floor test is not named, so not counted
  EXPECT_EQ(s.deciding_proposals_for_truth, 1);
  EXPECT_EQ(s.named_after_proposed_tests, 0);  // journalled before the verdict after the record: the verdicts stand
}

// Named once the proposed tests are seen: a record that puts the wrong verdict right counts, one
// that overturns a right verdict takes it away, one that keeps it leaves it.
TEST(SelftestSummary, TheVerdictAfterAProposedTestsRecordReplacesTheVerdict) {
  std::vector<SelftestRow> rows{row("squeeze_film", "rate_dependent_static", 0.4, kIndependentGenerator),
                                row("thermal_thinning", "thermal_thinning", 0.6, kIndependentGenerator),
                                row("instrument", "instrument", 0.9, kIndependentGenerator),
                                row("none", "none", 0.7, kIndependentGenerator)};
  rows[0].proposal_checks = {{"squeeze_film", "heavier_load", 6.8, 0.3, 0.06, true, "squeeze_film"}};
  rows[1].proposal_checks = {{"hydrodynamic_lift", "wider_speeds", 3.0, 0.05, 0.02, false, "hydrodynamic_lift"}};
  rows[2].proposal_checks = {{"squeeze_film", "stiffer_spring", 2.5, 0.01, 0.05, true, "instrument"}};
  const SelftestSummary s = summarise(rows);
  EXPECT_DOUBLE_EQ(s.identified_fraction, 2.0 / 3.0);
  EXPECT_EQ(s.named_after_proposed_tests, 2);  // the film put right, the thinning overturned, the load cell kept
}

// A verdict whose candidate did not earn is tentative (verdict.h Decision::tentative); the summary
// counts such verdicts and the right ones among them, controls included; none is never tentative.
TEST(SelftestSummary, TentativeVerdictsAreCountedFromTheVerdictsCandidate) {
  std::vector<SelftestRow> rows{row("rate_dependent_static", "rate_dependent_static", 0.04, kIndependentGenerator),
                                row("squeeze_film", "rate_dependent_static", 0.1, kIndependentGenerator),
                                row("slip_transient", "slip_transient", 0.9, kIndependentGenerator),
                                row("none", "none", 0.7, kIndependentGenerator)};
  rows[0].candidates = {{"squeeze_film", 1.9, 16.3, 0.042, false}, {"rate_dependent_static", -24.4, 15.0, 0.089, false}};
  rows[1].candidates = {{"rate_dependent_static", -3.0, 5.0, 0.02, false}};
  rows[2].candidates = {{"slip_transient", 60.0, 6.0, 0.005, true}};
  rows[3].candidates = {{"squeeze_film", 1.0, 2.0, 0.01, false}};
  EXPECT_TRUE(rows[0].tentative());
  EXPECT_FALSE(rows[2].tentative());
  EXPECT_FALSE(rows[3].tentative());
  const SelftestSummary s = summarise(rows);
  EXPECT_EQ(s.tentative_verdicts, 2);
  EXPECT_EQ(s.tentative_right, 1);
}

// The detection table bins effects by their signal in noise floors; the named-or-listed count takes
// the truth named beside the verdict (either list), and controls and rows without a floor stay out.
TEST(SelftestSummary, DetectionTableCountsByTheEffectsSignal) {
  std::vector<SelftestRow> rows{row("slip_transient", "slip_transient", 0.9, kRigGenerator, 0.012, 0.01),   // 0.6 floors, named
                                row("squeeze_film", "rate_dependent_static", 0.4, kRigGenerator, 0.05, 0.02),  // 2.5, listed alike
                                row("rate_dependent_static", "strain_rate_hardening", 0.3, kRigGenerator, 0.06, 0.02),  // 3.0, listed
                                row("thermal_thinning", "hydrodynamic_lift", 0.2, kRigGenerator, 0.099, 0.02),  // 4.95, missed
                                row("instrument", "instrument", 1.0, kRigGenerator, 2.0, 0.02),               // 100 floors, named
                                row("none", "none", 1.0, kRigGenerator, 0.02, 0.02),                          // a control
                                row("viscous_friction", "none", 0.5, kRigGenerator, 0.5, 0.5)};               // no floor
  for (std::size_t i = 0; i + 1 < rows.size(); ++i) rows[i].noise_floor = 0.02;
  rows[1].alike_mechanisms = {"squeeze_film"};
  rows[2].indistinguishable_from = {"rate_dependent_static"};
  rows[3].alike_mechanisms = {"slip_transient"};
  EXPECT_TRUE(rows[1].truth_named_or_listed());
  EXPECT_FALSE(rows[3].truth_named_or_listed());
  const std::vector<DetectionBin> bins = detection_table(rows);
  ASSERT_EQ(bins.size(), 6u);
  const std::vector<int> cases{1, 0, 1, 2, 0, 1}, named{1, 0, 0, 0, 0, 1}, listed{1, 0, 1, 1, 0, 1};
  for (std::size_t b = 0; b < bins.size(); ++b) {
    EXPECT_EQ(bins[b].effect_cases, cases[b]) << "bin " << b;
    EXPECT_EQ(bins[b].named, named[b]) << "bin " << b;
    EXPECT_EQ(bins[b].named_or_listed, listed[b]) << "bin " << b;
  }
  EXPECT_DOUBLE_EQ(bins[2].lower_floors, 2.0);
  EXPECT_TRUE(std::isinf(bins.back().upper_floors));
}

TEST(SelftestSummary, ReliabilityBinsCoverZeroToOneInclusive) {
  const std::vector<SelftestRow> rows{row("a", "a", 0.0, kRigGenerator), row("a", "b", 0.5, kRigGenerator), row("a", "a", 0.89, kRigGenerator),
                                      row("a", "a", 0.9, kRigGenerator), row("a", "b", 1.0, kIndependentGenerator)};
  const std::vector<ReliabilityBin> bins = reliability_table(rows);
  ASSERT_EQ(bins.size(), 4u);
  EXPECT_EQ(bins[0].verdicts, 1);
  EXPECT_EQ(bins[1].verdicts, 1);
  EXPECT_EQ(bins[1].right, 0);
  EXPECT_EQ(bins[2].verdicts, 1);
  EXPECT_EQ(bins[3].verdicts, 2);  // 0.9 and 1.0
  EXPECT_EQ(bins[3].right, 1);
}

TEST(SelftestSummary, QuickSetHoldsIndependentEffectAndControl) {
  const std::vector<SelftestCase> quick = selftest_cases(true, 1);
  auto count = [&](const std::vector<SelftestCase>& cs, const char* g, bool control) {
    return std::count_if(cs.begin(), cs.end(), [&](const SelftestCase& c) { return c.generator == g && (c.true_effect == "none") == control; });
  };
  EXPECT_GE(count(quick, kIndependentGenerator, true), 1);
  EXPECT_GE(count(quick, kIndependentGenerator, false), 1);
  EXPECT_GE(count(quick, kRigGenerator, true), 2);
  // The quick set's independent cases are cases of the full set (same seeds), so their journals agree.
  const std::vector<SelftestCase> full = selftest_cases(false, 1);
  for (const SelftestCase& c : quick) {
    if (c.generator != kIndependentGenerator) continue;
    EXPECT_TRUE(std::any_of(full.begin(), full.end(), [&](const SelftestCase& f) { return same_case(f, c); })) << c.true_effect;
  }
  SelftestCase other = quick.front();
  other.generator = kIndependentGenerator;
  EXPECT_FALSE(same_case(other, quick.front()));
}

}  // namespace
}  // namespace tribo::gap
