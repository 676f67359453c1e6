// The catalogue's slip_transient with a rate weakening (rig/effects/slip_transient.h) reads a
// Dieterich–Ruina slip-law rig from the independent generator (gap/independent/laws.h): friction
// reset to μs at each breakaway, relaxing over D_c of slip to μss = μ0 + a ln(1 + V/V0) + b ln(V0/V).
// Before the rate weakening, the thesis form (a constant level μk after the decay) could not follow
// the troughs and amplitudes falling with speed, and squeeze_film, whose steady film share grows
// with speed, was named instead (issue 15; seeds 303, 403 of the full independent set). The same
// form on Dieterich's ageing law needs the search to start β inside its range (second test), and
// the thesis form itself a search from β = 0 as well (third).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gap/selftest.h"
#include "tests/gap/one_candidate_fit.h"

namespace tribo::gap {
namespace {

TEST(SlipLaw, SlipTransientFitRecoversResetDecayDistanceAndSteadyStateWeakening) {
  // The full independent set's case (five speeds, 2 s each).
  const independent::IndependentCase c = independent::make_independent_case("slip_transient", 403);
  ASSERT_TRUE(c.truth.rate_state.has_value());
  const independent::RateState& rs = *c.truth.rate_state;
  ASSERT_EQ(rs.evolution, independent::RateState::Evolution::slip);
  const Diagnosis d = diagnose_with_one_candidate(c, "slip_transient");
  ASSERT_EQ(d.candidates.size(), 1u);
  const auto& p = d.candidates.front().params;
  const double amplitude = p.at("slip_transient.amplitude"), dc = p.at("slip_transient.decay_distance_m"),
               beta = p.at("slip_transient.rate_weakening");
  std::printf("amplitude %.4f (reset: 1), D_c %.3g m (truth %.3g), beta %.4f (b - a = %.4f); held-out gap %.4f -> %.4f\n", amplitude, dc,
              rs.decay_distance_m, beta, rs.b - rs.a, d.candidates.front().heldout_gap_before, d.candidates.front().heldout_gap_after);
  // The reset puts the whole excess μs − μss at onset: the amplitude's physical bound. The fit ends
  // within 3 % of it: since the slow runs are simulated for whole cycles (2026-11-27) the
  // refinement stops at 0.979, where the cost is flat to its tolerance (before, 0.995 and up).
  EXPECT_GT(amplitude, 0.97);
  // D_c and β = b − a to the accuracy the direct effect a ln(1 + V/V0) (0.1 b here, not in the
  // form) and a 1.5-s record allow.
  EXPECT_NEAR(dc / rs.decay_distance_m, 1.0, 0.3);
  EXPECT_NEAR(beta / (rs.b - rs.a), 1.0, 0.3);
  EXPECT_LT(d.candidates.front().heldout_gap_after, 0.2 * d.candidates.front().heldout_gap_before);
}

TEST(SlipLaw, OnDieterichsAgeingLawTheSearchReachesTheSlipTransientsBasin) {
  // A development draw at the validation set's speeds and strengths (seed 20002, never a validation
  // seed): the ageing law takes ln θ down linearly with slip, so friction falls from μs in a ramp,
  // not the catalogue's exponential. Started at β = 0, the search ended with β on its upper bound
  // (0.049), μk 0.042 and a = 0.68, held-out gap 0.079 → 0.047, and the squeeze film was named;
  // with β started mid-range it reaches a = 1.00, μk 0.21, β 0.018, held-out gap → 0.014.
  const SelftestCase sc{"slip_transient", {}, 20002, kIndependentGenerator};
  const CaseBundles c = make_case_bundles(sc, synthetic_options(SelftestSet::validation));
  ASSERT_EQ(c.form, "Dieterich-Ruina rate and state, ageing law");
  const Diagnosis d = diagnose_with_one_candidate(c.bundle, c.model, "slip_transient", sc.seed);
  ASSERT_EQ(d.candidates.size(), 1u);
  const Candidate& k = d.candidates.front();
  const double amplitude = k.params.at("slip_transient.amplitude"), beta = k.params.at("slip_transient.rate_weakening");
  const double mu_k_truth = c.truth_parameters.at("coulomb.mu_k");
  std::printf("amplitude %.3f, beta %.4f, mu_k %.4f (truth %.4f); held-out gap %.4f -> %.4f\n", amplitude, beta, k.model.baseline.mu_k,
              mu_k_truth, k.heldout_gap_before, k.heldout_gap_after);
  // The reset puts the whole excess at onset (a = 1); the stable level near the truth's μk (the
  // ramp's end at the middle speed, within 15 %: the direct effect is not in the form); β inside
  // its range, off the bound the failed search ended on.
  EXPECT_GT(amplitude, 0.9);
  EXPECT_NEAR(k.model.baseline.mu_k / mu_k_truth, 1.0, 0.15);
  EXPECT_LT(beta, 0.04);
  // The gap to less than 30 % of the baseline's (0.18 found; 0.60 from β = 0).
  EXPECT_LT(k.heldout_gap_after, 0.3 * k.heldout_gap_before);
}

TEST(SlipLaw, OnTheThesisFormTheSearchFromZeroWeakeningReachesTheTruthsBasin) {
  // A development draw of the first generator (seed 1206, never a validation seed): the thesis
  // form, amplitude 0.97, D_c 0.51 mm, no rate weakening. Searched from mid-range β alone, the fit
  // ended at β 0.032, amplitude 0.23 and μk 0.219 (truth 0.163), train gap 0.033, and squeeze_film
  // was named at 100 %; the truth itself leaves 0.0033.
  const SelftestCase sc{"slip_transient", {}, 1206};
  const CaseBundles c = make_case_bundles(sc, synthetic_options(SelftestSet::development));
  const Diagnosis d = diagnose_with_one_candidate(c.bundle, c.model, "slip_transient", sc.seed);
  ASSERT_EQ(d.candidates.size(), 1u);
  const Candidate& k = d.candidates.front();
  const double amplitude = k.params.at("slip_transient.amplitude"), beta = k.params.at("slip_transient.rate_weakening");
  const double mu_k_truth = c.model.baseline.mu_k / 0.9;  // the selftest's model is told μk 10 % low (make_synthetic_case)
  std::printf("amplitude %.3f (truth %.3f), beta %.4f, mu_k %.4f (truth %.4f); train gap %.4f, held-out %.4f -> %.4f\n", amplitude,
              c.truth_parameters.at("slip_transient.amplitude"), beta, k.model.baseline.mu_k, mu_k_truth, k.train_gap, k.heldout_gap_before,
              k.heldout_gap_after);
  // The truth's parameters to a few per cent, β near its bound, and the train gap near the truth's.
  EXPECT_NEAR(amplitude / c.truth_parameters.at("slip_transient.amplitude"), 1.0, 0.05);
  EXPECT_NEAR(k.params.at("slip_transient.decay_distance_m") / c.truth_parameters.at("slip_transient.decay_distance_m"), 1.0, 0.1);
  EXPECT_LT(beta, 0.005);
  EXPECT_NEAR(k.model.baseline.mu_k / mu_k_truth, 1.0, 0.03);
  EXPECT_LT(k.train_gap, 0.005);
}

}  // namespace
}  // namespace tribo::gap
