// gap/discriminate.h: the tests the diagnosis proposes to tell two indistinguishable candidates
// apart, and the slide-hold-slide records the rig generator writes for them (gap/synthesize.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/junction_locus.h"
#include "gap/compare.h"
#include "gap/discriminate.h"
#include "gap/report.h"
#include "gap/verdict.h"
#include "gap/synthesize.h"

namespace tribo::gap {
namespace {

const std::vector<double> kSpeeds{4.5e-3, 8e-3, 1.4e-2, 2.4e-2, 3.8e-2};

// A static-friction locus through μs = 0.33 at the middle speed's load rate, asymptote 0.5 (the
// selftest's draw, gap/selftest.cpp).
contact::JunctionLocus locus_through_middle(const rig::RigParameters& rig) {
  contact::JunctionLocus l;
  l.sigma0_over_tau_i = contact::sigma0_over_tau_i_from_upper_asymptote(0.5, l.alpha);
  l.location_per_s = contact::location_through_point_per_s(l, rig.stiffness_N_per_m * kSpeeds[2] / rig.normal_load_N, 0.33);
  return l;
}

rig::FrictionModel locus_model(const contact::JunctionLocus& l) {
  rig::FrictionModel m;
  m.baseline.mu_s = 0.33, m.baseline.mu_k = 0.18;
  m.add("rate_dependent_static");
  m.set("rate_dependent_static", "mu_s_max", 0.5);
  m.set("rate_dependent_static", "location_per_s", l.location_per_s);
  return m;
}

// A squeeze film with τ_sq = (3π η R⁴ / 4W)(4/h² − 1/h²) = 0.25 s on the thesis rig (h = 0.32 µm,
// R = 2 mm, η = 0.021 Pa s, W = 93.9 N): gone after a 10 s hold (e^−40 of it left).
rig::FrictionModel squeeze_model() {
  rig::FrictionModel m;
  m.baseline.mu_s = 0.33, m.baseline.mu_k = 0.18;
  m.add("squeeze_film");
  m.set("squeeze_film", "film_fraction", 0.5);
  m.set("squeeze_film", "build_up_distance_m", 1e-3);
  m.set("squeeze_film", "film_thickness_m", 3.18e-7);
  return m;
}

// The largest μ in the first 0.5 s after each resumption of the drive: the first breakaway after
// each hold (the spring reloads from where the hold left it at k V, within 0.25 s here).
std::vector<double> peaks_after_holds(const ExperimentBundle& b, double W) {
  const Trace& tr = b.runs.at(0).trace;
  std::vector<double> peaks;
  for (std::size_t i = 1; i < tr.t_s.size(); ++i) {
    if (!(tr.v_drive_m_per_s[i - 1] == 0.0 && tr.v_drive_m_per_s[i] > 0.0)) continue;
    double peak = 0.0;
    for (std::size_t j = i; j < tr.t_s.size() && tr.t_s[j] < tr.t_s[i] + 0.5; ++j) peak = std::max(peak, tr.friction_N[j] / W);
    peaks.push_back(peak);
  }
  return peaks;
}

SyntheticOptions noiseless_holds() {
  SyntheticOptions o;
  o.speeds_m_per_s = kSpeeds;
  o.noise_fraction = 0.0;
  o.hold_times_s = {1.0, 3.0, 10.0};
  return o;
}

// Thesis (3.1.24): static friction read from the load rate at slip alone. After a hold the spring
// reloads at k V as before it, so every peak is μs(k V / W) of the locus, whatever the hold — no
// healing. To 1e-3: the largest sample lies below the breakaway by at most one stick sample's rise
// (2.6e-4 here, the same after every hold).
TEST(ProposedTests, ALoadRateLocusDoesNotHealInAHold) {
  const rig::RigParameters rig;
  const contact::JunctionLocus l = locus_through_middle(rig);
  const ExperimentBundle b = synthesize_bundle(rig, locus_model(l), noiseless_holds(), 1);
  ASSERT_EQ(b.kind, "slide_hold_slide");
  const std::vector<double> peaks = peaks_after_holds(b, rig.normal_load_N);
  ASSERT_EQ(peaks.size(), 3u);
  const double mu_s = contact::static_friction_from_load_rate(l, rig.stiffness_N_per_m * kSpeeds[2] / rig.normal_load_N);
  for (double p : peaks) EXPECT_NEAR(p, mu_s, 1e-3);
}

// A squeeze film (thesis Appendix III) thins at rest as e^(−t/τ_sq): after a hold of 40 τ_sq the
// solid contact carries the whole load and the peak is the baseline μs, 0.33, to the same 1e-3;
// after the 1 s hold (4 τ_sq: up to 2 % of the film's share left) it is lower — where the locus'
// peaks above agree to the last digit.
TEST(ProposedTests, ASqueezeFilmHealsInAHoldToTheSolidStaticFriction) {
  const rig::RigParameters rig;
  const ExperimentBundle b = synthesize_bundle(rig, squeeze_model(), noiseless_holds(), 1);
  const std::vector<double> peaks = peaks_after_holds(b, rig.normal_load_N);
  ASSERT_EQ(peaks.size(), 3u);
  EXPECT_NEAR(peaks[2], 0.33, 1e-3);
  EXPECT_LT(peaks[0], peaks[2]);
}

// A model against itself: both predictions are the same simulation, so every test separates them
// by exactly nothing, while each test's record carries its noise (a floor above 0). A separation
// measured against the noisy record instead of between the predictions would read about one
// floor here.
TEST(ProposedTests, AModelIsSeparatedFromItselfByNothing) {
  const rig::RigParameters rig;
  const rig::FrictionModel m = squeeze_model();
  const std::vector<ProposedTest> tests = proposed_tests(kSpeeds, 2.0, 0.01);
  ASSERT_EQ(tests.size(), 4u);
  for (const ProposedTest& t : tests) {
    const Separation s = TestRecord(t, rig, m, 3).against(rig, m);
    EXPECT_EQ(s.gap, 0.0) << t.name;
    EXPECT_GT(s.noise_floor, 0.0) << t.name;
    EXPECT_GT(s.items, 0) << t.name;
  }
}

// A proposed test's floor is what its record's noise leaves or, when that is more, what the
// record's own model leaves on it. The constant-speed analysis predicts a model's own record to a
// fifth of its noise floor (a Coulomb slider and a rugosity lift, thesis rig): their floors are
// the noise's. A slide-hold-slide on this stick-slipping rig does not — its steady levels are
// window means of a stick-slip whose phase each restart sets — and misses its own record by about
// its noise floor (0.96 of it for this lift), which a separation has to clear as well.
TEST(ProposedTests, ATestIsJudgedAgainstWhatItsOwnModelMissesOnItsRecord) {
  const rig::RigParameters rig;
  rig::FrictionModel m;
  m.baseline.mu_s = 0.33, m.baseline.mu_k = 0.18;
  m.add("hydrodynamic_lift");
  m.set("hydrodynamic_lift", "max_fraction", 0.5);
  m.set("hydrodynamic_lift", "half_speed_m_per_s", 0.02);
  for (const ProposedTest& t : proposed_tests(kSpeeds, 2.0, 0.01)) {
    const rig::RigParameters scaled = t.rig_for(rig);
    const Comparison c(synthesize_bundle(scaled, m, t.runs, 5), scaled);
    const std::vector<bool> all(c.items().size(), true);
    const double noise = breakdown(c.items(), c.relative_noise(), all).gap;
    const double own = breakdown(c.items(), c.residuals(c.predict(scaled, m, 5)), all).gap;
    EXPECT_DOUBLE_EQ(TestRecord(t, rig, m, 5).against(rig, m).noise_floor, std::max(noise, own)) << t.name;
    if (t.name == "slide_hold_slide") EXPECT_GT(own, 0.5 * noise) << t.name;
    else EXPECT_LT(own, 0.2 * noise) << t.name;
  }
}

// The conclusion names, for each candidate the held-out data do not tell from the verdict, the
// proposed test that parts them most when it parts them by two floors or more, and says so when
// none does — read off the rows the diagnosis stored, largest first per candidate.
TEST(ProposedTests, TheConclusionNamesTheTestThatDecidesOrSaysNoneDoes) {
  Diagnosis d;
  Candidate chosen;
  chosen.effects = {"rate_dependent_static"};
  chosen.heldout_gap_before = 0.07, chosen.heldout_gap_after = 0.035;
  d.candidates = {chosen};
  d.verdict.effects = d.verdict.adds = chosen.effects;
  d.verdict.heldout_gap_before = 0.07, d.verdict.heldout_gap_after = 0.035;
  d.verdict.indistinguishable = {"squeeze_film", "strain_rate_hardening"};
  d.proposed_tests = {{"squeeze_film", "stiffer_spring", "the present speeds with a spring twice as stiff", 0.057, 0.011, 5.2},
                      {"squeeze_film", "heavier_load", "the present speeds at twice the normal load", 0.13, 0.035, 3.6},
                      {"strain_rate_hardening", "wider_speeds", "runs at 0.0015 and 0.114 m/s", 0.088, 0.051, 1.7}};
  const std::string text = conclusion(d, &d.candidates.front());
  EXPECT_NE(text.find("to decide against squeeze_film: the present speeds with a spring twice as stiff (stiffer_spring), where their "
                      "predictions differ by 5.2 noise floors"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("heavier_load"), std::string::npos) << text;
  EXPECT_NE(text.find("against strain_rate_hardening none of the proposed tests decides (the best, wider_speeds, separates them by 1.7"),
            std::string::npos)
      << text;
}

// An alike mechanism (verdict.h alike_mechanisms) is named with why the confidence is shared, and
// with the proposed test that parts it from the verdict's.
TEST(ProposedTests, TheConclusionSaysWhichMechanismShareTheConfidenceAndWhatPartsThem) {
  Diagnosis d;
  Candidate chosen;
  chosen.effects = {"squeeze_film"};
  d.candidates = {chosen};
  d.verdict.effects = d.verdict.adds = chosen.effects;
  d.verdict.heldout_gap_before = 0.42, d.verdict.heldout_gap_after = 0.03;
  d.verdict.alike_mechanisms = {"rate_dependent_static"};
  d.proposed_tests = {{"rate_dependent_static", "slide_hold_slide", "a slide-hold-slide at 0.014 m/s", 0.3, 0.02, 15.0}};
  const std::string text = conclusion(d, &d.candidates.front());
  EXPECT_NE(text.find("cannot tell its mechanism from that of rate_dependent_static, which explains the gap as well: the confidence is "
                      "shared between the two mechanisms; to decide against rate_dependent_static: a slide-hold-slide at 0.014 m/s "
                      "(slide_hold_slide)"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("held-out data do not tell"), std::string::npos) << text;
}

// Against a mechanism alike at constant speed only a hold or a heavier load is proposed: a stiffer
// spring shortens the stick time as a faster drive does, so it parts the two fitted forms (20
// floors on the case below) and says nothing of the mechanisms; against any other candidate every
// test may decide.
TEST(ProposedTests, OnlyAHoldOrAHeavierLoadCanDecideBetweenMechanismsAlikeAtConstantSpeed) {
  Verdict v;
  v.effects = {"squeeze_film"};
  v.alike_mechanisms = {"rate_dependent_static"};
  v.indistinguishable = {"viscous_friction"};
  EXPECT_TRUE(can_decide(v, "rate_dependent_static", "slide_hold_slide"));
  EXPECT_TRUE(can_decide(v, "rate_dependent_static", "heavier_load"));
  EXPECT_FALSE(can_decide(v, "rate_dependent_static", "stiffer_spring"));
  EXPECT_FALSE(can_decide(v, "rate_dependent_static", "wider_speeds"));
  EXPECT_TRUE(can_decide(v, "viscous_friction", "stiffer_spring"));
  EXPECT_TRUE(can_decide(v, "viscous_friction", "wider_speeds"));
}

// Constant-speed runs at one normal load do not part a squeeze film from the junction locus; a
// drive history (here the holds) or traces a factor 2 apart in normal stress do. 1.5 is not 2.
TEST(ProposedTests, OnlyAHoldOrATwofoldLoadPartsTheMechanismsAlikeAtConstantSpeed) {
  const rig::RigParameters rig;
  SyntheticOptions constant = noiseless_holds();
  constant.hold_times_s.clear();
  ExperimentBundle b = synthesize_bundle(rig, squeeze_model(), constant, 1);
  EXPECT_FALSE(parts_alike_mechanisms(b));
  EXPECT_TRUE(parts_alike_mechanisms(synthesize_bundle(rig, squeeze_model(), noiseless_holds(), 1)));
  b.runs[0].trace.normal_stress_Pa.assign(b.runs[0].trace.t_s.size(), 1.0e6);
  b.runs[1].trace.normal_stress_Pa.assign(b.runs[1].trace.t_s.size(), 1.5e6);
  EXPECT_FALSE(parts_alike_mechanisms(b));
  b.runs[1].trace.normal_stress_Pa.back() = 2.0e6;
  EXPECT_TRUE(parts_alike_mechanisms(b));
}

}  // namespace
}  // namespace tribo::gap
