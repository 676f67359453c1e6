// The diagnosis' stages after the fits (diagnosis.h, steps 3–4), with explicit inputs and outputs:
// the one gap function and the one likelihood that every stage uses, where the baseline
// misses (localisation), the verdict rule, and the verdict's bootstrap confidence. They need no
// simulation, so their unit tests run in milliseconds (tests/gap/verdict_test.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "gap/compare.h"
#include "gap/diagnosis_types.h"

namespace tribo::gap {

// How often each item counts in a split: 0 outside it, 1 inside, k when a bootstrap resample drew
// its unit k times.
using Multiplicity = std::vector<double>;
Multiplicity multiplicity(const std::vector<bool>& mask);

// The gap (diagnosis.h): gap = mean_o sqrt(Σ_{i in o} m_i r_i² / Σ_{i in o} m_i) over the
// observables o with items in the split; 0 for an empty split.
double gap(const std::vector<Item>& items, const std::vector<double>& r, const Multiplicity& m);
// The same gap with its tables by observable, regime, phase and speed class.
GapBreakdown breakdown(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<bool>& mask);

// Residual weights that make every observable in `mask` weigh the same whatever its number of
// items: w_i = 1 / sqrt(n_o · N_obs) inside the split, 0 outside.
std::vector<double> weights(const std::vector<Item>& items, const std::vector<bool>& mask);
// S = Σ m_i w_i² r_i².
double weighted_sse(const std::vector<double>& r, const std::vector<double>& w, const Multiplicity& m);

// The likelihood the candidates are compared by (diagnosis.h step 3). Item i's residual has the
// scale σ_i² = s_i² + τ_o²(model):
//   s_i   the item's measurement standard error in gap units (Item::noise / scale), its own
//         estimate or, where the data give none, the RMS of its observable's estimates (0 when
//         the observable has none) — `item_noise`;
//   τ_o²  what the model leaves beyond that noise on the training items of the item's
//         observable, max(0, mean_train (r_i² − s_i²)) — the model's own claim of its error,
//         made before it sees the held-out items (all items of o when o has no training item);
// and, since τ_o is estimated from the n_o training items of its observable, the predictive
// density is Student's t with ν = n_o degrees of freedom about 0 with that scale (the posterior
// predictive of a Gaussian of unknown variance): a scale claimed from two items that happened to
// fit does not turn a small held-out miss into thousands of nats. σ is at least kResolution,
// 0.1 % of the observable's typical size — finer than the simulation resolves (its integration
// error is kept 1e-3 below the data's noise). The held-out log predictive density Σ_held m_i
// ln t_ν(r_i; σ_i) rewards a model for predicting held-out items within what it claimed and
// charges one that fitted its training noise; noise-free observables weigh more than noisy ones.
// A fitted model's σ_i² also carries what its fit leaves unknown about its parameters, v_i
// (gap/laplace.h: the Laplace variance J_i Σ_u J_iᵀ; empty: none): a model that fits its training
// items below their noise with parameters those items fix loosely is not, for that, sure of the
// held-out items (set 9092's Kato case, docs/gap.md: fitted to 0.015, σ the noise alone, 0.001 on
// one held-out item it then missed by 0.029).
std::vector<double> item_noise(const std::vector<Item>& items, const std::vector<double>& noise_r);
struct Predictive {
  static constexpr double kResolution = 1e-3;
  std::vector<double> sd, dof;  // σ_i and ν_i of every item
};
// The predictive of a model with residuals `r` (its τ_o and ν from the items in `train`).
Predictive predictive(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& s,
                      const std::vector<bool>& train, const std::vector<double>& parameter_variance = {});
// The weights the fits use once the calibration has a first answer (diagnosis.h step 1): item i
// on train weighs 1/σ_i, σ_i the predictive scale of the model with residuals `r` (its noise s_i
// plus the error τ_o that model leaves on its observable), 0 elsewhere. A least-squares fit with
// them maximises the Gaussian likelihood of the training items at that scale — one reweighting
// of iteratively reweighted least squares — so the fits and the verdict weigh items alike: a level
// measured to 0.1 % counts for more than a transient the model misses by half.
std::vector<double> likelihood_weights(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& s,
                                       const std::vector<bool>& train);
// ln t_ν(r_i; 0, σ_i) per item.
std::vector<double> log_density(const std::vector<double>& r, const Predictive& p);

// The held-out evidence of model a over model b: gain = Σ m_i (lpd_a,i − lpd_b,i) in nats, and
// its standard error √(n var_m(d_i)), n = Σ m_i (Vehtari, Gelman & Gabry 2017, Stat. Comput. 27,
// 1413, for the elpd difference of cross-validation).
struct Evidence {
  double gain = 0.0, se = 0.0;
  // A likelihood ratio of 20: "strong" on Kass & Raftery's scale (1995, J. Am. Stat. Assoc. 90, 773).
  static constexpr double kStrong = 3.0;
};
Evidence evidence(const std::vector<double>& lpd_a, const std::vector<double>& lpd_b, const Multiplicity& m);
// Whether model a's evidence over model b is decisive: above 3 nats, and either above z_K of its
// standard errors or, where it rests on a few items (a large se — a velocity step's transient and
// the steady window after it), with a's held-out gap at most half of b's: a cut the noise of those
// few items cannot make (the same halving that tells an explained gap from an unexplained one).
// K = `comparisons`, the number of candidates the data were searched over for a: the best of K
// that are all wrong clears a fixed z more often the larger K is (a control's best of eight
// candidates took 4.0 ± 1.9 nats, 2.1 se, in the validation set of 2026-11-26), so z_K keeps the
// chance that any of them clears it by noise alone at one comparison's Φ(−2) = 2.3 % (Šidák
// 1967, J. Am. Stat. Assoc. 62, 626): z_K = Φ⁻¹(Φ(2)^{1/K}) — 2 for one, 2.76 for eight.
double decisive_z(int comparisons);
bool decisive(const Evidence& e, double heldout_gap_a, double heldout_gap_b, int comparisons = 1);

// A candidate's standing on one set of held-out items (the data's, or a resample's): its
// pointwise log density, held-out gap, and whether it earns its parameters — its evidence over
// the baseline is decisive among the `comparisons` candidates tried.
struct Standing {
  std::vector<double> lpd;
  double heldout_gap = 0.0;
  bool earns = false;
  Evidence evidence;  // over the baseline
};

// A model's standing from its residuals `r` and parameter variances `v` on every item (its σ from
// the items in `train`, predictive) against the baseline's pointwise log density and held-out gap, on the held-out multiplicity `m`.
Standing standing_of(const std::vector<Item>& items, const std::vector<double>& r, const std::vector<double>& v,
                     const std::vector<double>& s, const std::vector<bool>& train, const std::vector<double>& baseline_lpd, double baseline_gap, const Multiplicity& m,
                     int comparisons);

// The verdict's index among `cs` (standings `st`, held-out multiplicity `m`), or −1 when none
// earns its parameters: the simplest earning candidate (the most evidence among equals) over which
// no earning candidate with more parameters has decisive evidence — each parameter count's leader
// judged against every larger candidate, so that a larger one beating the simplest does not pass
// over a middle one as good as it (validation case 15008: thermal thinning, 2 parameters and
// 14.6 ± 3.4 nats, was passed over for the slip transient, 3 and 13.2, decisive over the viscous
// force, 1 and 8.0, that thermal thinning was not decisive over); then, between that one and an earning
// single effect of a mechanism alike to it (rig::EffectInfo::alike_at_constant_speed), the one
// with the more evidence. Alike mechanisms are not nested — neither is the other in a limit — so
// their parameter counts do not say which is the simpler, and the held-out evidence already
// charges a fit for what it does not predict.
int verdict_index(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const Multiplicity& m);

// The earning candidates the held-out data do not tell from the verdict's (index `chosen`): neither
// has decisive evidence over the other. Named beside the verdict, so that a near-tie (two film
// mechanisms at 38 ± 15 and 40 ± 5 nats) reads as one and a reader knows what test would decide.
std::vector<int> indistinguishable(const std::vector<Standing>& st, int chosen, const Multiplicity& m);

// A held-out gap the data's noise cannot account for: above unexplained_floors noise floors. The
// verdict calls such a gap `unexplained` when no candidate halves it (decide), and only
// such a gap is worth a pair (pipeline.h pair).
inline bool beyond_noise(double gap, double noise_floor, const DiagnosisOptions& o) { return gap > o.unexplained_floors * noise_floor; }

// Whether a model's held-out gap `after` explains the baseline's `before`: it halves the excess
// over the noise floor, √(g² − floor²) — decide's rule, and alike_mechanisms'.
inline bool halves_excess(double after, double before, double floor) {
  const auto excess = [floor](double g) { return std::sqrt(std::max(g * g - floor * floor, 0.0)); };
  return excess(after) <= 0.5 * excess(before);
}

// The verdict rule with the open world: `index` ≥ 0 names a candidate; else `unexplained` when
// the held-out gap lies above unexplained_floors noise floors and no candidate halves its excess
// over the floor, else "none". Without a floor nothing is called unexplained.
// When no earning candidate explains a gap beyond the noise but some candidate halves its excess
// all the same, "look outside the catalogue" would be false advice: the simplest such candidate
// (fewest extra parameters, then the smallest held-out gap) is named, `tentative` — its likelihood
// did not decide it, so evidence among such candidates does not order them either.
struct Decision {
  int index = -1;
  bool unexplained = false;
  bool tentative = false;  // named for halving the excess, without earning its parameters
};
Decision decide(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const Multiplicity& m, const DiagnosisOptions& o,
                double gap_before, double floor);

// Share of the summed squared residuals by (observable, phase + speed class), largest first.
std::vector<Localization> localize(const std::vector<Item>& items, const std::vector<double>& r);

// The leaders refitted on one redraw of the training data (pipeline.h confidence, refit_leaders): the
// residuals the baseline and each refitted candidate (by its index in `candidates`) leave on every
// item, held-out ones included.
struct Refit {
  std::vector<double> baseline;
  std::map<std::size_t, std::vector<double>> candidates;
};

// The verdict's confidence: the share of `samples` bootstrap resamples whose standings give the
// same verdict name as `verdict`, and the standard deviation over the resamples of the held-out
// gap the verdict's candidate (`chosen`, its index in `candidates`; −1 for the baseline) leaves.
// A resample draws the held-out units (blocks) with replacement and
// measures every held-out item again within its own standard error: r_i + noise_r_i z_i, z_i a
// standard normal, the same shift for the baseline and every candidate (a new measurement moves
// the measured value, not the models). Held-out data are a few blocks (two of five speeds), too
// few for a block bootstrap alone to say whether a cut stands above the data's noise; with one
// held-out block, the redrawn noise is all the resamples can vary, and without a noise estimate
// either the agreement is NaN (not estimable). Seeded: the same inputs give the same confidence.
// With `refits`, resample b takes the baseline's and the refitted candidates' residuals from
// refits[b mod R] (the training redraws and the held-out redraws are independent, so pairing them
// in turn samples both); the other candidates keep their fitted residuals. Every model keeps its
// parameter variances (the baseline's `baseline_variance`, a candidate's its own).
struct Confidence {
  double agreement = 0.0;
  double heldout_gap_after_std = 0.0;
};
Confidence bootstrap_confidence(const std::vector<Item>& items, const std::vector<bool>& heldout, const std::vector<double>& noise_r,
                                const std::vector<double>& baseline_residuals, const std::vector<double>& baseline_variance,
                                const std::vector<Candidate>& candidates, int chosen, const std::string& verdict, const DiagnosisOptions& o,
                                const std::vector<Refit>& refits = {});

// Whether two candidates' effects hold mechanisms the catalogue calls alike at constant speed
// (rig::EffectInfo::alike_at_constant_speed, a relation both ways:
// Verdict.AlikeMechanismsAreCatalogueEffectsAlikeBothWays).
bool alike_at_constant_speed(const std::vector<std::string>& a, const std::vector<std::string>& b);

// The candidates of another mechanism that explain the held-out gap as the verdict's does and that
// runs at constant speed and one normal load cannot tell from it (rig::EffectInfo::
// alike_at_constant_speed), by name: single effects listed there for an effect of the verdict
// (`chosen`, its index in `cs`; none for −1), not in the verdict, whose held-out gap halves the
// baseline's excess over the noise floor — decide's rule for a gap explained. The caller asks only
// of such a record. There the data cannot attribute the gap between the two mechanisms whichever
// form fits better: set 9122's stick-time ageing (Kato's) was named squeeze_film at 100 %, the
// film's form at +40 nats and the junction locus' at −67, though the locus, too, cut the gap by two
// thirds; over the 21 validation sets before it the independent generator's ageing and squeeze film
// were named as each other's mechanism in 14 of 42 cases (docs/gap.md). Without a floor: none.
std::vector<std::string> alike_mechanisms(const std::vector<Candidate>& cs, int chosen, double gap_before, double floor);

// The verdict's confidence from its bootstrap agreement: for "none" the agreement times
// DiagnosisOptions::none_reliability (the bootstrap cannot see an effect below the noise); for a
// named verdict whose gap a candidate of another mechanism explains as well on a record that cannot
// part them (`shared`: alike_mechanisms not empty), the agreement shared equally
// between the two mechanisms — half of it, a uniform prior over what the data cannot decide; else
// the agreement. NaN (not estimable) stays NaN.
double verdict_confidence(double agreement, const std::string& verdict, const DiagnosisOptions& o, bool shared = false);

}  // namespace tribo::gap
