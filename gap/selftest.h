// Withheld-effect validation of the diagnosis (issue 6): synthetic "measured" bundles from the
// full model with exactly one catalogue effect switched on (random physical parameters, sensor
// noise, several seeds) plus controls with none; the diagnosis gets the model without that effect
// (and with a miscalibrated baseline) and must name it — or "none" for the controls.
//
// Two generators (issue 15):
//   "rig"          the rig's own simulator, the catalogue's effect code and instrument (below);
//   "independent"  gap/independent/: another integrator, each mechanism in another published
//                  form, a measuring chain (gain, lag, anti-alias filter at a recorder rate,
//                  drift, AR(1) noise, quantisation), rig constants a few per cent off the told
//                  ones. A verdict on these is right when it names the catalogue mechanism the
//                  alternative form stands for.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/diagnosis.h"
#include "gap/synthesize.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

// The development set is what the diagnosis was tuned on (seeds, speeds and strengths of
// SyntheticOptions' defaults); the validation set is drawn afresh and only reported: other seeds
// (a stream of their own for each generator), other driven speeds and test speeds, and effect
// strengths scaled by 0.5–1.5 on the first generator.
enum class SelftestSet { development, validation };
SyntheticOptions synthetic_options(SelftestSet set);

struct SyntheticCase {
  std::string true_effect;                 // "none" for a control
  rig::FrictionModel truth, model;         // model = truth without true_effect, baseline miscalibrated
  ExperimentBundle bundle;
};

// `model_effects` are in both truth and model (e.g. rate_dependent_static with
// strain_rate_hardening as the effect to find).
SyntheticCase make_synthetic_case(const std::string& true_effect, const std::vector<std::string>& model_effects, std::uint64_t seed,
                                  const SyntheticOptions& options);

inline constexpr const char* kRigGenerator = "rig";
inline constexpr const char* kIndependentGenerator = "independent";

struct SelftestCase {
  std::string true_effect;
  std::vector<std::string> model_effects;  // first generator only
  std::uint64_t seed = 1;
  std::string generator = kRigGenerator;
};

// One candidate as a case's diagnosis left it: how close the truth came when it was not named.
struct CandidateFigures {
  std::string effect;  // verdict_name of its effects
  double evidence_nats = 0.0, evidence_se_nats = 0.0, heldout_gap = 0.0;
  bool earns = false;
};

// A proposed test (discriminate.h) run on the truth: for a pair of the verdict and a candidate
// named beside it, one of them the truth, the test that parts their predictions most among those
// the case's generator can run (make_proposed_test_bundles), the truth recorded under it, and which
// of the two fitted models comes nearer that record (TestBlockGap).
struct ProposalCheck {
  std::string against;             // the candidate beside the verdict
  std::string test;                // the proposed test run
  double floors = 0.0;             // its separation of the pair as proposed (ProposedSeparation::floors)
  double gap_verdict = 0.0, gap_against = 0.0;  // each fitted model's gap on the truth's record
  bool truth_nearer = false;       // the one of the pair that is the truth has the smaller gap
  std::string verdict_after;       // the verdict once its record is seen, as `tribo gap diagnose --test` states it (TestBlockGap)
};

struct SelftestRow {
  SelftestCase c;
  std::string verdict;
  std::string form;  // independent generator: the form the mechanism was written in
  double heldout_gap_before = 0.0, heldout_gap_after = 0.0, confidence = 0.0;
  // The held-out gap the data's own noise leaves (Verdict::noise_floor); NaN in journals from before.
  double noise_floor = std::numeric_limits<double>::quiet_NaN();
  // The effect's signal: the calibrated baseline's held-out gap in noise floors (NaN without a floor).
  double signal_floors() const { return noise_floor > 0.0 ? heldout_gap_before / noise_floor : std::numeric_limits<double>::quiet_NaN(); }
  // What the calibrated baseline leaves on the training items, in their noise floors
  // (CalibrationSummary::train_floors); NaN without a floor and in journals from before.
  double train_floors = std::numeric_limits<double>::quiet_NaN();
  // The bootstrap with every fit held (Verdict::confidence_fixed_fits); NaN in journals from before.
  double confidence_fixed_fits = std::numeric_limits<double>::quiet_NaN();
  // The bootstrap's agreement (Verdict::confidence_bootstrap); NaN in journals from before.
  double confidence_bootstrap = std::numeric_limits<double>::quiet_NaN();
  // On the test block (SyntheticOptions::test_speeds_m_per_s); NaN in journals from before it.
  double test_gap_before = std::numeric_limits<double>::quiet_NaN(), test_gap_after = std::numeric_limits<double>::quiet_NaN();
  bool correct = false;
  double wall_s = 0.0;  // the diagnosis' wall time (the speed target is per bundle); 0: not recorded
  StageTimes stage_times;  // where that time went (Diagnosis::stage_times); zeros: not recorded
  std::vector<CandidateFigures> candidates;  // in the diagnosis' ranking; empty in journals from before
  // What the verdict's change adds to the model (Verdict::adds): the verdict's effects, and the locus
  // the hardening brings to a model without one. Journals from before: derived from the verdict.
  std::vector<std::string> verdict_adds;
  std::vector<std::string> indistinguishable_from;  // earning candidates the held-out data do not tell from the verdict
  std::vector<std::string> alike_mechanisms;        // Verdict::alike_mechanisms (empty in journals from before)
  std::vector<ProposalCheck> proposal_checks;       // pairs that hold the truth (empty in journals from before)
  std::string git_commit;                    // the build that diagnosed it (journals); empty: not recorded
  // The truth is the verdict or named beside it (indistinguishable_from, alike_mechanisms).
  bool truth_named_or_listed() const;
  // The truth is among what the verdict adds (verdict_adds); false for controls.
  bool truth_added() const {
    return c.true_effect != "none" && std::find(verdict_adds.begin(), verdict_adds.end(), c.true_effect) != verdict_adds.end();
  }
  // Named without earning its parameters (Verdict::tentative), read from the verdict's candidate
  // figures; false for none, unexplained and journals without candidates.
  bool tentative() const;
};

// An effect is visible in its data when the calibrated baseline misses the held-out items by more
// than this many noise floors (SelftestRow::signal_floors): a control's calibrated baseline sits at
// or below about one floor (the floor is the gap the data's noise alone leaves), so below two the
// data hold little an effect could be told by, whatever the method. Cases are split by it so that
// a score is read against the power the data give (a power analysis, not a filter: every case
// stays in identified_fraction).
inline constexpr double kVisibleSignalFloors = 2.0;

// Confusion matrix and shrink over one generator's cases (or all).
struct SelftestSummary {
  std::map<std::string, std::map<std::string, int>> confusion;  // true → verdict → count
  int effect_cases = 0, controls = 0;
  double identified_fraction = 0.0;   // effect cases with the right verdict
  // Effect cases with signal_floors() ≥ kVisibleSignalFloors, and the share of them named (NaN
  // when none is visible or the rows carry no floor).
  int visible_effect_cases = 0;
  double visible_identified_fraction = std::numeric_limits<double>::quiet_NaN();
  // Effect cases whose true effect is the verdict or among the earning candidates the held-out data
  // do not tell from it (SelftestRow::indistinguishable_from), and how many names those verdicts
  // give on average (1 + the indistinguishable ones): what a reader is told to test next, not the
  // bar — identified_fraction counts the verdict alone. NaN without effect cases.
  double named_or_indistinguishable_fraction = std::numeric_limits<double>::quiet_NaN();
  double mean_names_per_verdict = std::numeric_limits<double>::quiet_NaN();
  // Proposed tests run on the truth (SelftestRow::proposal_checks) whose proposed separation was
  // two floors or more — the ones the conclusion names — and how many of them came out for the truth.
  int deciding_proposals = 0, deciding_proposals_for_truth = 0;
  // Effect cases named once the proposed tests run on the truth are seen: each check's verdict after
  // its record (ProposalCheck::verdict_after) in place of the verdict; a check without one (journals
  // from before it) leaves the verdict.
  int named_after_proposed_tests = 0;
  // Effect cases whose truth is among what the verdict adds (SelftestRow::truth_added): the verdict,
  // or the junction locus a hardening verdict brings to a model without one. Not the bar, which
  // counts the verdict alone: a hardened locus named for a truth the generator wrote as the plain
  // locus's mechanism (static friction that grows with the time at rest) counts here, not there.
  int truth_among_adds = 0;
  // Tentative verdicts (SelftestRow::tentative) of effect cases and controls, and how many were right.
  int tentative_verdicts = 0, tentative_right = 0;
  double controls_none_fraction = 0.0;
  std::map<std::string, double> mean_shrink;  // per true effect, of correctly identified cases: 1 − after/before
  std::map<std::string, double> mean_test_shrink;  // the same on the test block (cases that have one)
};

// Reliability of the reported confidence: verdicts with confidence in [lower, upper) (the last
// bin includes 1), and how many of them were right.
struct ReliabilityBin {
  double lower = 0.0, upper = 1.0;
  int verdicts = 0, right = 0;
};

// The share named by the strength of the effect (SelftestRow::signal_floors): effect cases whose
// signal lies in [lower_floors, upper_floors), how many were named, and how many had the truth named
// or listed beside the verdict (indistinguishable_from, alike_mechanisms: what the report tells a
// reader to tell apart by a further test). A bar such as "90 % named" is read against it: below about
// two floors the data hold little an effect could be told by (kVisibleSignalFloors), and a share
// that stays flat above that is the method's, not the noise's. Cases without a floor are left out.
struct DetectionBin {
  double lower_floors = 0.0, upper_floors = std::numeric_limits<double>::infinity();
  int effect_cases = 0, named = 0, named_or_listed = 0;
};

struct SelftestResult {
  std::vector<SelftestRow> rows;
  // Over all cases (both generators), kept for callers of the one-generator selftest.
  std::map<std::string, std::map<std::string, int>> confusion;
  double identified_fraction = 0.0;
  double controls_none_fraction = 0.0;
  std::map<std::string, double> mean_shrink, mean_test_shrink;
  std::map<std::string, SelftestSummary> by_generator;  // "rig", "independent"
  std::vector<ReliabilityBin> reliability;              // over both generators
  std::map<std::string, std::vector<DetectionBin>> detection;  // by generator
};

// Summaries from rows (used by run_selftest; exposed for tests and resumed journals).
SelftestSummary summarise(const std::vector<SelftestRow>& rows);
std::vector<ReliabilityBin> reliability_table(const std::vector<SelftestRow>& rows);
// Bins of 0–1, 1–2, 2–3, 3–5, 5–10 and ≥ 10 noise floors.
std::vector<DetectionBin> detection_table(const std::vector<SelftestRow>& rows);

// The quick set (CI) or the full set. First generator: every effect × seeds, controls, and the
// second-effect case. Independent generator: quick — one effect and one control; full — every
// effect it has a form for × 2 seeds and 3 controls.
std::vector<SelftestCase> selftest_cases(bool quick, std::uint64_t seed, SelftestSet set = SelftestSet::development);
// The effects the rig generator's model has beside a withheld `effect`: the locus under strain-rate
// hardening, which reshapes it (the selftest's second-effect case); none for any other.
std::vector<std::string> rig_model_effects(const std::string& effect);

// `finished` holds rows of an earlier, interrupted run: a case found there (same true effect,
// model effects and seed) is taken as it is rather than diagnosed again. `on_row` is called for
// every newly diagnosed case, as soon as it is done (to flush it to disk).
SelftestResult run_selftest(const std::vector<SelftestCase>& cases, const SyntheticOptions& synthetic, DiagnosisOptions diagnosis,
                            const std::function<void(const SelftestRow&)>& on_row,
                            const std::vector<SelftestRow>& finished = {});

bool same_case(const SelftestCase& a, const SelftestCase& b);

// A case as the selftest diagnoses it: the bundle, the test block (the same truth at the test
// speeds, its noise drawn with another seed; empty without test speeds), the model the diagnosis starts from (the baseline
// miscalibrated, the withheld effect left out) and the form the effect was written in.
struct CaseBundles {
  ExperimentBundle bundle, test;
  rig::FrictionModel model;
  std::string form;
  std::map<std::string, double> truth_parameters;  // rig generator: "effect.parameter" of the withheld effect;
                                                    // independent: its own forms (independent::truth_parameters)
};
CaseBundles make_case_bundles(const SelftestCase& c, const SyntheticOptions& synthetic);

// The case's truth recorded under each test the diagnosis may propose (discriminate.h, around the
// case's speeds and run length), by test name, noise seeded apart from the bundle's: the rig
// generator every test, the independent one the constant-speed tests (its slide-hold-slide is a
// machine of its own). So that a proposal can be run on a case whose answer is known
// (`tribo gap generate`, then `tribo gap diagnose --test`).
std::map<std::string, ExperimentBundle> make_proposed_test_bundles(const SelftestCase& c, const SyntheticOptions& synthetic);

}  // namespace tribo::gap
