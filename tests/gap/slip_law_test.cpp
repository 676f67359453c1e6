// The catalogue's slip_transient with a rate weakening (rig/effects/slip_transient.h) reads a
// Dieterich–Ruina slip-law rig from the independent generator (gap/independent/laws.h): friction
// reset to μs at each breakaway, relaxing over D_c of slip to μss = μ0 + a ln(1 + V/V0) + b ln(V0/V).
// Before the rate weakening, the thesis form (a constant level μk after the decay) could not follow
// the troughs and amplitudes falling with speed, and squeeze_film, whose steady film share grows
// with speed, was named instead (issue 15; seeds 303, 403 of the full independent set).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

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

}  // namespace
}  // namespace tribo::gap
