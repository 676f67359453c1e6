// The diagnosis of slide-hold-slide tests (issue 15) on bundles from the independent generator
// (gap/independent/: its own integrator, Dieterich's ageing law written apart from rig/, a
// measuring chain, rig constants a few per cent off): static friction that heals with the hold
// time is named rate_and_state; a Coulomb machine with the same drive and chain is "none".
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "gap/diagnosis.h"
#include "gap/independent/generator.h"

namespace tribo::gap {
namespace {

Diagnosis diagnose_case(const independent::IndependentCase& c) {
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 100;
  const rig::RigParameters rig = apply_bundle_rig(c.bundle, rig::RigParameters{});
  return diagnose(c.bundle, rig, rig::coulomb(c.model_mu_s, c.model_mu_k), o);
}

void print(const char* what, const Diagnosis& d) {
  std::printf("  %s: verdict %s, held-out %.4g -> %.4g, floor %.3g, confidence %.2f\n", what, verdict_name(d.verdict).c_str(),
              d.verdict.heldout_gap_before, d.verdict.heldout_gap_after, d.verdict.noise_floor, d.verdict.confidence);
  for (const Candidate& c : d.candidates)
    std::printf("    %-28s held-out %.4g  C %.3g  earns %d\n", verdict_name(c.effects).c_str(), c.heldout_gap_after, c.criterion, c.earns);
}

TEST(SlideHoldSlide, HealingFromTheIndependentGeneratorIsRateAndState) {
  for (std::uint64_t seed : {21, 22}) {
    const independent::IndependentCase c = independent::make_slide_hold_slide_case("rate_and_state", seed);
    const Diagnosis d = diagnose_case(c);
    print(("rate_and_state seed " + std::to_string(seed)).c_str(), d);
    EXPECT_EQ(verdict_name(d.verdict), "rate_and_state") << "seed " << seed;
  }
}

TEST(SlideHoldSlide, ACoulombMachineAnswersNone) {
  const independent::IndependentCase c = independent::make_slide_hold_slide_case("none", 23);
  const Diagnosis d = diagnose_case(c);
  print("control seed 23", d);
  EXPECT_EQ(verdict_name(d.verdict), "none");
}

}  // namespace
}  // namespace tribo::gap
