// The diagnosis' stages after the fits (gap/verdict.h) on hand-made items and residuals: the gap
// and the likelihood against their definitions (diagnosis.h, verdict.h), the verdict rule's three outcomes, where
// the residual lies, and the bootstrap confidence at its two ends and with the data's noise. No
// simulation: milliseconds.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gap/verdict.h"
#include "numerics/normal.h"

namespace tribo::gap {
namespace {

Item item(const std::string& observable, int unit, const std::string& phase = "cycle") {
  Item it;
  it.observable = observable;
  it.unit = unit;
  it.phase = phase;
  it.regime = "stick_slip";
  it.speed_class = unit < 2 ? "low v" : "high v";
  it.where = observable + " unit " + std::to_string(unit);
  return it;
}

// A standing on four held-out items, each with log density `lpd` (so 4 lpd nats over a baseline at 0).
Standing st(double lpd, double gap, bool earns) { return Standing{std::vector<double>(4, lpd), gap, earns, {4.0 * lpd, 0.0}}; }

Candidate candidate(const std::string& effect, int parameters, std::vector<double> residuals) {
  Candidate c;
  c.effects = {effect};
  c.extra_parameters = parameters;
  c.residuals = std::move(residuals);
  return c;
}

// Eight units of two items each (mu_peak, period_s), the bootstrap tests' held-out data.
std::vector<Item> eight_held_out_units() {
  std::vector<Item> items;
  for (int u = 0; u < 8; ++u)
    for (const char* obs : {"mu_peak", "period_s"}) items.push_back(item(obs, u));
  return items;
}

// Two observables, three items of one and one of the other: the gap is the mean over observables
// of the RMS residual, so the lone item weighs as much as the three (definition in diagnosis.h).
TEST(Verdict, GapIsTheMeanOverObservablesOfTheRmsResidual) {
  const std::vector<Item> items{item("mu_peak", 0), item("mu_peak", 1), item("mu_peak", 2), item("period_s", 3)};
  const std::vector<double> r{0.1, -0.2, 0.2, 0.5};
  const double expected = 0.5 * (std::sqrt((0.01 + 0.04 + 0.04) / 3.0) + 0.5);
  EXPECT_NEAR(gap(items, r, multiplicity({true, true, true, true})), expected, 1e-15);
  EXPECT_NEAR(breakdown(items, r, {true, true, true, true}).gap, expected, 1e-15);
  EXPECT_NEAR(breakdown(items, r, {true, true, true, true}).by_observable.at("mu_peak"), std::sqrt(0.03), 1e-15);
  // Outside the split an item does not count; counted twice it counts as two copies would.
  EXPECT_NEAR(gap(items, r, multiplicity({true, false, false, false})), 0.1, 1e-15);
  const std::vector<Item> doubled{item("mu_peak", 0), item("mu_peak", 1), item("mu_peak", 1)};
  EXPECT_NEAR(gap(items, r, {1.0, 2.0, 0.0, 0.0}), gap(doubled, {0.1, -0.2, -0.2}, {1.0, 1.0, 1.0}), 1e-15);
  EXPECT_EQ(gap(items, r, {0.0, 0.0, 0.0, 0.0}), 0.0);
}

// Weights make every observable's summed squared weight 1 / N_obs, whatever its item count.
TEST(Verdict, WeightsGiveEveryObservableTheSameShare) {
  const std::vector<Item> items{item("mu_peak", 0), item("mu_peak", 1), item("mu_peak", 2), item("period_s", 3)};
  const std::vector<double> w = weights(items, {true, true, true, true});
  EXPECT_NEAR(w[0] * w[0] + w[1] * w[1] + w[2] * w[2], 0.5, 1e-15);
  EXPECT_NEAR(w[3] * w[3], 0.5, 1e-15);
  EXPECT_NEAR(weighted_sse({1.0, 1.0, 1.0, 1.0}, w, {1.0, 1.0, 1.0, 1.0}), 1.0, 1e-15);
  EXPECT_EQ(weights(items, {true, false, false, false})[1], 0.0);
}

// The likelihood (verdict.h) by hand. Observable mu_peak: noise 0.1 on three items, none on the
// fourth, which takes their RMS; train residuals 0.3 and 0.1 claim τ² = mean(r² − s²) = 0.04, so
// σ² = 0.01 + 0.04 on every mu_peak item, with ν = 2 (two training items): t₂'s density is
// (1 + z²/2)^(−3/2) / (2√2 σ). period_s has no training item and no noise: its τ² is its own one
// item's r² (in-sample), σ = 0.5, ν = 1 — Cauchy, 1 / (π σ (1 + z²)).
TEST(Verdict, LikelihoodScoresEachItemByItsNoisePlusTheErrorTheModelClaimsOnTrain) {
  const std::vector<Item> items{item("mu_peak", 0), item("mu_peak", 1), item("mu_peak", 2), item("mu_peak", 3), item("period_s", 4)};
  const std::vector<double> s = item_noise(items, {0.1, 0.1, 0.1, 0.0, 0.0});
  EXPECT_NEAR(s[3], 0.1, 1e-15);
  EXPECT_EQ(s[4], 0.0);
  const std::vector<double> r{0.3, 0.1, 0.2, -0.2, 0.5};
  const std::vector<bool> train{true, true, false, false, false};
  const Predictive p = predictive(items, r, s, train);
  EXPECT_NEAR(p.sd[2], std::sqrt(0.05), 1e-15);
  EXPECT_NEAR(p.sd[3], std::sqrt(0.05), 1e-15);
  EXPECT_EQ(p.dof[2], 2.0);
  EXPECT_NEAR(p.sd[4], 0.5, 1e-15);
  EXPECT_EQ(p.dof[4], 1.0);
  const std::vector<double> lpd = log_density(r, p);
  const double z2 = 0.04 / 0.05;
  EXPECT_NEAR(lpd[2], -std::log(2.0 * std::sqrt(2.0) * std::sqrt(0.05)) - 1.5 * std::log(1.0 + z2 / 2.0), 1e-13);
  EXPECT_NEAR(lpd[4], -std::log(M_PI * 0.5 * 2.0), 1e-13);
  // Many degrees of freedom: the Gaussian.
  const Predictive wide{{0.2}, {1e8}};
  EXPECT_NEAR(log_density({0.3}, wide)[0], -0.5 * (std::log(2.0 * M_PI * 0.04) + 0.09 / 0.04), 1e-6);
  // A model that claims more error than it makes pays the log of its width; one that claims
  // less pays for its miss: at r = 0.2 the density is highest for σ = 0.2, whatever ν.
  for (double nu : {1.0, 3.0, 30.0}) {
    const double at_own = log_density({0.2}, Predictive{{0.2}, {nu}})[0];
    EXPECT_GT(at_own, log_density({0.2}, Predictive{{0.19}, {nu}})[0]);
    EXPECT_GT(at_own, log_density({0.2}, Predictive{{0.21}, {nu}})[0]);
  }
  // A perfect training fit of a noise-free observable claims σ = 0: it is held at the
  // resolution, 1e-3 of the observable's size.
  EXPECT_EQ(predictive(items, {0.0, 0.0, 0.3, 0.3, 0.0}, std::vector<double>(5, 0.0), train).sd[2], Predictive::kResolution);
  // A fitted model's parameter variance (gap/laplace.h) adds to σ²: 0.05 + 0.03.
  EXPECT_NEAR(predictive(items, r, s, train, {0.0, 0.0, 0.03, 0.0, 0.0}).sd[2], std::sqrt(0.08), 1e-15);
}

// One step of iteratively reweighted least squares for a level L seen by two observables: A reads
// 1.0 on every item to its noise 0.01; B scatters by ±0.3 about 0.8, which no level follows. With
// every observable weighing the same L = 0.9, where A misses by 0.1 (τ_A² = 0.01 − 0.0001) and B by
// its scatter and offset (τ_B² = 0.09 + 0.01 − 0.0001); weighted by 1/σ² the next level is the
// inverse-variance mean of the two means, which follows the precise observable.
TEST(Verdict, LikelihoodWeightsPutAFittedLevelWhereThePreciseObservableHasIt) {
  std::vector<Item> items;
  std::vector<double> measured, noise;
  for (int k = 0; k < 4; ++k) {
    items.push_back(item("steady_mu", k)), measured.push_back(1.0), noise.push_back(0.01);
    items.push_back(item("mu_after_step", k)), measured.push_back(0.8 + (k % 2 ? 0.3 : -0.3)), noise.push_back(0.01);
  }
  const std::vector<bool> train(items.size(), true);
  const std::vector<double> w_equal = weights(items, train);
  auto weighted_level = [&](const std::vector<double>& w) {
    double num = 0.0, den = 0.0;
    for (std::size_t i = 0; i < items.size(); ++i) num += w[i] * w[i] * measured[i], den += w[i] * w[i];
    return num / den;
  };
  const double first = weighted_level(w_equal);
  EXPECT_NEAR(first, 0.9, 1e-12);
  std::vector<double> r;
  for (double m : measured) r.push_back(first - m);
  const std::vector<double> w = likelihood_weights(items, r, item_noise(items, noise), train);
  const double var_a = 0.01 - 1e-4 + 1e-4, var_b = 0.09 + 0.01 - 1e-4 + 1e-4;  // τ² + s²
  EXPECT_NEAR(w[0], 1.0 / std::sqrt(var_a), 1e-9);
  EXPECT_NEAR(w[1], 1.0 / std::sqrt(var_b), 1e-9);
  EXPECT_NEAR(weighted_level(w), (1.0 / var_a + 0.8 / var_b) / (1.0 / var_a + 1.0 / var_b), 1e-12);  // 0.9818
  EXPECT_GT(weighted_level(w), 0.98);
  // Held-out items do not enter a fit.
  std::vector<bool> half(items.size(), true);
  half[2] = half[3] = false;
  const std::vector<double> w_half = likelihood_weights(items, r, item_noise(items, noise), half);
  EXPECT_EQ(w_half[2], 0.0);
  EXPECT_EQ(w_half[3], 0.0);
}

// Evidence: Σ m_i d_i and √(n var d_i); decisive above 3 nats and either 2 se or a halved gap.
TEST(Verdict, EvidenceIsTheSummedGainWithItsStandardErrorAndMustBeStrong) {
  const Evidence e = evidence({1.0, 2.0, 0.0}, {0.0, 0.0, 0.0}, {1.0, 2.0, 0.0});
  EXPECT_NEAR(e.gain, 5.0, 1e-15);
  // d = 1, 2, 2 (the second drawn twice): mean 5/3, var (4/9 + 1/9 + 1/9)/2 = 1/3, se = √(3 · 1/3) = 1.
  EXPECT_NEAR(e.se, 1.0, 1e-15);
  EXPECT_TRUE(decisive(e, 0.09, 0.1));
  EXPECT_FALSE(decisive({2.9, 0.0}, 0.01, 0.1));  // a likelihood ratio of 18: not strong, whatever the cut
  EXPECT_FALSE(decisive({5.0, 3.0}, 0.06, 0.1));  // within two standard errors, and the gap not halved
  EXPECT_TRUE(decisive({5.0, 3.0}, 0.05, 0.1));   // resting on few items, but the gap halved
  EXPECT_EQ(evidence({1.0}, {0.0}, {0.0}).gain, 0.0);
}

// The best of K wrong candidates clears z standard errors by noise alone with probability
// 1 − Φ(z)^K; z_K holds that at one comparison's Φ(−2) = 0.02275 (Šidák). Reference values
// from Φ⁻¹ of (0.97725)^(1/K): K = 1 → 2, K = 8 → 2.762 (0.97725^(1/8) = 0.997128, between the
// tabulated Φ(2.76) = 0.99711 and Φ(2.77) = 0.99720).
TEST(Verdict, DecisiveThresholdGrowsWithTheCandidatesTriedAtAFixedFamilyFalseAlarmRate) {
  EXPECT_NEAR(decisive_z(1), 2.0, 1e-12);
  EXPECT_NEAR(decisive_z(8), 2.762, 1e-3);
  for (int k : {1, 2, 8, 9, 30}) {
    const double none_clear = std::pow(numerics::standard_normal_cdf(decisive_z(k)), k);
    EXPECT_NEAR(1.0 - none_clear, numerics::standard_normal_cdf(-2.0), 1e-12) << k << " candidates";
  }
  // A control's best of eight: 4.0 ± 1.9 nats is 2.1 se — decisive alone, not as the best of eight.
  EXPECT_TRUE(decisive({4.0, 1.9}, 0.0073, 0.0089, 1));
  EXPECT_FALSE(decisive({4.0, 1.9}, 0.0073, 0.0089, 8));
}

// The verdict rule: the simplest earning candidate; a larger one only with decisive evidence over
// it; unexplained above 5 floors when nothing halves the excess over the floor; none below.
TEST(Verdict, RuleNamesTheSimplestEarnerAndOwnsUpToWhatItCannotExplain) {
  const DiagnosisOptions o;
  const std::vector<Candidate> cs{candidate("a", 1, {}), candidate("b", 2, {})};
  const Multiplicity m{1.0, 1.0, 1.0, 1.0};
  // b beats a by 2 nats: not decisive, a stays.
  EXPECT_EQ(verdict_index(cs, {st(2.0, 0.05, true), st(2.5, 0.01, true)}, m), 0);
  // by 4 nats: b.
  EXPECT_EQ(verdict_index(cs, {st(2.0, 0.05, true), st(3.0, 0.01, true)}, m), 1);
  EXPECT_EQ(verdict_index(cs, {st(0.0, 0.05, false), st(0.0, 0.01, false)}, m), -1);
  // c beats a by 3.2 nats, b only by 2, and c is not decisive over b: b, the simplest that nothing
  // larger beats — not c for having beaten a (validation case 15008's order: viscous friction,
  // thermal thinning, slip transient).
  const std::vector<Candidate> three{candidate("a", 1, {}), candidate("b", 2, {}), candidate("c", 3, {})};
  EXPECT_EQ(verdict_index(three, {st(2.0, 0.05, true), st(2.5, 0.03, true), st(2.8, 0.02, true)}, m), 1);
  // c decisive over b too: c.
  EXPECT_EQ(verdict_index(three, {st(2.0, 0.05, true), st(2.0, 0.03, true), st(2.8, 0.02, true)}, m), 2);
  // A level's leader is the most evidence among equals: b2 (2.6) over b (2.5); c beats neither.
  const std::vector<Candidate> four{candidate("a", 1, {}), candidate("b", 2, {}), candidate("b2", 2, {}), candidate("c", 3, {})};
  EXPECT_EQ(verdict_index(four, {st(2.0, 0.05, true), st(2.5, 0.03, true), st(2.6, 0.03, true), st(2.8, 0.02, true)}, m), 2);

  const double floor = 0.01;
  // Gap 0.2 = 20 floors; a leaves 0.15: its excess is not halved → unexplained.
  Decision d = decide(cs, {st(2.0, 0.15, true), st(0.0, 0.2, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, -1);
  EXPECT_TRUE(d.unexplained);
  // a brings it to 0.02 (2 floors): named.
  d = decide(cs, {st(2.0, 0.02, true), st(0.0, 0.2, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, 0);
  EXPECT_FALSE(d.unexplained);
  // 3 floors and no earner: none, not unexplained (the rig-constants-off controls' case).
  d = decide(cs, {st(0.0, 0.03, false), st(0.0, 0.03, false)}, m, o, 0.03, floor);
  EXPECT_EQ(d.index, -1);
  EXPECT_FALSE(d.unexplained);
  // Without a floor nothing is unexplained.
  EXPECT_FALSE(decide(cs, {st(0.0, 0.2, false), st(0.0, 0.2, false)}, m, o, 0.2, 0.0).unexplained);
}

// Occam's order is for nested candidates: the hardened locus is the locus with m = 0, so it must
// beat the locus decisively. The squeeze film and the locus are alike mechanisms, neither a limit of
// the other: between them the larger held-out evidence is named, by however little (its confidence
// is shared with the other, verdict_confidence). Neither a pair nor a candidate that does not earn
// takes the verdict so.
TEST(Verdict, BetweenAlikeMechanismsTheEvidenceDecidesNotTheParameterCount) {
  const Multiplicity m{1.0, 1.0, 1.0, 1.0};
  const std::vector<Candidate> cs{candidate("rate_dependent_static", 2, {}), candidate("squeeze_film", 3, {}),
                                  candidate("strain_rate_hardening", 3, {})};
  // 2 nats more for the film: not decisive, but alike — the film.
  EXPECT_EQ(verdict_index(cs, {st(2.0, 0.05, true), st(2.5, 0.04, true), st(0.0, 0.2, false)}, m), 1);
  EXPECT_EQ(verdict_index(cs, {st(2.5, 0.04, true), st(2.0, 0.05, true), st(0.0, 0.2, false)}, m), 0);
  // The same 2 nats for the hardened locus, which nests the locus: the locus stays.
  EXPECT_EQ(verdict_index(cs, {st(2.0, 0.05, true), st(0.0, 0.2, false), st(2.5, 0.04, true)}, m), 0);
  // A film that does not earn is not named.
  EXPECT_EQ(verdict_index(cs, {st(2.0, 0.05, true), st(2.5, 0.04, false), st(0.0, 0.2, false)}, m), 0);
  // Nor is a pair with the film in it.
  std::vector<Candidate> with_pair = cs;
  with_pair[1].effects = {"rate_dependent_static", "squeeze_film"};
  EXPECT_EQ(verdict_index(with_pair, {st(2.0, 0.05, true), st(2.5, 0.04, true), st(0.0, 0.2, false)}, m), 0);
}

// "Unexplained" tells the user to look outside the catalogue, so it must not be said of a gap a
// catalogue candidate halves (issue 35: a Kato ageing case called unexplained although the squeeze
// film cut its held-out gap by 87 % without earning on likelihood). Gap 20 floors, no earner: the
// simplest candidate that halves the excess over the floor is named, tentatively; among equals
// the smaller gap; an earner still comes first, and below 5 floors it stays "none".
TEST(Verdict, AGapNoEarnerExplainsIsNamedTentativelyAfterTheSimplestCandidateThatHalvesIt) {
  const DiagnosisOptions o;
  const std::vector<Candidate> cs{candidate("a", 1, {}), candidate("b", 2, {}), candidate("c", 2, {})};
  const Multiplicity m{1.0, 1.0, 1.0, 1.0};
  const double floor = 0.01;
  // a leaves 0.15 (excess 0.150 > half of 0.200): b and c halve it, c leaves less.
  Decision d = decide(cs, {st(0.0, 0.15, false), st(0.0, 0.05, false), st(0.0, 0.03, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, 2);
  EXPECT_TRUE(d.tentative);
  EXPECT_FALSE(d.unexplained);
  // a at 0.08 (excess 0.079 ≤ 0.100) halves it too and has fewer parameters: a.
  d = decide(cs, {st(0.0, 0.08, false), st(0.0, 0.05, false), st(0.0, 0.03, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, 0);
  EXPECT_TRUE(d.tentative);
  // b earns and halves it: named as before, not tentative.
  d = decide(cs, {st(0.0, 0.08, false), st(5.0, 0.05, true), st(0.0, 0.03, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, 1);
  EXPECT_FALSE(d.tentative);
  // 4 floors: not beyond the noise, so none, though c halves it.
  d = decide(cs, {st(0.0, 0.04, false), st(0.0, 0.04, false), st(0.0, 0.01, false)}, m, o, 0.04, floor);
  EXPECT_EQ(d.index, -1);
  EXPECT_FALSE(d.tentative || d.unexplained);
  // Nothing halves it (0.11: excess 0.1095 > 0.0999): unexplained.
  d = decide(cs, {st(0.0, 0.15, false), st(0.0, 0.11, false), st(0.0, 0.12, false)}, m, o, 0.2, floor);
  EXPECT_EQ(d.index, -1);
  EXPECT_TRUE(d.unexplained);
  EXPECT_FALSE(d.tentative);
}

// Beside the verdict, the earning candidates it cannot be told from: 2 nats apart on four items is
// no decision either way; 4 nats is (b over a), so a is not named beside b; one that does not
// earn is never named.
TEST(Verdict, CandidatesWithoutDecisiveEvidenceEitherWayAreNamedBesideTheVerdict) {
  const Multiplicity m{1.0, 1.0, 1.0, 1.0};
  EXPECT_EQ(indistinguishable({st(2.0, 0.05, true), st(2.5, 0.04, true), st(2.4, 0.04, false)}, 0, m), std::vector<int>{1});
  EXPECT_TRUE(indistinguishable({st(2.0, 0.05, true), st(3.0, 0.04, true)}, 1, m).empty());
  EXPECT_TRUE(indistinguishable({st(2.0, 0.05, true), st(2.5, 0.04, true)}, -1, m).empty());  // "none": nothing to tie with
}

TEST(Verdict, LocalisationSharesSumToOneLargestFirstWithTheWorstItem) {
  const std::vector<Item> items{item("mu_peak", 0, "slip onset"), item("mu_peak", 1, "slip onset"), item("period_s", 2)};
  const std::vector<Localization> l = localize(items, {0.1, 0.3, 0.2});
  ASSERT_EQ(l.size(), 2u);  // (mu_peak; slip onset, low v) holds units 0 and 1; (period_s; cycle, high v)
  double total = 0.0;
  for (const Localization& x : l) total += x.share;
  EXPECT_NEAR(total, 1.0, 1e-15);
  EXPECT_EQ(l.front().observable, "mu_peak");
  EXPECT_NEAR(l.front().share, (0.01 + 0.09) / 0.14, 1e-15);
  EXPECT_EQ(l.front().worst_item, "mu_peak unit 1");
}

// Confidence at its ends: a candidate that cuts every held-out unit's residual tenfold wins in
// every resample (1.0), and its gap does not vary; a candidate that helps one unit of eight and
// spoils none wins only in resamples that draw that unit often enough — well below 1.
TEST(Verdict, BootstrapConfidenceIsOneForAUniformWinAndLowForAOneUnitWin) {
  const std::vector<Item> items = eight_held_out_units();
  const std::vector<bool> held(items.size(), true);
  const std::size_t n = items.size();
  // No noise floor: the rule is the evidence alone (no "unexplained").
  const std::vector<double> baseline(n, 0.2), noise(n, 0.0);
  DiagnosisOptions o;
  o.bootstrap_samples = 400;
  std::vector<double> uniform(n, 0.02);
  const std::vector<Candidate> one{candidate("uniform", 1, uniform)};
  const Confidence sure = bootstrap_confidence(items, held, noise, baseline, {}, one, 0, "uniform", o);
  EXPECT_EQ(sure.agreement, 1.0);
  EXPECT_NEAR(sure.heldout_gap_after_std, 0.0, 1e-8);  // a constant 0.02, up to the sums' rounding

  std::vector<double> local = baseline;
  local[0] = local[1] = 0.0;  // unit 0 only
  const std::vector<Candidate> other{candidate("local", 1, local)};
  const Confidence weak = bootstrap_confidence(items, held, noise, baseline, {}, other, 0, "local", o);
  // Nothing is trained, so each model's σ² is its own mean r² per observable (ν = 8) and, in the
  // Gaussian limit, the quadratic terms cancel: with unit 0 drawn k times of eight the evidence
  // is about 8 ln(8 / (8 − k)) nats — 1.1 (k = 1), 2.3 (k = 2), 3.8 (k = 3, se 1.6): decisive from
  // k = 3, P = 0.067 for a binomial(8, 1/8); 400 resamples estimate it to ± 0.0125.
  EXPECT_GT(weak.agreement, 0.02);
  EXPECT_LT(weak.agreement, 0.15);
  EXPECT_GT(weak.heldout_gap_after_std, 0.0);
  // No held-out unit: no confidence.
  EXPECT_EQ(bootstrap_confidence(items, std::vector<bool>(n, false), noise, baseline, {}, one, 0, "uniform", o).agreement, 0.0);
}

// A resample measures the held-out items again within their own standard error. A candidate
// that cuts every residual from 0.2 to 0.15 wins every resample when the data carry no noise
// (16 ln(0.2/0.15) = 4.6 nats, se 0). With a standard error of 0.1 on each of the 16 items the
// same shift δ_i moves the baseline's and the candidate's residual; nothing is trained, so each
// σ² is the model's own mean r² and the evidence is, in the Gaussian limit,
// 8 ln((0.04 + 0.4 δ̄ + q) / (0.0225 + 0.3 δ̄ + q)) (q = mean δ², 0.01 on average; δ̄ ± 0.025):
// above 3 nats only while q ≲ 0.016 at δ̄ = 0, which χ²₁₆ gives 94 % of the time — less with the
// units' redraw and the 2-se rule (measured 0.895 with this seed and Student's t, ν = 8).
// Seeded: the same inputs, the same confidence.
// The bootstrap asks whether data measured again would give the same verdict; for "none" that is
// not whether it is right, since an effect below the noise gives "none" in every redraw. Over the
// validation sets of seeds 9001-9062, 8 of 32 "none" verdicts were such effects (docs/gap.md).
TEST(Verdict, NoneIsAsLikelyRightAsItsAgreementTimesTheReliabilityOfNone) {
  DiagnosisOptions o;
  EXPECT_DOUBLE_EQ(o.none_reliability, 0.75);
  EXPECT_DOUBLE_EQ(verdict_confidence(1.0, "none", o), 0.75);
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "none", o), 0.675);
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "viscous_friction", o), 0.9);  // a named verdict keeps its agreement
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "unexplained", o), 0.9);
  EXPECT_TRUE(std::isnan(verdict_confidence(std::nan(""), "none", o)));
  o.none_reliability = 0.0;
  EXPECT_NE(o.invalid_reason().find("none_reliability"), std::string::npos);
}

// Set 9122's Kato case in figures (held-out gap 0.423, floor 0.044): the squeeze film chosen at
// 0.030; the junction locus (rate_dependent_static), a mechanism constant-speed runs at one load
// do not part from the film's, at 0.137 — its excess over the floor 0.130 against the baseline's
// 0.421, less than half: it explains the gap too and is named. At 0.30 (excess 0.297 > 0.211) it
// does not. slip_transient at 0.03 explains it as well but is not the film's alike (the held-out
// data part those); a pair holding the locus already does not name it again; no floor, no verdict:
// nothing.
TEST(Verdict, AMechanismAlikeAtConstantSpeedIsNamedWhenItHalvesTheGapToo) {
  auto with_gap = [](const std::string& effect, double g) {
    Candidate c = candidate(effect, 3, {});
    c.heldout_gap_after = g;
    return c;
  };
  std::vector<Candidate> cs{with_gap("squeeze_film", 0.030), with_gap("slip_transient", 0.030), with_gap("rate_dependent_static", 0.137),
                            with_gap("strain_rate_hardening", 0.30)};
  EXPECT_EQ(alike_mechanisms(cs, 0, 0.423, 0.044), std::vector<std::string>{"rate_dependent_static"});
  EXPECT_EQ(alike_mechanisms(cs, 2, 0.423, 0.044), std::vector<std::string>{"squeeze_film"});  // and the other way round
  EXPECT_TRUE(alike_mechanisms(cs, 1, 0.423, 0.044).empty());
  EXPECT_EQ(alike_mechanisms(cs, 3, 0.423, 0.044), std::vector<std::string>{"squeeze_film"});  // the verdict's own gap is not asked
  cs[2].heldout_gap_after = 0.30;
  EXPECT_TRUE(alike_mechanisms(cs, 0, 0.423, 0.044).empty());
  cs[2].heldout_gap_after = 0.137;
  EXPECT_TRUE(alike_mechanisms(cs, -1, 0.423, 0.044).empty());
  EXPECT_TRUE(alike_mechanisms(cs, 0, 0.423, 0.0).empty());
  Candidate pair = with_gap("squeeze_film", 0.02);
  pair.effects = {"rate_dependent_static", "squeeze_film"};
  cs.push_back(pair);
  EXPECT_TRUE(alike_mechanisms(cs, 4, 0.423, 0.044).empty());
}

// What the data cannot decide is shared: a named verdict with an alike mechanism beside it keeps
// half its agreement (a uniform prior over the two); "none" and "unexplained" name no mechanism.
TEST(Verdict, AVerdictSharesItsConfidenceWithAnAlikeMechanism) {
  const DiagnosisOptions o;
  EXPECT_DOUBLE_EQ(verdict_confidence(1.0, "squeeze_film", o, true), 0.5);
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "squeeze_film", o, false), 0.9);
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "unexplained", o, true), 0.9);
  EXPECT_DOUBLE_EQ(verdict_confidence(0.9, "none", o, true), 0.675);
}

// The catalogue's alike mechanisms are catalogue effects and alike both ways.
TEST(Verdict, AlikeMechanismsAreCatalogueEffectsAlikeBothWays) {
  int pairs = 0;
  for (const rig::EffectInfo& e : rig::effect_catalogue())
    for (const std::string& a : e.alike_at_constant_speed) {
      const std::vector<std::string>& back = rig::effect_info(a).alike_at_constant_speed;
      EXPECT_NE(std::find(back.begin(), back.end(), e.name), back.end()) << e.name << " ~ " << a;
      ++pairs;
    }
  EXPECT_EQ(pairs, 4);  // the squeeze film with each of the two locus effects, both ways
}

TEST(Verdict, BootstrapMeasuresTheHeldOutItemsAgainWithinTheirNoise) {
  const std::vector<Item> items = eight_held_out_units();
  const std::vector<bool> held(items.size(), true);
  const std::size_t n = items.size();
  const std::vector<double> baseline(n, 0.2), cut(n, 0.15);
  const std::vector<Candidate> one{candidate("cut", 1, cut)};
  DiagnosisOptions o;
  o.bootstrap_samples = 400;
  o.unexplained_floors = 1e6;  // the floor rises with the noise; judge the evidence alone here
  const Confidence exact = bootstrap_confidence(items, held, std::vector<double>(n, 0.0), baseline, {}, one, 0, "cut", o);
  EXPECT_EQ(exact.agreement, 1.0);
  const Confidence noisy = bootstrap_confidence(items, held, std::vector<double>(n, 0.1), baseline, {}, one, 0, "cut", o);
  std::printf("confidence %.3f without noise, %.3f with\n", exact.agreement, noisy.agreement);
  EXPECT_GT(noisy.agreement, 0.5);
  EXPECT_LT(noisy.agreement, 0.94);
  EXPECT_GT(noisy.heldout_gap_after_std, exact.heldout_gap_after_std);
  EXPECT_EQ(bootstrap_confidence(items, held, std::vector<double>(n, 0.1), baseline, {}, one, 0, "cut", o).agreement, noisy.agreement);

  // One held-out block: without its noise nothing varies — not estimable. With it, two items
  // cannot carry strong evidence: σ² from the 14 trained items is 0.04 and 0.0225, and in the
  // Gaussian limit each held-out item gains at most ½ ln(0.04/0.0225) + ½ (0.2 + δ)²/0.04 −
  // ½ (0.15 + δ)²/0.0225 ≤ 0.35 nats whatever δ (t₇'s heavier tails change that little) — far
  // below 3, so every resample says "none".
  std::vector<bool> one_block(n, false);
  one_block[0] = one_block[1] = true;
  EXPECT_TRUE(std::isnan(bootstrap_confidence(items, one_block, std::vector<double>(n, 0.0), baseline, {}, one, 0, "cut", o).agreement));
  EXPECT_EQ(bootstrap_confidence(items, one_block, std::vector<double>(n, 0.1), baseline, {}, one, 0, "cut", o).agreement, 0.0);
  EXPECT_EQ(bootstrap_confidence(items, one_block, std::vector<double>(n, 0.1), baseline, {}, one, 0, "none", o).agreement, 1.0);
}

// Refits in the resamples: resample b judges the candidate by its refit on training redraw b mod R.
// A cut that holds with the fit as found (25 %, every resample without noise) but that half of
// the refits lose (the candidate refitted to the baseline's residuals) is confirmed by exactly
// the half of the resamples that pair with a refit keeping it — 0.5 with an even number of
// resamples and no noise. Refitting the baseline to the candidate's residuals, none is.
TEST(Verdict, BootstrapJudgesTheLeadersByTheirRefitsOnTheTrainingRedraws) {
  const std::vector<Item> items = eight_held_out_units();
  const std::vector<bool> held(items.size(), true);
  const std::size_t n = items.size();
  const std::vector<double> baseline(n, 0.2), cut(n, 0.15), noise(n, 0.0);
  const std::vector<Candidate> one{candidate("cut", 1, cut)};
  DiagnosisOptions o;
  o.bootstrap_samples = 400;
  const std::vector<Refit> half{{baseline, {{0, cut}}}, {baseline, {{0, baseline}}}};
  const Confidence c = bootstrap_confidence(items, held, noise, baseline, {}, one, 0, "cut", o, half);
  EXPECT_EQ(c.agreement, 0.5);
  // The chosen candidate's gap alternates between 0.15 and 0.2: its standard deviation is 0.025
  // (times sqrt(400/399) for the sample estimate).
  EXPECT_NEAR(c.heldout_gap_after_std, 0.025 * std::sqrt(400.0 / 399.0), 1e-9);
  const std::vector<Refit> level{{cut, {{0, cut}}}};
  EXPECT_EQ(bootstrap_confidence(items, held, noise, baseline, {}, one, 0, "cut", o, level).agreement, 0.0);
  EXPECT_EQ(bootstrap_confidence(items, held, noise, baseline, {}, one, 0, "none", o, level).agreement, 1.0);
}

}  // namespace
}  // namespace tribo::gap
