// The diagnosis' stages after the fits (diagnosis.h, steps 3–4), with explicit inputs and outputs:
// the one gap function and the one criterion function that every stage uses, where the baseline
// misses (localisation), the verdict rule, and the verdict's bootstrap confidence. They need no
// simulation, so their unit tests run in milliseconds (tests/gap/verdict_test.cpp).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "gap/compare.h"
#include "gap/diagnosis.h"

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

// The criterion (BIC form, diagnosis.h step 3): C = n ln(S_after / S_before) + p ln(max(n, 2)).
double criterion(double sse_after, double sse_before, double n, int extra_parameters);

// An effect must cut the held-out gap by this much: the fixed minimum or floor_margin floors.
double gap_margin(const DiagnosisOptions& o, double floor);

// A candidate's standing on one set of held-out items (the data's, or a resample's).
struct Standing {
  double criterion, heldout_gap;
  bool earns;
};
// Whether a candidate with held-out gap `after` and criterion `c` earns its parameters against a
// baseline gap `before`: C < 0, and the gap cut by min_relative_shrink and by `margin`.
bool earns(double c, double after, double before, const DiagnosisOptions& o, double margin);

// The verdict's index among `cs` (standings `st`), or −1 when none earns its parameters: the
// simplest earning candidate, unless one with more parameters beats it by the same margins and by
// more than 2 in the criterion.
int verdict_index(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const DiagnosisOptions& o, double margin);

// The verdict rule with the open world: `index` ≥ 0 names a candidate; else `unexplained` when
// the held-out gap lies above unexplained_floors noise floors and no earning candidate halves its
// excess over the floor, else "none". Without a floor nothing is called unexplained.
struct Decision {
  int index = -1;
  bool unexplained = false;
};
Decision decide(const std::vector<Candidate>& cs, const std::vector<Standing>& st, const DiagnosisOptions& o, double margin,
                double gap_before, double floor);

// Share of the summed squared residuals by (observable, phase + speed class), largest first.
std::vector<Localization> localize(const std::vector<Item>& items, const std::vector<double>& r);

// The leaders refitted on one redraw of the training data (diagnosis.cpp, refit_leaders): the
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
// in turn samples both); the other candidates keep their fitted residuals.
struct Confidence {
  double agreement = 0.0;
  double heldout_gap_after_std = 0.0;
};
Confidence bootstrap_confidence(const std::vector<Item>& items, const std::vector<bool>& heldout, const std::vector<double>& noise_r,
                                const std::vector<double>& baseline_residuals, const std::vector<Candidate>& candidates, int chosen,
                                const std::string& verdict, const DiagnosisOptions& o, const std::vector<Refit>& refits = {});

}  // namespace tribo::gap
