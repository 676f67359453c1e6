// The shrink on a separate test block (gap/test_block.h, issue 15): the fitted models predict runs
// at driven speeds the diagnosis never saw, and the gap is measured there.
//   - exactness: a model that is the truth leaves no gap on noiseless test runs, and the same
//     model without the effect leaves the effect's whole signature;
//   - the floor: on test runs with 1 % sensor noise the truth leaves a gap under the noise floor
//     the test items' own standard errors give, and not far under it;
//   - a changed rig: a test on a stiffer spring is predicted on the calibrated rig scaled as the
//     told one is;
//   - no inverse crime: a diagnosis of the independent generator's Kato-ageing case (another
//     integrator, another form of rate-dependent static friction, a measuring chain) still
//     halves the gap on that generator's runs at four speeds between the diagnosed five.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gap/discriminate.h"
#include "gap/selftest.h"
#include "gap/test_block.h"
#include "tests/gap/one_candidate_fit.h"

namespace tribo::gap {
namespace {

// A diagnosis whose baseline is `before` and whose verdict is `effect` fitted as `after`.
Diagnosis diagnosis_of(const rig::FrictionModel& before, const rig::FrictionModel& after, const std::string& effect) {
  Diagnosis d;
  d.calibrated = before;
  Candidate c;
  c.effects = {effect};
  c.model = after;
  d.candidates.push_back(c);
  d.verdict.effects = c.effects;
  return d;
}

rig::FrictionModel viscous_truth() {
  rig::FrictionModel m = rig::coulomb(0.32, 0.19);
  m.set("viscous_friction", "coefficient_N_s_per_m", 35.0);
  return m;
}

ExperimentBundle test_runs(const rig::FrictionModel& truth, double noise_fraction) {
  SyntheticOptions o;
  o.speeds_m_per_s = o.test_speeds_m_per_s;
  o.noise_fraction = noise_fraction;
  return synthesize_bundle(rig::RigParameters{}, truth, o, 17);
}

TEST(TestBlock, TheTruthLeavesNoGapOnNoiselessRunsAndTheModelWithoutTheEffectItsSignature) {
  const rig::FrictionModel truth = viscous_truth();
  const ExperimentBundle test = test_runs(truth, 0.0);
  const TestBlockGap t = test_block_gap(test, rig::RigParameters{}, diagnosis_of(rig::coulomb(0.32, 0.19), truth, "viscous_friction"), 1);
  std::printf("test block: %d items, gap %.5f -> %.5f, floor %.5f\n", t.items, t.gap_before, t.gap_after, t.noise_floor);
  EXPECT_GE(t.items, 40);  // four runs: peaks, troughs, slip drops, times, a static point each
  // The same simulator on both sides: only the integration tolerance, 1e-10 without noise, is left.
  EXPECT_LT(t.gap_after, 1e-4);
  // c = 35 N s/m at 8–36 mm/s adds 0.1–0.5 N to a friction of ≈ 1.9 N: several per cent of μ.
  EXPECT_GT(t.gap_before, 0.01);
  EXPECT_GT(t.shrink(), 0.99);
}

TEST(TestBlock, OnNoisyRunsTheTruthLeavesAGapUnderTheNoiseFloor) {
  const rig::FrictionModel truth = viscous_truth();
  const ExperimentBundle test = test_runs(truth, 0.01);
  const TestBlockGap t = test_block_gap(test, rig::RigParameters{}, diagnosis_of(rig::coulomb(0.32, 0.19), truth, "viscous_friction"), 1);
  std::printf("test block at 1 %% noise: gap %.5f -> %.5f, floor %.5f\n", t.gap_before, t.gap_after, t.noise_floor);
  ASSERT_GT(t.noise_floor, 0.0);
  // The floor bounds what a right model leaves. On 2-s runs it overstates it about twofold (0.0031
  // against 0.0015 here): each of the four blocks holds one or two stick-slip cycles, and the
  // blocks differ even without noise (floor 0.0022 on the noiseless runs above; docs/gap.md
  // step 8). So: under the floor, and above a fifth of it — the noise does show.
  EXPECT_LT(t.gap_after, t.noise_floor);
  EXPECT_GT(t.gap_after, 0.2 * t.noise_floor);
}

// A test on a changed rig (a proposed test, gap/discriminate.h: the spring twice as stiff): the
// calibrated rig is scaled as the test's told one is, so the truth, on noiseless runs, again
// leaves only the integration tolerance; on the diagnosed spring it would miss every period and
// rise time by √2 and 2. A candidate named beside the verdict is predicted there too — here the
// Coulomb baseline under another name, which must leave the baseline's gap to the bit.
TEST(TestBlock, ATestOnAStifferSpringIsPredictedOnTheCalibratedRigScaledAsTheToldOne) {
  const rig::FrictionModel truth = viscous_truth();
  SyntheticOptions o;
  o.speeds_m_per_s = o.test_speeds_m_per_s;
  o.noise_fraction = 0.0;
  rig::RigParameters stiffer;
  stiffer.stiffness_N_per_m *= 2.0;
  const ExperimentBundle test = synthesize_bundle(stiffer, truth, o, 17);
  Diagnosis d = diagnosis_of(rig::coulomb(0.32, 0.19), truth, "viscous_friction");
  Candidate beside;
  beside.effects = {"thermal_thinning"};
  beside.model = rig::coulomb(0.32, 0.19);
  d.candidates.push_back(beside);
  d.verdict.indistinguishable = {"thermal_thinning"};
  const rig::RigParameters told = apply_bundle_rig(test, rig::RigParameters{});
  ASSERT_DOUBLE_EQ(told.stiffness_N_per_m, stiffer.stiffness_N_per_m);
  const TestBlockGap scaled = test_block_gap(test, told, d, 1, rig::RigParameters{});
  EXPECT_LT(scaled.gap_after, 1e-4);
  EXPECT_EQ(scaled.gap_beside.at("thermal_thinning"), scaled.gap_before);
  const TestBlockGap unscaled = test_block_gap(test, told, d, 1);
  std::printf("stiffer spring: truth on the scaled rig %.2e, on the diagnosed one %.4f\n", scaled.gap_after, unscaled.gap_after);
  EXPECT_GT(unscaled.gap_after, 0.1);
}

// What a test decides: a candidate named is ruled out when it misses the record by two noise
// floors more than the nearest. Viscous friction as the truth, at 1 % noise, against the Coulomb
// baseline named beside it: c = 35 N s/m leaves the baseline several floors out, so the test
// decides for the truth — the verdict, or the one beside it when the verdict is wrong, which then
// becomes the verdict after the test.
TEST(TestBlock, ATestRulesOutTheCandidatesThatMissTheRecordByTwoFloorsMoreThanTheNearest) {
  const rig::FrictionModel truth = viscous_truth(), coulomb = rig::coulomb(0.32, 0.19);
  const ExperimentBundle test = test_runs(truth, 0.01);
  const auto named = [](Diagnosis d, const std::string& effect, const rig::FrictionModel& model) {
    Candidate c;
    c.effects = {effect};
    c.model = model;
    d.candidates.push_back(c);
    d.verdict.indistinguishable.push_back(effect);
    return d;
  };
  const Diagnosis right = named(diagnosis_of(coulomb, truth, "viscous_friction"), "thermal_thinning", coulomb);
  const TestBlockGap t = test_block_gap(test, rig::RigParameters{}, right, 1);
  std::printf("decision: %s by %.1f floors\n", t.decided_for.c_str(), t.decision_floors);
  ASSERT_GT(t.decision_floors, kDecidingFloors);
  EXPECT_NEAR(t.decision_floors, (t.gap_beside.at("thermal_thinning") - t.gap_after) / t.noise_floor, 1e-12);
  EXPECT_EQ(t.ruled_out, std::vector<std::string>{"thermal_thinning"});
  EXPECT_EQ(t.decided_for, "viscous_friction");
  EXPECT_EQ(t.verdict_after, "viscous_friction");
  // The same pair with the verdict and the one beside it swapped: the verdict is ruled out.
  const TestBlockGap swapped = test_block_gap(test, rig::RigParameters{}, named(diagnosis_of(coulomb, coulomb, "thermal_thinning"), "viscous_friction", truth), 1);
  EXPECT_EQ(swapped.decided_for, "viscous_friction");
  EXPECT_EQ(swapped.verdict_after, "viscous_friction");
  // Two named that predict the record alike both stand (the truth twice, as two names): the test
  // rules out the wrong verdict and decides for neither; the nearer standing one is the verdict after.
  const Diagnosis three = named(named(diagnosis_of(coulomb, coulomb, "thermal_thinning"), "viscous_friction", truth), "hydrodynamic_lift", truth);
  const TestBlockGap pair = test_block_gap(test, rig::RigParameters{}, three, 1);
  EXPECT_EQ(pair.ruled_out, std::vector<std::string>{"thermal_thinning"});
  EXPECT_EQ(pair.standing.size(), 2u);
  EXPECT_TRUE(pair.decided_for.empty());
  EXPECT_EQ(pair.verdict_after, pair.standing.front());
  // Nothing beside the verdict: nothing to decide.
  const TestBlockGap alone = test_block_gap(test, rig::RigParameters{}, diagnosis_of(coulomb, truth, "viscous_friction"), 1);
  EXPECT_TRUE(alone.standing.empty() && alone.decided_for.empty() && alone.verdict_after.empty());
  EXPECT_TRUE(std::isnan(alone.decision_floors));
}

// Mechanisms alike at constant speed (rig::EffectInfo::alike_at_constant_speed: a squeeze film and
// the junction locus) are parted only by a test that holds what parts them — here a normal load
// twice the diagnosed one. The rule reads the candidates' names, so the same two models as above
// serve, named squeeze_film and rate_dependent_static: on runs at the diagnosed load the margin is
// as large, and the test still does not decide; at the heavier load it does.
TEST(TestBlock, AlikeMechanismsAreDecidedOnlyByATestThatPartsThem) {
  const rig::FrictionModel truth = viscous_truth(), coulomb = rig::coulomb(0.32, 0.19);
  Diagnosis d = diagnosis_of(coulomb, truth, "squeeze_film");
  Candidate alike;
  alike.effects = {"rate_dependent_static"};
  alike.model = coulomb;
  d.candidates.push_back(alike);
  d.verdict.alike_mechanisms = {"rate_dependent_static"};
  const TestBlockGap same_load = test_block_gap(test_runs(truth, 0.01), rig::RigParameters{}, d, 1, rig::RigParameters{});
  EXPECT_GT((same_load.gap_beside.at("rate_dependent_static") - same_load.gap_after) / same_load.noise_floor, kDecidingFloors);
  EXPECT_TRUE(same_load.ruled_out.empty());
  EXPECT_TRUE(same_load.decided_for.empty());
  EXPECT_EQ(same_load.verdict_after, "squeeze_film");
  SyntheticOptions o;
  o.speeds_m_per_s = o.test_speeds_m_per_s;
  rig::RigParameters heavier;
  heavier.normal_load_N *= kHeavierLoadFactor;
  const ExperimentBundle test = synthesize_bundle(heavier, truth, o, 17);
  const TestBlockGap t = test_block_gap(test, apply_bundle_rig(test, rig::RigParameters{}), d, 1, rig::RigParameters{});
  std::printf("heavier load: decision %s by %.1f floors\n", t.decided_for.c_str(), t.decision_floors);
  EXPECT_GT(t.decision_floors, kDecidingFloors);
  EXPECT_EQ(t.decided_for, "squeeze_film");
}

TEST(TestBlock, ADiagnosisOfTheIndependentGeneratorHalvesTheGapAtSpeedsItNeverSaw) {
  independent::GeneratorOptions go;
  const independent::IndependentCase c = independent::make_independent_case("rate_dependent_static", 301, go);
  const Diagnosis d = diagnose_with_one_candidate(c, "rate_dependent_static");
  ASSERT_EQ(verdict_name(d.verdict), "rate_dependent_static");
  go.speeds_m_per_s = SyntheticOptions{}.test_speeds_m_per_s;
  const ExperimentBundle test = independent::record_bundle(c.truth, c.actual, c.told, c.friction_chain, c.displacement_chain,
                                                           c.velocity_chain, go, 301 + 1'000'003);
  const TestBlockGap t = test_block_gap(test, apply_bundle_rig(test, rig::RigParameters{}), d, 301);
  const double heldout_shrink = 1.0 - d.verdict.heldout_gap_after / d.verdict.heldout_gap_before;
  std::printf("held-out %.4f -> %.4f (%.0f %%); test block %.4f -> %.4f (%.0f %%), floor %.4f\n", d.verdict.heldout_gap_before,
              d.verdict.heldout_gap_after, 100.0 * heldout_shrink, t.gap_before, t.gap_after, 100.0 * t.shrink(), t.noise_floor);
  EXPECT_GT(t.shrink(), 0.5);
  // The held-out shrink is the winner's number; on unseen speeds it may be lower, not by half.
  EXPECT_GT(t.shrink(), heldout_shrink - 0.25);
}

}  // namespace
}  // namespace tribo::gap
