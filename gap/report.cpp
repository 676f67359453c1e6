#include "gap/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gap/discriminate.h"
#include "gap/verdict.h"
#include "numerics/format.h"
#include "numerics/json_numbers.h"

namespace tribo::gap {
namespace {

using numerics::join;

nlohmann::json fit_json(const FitTermination& f) {
  return {{"termination", f.termination}, {"iterations", f.iterations}, {"max_iterations", f.max_iterations}, {"wall_s", f.wall_s}};
}

// The baseline as the conclusion names it: a homogenised law has no μs, μk of its own to quote.
std::string baseline_text(const rig::FrictionModel& m) {
  if (m.baseline.homogenised) return "the homogenised law as it is";
  char buf[96];
  std::snprintf(buf, sizeof buf, "the calibrated baseline (mu_s = %.3g, mu_k = %.3g)", m.baseline.mu_s, m.baseline.mu_k);
  return buf;
}

// What the conclusion says of each of `others`, candidates the data do not tell from the verdict:
// the proposed test (discriminate.h) that separates their predictions most, if by two noise floors.
std::string deciding_tests_text(const Diagnosis& d, const std::vector<std::string>& others) {
  std::string text;
  for (const std::string& other : others) {
    const auto best = std::find_if(d.proposed_tests.begin(), d.proposed_tests.end(),
                                   [&](const auto& t) { return t.other == other; });
    char b[512];
    if (best == d.proposed_tests.end() || !std::isfinite(best->floors))
      std::snprintf(b, sizeof b, "against %s no test was proposed (constant-speed runs are needed to start from)", other.c_str());
    else if (best->floors >= kDecidingFloors)
      std::snprintf(b, sizeof b, "to decide against %s: %s (%s), where their predictions differ by %.1f noise floors", other.c_str(),
                    best->description.c_str(), best->test.c_str(), best->floors);
    else
      std::snprintf(b, sizeof b, "against %s none of the proposed tests decides (the best, %s, separates them by %.1f noise floors)",
                    other.c_str(), best->test.c_str(), best->floors);
    text += (text.empty() ? "" : "; ") + std::string(b);
  }
  return text;
}

}  // namespace

std::string verdict_name(const std::vector<std::string>& effects) { return effects.empty() ? "none" : join(effects, "+"); }

std::string verdict_name(const Verdict& v) { return v.unexplained ? "unexplained" : verdict_name(v.effects); }

std::string confidence_text(double confidence) {
  if (!std::isfinite(confidence)) return "not estimable: one held-out block and no noise estimate";
  char buf[16];
  std::snprintf(buf, sizeof buf, "%.0f %%", 100.0 * confidence);
  return buf;
}

std::string conclusion(const Diagnosis& d, const Candidate* chosen) {
  char buf[1400];
  const Localization* top = d.localization.empty() ? nullptr : &d.localization.front();
  char floor_text[160] = "";
  if (d.verdict.noise_floor > 0.0)
    std::snprintf(floor_text, sizeof floor_text, " (%.1f noise floors; the data's own noise leaves %.3g)", d.verdict.remaining_floors,
                  d.verdict.noise_floor);
  const auto nearest = std::min_element(d.candidates.begin(), d.candidates.end(),
                                         [](const Candidate& a, const Candidate& b) { return a.heldout_gap_after < b.heldout_gap_after; });
  const std::string closest = nearest == d.candidates.end() ? std::string("-") : verdict_name(nearest->effects);
  const double closest_gap = nearest == d.candidates.end() ? d.verdict.heldout_gap_before : nearest->heldout_gap_after;
  if (chosen) {
    std::string params;
    for (const auto& [k, v] : chosen->params)
      if (k.rfind("baseline.", 0) != 0 && k.rfind("rig.", 0) != 0) {
        char p[96];
        std::snprintf(p, sizeof p, "%s%s = %.3g", params.empty() ? "" : ", ", k.c_str(), v);
        params += p;
      }
    std::snprintf(buf, sizeof buf,
                  "Add %s to the model (%s): it cuts the held-out gap from %.3g to %.3g%s (%.0f %% smaller, bootstrap confidence %s); "
                  "the baseline misses most in %s (%s, %.0f %% of the squared residual).",
                  join(d.verdict.adds, " and ").c_str(), params.c_str(), d.verdict.heldout_gap_before, d.verdict.heldout_gap_after,
                  floor_text, 100.0 * (1.0 - d.verdict.heldout_gap_after / std::max(d.verdict.heldout_gap_before, 1e-300)),
                  confidence_text(d.verdict.confidence).c_str(), top ? top->observable.c_str() : "-", top ? top->where.c_str() : "-",
                  top ? 100.0 * top->share : 0.0);
    std::string text = buf;
    if (d.verdict.tentative) {
      std::string others;
      for (const Candidate& c : d.candidates)
        if (&c != chosen && halves_excess(c.heldout_gap_after, d.verdict.heldout_gap_before, d.verdict.noise_floor))
          others += (others.empty() ? "; so do " : ", ") + verdict_name(c.effects) + " (" + numerics::fmt(c.heldout_gap_after, "%.3g") + ")";
      std::snprintf(buf, sizeof buf,
                    " A tentative answer: it does not earn its parameters on the held-out likelihood (%+.1f ± %.1f nats over the "
                    "baseline), nor does any candidate; it is the simplest that halves the gap's excess over the noise floor",
                    chosen->evidence_nats, chosen->evidence_se_nats);
      text += buf + others + ".";
    }
    if (!d.verdict.alike_mechanisms.empty())
      text += " Runs at constant speed and one normal load cannot tell its mechanism from " +
              std::string(d.verdict.alike_mechanisms.size() > 1 ? "those of " : "that of ") + join(d.verdict.alike_mechanisms, ", ") +
              ", which explain" + (d.verdict.alike_mechanisms.size() > 1 ? "" : "s") +
              " the gap as well: the confidence is shared between the two mechanisms; " + deciding_tests_text(d, d.verdict.alike_mechanisms) + ".";
    if (!d.verdict.indistinguishable.empty())
      text += " The held-out data do not tell it from " + join(d.verdict.indistinguishable, ", ") + ": " +
              deciding_tests_text(d, d.verdict.indistinguishable) + ".";
    return text;
  } else if (d.verdict.unexplained) {
    std::snprintf(buf, sizeof buf,
                  "Unexplained: %s leaves a held-out gap of %.3g%s, and no catalogue "
                  "effect halves its excess over the floor (closest %s at %.3g); most of it lies in %s. Look for a mechanism outside "
                  "the catalogue there (bootstrap confidence %s).",
                  baseline_text(d.calibrated).c_str(), d.verdict.heldout_gap_before, floor_text, closest.c_str(), closest_gap,
                  d.verdict.remaining_where.c_str(), confidence_text(d.verdict.confidence).c_str());
  } else {
    // Without an estimate (one held-out block, no noise) there is no agreement to scale.
    const std::string confidence =
        std::isfinite(d.verdict.confidence)
            ? "Confidence " + confidence_text(d.verdict.confidence) + ": the bootstrap's " + confidence_text(d.verdict.confidence_bootstrap) +
                  " times the share of \"none\" verdicts that were right in the development selftests"
            : "Confidence " + confidence_text(d.verdict.confidence);
    std::snprintf(buf, sizeof buf,
                  "No catalogue effect earns its parameters on held-out data: keep %s, "
                  "whose held-out gap is %.3g%s; the largest remaining share is %s (%s, %.0f %%), closest candidate %s at held-out gap %.3g. "
                  "%s — an effect that moves the held-out data by less than about one noise floor is not excluded.",
                  baseline_text(d.calibrated).c_str(), d.verdict.heldout_gap_before, floor_text,
                  top ? top->observable.c_str() : "-", top ? top->where.c_str() : "-", top ? 100.0 * top->share : 0.0, closest.c_str(),
                  closest_gap, confidence.c_str());
    if (d.verdict.baseline_misses_training) {
      std::string text = buf;
      std::snprintf(buf, sizeof buf,
                    " But it misses its own training items by %.3g times their noise floor: it is not the whole story there, only "
                    "what the held-out speeds cannot fault.",
                    d.calibration.train_floors());
      return text + buf;
    }
  }
  return buf;
}

nlohmann::json stage_times_json(const StageTimes& t) {
  return {{"calibration", t.calibration_s},
          {"candidates", t.candidates_s},
          {"recalibration", t.recalibration_s},
          {"refinement", t.refinement_s},
          {"confidence", t.confidence_s}};
}

nlohmann::json report_json(const Diagnosis& d) {
  using nlohmann::json;
  auto breakdown_json = [](const GapBreakdown& g) {
    return json{{"gap", g.gap}, {"by_observable", g.by_observable}, {"by_regime", g.by_regime}, {"by_phase", g.by_phase}, {"by_speed", g.by_speed}};
  };
  json j;
  j["gap_definition"] =
      "r_i = (simulated_i - measured_i) / s_o with s_o the RMS of the measured values of observable o (for friction levels - mu_peak, "
      "mu_trough, mean_mu, mu_s_vs_load_rate, steady_mu - the RMS of all measured levels; for steady_scatter at least the record's "
      "noise, and only a simulated scatter above the measured one counts: r_i = max(r_i, 0)); r_i = 1 where the simulation lacks the "
      "feature; gap_o = sqrt(mean r_i^2) over the items of o; gap = mean over observables of gap_o";
  j["baseline"] = breakdown_json(d.baseline);
  j["baseline"]["heldout"] = breakdown_json(d.baseline_heldout);
  j["baseline"]["heldout_parameter_sd"] = d.baseline_heldout_parameter_sd;
  j["baseline"]["calibrated"] = d.calibrated_params;
  j["baseline"]["rig_relative_uncertainty"] = d.rig_relative_uncertainty;  // refined within ± u of the bundle's value
  j["baseline"]["fit"] = fit_json(d.calibration_fit);
  j["stage_wall_s"] = stage_times_json(d.stage_times);
  j["baseline"]["calibration"] = {{"starts", d.calibration.starts},
                                  {"train_gap", d.calibration.train_gap},
                                  {"train_noise_floor", d.calibration.train_noise_floor},
                                  {"train_gap_in_floors", numerics::finite_or_null(d.calibration.train_floors())},
                                  {"fit_scale_by_observable", d.calibration.fit_scale_by_observable}};
  j["heldout_is_in_sample"] = !d.has_heldout;
  j["integration_relative_tolerance"] = d.integration_tolerance;
  j["localization"] = json::array();
  for (const auto& l : d.localization)
    j["localization"].push_back({{"observable", l.observable}, {"where", l.where}, {"share", l.share}, {"worst_item", l.worst_item}});
  j["candidates"] = json::array();
  for (const auto& c : d.candidates) {
    json e = c.effects.size() == 1 ? json(c.effects.front()) : json(c.effects);
    j["candidates"].push_back({{"effect", e},
                               {"params", c.params},
                               {"extra_parameters", c.extra_parameters},
                               {"train_gap", c.train_gap},
                               {"heldout_gap_before", c.heldout_gap_before},
                               {"heldout_gap_after", c.heldout_gap_after},
                               {"heldout_after_by_observable", c.heldout_after_by_observable},
                               {"heldout_parameter_sd", c.heldout_parameter_sd},
                               {"heldout_evidence_nats", c.evidence_nats}, {"heldout_evidence_se_nats", c.evidence_se_nats},
                               {"earns_parameters", c.earns},
                               {"fit", fit_json(c.fit)}});
  }
  json effect = d.verdict.effects.size() > 1 ? json(d.verdict.effects) : json(verdict_name(d.verdict));
  j["verdict"] = {{"effect", effect},
                  {"adds", d.verdict.adds},
                  {"heldout_gap_before", d.verdict.heldout_gap_before},
                  {"heldout_gap_after", d.verdict.heldout_gap_after},
                  {"heldout_gap_after_bootstrap_std", d.verdict.heldout_gap_after_std},
                  {"confidence", numerics::finite_or_null(d.verdict.confidence)},
                  {"confidence_bootstrap", numerics::finite_or_null(d.verdict.confidence_bootstrap)},
                  {"confidence_fixed_fits", numerics::finite_or_null(d.verdict.confidence_fixed_fits)},
                  {"refitted_in_resamples", d.verdict.refitted},
                  {"indistinguishable_from", d.verdict.indistinguishable},
                  {"alike_mechanisms", d.verdict.alike_mechanisms},
                  {"tentative", d.verdict.tentative},
                  {"baseline_misses_training", d.verdict.baseline_misses_training},
                  {"noise_floor", d.verdict.noise_floor},
                  {"remaining_gap_in_floors", numerics::finite_or_null(d.verdict.remaining_floors)},
                  {"remaining_where", d.verdict.remaining_where},
                  {"conclusion", d.verdict.conclusion}};
  j["proposed_tests"] = json::array();
  for (const auto& t : d.proposed_tests)
    j["proposed_tests"].push_back({{"against", t.other}, {"test", t.test}, {"description", t.description}, {"separation_gap", t.gap},
                                   {"noise_floor", t.noise_floor}, {"separation_floors", numerics::finite_or_null(t.floors)}});
  j["noise_floor_definition"] =
      "gap of the items' standard errors read off the data (blocks of each run analysed as repeats; a step bin's high-pass noise / "
      "sqrt(samples)): the held-out gap a model right in every mechanism would still leave";
  j["items"] = json::array();
  for (std::size_t i = 0; i < d.items.size(); ++i)
    j["items"].push_back({{"observable", d.items[i].observable},
                          {"where", d.items[i].where},
                          {"phase", d.items[i].phase},
                          {"heldout", static_cast<bool>(d.heldout[i])},
                          {"measured", d.measured[i]},
                          {"noise", d.items[i].noise},
                          {"baseline", numerics::finite_or_null(d.baseline_simulated[i])},
                          {"best", numerics::finite_or_null(d.best_simulated[i])}});
  return j;
}

}  // namespace tribo::gap
