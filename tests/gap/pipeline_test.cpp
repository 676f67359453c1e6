// The diagnosis' stages one at a time (gap/pipeline.h), each on a small synthetic bundle whose truth
// is known: what a stage must do, checked without running the stages after it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "gap/pipeline.h"
#include "gap/selftest.h"

namespace tribo::gap {
namespace {

// Static-friction points only from a Coulomb rig (μs 0.3, μk 0.2; noise 1 % of μk W per point),
// diagnosed against a model whose μs is 20 % high.
ExperimentBundle static_points_bundle() {
  SyntheticOptions so;
  so.speeds_m_per_s = {8e-3, 1.4e-2, 2.4e-2};
  so.duration_s = 1.5;
  ExperimentBundle b = synthesize_bundle(rig::RigParameters{}, rig::coulomb(0.3, 0.2), so, 5);
  b.runs.clear();
  return b;
}

DiagnosisOptions static_options() {
  DiagnosisOptions o;
  o.max_iterations = 6;
  return o;
}

// What a problem fixes before any fit: the split (even units train, odd units held out), weights
// that give every observable on train the same share (Σ_{i in o} w_i² = 1/N_obs), and a search
// space without rig keys.
TEST(Pipeline, TheProblemSplitsByUnitAndWeighsEveryObservableTheSame) {
  const FitProblem p = make_fit_problem(static_points_bundle(), rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  ASSERT_TRUE(p.has_heldout);
  std::map<std::string, double> share;
  for (std::size_t i = 0; i < p.items.size(); ++i) {
    EXPECT_EQ(p.heldout[i], p.items[i].unit % 2 == 1);
    EXPECT_EQ(p.train[i], !p.heldout[i]);
    EXPECT_EQ(p.equal_w[i] > 0.0, p.train[i]);
    share[p.items[i].observable] += p.equal_w[i] * p.equal_w[i];
  }
  for (const auto& [observable, s] : share) EXPECT_NEAR(s, 1.0 / static_cast<double>(share.size()), 1e-12) << observable;
  EXPECT_EQ(p.base_space.size(), 2u);  // μs and μk/μs: the bundle states no rig uncertainty
  EXPECT_EQ(p.search_base.size(), 2u);
  EXPECT_FALSE(p.candidates.empty());
}

// A spring-force channel reads no acceleration, so the instrument's accelerometer lag cannot be
// informed by it: the instrument candidate is searched, and counted, without it — the gain, the
// sensor's time constant and the noise stay.
TEST(Pipeline, OnASpringForceChannelTheInstrumentHasNoLagToFit) {
  const auto instrument_names = [](const FitProblem& p) {
    std::vector<std::string> names;
    for (const FitParameter& q : p.space_of({rig::kInstrument}, false))
      if (q.target == FitParameter::Target::effect) names.push_back(q.name);
    return names;
  };
  ExperimentBundle b = static_points_bundle();
  const FitProblem thesis = make_fit_problem(b, rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  b.spring_force_channel = true;
  const FitProblem spring = make_fit_problem(b, rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  const std::vector<std::string> with = instrument_names(thesis), without = instrument_names(spring);
  EXPECT_EQ(std::count(with.begin(), with.end(), "lag_s"), 1);
  EXPECT_EQ(std::count(without.begin(), without.end(), "lag_s"), 0);
  EXPECT_EQ(without.size() + 1, with.size());
}

// Bad options and candidates the model cannot take are refused before the bundle is read.
TEST(Pipeline, TheProblemRefusesBadOptionsBeforeAnyWork) {
  DiagnosisOptions o = static_options();
  o.starts = 0;
  try {
    make_fit_problem(static_points_bundle(), rig::RigParameters{}, rig::coulomb(0.36, 0.2), o);
    ADD_FAILURE() << "starts = 0 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "gap options: starts must be at least 1");
  }
}

// With an instrument of gain g every friction reading is g times the contact's, so the μs
// coordinate is the reading g μs (fit.h): moving the gain's coordinate alone holds the reading —
// g μs 0.8 × 0.3 = 0.24 at g = 0.6 too, and μk/μs — and coordinates() inverts apply() exactly.
TEST(Pipeline, WithAnInstrumentTheStaticCoordinateIsTheReadingSoTheGainMovesOnlyTheDynamics) {
  std::vector<FitParameter> space = baseline_space(rig::coulomb(0.3, 0.2), rig::RigParameters{}, DiagnosisOptions{}, {});
  const std::vector<FitParameter> gain = effect_parameters("instrument");
  space.insert(space.end(), gain.begin(), gain.end());
  FitSetup s{rig::RigParameters{}, rig::coulomb(0.3, 0.2)};
  s.model.add("instrument");
  s.model.set("instrument", "gain", 0.8);
  std::vector<double> u = coordinates(space, s, false);
  FitSetup back{rig::RigParameters{}, rig::coulomb(0.5, 0.1)};
  back.model.add("instrument");
  apply(space, u, back);
  EXPECT_NEAR(back.model.baseline.mu_s, 0.3, 1e-12);
  EXPECT_NEAR(back.model.baseline.mu_k, 0.2, 1e-12);
  const auto g = std::find_if(space.begin(), space.end(), [](const FitParameter& q) { return q.name == "gain"; });
  u[static_cast<std::size_t>(g - space.begin())] = g->coordinate(0.6);
  apply(space, u, back);
  EXPECT_NEAR(back.model.get("instrument", "gain"), 0.6, 1e-12);
  EXPECT_NEAR(0.6 * back.model.baseline.mu_s, 0.24, 1e-12);
  EXPECT_NEAR(back.model.baseline.mu_k / back.model.baseline.mu_s, 0.2 / 0.3, 1e-12);
}

// Thermal thinning's hump F = c0 U exp(−U/U_T) peaks at c0 U_T / e (rig/effects/thermal_thinning.h).
// Its traction coefficient is searched as c0 U_T / W (FitRange::times_per_normal_load): at W = 50 N,
// c0 = 700 N s/m and U_T = 0.03 m/s that coordinate is 0.42 (= e × the peak μ 0.1545), coordinates()
// inverts apply(), and moving U_T's coordinate alone keeps the hump's height while c0 follows.
TEST(Pipeline, ThermalThinningIsSearchedAlongItsHumpSoMovingTheSpeedKeepsTheHeight) {
  rig::RigParameters r;
  r.normal_load_N = 50.0;
  FitSetup s{r, rig::coulomb(0.3, 0.2)};
  s.model.add("thermal_thinning");
  s.model.set("thermal_thinning", "traction_coefficient_N_s_per_m", 700.0);
  s.model.set("thermal_thinning", "thermal_speed_m_per_s", 0.03);
  const std::vector<FitParameter> space = effect_parameters("thermal_thinning");
  ASSERT_EQ(space.size(), 2u);
  ASSERT_EQ(space[0].name, "traction_coefficient_N_s_per_m");
  std::vector<double> u = coordinates(space, s, false);
  EXPECT_NEAR(space[0].value(u[0]), 700.0 * 0.03 / 50.0, 1e-12);
  FitSetup back{r, rig::coulomb(0.3, 0.2)};
  back.model.add("thermal_thinning");
  apply(space, u, back);
  EXPECT_NEAR(back.model.get("thermal_thinning", "traction_coefficient_N_s_per_m"), 700.0, 1e-9);
  EXPECT_NEAR(back.model.get("thermal_thinning", "thermal_speed_m_per_s"), 0.03, 1e-15);
  u[1] = space[1].coordinate(0.06, false);
  apply(space, u, back);
  EXPECT_NEAR(back.model.get("thermal_thinning", "traction_coefficient_N_s_per_m"), 350.0, 1e-9);
  EXPECT_NEAR(back.model.get("thermal_thinning", "thermal_speed_m_per_s"), 0.06, 1e-15);
}

// Calibration alone: μs recovered from static points to 1 % (each point's noise is 1 % of μk W,
// averaged over the points), and the calibrated baseline fits the training points at least as
// well as the truth does (within 1 %: the truth lies in the model's family, so a calibration that
// converged cannot leave more than the truth's own noise).
TEST(Pipeline, CalibrationRecoversMuSAndFitsTrainAsWellAsTheTruth) {
  const FitProblem p = make_fit_problem(static_points_bundle(), rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  const Calibration cal = calibrate(p);
  EXPECT_NEAR(cal.fit.setup.model.baseline.mu_s, 0.3, 0.003);
  EXPECT_EQ(cal.starts, 5);  // model, data, data ± 20 % excess, and the first answer re-weighed
  const Baseline b = baseline_at(p, cal.fit);
  const std::vector<double> truth = p.comparison->residuals(p.comparison->predict(p.model_rig, rig::coulomb(0.3, 0.2), p.options.seed));
  const double truth_gap = breakdown(p.items, truth, p.train).gap;
  ASSERT_GT(truth_gap, 0.0);
  EXPECT_LE(b.train_gap, 1.01 * truth_gap) << "calibrated " << b.train_gap << ", truth " << truth_gap;
}

// Re-calibration from the leaders: a baseline left 10 % off in μs is replaced by the fit that
// starts from a leader's baseline parameters (the truth here), which fits train better.
TEST(Pipeline, RecalibrationFromALeaderReplacesABaselineLeftOff) {
  const FitProblem p = make_fit_problem(static_points_bundle(), rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  const Calibration cal = calibrate(p);
  const FitSetup off{p.model_rig, rig::coulomb(0.33, 0.2)};
  const Baseline off_baseline = baseline_at(p, fit(*p.comparison, {}, off, cal.weights, p.options, p.options.seed, 1, 0));
  Candidate leader;
  leader.model = rig::coulomb(0.3, 0.2);
  leader.rig = p.model_rig;
  const std::optional<FitResult> better = recalibrate(p, cal, off_baseline, {leader});
  ASSERT_TRUE(better.has_value());
  EXPECT_LT(better->cost, off_baseline.fit.cost);
  EXPECT_NEAR(better->setup.model.baseline.mu_s, 0.3, 0.003);
}

// A candidate that gained only through the baseline's parameters: against a baseline left 10 % off
// in μs, the truth's Coulomb model carrying a viscous term too small to act (c = 1e-6 N s/m) has
// decisive evidence; rebased on it, the baseline is the calibration again (μs within 1 %, the
// noise's reach as above) and the candidate's evidence is below the strong ratio — what it
// gained was the baseline's, so it earns nothing.
TEST(Pipeline, ACandidateThatOnlyMovedTheBaselineEarnsNothingOnceTheBaselineIsRebased) {
  const FitProblem p = make_fit_problem(static_points_bundle(), rig::RigParameters{}, rig::coulomb(0.36, 0.2), static_options());
  const Calibration cal = calibrate(p);
  Baseline b = baseline_at(p, fit(*p.comparison, {}, FitSetup{p.model_rig, rig::coulomb(0.33, 0.2)}, cal.weights, p.options,
                                  p.options.seed, 1, 0));
  Candidate leader;
  leader.effects = {"viscous_friction"};
  leader.extra_parameters = 1;
  leader.rig = p.model_rig;
  leader.model = rig::coulomb(0.3, 0.2);
  leader.model.set("viscous_friction", "coefficient_N_s_per_m", 1e-6);
  leader.residuals = p.comparison->residuals(p.comparison->predict(leader.rig, leader.model, p.options.seed));
  std::vector<Candidate> ranked{leader};
  judge(p, b, 1, ranked[0]);
  ASSERT_TRUE(ranked[0].earns) << ranked[0].evidence_nats << " nats";
  ASSERT_TRUE(rebase(p, cal, b, ranked, 1));
  EXPECT_NEAR(b.setup.model.baseline.mu_s, 0.3, 0.003);
  EXPECT_LT(std::abs(ranked[0].evidence_nats), Evidence::kStrong);
  EXPECT_FALSE(ranked[0].earns);
}

// Traces of a rig with viscous friction (c = 60 N s/m) withheld, against a Coulomb model: the
// problem, calibration and baseline computed once for the stages after them.
class ViscousPipeline : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rig::FrictionModel truth = rig::coulomb(0.32, 0.18);
    truth.set("viscous_friction", "coefficient_N_s_per_m", 60.0);
    SyntheticOptions so;
    so.speeds_m_per_s = {6e-3, 9e-3, 1.3e-2, 1.8e-2};  // below the speed where c = 60 N s/m stabilises sliding
    so.duration_s = 1.5;
    ExperimentBundle bundle = synthesize_bundle(rig::RigParameters{}, truth, so, 11);
    bundle.static_points.clear();
    DiagnosisOptions o;
    o.max_iterations = 8;
    o.candidates = {"viscous_friction", "thermal_thinning"};
    o.bootstrap_samples = 40;
    o.seed = 4;
    problem_ = std::make_unique<FitProblem>(make_fit_problem(bundle, rig::RigParameters{}, rig::coulomb(0.3, 0.2), o));
    calibration_ = std::make_unique<Calibration>(calibrate(*problem_));
    baseline_ = std::make_unique<Baseline>(baseline_at(*problem_, calibration_->fit));
    viscous_ = std::make_unique<Candidate>(search(*problem_, *baseline_, {"viscous_friction"}, 7, 2));
  }
  static void TearDownTestSuite() { problem_.reset(), calibration_.reset(), baseline_.reset(), viscous_.reset(); }
  // A candidate with `model` as its fit, its residuals and gaps from the problem's predictions.
  static Candidate candidate_at(const std::vector<std::string>& effects, const rig::FrictionModel& model) {
    const FitProblem& p = *problem_;
    Candidate c;
    c.effects = effects;
    c.model = model;
    c.rig = baseline_->setup.rig;
    c.residuals = p.comparison->residuals(p.comparison->predict(c.rig, c.model, p.options.seed));
    c.train_gap = breakdown(p.items, c.residuals, p.train).gap;
    c.heldout_gap_after = breakdown(p.items, c.residuals, p.heldout).gap;
    judge(p, *baseline_, 2, c);
    return c;
  }
  static double train_sse(const Candidate& c) {
    return weighted_sse(c.residuals, problem_->equal_w, multiplicity(problem_->train));
  }
  static std::unique_ptr<FitProblem> problem_;
  static std::unique_ptr<Calibration> calibration_;
  static std::unique_ptr<Baseline> baseline_;
  static std::unique_ptr<Candidate> viscous_;
};
std::unique_ptr<FitProblem> ViscousPipeline::problem_;
std::unique_ptr<Calibration> ViscousPipeline::calibration_;
std::unique_ptr<Baseline> ViscousPipeline::baseline_;
std::unique_ptr<Candidate> ViscousPipeline::viscous_;

// The search of the withheld effect alone: it earns its parameter (decisive evidence over the
// baseline, verdict.h) and more than halves the held-out gap; its c lies within a third of the
// truth (eight iterations on a piecewise-smooth cost, as the full diagnosis' test allows).
TEST_F(ViscousPipeline, SearchOfTheWithheldEffectEarnsItsParameter) {
  const Candidate& c = *viscous_;
  EXPECT_TRUE(c.earns) << c.evidence_nats << " ± " << c.evidence_se_nats << " nats";
  EXPECT_GT(c.evidence_nats, Evidence::kStrong);
  EXPECT_DOUBLE_EQ(c.heldout_gap_before, baseline_->heldout.gap);
  EXPECT_LT(c.heldout_gap_after, 0.5 * c.heldout_gap_before);
  EXPECT_NEAR(c.params.at("viscous_friction.coefficient_N_s_per_m"), 60.0, 20.0);
  EXPECT_EQ(c.extra_parameters, 1);
}

// The instrument taken out of a pair keeps what was read: at gain 0.8 a contact μs of 0.4 reads
// 0.32, so the member alone starts from μs 0.32 and μk 0.2 (0.8 × 0.25), with the pair's own
// parameters for the member (c = 45 N s/m) and its rig, and no instrument. The other way round, the
// instrument alone takes the pair's gain and lag and keeps the contact's levels.
TEST(Pipeline, APairWithoutItsInstrumentKeepsTheReadLevels) {
  Candidate pr;
  pr.effects = {"viscous_friction", rig::kInstrument};
  pr.rig.stiffness_N_per_m = 1234.0;
  pr.model = rig::coulomb(0.4, 0.25);
  pr.model.set("viscous_friction", "coefficient_N_s_per_m", 45.0);
  pr.model.add(rig::kInstrument);
  pr.model.set(rig::kInstrument, "gain", 0.8);
  pr.model.set(rig::kInstrument, "lag_s", 2e-3);
  Candidate viscous;
  viscous.effects = {"viscous_friction"};
  viscous.model = rig::coulomb(0.3, 0.2);
  viscous.model.set("viscous_friction", "coefficient_N_s_per_m", 10.0);
  const Candidate from = without_partner(viscous, pr);
  EXPECT_DOUBLE_EQ(from.model.baseline.mu_s, 0.32);
  EXPECT_DOUBLE_EQ(from.model.baseline.mu_k, 0.2);
  EXPECT_EQ(from.model.get("viscous_friction", "coefficient_N_s_per_m"), 45.0);
  EXPECT_FALSE(from.model.instrument.has_value());
  EXPECT_EQ(from.rig.stiffness_N_per_m, 1234.0);

  Candidate instrument;
  instrument.effects = {rig::kInstrument};
  instrument.model = rig::coulomb(0.3, 0.2);
  instrument.model.add(rig::kInstrument);
  const Candidate gain = without_partner(instrument, pr);
  EXPECT_EQ(gain.model.get(rig::kInstrument, "gain"), 0.8);
  EXPECT_EQ(gain.model.get(rig::kInstrument, "lag_s"), 2e-3);
  EXPECT_EQ(gain.model.baseline.mu_s, 0.4);
  EXPECT_TRUE(gain.model.effects.empty());
}

// Refinement continues the search's fit: Levenberg–Marquardt accepts no step uphill, so the
// training cost (the fits' weighted sum of squares) cannot rise — to the simulation's round-off.
TEST_F(ViscousPipeline, RefinementNeverLeavesTheTrainingCostHigher) {
  const Candidate refined = refine(*problem_, *baseline_, *viscous_, 2);
  EXPECT_LE(train_sse(refined), train_sse(*viscous_) * (1.0 + 1e-9));
  EXPECT_GE(refined.fit.wall_s, viscous_->fit.wall_s);  // the search's time counted in
}

// The first five of the ranking are refined (the rig free, the refinement's budget of at least 20
// iterations) and the rest keep their searches: a search holds the rig where the calibration put
// it, which absorbs part of the missing effect, so a leader ranked fifth by its search may be the
// one that earns once the rig moves (development seed 404, docs/gap.md). A leader that explains
// nothing held out (no evidence, no held-out gap below the baseline's) keeps its search too.
TEST_F(ViscousPipeline, TheFiveLeadersThatExplainSomethingAreRefinedAndTheOthersKeepTheirSearch) {
  std::vector<Candidate> ranked(6, *viscous_);
  ranked[2].evidence_nats = -0.3;
  ranked[2].heldout_gap_after = ranked[2].heldout_gap_before;
  const std::vector<Candidate> out = refine_leaders(*problem_, *baseline_, ranked, 2);
  ASSERT_EQ(out.size(), 6u);
  for (std::size_t k : {0u, 1u, 3u, 4u}) {
    EXPECT_EQ(out[k].fit.max_iterations, 20) << k;
    EXPECT_GT(out[k].fit.wall_s, viscous_->fit.wall_s) << k;
    EXPECT_LE(train_sse(out[k]), train_sse(*viscous_) * (1.0 + 1e-9)) << k;
  }
  for (std::size_t k : {2u, 5u}) {
    EXPECT_EQ(out[k].fit.max_iterations, viscous_->fit.max_iterations) << k;
    EXPECT_EQ(out[k].fit.wall_s, viscous_->fit.wall_s) << k;
    EXPECT_EQ(out[k].residuals, viscous_->residuals) << k;
  }
}

// A leader's other form (the slip transient's other state law) is refined beside it and the better
// of the two kept: the search ranks the forms before either has converged (validation case 15094,
// docs/gap.md). The viscous search (truth c = 60 N s/m) beside the viscous force at c = 0, which
// explains nothing held out and is not refined: whichever of the two leads, the refined search is
// kept. Its refined fit lands at 59.4 N s/m; 5 % is the noise of four speeds, not a search's miss
// (c = 0 kept would be 100 % off).
TEST_F(ViscousPipeline, ALeadersOtherFormIsRefinedBesideItAndTheBetterKept) {
  rig::FrictionModel without_force = baseline_->setup.model;
  without_force.set("viscous_friction", "coefficient_N_s_per_m", 0.0);
  const Candidate nothing = candidate_at({"viscous_friction"}, without_force);
  ASSERT_FALSE(explains(nothing));
  for (const bool search_leads : {false, true}) {
    Candidate leader = search_leads ? *viscous_ : nothing;
    leader.other_form = std::make_shared<const Candidate>(search_leads ? nothing : *viscous_);
    const std::vector<Candidate> out = refine_leaders(*problem_, *baseline_, {leader}, 2);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(out[0].fit.max_iterations, 20) << search_leads;  // a refinement's budget
    EXPECT_FALSE(out[0].other_form) << search_leads;
    EXPECT_TRUE(out[0].earns) << search_leads;
    EXPECT_LE(train_sse(out[0]), train_sse(*viscous_) * (1.0 + 1e-9)) << search_leads;
    EXPECT_NEAR(out[0].model.get("viscous_friction", "coefficient_N_s_per_m"), 60.0, 3.0) << search_leads;
  }
}

// Either sign of explaining suffices: positive held-out evidence, or a held-out gap below the
// baseline's (a candidate can cut the gap and still lose nats to its parameters' spread).
TEST(Pipeline, ACandidateExplainsByEvidenceOrByAHeldOutGapBelowTheBaselines) {
  Candidate c;
  c.heldout_gap_before = 0.2, c.heldout_gap_after = 0.2, c.evidence_nats = 0.0;
  EXPECT_FALSE(explains(c));
  c.evidence_nats = 0.5;
  EXPECT_TRUE(explains(c));
  c.evidence_nats = -3.0, c.heldout_gap_after = 0.19;
  EXPECT_TRUE(explains(c));
}

// Nested candidates: thermal thinning with U_T far above the slip speeds is viscous friction with
// c = c0. With thermal thinning at the truth (μs, μk and c0 = 60 N s/m, U_T = 10 m/s) fitting train better
// than a viscous fit stopped at c = 25 N s/m, viscous friction is refined from the projection
// c = 60 and kept: it then fits train as well as its generalisation (within 5 %) and its c lies
// within 10 % of the truth.
TEST_F(ViscousPipeline, ANestedSpecialEffectIsRefinedFromItsGeneralisationsProjection) {
  rig::FrictionModel thermal = rig::coulomb(0.32, 0.18);  // the truth's levels
  thermal.set("thermal_thinning", "traction_coefficient_N_s_per_m", 60.0);
  thermal.set("thermal_thinning", "thermal_speed_m_per_s", 10.0);
  rig::FrictionModel stopped = rig::coulomb(0.32, 0.18);
  stopped.set("viscous_friction", "coefficient_N_s_per_m", 25.0);
  const Candidate general = candidate_at({"thermal_thinning"}, thermal), special = candidate_at({"viscous_friction"}, stopped);
  ASSERT_LT(general.train_gap, special.train_gap);
  const std::vector<Candidate> out = nest(*problem_, *baseline_, {general, special}, 2);
  const auto viscous = std::find_if(out.begin(), out.end(), [](const Candidate& c) { return c.effects[0] == "viscous_friction"; });
  ASSERT_NE(viscous, out.end());
  EXPECT_LT(viscous->train_gap, 1.05 * general.train_gap);
  EXPECT_NEAR(viscous->model.get("viscous_friction", "coefficient_N_s_per_m"), 60.0, 6.0);
}

// A pair nests each member: with an instrument at its null (gain 1, no lag) beside viscous friction
// at the truth (c = 60 N s/m), the pair fits train better than a viscous fit stopped at c = 25 N s/m;
// viscous friction is refined from the pair's fit without the instrument and kept: it then fits
// train as well as the pair (within 5 %) and its c lies within 10 % of the truth. The instrument's
// own single, which fits train worse than the pair too, is projected the same way but kept only
// if that refinement improved on it (never worse on train).
TEST_F(ViscousPipeline, APairsMembersAreRefinedFromThePairsFit) {
  rig::FrictionModel truth = rig::coulomb(0.32, 0.18);
  truth.set("viscous_friction", "coefficient_N_s_per_m", 60.0);
  truth.add(rig::kInstrument);
  rig::FrictionModel stopped = rig::coulomb(0.32, 0.18);
  stopped.set("viscous_friction", "coefficient_N_s_per_m", 25.0);
  rig::FrictionModel gain_only = rig::coulomb(0.32, 0.18);
  gain_only.add(rig::kInstrument);
  gain_only.set(rig::kInstrument, "gain", 1.1);
  const Candidate pr = candidate_at({"viscous_friction", rig::kInstrument}, truth);
  const Candidate special = candidate_at({"viscous_friction"}, stopped), instrument = candidate_at({rig::kInstrument}, gain_only);
  ASSERT_LT(pr.train_gap, special.train_gap);
  ASSERT_LT(pr.train_gap, instrument.train_gap);
  const std::vector<Candidate> out = reduce_pair(*problem_, *baseline_, {special, instrument}, pr, 2);
  ASSERT_EQ(out.size(), 2u);
  const auto viscous = std::find_if(out.begin(), out.end(), [](const Candidate& c) { return c.effects[0] == "viscous_friction"; });
  ASSERT_NE(viscous, out.end());
  EXPECT_LT(viscous->train_gap, 1.05 * pr.train_gap);
  EXPECT_NEAR(viscous->model.get("viscous_friction", "coefficient_N_s_per_m"), 60.0, 6.0);
  EXPECT_FALSE(viscous->model.instrument.has_value());
  const auto gain = std::find_if(out.begin(), out.end(), [](const Candidate& c) { return c.effects[0] == rig::kInstrument; });
  ASSERT_NE(gain, out.end());
  EXPECT_LE(gain->train_gap, instrument.train_gap);
}

// No pair when the best single closes more than pair_threshold (0.5) of the held-out gap: the
// candidates come back as they were, judged among as many comparisons as before.
TEST_F(ViscousPipeline, NoPairIsTriedWhenTheBestSingleClosesMostOfTheGap) {
  ASSERT_LT(viscous_->heldout_gap_after, 0.5 * viscous_->heldout_gap_before);
  Candidate other = *viscous_;
  other.effects = {"thermal_thinning"};
  const Paired out = pair(*problem_, *baseline_, {*viscous_, other}, 2, 0.0);
  EXPECT_EQ(out.candidates.size(), 2u);
  EXPECT_EQ(out.comparisons, 2);
}

// No pair either when no single closes anything but the gap lies within unexplained_floors (5)
// noise floors: here 4 floors. A pair would compete only with `none` on a gap the noise nearly
// covers; the candidates come back as they were, among as many comparisons.
TEST_F(ViscousPipeline, NoPairIsTriedWhenTheGapLiesWithinTheUnexplainedFloors) {
  Candidate flat = *viscous_, other = *viscous_;
  flat.heldout_gap_after = flat.heldout_gap_before;  // closes nothing
  other.effects = {"thermal_thinning"};
  other.heldout_gap_after = other.heldout_gap_before;
  ASSERT_GT(baseline_->heldout.gap, 0.0);
  const Paired out = pair(*problem_, *baseline_, {flat, other}, 2, flat.heldout_gap_before / 4.0);
  EXPECT_EQ(out.candidates.size(), 2u);
  EXPECT_EQ(out.comparisons, 2);
  EXPECT_EQ(problem_->options.unexplained_floors, 5.0);  // the 4 floors above lie below it
}

// No pair unless both leaders explain something alone, though the gap (20 floors) lies far above
// the unexplained floors and the best closes nothing: here the best explains nothing held out and
// the second does. A pair stands for two effects at once, each of which explains its part alone;
// pairs with a member that did not were never named in the validation sets (docs/gap.md).
TEST_F(ViscousPipeline, NoPairIsTriedUnlessBothLeadersExplainSomething) {
  Candidate flat = *viscous_, other = *viscous_;
  flat.heldout_gap_after = flat.heldout_gap_before, flat.evidence_nats = -1.0;
  other.effects = {"thermal_thinning"};
  ASSERT_TRUE(explains(other));
  const Paired out = pair(*problem_, *baseline_, {flat, other}, 2, flat.heldout_gap_before / 20.0);
  EXPECT_EQ(out.candidates.size(), 2u);
  EXPECT_EQ(out.comparisons, 2);
}

// A qualitative miss outranks any cost (fit.h better_fit): from a leader that slides steadily
// through the stick-slip runs (μs = μk, every extremum, period and drop missing, residual 1 each),
// the re-calibration reaches a lower cost than a baseline left far off (μs 0.38, μk 0.18 against
// the truth's 0.32 and 0.18; every feature there) — and does not replace it.
TEST_F(ViscousPipeline, ABaselineThatSlidesSteadilyNeverReplacesOneThatStickSlips) {
  const FitProblem& p = *problem_;
  const Baseline off = baseline_at(p, fit(*p.comparison, {}, FitSetup{baseline_->setup.rig, rig::coulomb(0.38, 0.18)}, calibration_->weights,
                                          p.options, p.options.seed, 1, 0));
  ASSERT_EQ(off.fit.missing_items, 0);
  Candidate steady;
  steady.effects = {"viscous_friction"};
  steady.rig = baseline_->setup.rig;
  steady.model = rig::coulomb(0.2, 0.2);
  const FitResult from_steady = fit(*p.comparison, p.base_space, FitSetup{steady.rig, steady.model}, calibration_->weights, p.options,
                                    p.options.seed, 1, p.base_space.size(), Resolution::refine);
  ASSERT_GT(from_steady.missing_items, 0);
  ASSERT_LT(from_steady.cost, off.fit.cost);  // by cost alone it would win
  EXPECT_FALSE(recalibrate(p, *calibration_, off, {steady}).has_value());
  // A leader that stick-slips still moves it: the truth's levels re-calibrate below the far-off cost.
  Candidate near = steady;
  near.model = rig::coulomb(0.32, 0.18);
  const auto moved = recalibrate(p, *calibration_, off, {near});
  ASSERT_TRUE(moved.has_value());
  EXPECT_EQ(moved->missing_items, 0);
  EXPECT_LT(moved->cost, off.fit.cost);
}

// The choice and its confidence: the earning candidate is chosen (not unexplained), and with the
// baseline and the verdict's candidate refitted on redrawn training data, the resamples agree with
// the verdict at least 80 % of the time (a cut of more than half the gap on four speeds).
TEST_F(ViscousPipeline, TheEarningCandidateIsChosenWithHighConfidence) {
  const std::vector<Candidate> cs{*viscous_};
  const Choice choice = choose(*problem_, *baseline_, cs, 1, breakdown(problem_->items, problem_->noise_r, problem_->heldout).gap);
  ASSERT_EQ(choice.index, 0);
  EXPECT_FALSE(choice.unexplained);
  const ConfidenceStage conf = confidence(*problem_, *calibration_, *baseline_, cs, 0, "viscous_friction");
  ASSERT_EQ(conf.refitted.size(), 2u);
  EXPECT_EQ(conf.refitted[0], "baseline");
  EXPECT_EQ(conf.refitted[1], "viscous_friction");
  EXPECT_GE(conf.with_refits.agreement, 0.8);
  EXPECT_GE(conf.fixed.agreement, 0.8);
}

}  // namespace
}  // namespace tribo::gap
