// Slide-hold-slide end to end (issue 35, item 5): the independent generator's drive-history
// cases (gap/independent/generator.h — its own Dieterich–Ruina integrator, a measuring chain that
// filters and decimates to 50 Hz, AR(1) noise, rig constants told a few per cent off) diagnosed
// with the defaults of `tribo gap diagnose` against the Coulomb model the case states. Holds of
// 1, 3, 10, 30 and 100 s; each hold gives one peak_after_hold item, alternately trained and held
// out. The rate-and-state truth heals (the peak grows ≈ b ln(1 + t_h V/D_c)), which the catalogue's
// rate_and_state must name; the Coulomb control on the same machine and drive heals not at all
// and must answer "none". Slow: one full diagnosis each, every candidate the kind admits.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "gap/diagnosis.h"
#include "gap/independent/generator.h"

namespace tribo::gap {
namespace {

Diagnosis diagnose_case(const independent::IndependentCase& c) {
  DiagnosisOptions o;  // the defaults of `tribo gap diagnose`
  const Diagnosis d = diagnose(c.bundle, apply_bundle_rig(c.bundle, rig::RigParameters{}), rig::coulomb(c.model_mu_s, c.model_mu_k), o);
  std::printf("truth %s: verdict %s at %.2f; held-out gap %.4f -> %.4f (noise floor %.4f); calibration %.4f = %.2f floors; stages",
              c.truth.rate_state ? "rate_and_state" : "none", verdict_name(d.verdict).c_str(), d.verdict.confidence,
              d.verdict.heldout_gap_before, d.verdict.heldout_gap_after, d.verdict.noise_floor, d.calibration.train_gap,
              d.calibration.train_floors());
  const StageTimes& s = d.stage_times;
  std::printf(" %.0f + %.0f + %.0f + %.0f + %.0f s\n", s.calibration_s, s.candidates_s, s.recalibration_s, s.refinement_s, s.confidence_s);
  for (const Candidate& k : d.candidates)
    std::printf("  %-32s held-out %.4f  evidence %.1f ± %.1f nats%s\n", verdict_name(k.effects).c_str(), k.heldout_gap_after, k.evidence_nats,
                k.evidence_se_nats, k.earns ? "  earns" : "");
  return d;
}

TEST(SlideHoldSlide, HealingAfterHoldsIsNamedRateAndState) {
  const Diagnosis d = diagnose_case(independent::make_slide_hold_slide_case("rate_and_state", 21));
  EXPECT_EQ(verdict_name(d.verdict), "rate_and_state");
  // Named, it must close most of what the Coulomb model leaves after the holds.
  EXPECT_LT(d.verdict.heldout_gap_after, 0.5 * d.verdict.heldout_gap_before);
}

TEST(SlideHoldSlide, ACoulombControlWithTheSameHoldsAnswersNone) {
  const Diagnosis d = diagnose_case(independent::make_slide_hold_slide_case("none", 21));
  EXPECT_EQ(verdict_name(d.verdict), "none");
}

}  // namespace
}  // namespace tribo::gap
