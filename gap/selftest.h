// Withheld-effect validation of the diagnosis (issue 6): synthetic "measured" bundles from the
// full model with exactly one catalogue effect switched on (random physical parameters, sensor
// noise, several seeds) plus controls with none; the diagnosis gets the model without that effect
// (and with a miscalibrated baseline) and must name it — or "none" for the controls.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/diagnosis.h"
#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::gap {

struct SyntheticOptions {
  // Driven speeds of the stick-slip traces on the thesis rig (φ̇ = k v / W ≈ 0.7 … 5 1/s).
  std::vector<double> speeds_m_per_s{6e-3, 1e-2, 1.7e-2, 2.8e-2, 4.5e-2};
  double duration_s = 2.0;
  int samples_per_period = 50;    // trace density while slipping (rig/simulator.h)
  // rms noise of the friction sensor as a fraction of μk W (thesis strain-gauge channel ≈ 1 %).
  double noise_fraction = 0.01;
};

// "Measured" bundle: the truth simulated at every speed, measured through its instrument plus
// noise; static_friction.csv with one point per run, the mean of its measured breakaways.
ExperimentBundle synthesize_bundle(const rig::RigParameters& rig, const rig::FrictionModel& truth, const SyntheticOptions& options,
                                   std::uint64_t seed);

struct SyntheticCase {
  std::string true_effect;                 // "none" for a control
  rig::FrictionModel truth, model;         // model = truth without true_effect, baseline miscalibrated
  ExperimentBundle bundle;
};

// `model_effects` are in both truth and model (e.g. rate_dependent_static with
// strain_rate_hardening as the effect to find).
SyntheticCase make_synthetic_case(const std::string& true_effect, const std::vector<std::string>& model_effects, std::uint64_t seed,
                                  const SyntheticOptions& options);

struct SelftestCase {
  std::string true_effect;
  std::vector<std::string> model_effects;
  std::uint64_t seed = 1;
};

struct SelftestRow {
  SelftestCase c;
  std::string verdict;
  double heldout_gap_before = 0.0, heldout_gap_after = 0.0, confidence = 0.0;
  bool correct = false;
};

struct SelftestResult {
  std::vector<SelftestRow> rows;
  std::map<std::string, std::map<std::string, int>> confusion;  // true → verdict → count
  double identified_fraction = 0.0;   // effect cases with the right verdict
  double controls_none_fraction = 0.0;
  std::map<std::string, double> mean_shrink;  // per true effect, of correctly identified cases: 1 − after/before
};

// The quick set (CI) or the full set: every effect × seeds, controls, and the second-effect case.
std::vector<SelftestCase> selftest_cases(bool quick, std::uint64_t seed);

// `finished` holds rows of an earlier, interrupted run: a case found there (same true effect,
// model effects and seed) is taken as it is rather than diagnosed again. `on_row` is called for
// every newly diagnosed case, as soon as it is done (to flush it to disk).
SelftestResult run_selftest(const std::vector<SelftestCase>& cases, const SyntheticOptions& synthetic, DiagnosisOptions diagnosis,
                            const std::function<void(const SelftestRow&)>& on_row,
                            const std::vector<SelftestRow>& finished = {});

bool same_case(const SelftestCase& a, const SelftestCase& b);

}  // namespace tribo::gap
