#include "gap/diagnosis.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "gap/discriminate.h"
#include "gap/laplace.h"
#include "gap/pipeline.h"
#include "gap/report.h"
#include "numerics/format.h"
#include "numerics/median.h"

namespace tribo::gap {
namespace {

// Lets the predictions' parallel runs (Comparison::predict) inside the candidates' parallel fits
// have threads of their own while the diagnosis runs: when one fit is left running alone — the
// longest refinement, the pair — its runs use both cores instead of one (independent seed 307:
// 126 → 109 s on 2 cores, the same CPU time and result). Restores the caller's setting.
class NestedParallelism {
 public:
  NestedParallelism() : levels_(omp_get_max_active_levels()) { omp_set_max_active_levels(std::max(levels_, 2)); }
  ~NestedParallelism() { omp_set_max_active_levels(levels_); }
  NestedParallelism(const NestedParallelism&) = delete;
  NestedParallelism& operator=(const NestedParallelism&) = delete;

 private:
  int levels_;
};

// The tests that would tell the verdict's candidate from each one named beside it (Verdict::beside,
// discriminate.h) and can decide between them (can_decide), around the bundle's constant-speed
// runs: their driven speeds and median length (1–5 s), at the rig generator's friction noise of 1 %
// of μk W. Drive histories are left out.
std::vector<ProposedSeparation> propose_tests(const ExperimentBundle& bundle, const Candidate& chosen, const std::vector<Candidate>& candidates,
                                              const Verdict& verdict, std::uint64_t seed) {
  std::vector<ProposedSeparation> out;
  const std::vector<std::string> others = verdict.beside();
  if (others.empty() || bundle.kind != "pin_on_disc") return out;
  std::vector<double> speeds, spans;
  for (const Run& r : bundle.runs)
    if (r.trace.t_s.size() > 1) speeds.push_back(r.v_m_per_s), spans.push_back(r.trace.t_s.back() - r.trace.t_s.front());
  if (speeds.empty()) return out;
  std::sort(speeds.begin(), speeds.end());
  const std::vector<ProposedTest> tests = proposed_tests(speeds, std::clamp(numerics::median(spans), 1.0, 5.0), 0.01);
  std::vector<const Candidate*> beside;
  for (const std::string& name : others) {
    const auto other = std::find_if(candidates.begin(), candidates.end(), [&](const Candidate& c) { return verdict_name(c.effects) == name; });
    if (other != candidates.end()) beside.push_back(&*other);
  }
  // Each test recorded once from the verdict's model; rows[k] collects candidate k's separations.
  std::vector<std::vector<ProposedSeparation>> rows(beside.size());
  // Only the tests that can decide (can_decide) are simulated: a test that parts two fitted forms
  // of mechanisms alike at constant speed says nothing of the mechanisms.
  for (const ProposedTest& t : tests) {
    std::vector<std::size_t> deciding;
    for (std::size_t k = 0; k < beside.size(); ++k)
      if (can_decide(verdict, verdict_name(beside[k]->effects), t.name)) deciding.push_back(k);
    if (deciding.empty()) continue;
    const TestRecord record(t, chosen.rig, chosen.model, seed);
    for (const std::size_t k : deciding) {
      const Separation s = record.against(beside[k]->rig, beside[k]->model);
      rows[k].push_back({verdict_name(beside[k]->effects), s.test, s.description, s.gap, s.noise_floor, s.floors()});
    }
  }
  const auto key = [](const ProposedSeparation& r) { return std::isnan(r.floors) ? -1.0 : r.floors; };  // no floor: last
  for (std::vector<ProposedSeparation>& r : rows) {
    std::stable_sort(r.begin(), r.end(), [&](const auto& a, const auto& b) { return key(a) > key(b); });
    out.insert(out.end(), r.begin(), r.end());
  }
  return out;
}

}  // namespace

std::string DiagnosisOptions::invalid_reason() const {
  if (starts < 1) return "starts must be at least 1";
  if (max_iterations < 1) return "max_iterations must be at least 1";
  if (!(unexplained_floors > 1.0)) return "unexplained_floors must exceed 1";
  if (bootstrap_samples < 0) return "bootstrap_samples must not be negative";
  if (refit_leaders < 0) return "refit_leaders must not be negative";
  if (!(none_reliability > 0.0 && none_reliability <= 1.0)) return "none_reliability must lie in (0, 1]";
  for (const auto& k : calibrate_rig)
    if (k != "stiffness_N_per_m" && k != "damping_N_s_per_m" && k != "damping_ratio" && k != "mass_kg")
      return "cannot calibrate rig key '" + k + "'";
  for (const auto& e : candidates) rig::effect_info(e);
  return "";
}


rig::RigParameters apply_bundle_rig(const ExperimentBundle& b, rig::RigParameters rig) {
  if (b.mass_kg) rig.mass_kg = *b.mass_kg;
  if (b.stiffness_N_per_m) rig.stiffness_N_per_m = *b.stiffness_N_per_m;
  if (b.damping_N_s_per_m) rig.damping_N_s_per_m = *b.damping_N_s_per_m;
  if (b.normal_load_N) rig.normal_load_N = *b.normal_load_N;
  if (b.slider_radius_m) rig.slider_radius_m = *b.slider_radius_m;
  return rig;
}

Diagnosis diagnose(const ExperimentBundle& bundle, const rig::RigParameters& model_rig, const rig::FrictionModel& model,
                   const DiagnosisOptions& o) {
  const NestedParallelism nested;
  const FitProblem p = make_fit_problem(bundle, model_rig, model, o);
  const Comparison& comparison = *p.comparison;
  Diagnosis d;
  d.items = p.items;
  d.heldout = p.heldout;
  d.has_heldout = p.has_heldout;
  d.integration_tolerance = comparison.integration_tolerance();
  for (const Item& it : d.items) d.measured.push_back(it.measured);
  // The data's own noise in gap units, and the floor it puts under any model's held-out gap.
  d.verdict.noise_floor = breakdown(d.items, p.noise_r, d.heldout).gap;
  auto lap = [mark = std::chrono::steady_clock::now()]() mutable {  // seconds since the last lap
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - mark).count();
    mark = now;
    return s;
  };

  // 1. Calibration of the model's own parameters.
  for (const FitParameter& q : p.base_space)
    if (q.stated_constant) d.rig_relative_uncertainty[q.name] = bundle.relative_uncertainty.at(q.name);
  const Calibration cal = calibrate(p);
  d.calibration.starts = cal.starts;
  d.calibration.fit_scale_by_observable = cal.fit_scale_by_observable;
  d.stage_times.calibration_s = lap();
  Baseline baseline = baseline_at(p, cal.fit);
  d.calibration.train_gap = baseline.train_gap;
  d.calibration.train_noise_floor = breakdown(d.items, p.noise_r, p.train).gap;
  p.report("baseline calibration: train gap " + numerics::fmt(d.calibration.train_gap, "%.3g") + ", " +
           numerics::fmt(d.calibration.train_floors(), "%.3g") + " noise floors");

  // 2. Candidates: the singles searched, the baseline re-calibrated from the leaders' baseline
  // parameters (so that no effect wins only because its fit also found better μs, μk than the
  // calibration), the leaders refined, nested candidates judged at their best, then a pair.
  // The re-calibration runs again once the leaders are refined (pipeline.h rebase).
  int comparisons = static_cast<int>(p.candidates.size());
  std::vector<Candidate> singles = search_singles(p, baseline);
  d.stage_times.candidates_s = lap();
  rebase(p, cal, baseline, singles, comparisons);
  d.stage_times.recalibration_s = lap();
  singles = nest(p, baseline, refine_leaders(p, baseline, std::move(singles), comparisons), comparisons);
  Paired paired = pair(p, baseline, std::move(singles), comparisons, d.verdict.noise_floor);
  d.candidates = std::move(paired.candidates);
  comparisons = paired.comparisons;
  d.stage_times.refinement_s = lap();
  rebase(p, cal, baseline, d.candidates, comparisons);
  d.stage_times.recalibration_s += lap();

  d.calibrated = baseline.setup.model;
  d.rig = baseline.setup.rig;
  d.calibrated_params = baseline.params;
  d.calibration_fit = baseline.fit.termination;
  d.baseline_simulated = baseline.simulated;
  d.baseline_residuals = baseline.residuals;
  d.calibration.train_gap = baseline.train_gap;
  d.baseline = baseline.all;
  d.baseline_heldout = baseline.heldout;
  d.baseline_heldout_parameter_sd = rms_parameter_sd(baseline.parameter_variance, p.heldout);
  // Localization: share of the baseline's squared residuals by observable, phase and speed class.
  d.localization = localize(d.items, d.baseline_residuals);

  // 3. Verdict.
  const Choice choice = choose(p, baseline, d.candidates, comparisons, d.verdict.noise_floor);
  const Candidate* chosen = choice.index >= 0 ? &d.candidates[static_cast<std::size_t>(choice.index)] : nullptr;
  d.verdict.indistinguishable = choice.indistinguishable;
  if (!parts_alike_mechanisms(bundle))
    d.verdict.alike_mechanisms = alike_mechanisms(d.candidates, choice.index, d.baseline_heldout.gap, d.verdict.noise_floor);
  d.verdict.unexplained = choice.unexplained;
  d.verdict.baseline_misses_training =
      d.calibration.train_noise_floor > 0.0 && beyond_noise(d.calibration.train_gap, d.calibration.train_noise_floor, o);
  d.verdict.tentative = choice.tentative;
  d.verdict.heldout_gap_before = d.baseline_heldout.gap;
  d.verdict.heldout_gap_after = chosen ? chosen->heldout_gap_after : d.baseline_heldout.gap;
  if (chosen) d.verdict.effects = chosen->effects, d.verdict.adds = implied_effects(chosen->effects, p.model);
  d.best_simulated = chosen ? comparison.predict(chosen->rig, chosen->model, o.seed) : d.baseline_simulated;
  d.verdict.remaining_floors = d.verdict.noise_floor > 0.0 ? d.verdict.heldout_gap_after / d.verdict.noise_floor
                                                           : std::numeric_limits<double>::quiet_NaN();
  {
    const std::vector<double>& remaining = chosen ? chosen->residuals : d.baseline_residuals;
    std::vector<double> held(d.items.size(), 0.0);
    for (std::size_t i = 0; i < d.items.size(); ++i)
      if (d.heldout[i]) held[i] = remaining[i];
    if (const std::vector<Localization> l = localize(d.items, held); !l.empty())
      d.verdict.remaining_where = l.front().observable + " (" + l.front().where + ", worst " + l.front().worst_item + ")";
  }

  if (chosen) d.proposed_tests = propose_tests(bundle, *chosen, d.candidates, d.verdict, o.seed);

  // 4. Confidence.
  const ConfidenceStage conf = confidence(p, cal, baseline, d.candidates, choice.index, verdict_name(d.verdict));
  d.verdict.refitted = conf.refitted;
  d.verdict.confidence_bootstrap = conf.with_refits.agreement;
  d.verdict.confidence = verdict_confidence(conf.with_refits.agreement, verdict_name(d.verdict), o, !d.verdict.alike_mechanisms.empty());
  d.verdict.confidence_fixed_fits = conf.fixed.agreement;
  d.verdict.heldout_gap_after_std = conf.with_refits.heldout_gap_after_std;
  d.stage_times.confidence_s = lap();

  d.verdict.conclusion = conclusion(d, chosen);
  return d;
}

const Candidate* verdict_candidate(const Diagnosis& d) {
  if (d.verdict.effects.empty()) return nullptr;
  for (const Candidate& c : d.candidates)
    if (c.effects == d.verdict.effects) return &c;
  return nullptr;
}

}  // namespace tribo::gap
