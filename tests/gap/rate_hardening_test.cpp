// The catalogue's strain_rate_hardening (σ0 = κ φ̇^m inside the junction locus, thesis (5.1.2),
// (3.1.24)) reads the independent generator's Johnson–Cook hardening (gap/independent/laws.h:
// σ0 = σ_ref (1 + C ln(φ̇/φ̇_ref)), so μs = μs,ref / (1 + C ln(φ̇/φ̇_ref))) on a rig whose model has
// no locus. The hardening implies the locus: fitted with the locus's own parameters it follows
// the logarithmic fall of μs over the 7.5× range of load rates, which the locus alone (α, n at
// the thesis values) bends away from towards its upper asymptote. Before, the hardening was fitted
// on the thesis-default locus, ended worse than no effect, and rate_dependent_static was named
// (issue 15; seeds 302, 402 of the full independent set).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/junction_locus.h"
#include "gap/diagnosis.h"
#include "gap/independent/generator.h"
#include "gap/selftest.h"
#include "rig/friction_model.h"

namespace tribo::gap {
namespace {

TEST(RateHardening, HardenedLocusFollowsJohnsonCookStaticFrictionWhereTheBareLocusCannot) {
  const independent::IndependentCase c = independent::make_independent_case("strain_rate_hardening", 302);
  ASSERT_TRUE(c.truth.rate_hardening.has_value());
  DiagnosisOptions o;
  o.bootstrap_samples = 20;
  o.candidates = {"rate_dependent_static", "strain_rate_hardening"};
  const Diagnosis d = diagnose(c.bundle, apply_bundle_rig(c.bundle, rig::RigParameters{}), rig::coulomb(c.model_mu_s, c.model_mu_k), o);
  const auto find = [&](const std::string& e) {
    for (const Candidate& k : d.candidates)
      if (k.effects == std::vector<std::string>{e}) return k;
    ADD_FAILURE() << "no candidate " << e;
    return Candidate{};
  };
  const Candidate hardening = find("strain_rate_hardening"), bare = find("rate_dependent_static");
  std::printf("held-out gap %.4f -> bare locus %.4f, hardened locus %.4f (m = %.3f); verdict %s\n", hardening.heldout_gap_before,
              bare.heldout_gap_after, hardening.heldout_gap_after, hardening.params.at("strain_rate_hardening.m"),
              verdict_name(d.verdict).c_str());
  // Each locus against the truth over the measured speeds: the truth's μs at the load rate of the
  // rig as it is, a fit's at the load rate of the rig it calibrated (both k v / W). Compared as
  // the fall μs(φ̇) / μs(φ̇ of the slowest run), which the measuring chain's gain (±2 %) leaves
  // alone; the level itself is read through that gain and the 200 Hz filter that blunts each
  // breakaway peak (the recorded static points lie 0.011–0.017 under the truth's threshold).
  const auto fall_error = [&](const Candidate& k) {
    const auto locus = rig::junction_locus(k.model);
    EXPECT_TRUE(locus.has_value());
    if (!locus) return 1.0;
    const auto fitted = [&](double v) {
      return contact::static_friction_from_load_rate(*locus, k.rig.stiffness_N_per_m * v / k.rig.normal_load_N);
    };
    const auto truth = [&](double v) { return c.truth.rate_hardening->mu_s(c.actual.stiffness_N_per_m * v / c.actual.normal_load_N); };
    const double v0 = c.bundle.runs.front().v_m_per_s;
    double worst = 0.0, level = 0.0;
    for (const auto& run : c.bundle.runs) {
      const double v = run.v_m_per_s;
      worst = std::max(worst, std::abs(fitted(v) / fitted(v0) - truth(v) / truth(v0)));
      level = std::max(level, std::abs(fitted(v) - truth(v)));
    }
    std::printf("%s: worst error of the fall %.4f, of the level %.4f\n", verdict_name(k.effects).c_str(), worst, level);
    EXPECT_LT(level, 0.025);
    return worst;
  };
  const double hardened_error = fall_error(hardening), bare_error = fall_error(bare);
  // The truth falls by 21 % over the speeds; the hardened locus follows it to 2 % of its value at
  // the slowest run, and the bare locus, bending towards its asymptote, misses it by more.
  EXPECT_LT(hardened_error, 0.02);
  EXPECT_GT(bare_error, 1.5 * hardened_error);
  // The bare locus leaves at least twice the held-out gap the hardened one does, and the
  // diagnosis prefers the hardening despite its extra parameter.
  EXPECT_LT(hardening.heldout_gap_after, 0.5 * bare.heldout_gap_after);
  EXPECT_EQ(verdict_name(d.verdict), "strain_rate_hardening");
}

// The other way round: the model has the junction locus (the rig generator's second-effect case,
// seed 61 of the full set: truth = locus + hardening from the slowest load rate). The hardening
// is then fitted on the locus the model gives, referred to the catalogue's rate; referred to the
// data's median rate instead (commit d781c04), the same m shifted μs at every rate and the held-out
// shrink fell to 38 % (0.108 → 0.067). Measured with the reference left alone: 0.108 → 0.040.
TEST(RateHardening, OnAModelWithTheLocusTheHardeningKeepsTheLocusReferenceAndHalvesTheGap) {
  const SyntheticCase c = make_synthetic_case("strain_rate_hardening", {"rate_dependent_static"}, 61, SyntheticOptions{});
  DiagnosisOptions o;
  o.bootstrap_samples = 20;
  o.seed = 61;
  o.candidates = {"strain_rate_hardening"};
  const Diagnosis d = diagnose(c.bundle, apply_bundle_rig(c.bundle, rig::RigParameters{}), c.model, o);
  ASSERT_EQ(d.candidates.size(), 1u);
  const Candidate& k = d.candidates.front();
  std::printf("held-out gap %.4f -> %.4f (m = %.3f, truth %.3f; reference %.3g 1/s); verdict %s\n", k.heldout_gap_before, k.heldout_gap_after,
              k.model.get("strain_rate_hardening", "m"), c.truth.get("strain_rate_hardening", "m"),
              k.model.get("strain_rate_hardening", "reference_load_rate_per_s"), verdict_name(d.verdict).c_str());
  rig::FrictionModel catalogue;
  catalogue.add("strain_rate_hardening");
  EXPECT_DOUBLE_EQ(k.model.get("strain_rate_hardening", "reference_load_rate_per_s"),
                   catalogue.get("strain_rate_hardening", "reference_load_rate_per_s"));
  EXPECT_LT(k.heldout_gap_after, 0.5 * k.heldout_gap_before);
  EXPECT_EQ(verdict_name(d.verdict), "strain_rate_hardening");
}

// Hardening at m = 0 is the locus it implies, so the two are a nested pair: when the hardened
// locus fits train better, the locus is refined once more from the hardened fit's μs,max and L
// and judged at that best. On the independent generator's Kato ageing (seed 301: μs grows with
// stick time, which the locus reads through the load rate) the locus search stops where the
// hardened locus, one parameter more, wins on held-out data (0.0085 against 0.0112, named at
// 47 % in the full selftest); refined from the projection, the locus keeps its train gap, closes
// 90 % of the held-out gap, and the verdict is the locus (56 % in the full selftest).
TEST(RateHardening, TheLocusIsJudgedAtTheProjectionOfTheHardenedLocusThatNestsIt) {
  const independent::IndependentCase c = independent::make_independent_case("rate_dependent_static", 301);
  DiagnosisOptions o;
  o.bootstrap_samples = 20;
  o.seed = 301;
  o.candidates = {"rate_dependent_static", "strain_rate_hardening"};
  const Diagnosis d = diagnose(c.bundle, apply_bundle_rig(c.bundle, rig::RigParameters{}), rig::coulomb(c.model_mu_s, c.model_mu_k), o);
  ASSERT_EQ(d.candidates.size(), 2u);
  for (const Candidate& k : d.candidates)
    std::printf("%s: train gap %.4f, held-out %.4f -> %.4f\n", verdict_name(k.effects).c_str(), k.train_gap, k.heldout_gap_before,
                k.heldout_gap_after);
  std::printf("verdict %s\n", verdict_name(d.verdict).c_str());
  EXPECT_EQ(verdict_name(d.verdict), "rate_dependent_static");
  EXPECT_LT(d.verdict.heldout_gap_after, 0.1 * d.verdict.heldout_gap_before);
}

// A validation draw's strength f reaches 1.5, and f × U(0.12, 0.25) then past the catalogue's upper
// m = 0.35: validation set 9352's case 14359 drew m = 0.355, and the selftest stopped there
// (make_friction_law refuses it). The draw is held at the bound; `tribo gap generate` makes the
// same case, its model with the locus as the selftest's.
TEST(RateHardening, AStrongValidationDrawStaysWithinTheCataloguesRangeOfM) {
  const SyntheticCase c = make_synthetic_case("strain_rate_hardening", rig_model_effects("strain_rate_hardening"), 14359,
                                              synthetic_options(SelftestSet::validation));
  EXPECT_DOUBLE_EQ(c.truth.get("strain_rate_hardening", "m"), 0.35);
  EXPECT_TRUE(c.model.has("rate_dependent_static"));
}

}  // namespace
}  // namespace tribo::gap
