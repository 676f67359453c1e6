// Sim-to-real gap diagnosis (DESIGN §7, §8): where the model and the measurements disagree,
// which unmodelled catalogue effect closes the gap, and how far it shrinks on held-out data.
//
// Gap. Every measured item i (compare.h) has a residual r_i = (sim_i − meas_i) / s_o, with s_o the
// RMS of the measured values of its observable o — for friction levels (μ at peaks and troughs,
// mean, static and steady μ) the RMS of all measured levels — and r_i = 1 when the simulation
// lacks the feature.
//     gap_o = sqrt(mean_{i in o} r_i²),     gap = mean_o gap_o,
// over the items of a split: the gap is a relative RMS error, 0.1 = the model is off by 10 % of
// the observable's typical size, averaged so that every observable weighs the same.
//
// Split. Items carry a unit, a block of data (compare.h: one driven speed — its run, static point
// and regime point —, a drive segment's level, three contiguous bins after a step); even units
// train, odd units are held out.
//
// Procedure.
//  1. Calibration, a stage of its own: the model's own free parameters (μs, μk, rig keys the model
//     lacks, and the rig constants the bundle states with a relative uncertainty, within it)
//     fitted on train from four starts (the model's values, levels read off the data, and that
//     reading with μs − μk 20 % smaller and larger), each searched, the best then refined with
//     central differences; what it leaves on train is reported against the training items' noise floor
//     (CalibrationSummary) before any candidate is tried.
//  2. For each catalogue effect not in the model: add it, fit its parameters together with the
//     baseline ones on train (Ceres, bounded, forward numeric differences over simulate(), several
//     starts), evaluate on held-out.
//  3. Likelihood on held-out (verdict.h): every item's residual has the scale of the data's own
//     noise for it plus the error the model claims on its observable's training items (Student's
//     t, its degrees of freedom the number of those training items); a
//     candidate earns its parameters when its held-out log predictive density beats the
//     calibrated baseline's decisively — by more than 3 nats (a likelihood ratio of 20), and by two
//     standard errors of the difference or, where the evidence rests on a few items, with the
//     held-out gap halved. If the best single closes less than `pair_threshold` of the gap, the
//     two best singles are fitted together.
//     A nested pair is judged with each at its best: when thermal thinning (which is viscous
//     friction as U_T → ∞) fits train better, viscous friction is refined again from its projection.
//  4. Verdict: the simplest earning candidate, unless one with more parameters has decisive
//     evidence over it; else "none". Confidence: share of bootstrap resamples of the held-out
//     units that give the same verdict, with the baseline and the leading candidates refitted on
//     redrawn training data.
//
// Open world. The data's own noise (Item::noise, compare.h) gives the *noise floor*: the gap of
// the item standard errors, floor = mean_o sqrt(mean_{i in o} (noise_i / s_o)²) over held-out —
// what a model right in every mechanism would still leave. A gap above
// `unexplained_floors` floors that no earning candidate halves (its excess over the floor,
// sqrt(gap² − floor²)) is reported as "unexplained" with the remaining gap in floors and where it
// lies — rather than naming the least bad catalogue effect.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/compare.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

struct DiagnosisOptions {
  int starts = 3;                      // fits per candidate: from the best grid points (else the defaults, then random points)
  int max_iterations = 12;             // Levenberg-Marquardt iterations per start
  // A held-out gap above this many noise floors is a real disagreement: if no earning candidate
  // halves its excess over the floor, the verdict is "unexplained". The floor holds noise only;
  // a model right in every mechanism but told rig constants a few per cent off (the independent
  // generator's controls: k, M, W, r off by 3-10 %) leaves about 3 floors, which must stay "none".
  double unexplained_floors = 5.0;
  double pair_threshold = 0.5;         // pairs are tried when the best single closes less than this
  int bootstrap_samples = 200;
  // Refits in the resamples: each resample also measures the training items again within their
  // noise, and the baseline and this many leading candidates (the verdict's first) are refitted to
  // it (linearised, gap/refit.h); the others keep their fits. 0, or data without a noise estimate
  // on the training items: every candidate keeps its fit in every resample.
  int refit_leaders = 2;
  std::uint64_t seed = 1;              // random starts, bootstrap, instrument noise
  // Rig keys the model leaves out: stiffness_N_per_m, mass_kg, damping_N_s_per_m (×/÷ 100 around the
  // start), or damping_ratio ζ = r / (2√(kM)) in [1e-3, 0.9] (the damping when k is fitted too).
  std::vector<std::string> calibrate_rig;
  std::vector<std::string> candidates;     // empty: default_candidates(model, bundle kind)
  std::function<void(const std::string&)> progress;  // called after each fit (any thread, serialised)
  // Returns an empty string when valid, else why not.
  std::string invalid_reason() const;
};

struct GapBreakdown {
  double gap = 0.0;
  std::map<std::string, double> by_observable, by_regime, by_phase, by_speed;
};

struct Localization {
  std::string observable, where, worst_item;
  double share = 0.0;  // of the baseline's summed squared residuals
};

// How a least-squares fit (Ceres) ended: its termination type ("CONVERGENCE", "NO_CONVERGENCE" when
// the iteration limit stopped it, ...) and iterations, for the start that gave the result.
struct FitTermination {
  std::string termination = "not fitted";
  int iterations = 0;
  int max_iterations = 0;
  double wall_s = 0.0;  // wall time of the fit, grid and every start included (a candidate's: search and refinement)
};

struct Candidate {
  std::vector<std::string> effects;
  std::map<std::string, double> params;  // "effect.parameter" → fitted value (plus refitted baseline)
  int extra_parameters = 0;
  double train_gap = 0.0, heldout_gap_before = 0.0, heldout_gap_after = 0.0;
  // Held-out evidence over the calibrated baseline (verdict.h): the log-likelihood gain in nats
  // and its standard error; the candidate earns its parameters when it is decisive.
  double evidence_nats = 0.0, evidence_se_nats = 0.0;
  bool earns = false;
  std::map<std::string, double> heldout_after_by_observable;
  rig::FrictionModel model;
  rig::RigParameters rig;
  std::vector<double> residuals;
  FitTermination fit;  // the last fit that made it (search, or refinement for the leaders)
};

struct Verdict {
  std::vector<std::string> effects;  // empty: "none" or "unexplained"
  bool unexplained = false;          // the gap stays well above the noise floor whatever is added
  double heldout_gap_before = 0.0, heldout_gap_after = 0.0, heldout_gap_after_std = 0.0;
  double noise_floor = 0.0;          // held-out gap of the data's own noise (0: the data cannot tell)
  double remaining_floors = 0.0;     // heldout_gap_after / noise_floor (NaN without a floor)
  std::string remaining_where;       // observable and place holding most of what remains
  double confidence = 0.0;
  double confidence_fixed_fits = 0.0;  // the same bootstrap with every fit held where it is
  std::vector<std::string> refitted;   // refitted in the resamples: "baseline" and the leaders
  std::string conclusion;            // one sentence a tribologist can act on
};

// The calibration stage (step 1): how close the baseline's own parameters bring it to the
// training items, against what the data's noise leaves there. A baseline that stays several floors
// above its noise cannot be the whole story whatever a candidate then does; a control's sits
// near one floor.
struct CalibrationSummary {
  int starts = 0;                  // each searched; the best refined
  double train_gap = 0.0;          // the calibrated baseline's gap on the training items
  double train_noise_floor = 0.0;  // the noise floor of the training items (0: the data cannot tell)
  double train_floors() const {    // train_gap / train_noise_floor (NaN without a floor)
    return train_noise_floor > 0.0 ? train_gap / train_noise_floor : std::numeric_limits<double>::quiet_NaN();
  }
};

// Wall time of each stage of diagnose(), so that a slow diagnosis says where its time went.
struct StageTimes {
  double calibration_s = 0.0;    // the starts' searches and the refinement of the best
  double candidates_s = 0.0;     // every single candidate's search
  double recalibration_s = 0.0;  // the baseline re-fitted from the leaders' baseline parameters
  double refinement_s = 0.0;     // the leaders' and nested candidates' refinements, and the pair
  double confidence_s = 0.0;     // the leaders' linearised refits and the bootstrap
};

struct Diagnosis {
  std::vector<Item> items;
  std::vector<bool> heldout;          // per item
  bool has_heldout = true;            // false: one unit only, the "held-out" gap is in-sample
  rig::FrictionModel calibrated;      // baseline after calibration
  rig::RigParameters rig;
  std::map<std::string, double> calibrated_params;  // "baseline.mu_s", "rig.stiffness_N_per_m", ...
  std::map<std::string, double> rig_relative_uncertainty;  // the bundle's, for the rig keys refined within it
  FitTermination calibration_fit;
  CalibrationSummary calibration;
  StageTimes stage_times;
  GapBreakdown baseline, baseline_heldout;
  std::vector<double> baseline_residuals, measured, baseline_simulated, best_simulated;
  std::vector<Localization> localization;
  std::vector<Candidate> candidates;  // best first
  Verdict verdict;
  double integration_tolerance = 0.0;  // CVODE's relative tolerance of the predictions (Comparison)
};

// `model_rig` is the model's rig with the bundle's [rig] keys applied by the caller (apply_bundle_rig).
Diagnosis diagnose(const ExperimentBundle& bundle, const rig::RigParameters& model_rig, const rig::FrictionModel& model,
                   const DiagnosisOptions& options);

// The candidates when the options name none: every catalogue effect the model lacks that the
// catalogue tries on this experiment kind (rig::EffectInfo::diagnosed_in).
std::vector<std::string> default_candidates(const rig::FrictionModel& model, const std::string& kind);

// The model's rig with every [rig] key the bundle gives.
rig::RigParameters apply_bundle_rig(const ExperimentBundle& bundle, rig::RigParameters rig);

// The candidate the verdict names; nullptr for "none" and "unexplained".
const Candidate* verdict_candidate(const Diagnosis& d);

std::string verdict_name(const std::vector<std::string>& effects);  // "none", "a" or "a+b"
std::string verdict_name(const Verdict& v);                         // the same, or "unexplained"

}  // namespace tribo::gap
