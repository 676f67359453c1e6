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
//     central differences — with every observable weighing the same (as in the gap), then again with the
//     likelihood's weights at the scale that fit leaves (DiagnosisOptions::fit_weights,
//     likelihood_weights in verdict.h; the first answer one more start), which the re-calibration
//     and the baseline's bootstrap refits use too; what it leaves on train is reported against the training items' noise floor
//     (CalibrationSummary) before any candidate is tried.
//  2. For each catalogue effect not in the model: add it, fit its parameters together with the
//     baseline ones on train, every observable weighing the same (Ceres, bounded, forward numeric differences over simulate(), several
//     starts), evaluate on held-out.
//  3. Likelihood on held-out (verdict.h): every item's residual has the scale of the data's own
//     noise for it plus the error the model claims on its observable's training items (Student's
//     t, its degrees of freedom the number of those training items); a
//     candidate earns its parameters when its held-out log predictive density beats the
//     calibrated baseline's decisively — by more than 3 nats (a likelihood ratio of 20), and by two
//     standard errors of the difference or, where the evidence rests on a few items, with the
//     held-out gap halved. If the best single closes less than `pair_threshold` of the gap and
//     leaves more than `unexplained_floors` noise floors, the two best singles, when each explains
//     something held out alone (pipeline.h explains), are fitted together, and each is refined
//     again from the pair's fit without the other (pipeline.h reduce_pair).
//     A nested pair is judged with each at its best: when thermal thinning (which is viscous
//     friction as U_T → ∞) fits train better, viscous friction is refined again from its projection.
//  4. Verdict: the simplest earning candidate, unless one with more parameters has decisive
//     evidence over it; else "none" — or, above `unexplained_floors` floors, the simplest candidate
//     that halves the gap's excess over the floor, named tentatively (verdict.h decide).
//     Confidence: share of bootstrap resamples of the held-out
//     units that give the same verdict, with the baseline and the leading candidates refitted on
//     redrawn training data.
//
// Open world. The data's own noise (Item::noise, compare.h) gives the *noise floor*: the gap of
// the item standard errors, floor = mean_o sqrt(mean_{i in o} (noise_i / s_o)²) over held-out —
// what a model right in every mechanism would still leave. A gap above
// `unexplained_floors` floors that no candidate halves (its excess over the floor,
// sqrt(gap² − floor²)) is reported as "unexplained" with the remaining gap in floors and where it
// lies — rather than naming the least bad catalogue effect.
#pragma once

#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/diagnosis_types.h"
#include "gap/pipeline.h"  // default_candidates
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

// `model_rig` is the model's rig with the bundle's [rig] keys applied by the caller (apply_bundle_rig).
Diagnosis diagnose(const ExperimentBundle& bundle, const rig::RigParameters& model_rig, const rig::FrictionModel& model,
                   const DiagnosisOptions& options);

// The model's rig with every [rig] key the bundle gives.
rig::RigParameters apply_bundle_rig(const ExperimentBundle& bundle, rig::RigParameters rig);

// The candidate the verdict names; nullptr for "none" and "unexplained".
const Candidate* verdict_candidate(const Diagnosis& d);

}  // namespace tribo::gap
