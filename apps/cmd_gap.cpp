// `tribo gap diagnose --experiment DIR --model MODEL.toml [--test DIR] --out OUT`: where a model and a measured
// experiment bundle disagree, which catalogue effect closes the gap and by how much (gap/diagnosis.h).
// `tribo gap selftest [--out OUT] [--quick]`: the diagnosis on synthetic bundles with a withheld effect.
// `tribo gap generate`: one such bundle, written out (cmd_gap_generate.cpp).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "apps/commands.h"
#include "apps/config.h"
#include "apps/gap_model.h"
#include "apps/output.h"
#include "apps/provenance.h"
#include "apps/rig_config.h"
#include "apps/rig_output.h"
#include "apps/selftest_journal.h"
#include "gap/bundle.h"
#include "gap/diagnosis.h"
#include "gap/discriminate.h"
#include "gap/report.h"
#include "gap/selftest.h"
#include "gap/test_block.h"
#include "numerics/json_numbers.h"

namespace tribo::cli {
namespace {

struct DiagnoseArgs {
  std::string experiment, model, test, out = "out/gap";
  std::vector<std::string> candidates;  // as given: all "+name" (added to the defaults) or all plain names
  std::string friction_channel;         // overrides the bundle's [rig] friction_channel when given
  std::uint64_t seed = 1;
  bool quick = false, plot = true;
};

struct SelftestArgs {
  std::string out = "out/gap-selftest";
  std::uint64_t seed = 1;
  bool quick = false;
  std::string generator = "both";  // rig, independent or both
  std::string set = "development";  // or validation (gap::SelftestSet)
  bool mix_builds = false;          // resume from journal rows another build diagnosed
};

gap::DiagnosisOptions fitting_options(bool quick, std::uint64_t seed) {
  gap::DiagnosisOptions o;
  o.seed = seed;
  if (quick) {
    o.max_iterations = 8;
    o.bootstrap_samples = 100;
  }
  return o;
}

void write_overlays(const std::filesystem::path& path, const gap::ExperimentBundle& bundle, const std::vector<gap::SimulatedRun>& before,
                    const std::vector<gap::SimulatedRun>& after, double W, const nlohmann::json& provenance) {
  CsvFile f(path, provenance);
  auto& os = f.stream();
  os << "run,source,t_s,mu\n";
  for (const gap::Run& r : bundle.runs) {
    const gap::Trace& t = r.trace;
    for (std::size_t i = 0; i < t.t_s.size(); ++i) {
      const double mu = !t.mu.empty() ? t.mu[i] : !t.friction_N.empty() ? t.friction_N[i] / W : std::nan("");
      if (std::isfinite(mu)) os << "run " << r.run_id << ",measured," << t.t_s[i] - t.t_s.front() << "," << mu << "\n";
    }
  }
  for (const auto& [runs, source] : {std::pair{&before, "baseline"}, std::pair{&after, "with effect"}})
    for (const gap::SimulatedRun& r : *runs)
      for (std::size_t i = 0; i < r.t_s.size(); ++i) os << r.label << "," << source << "," << r.t_s[i] << "," << r.mu[i] << "\n";
  f.commit();
}

std::string markdown_report(const gap::Diagnosis& d, const DiagnoseArgs& args, const nlohmann::json& j,
                            const std::optional<gap::TestBlockGap>& test) {
  std::ostringstream md;
  md << "# Gap report: " << args.experiment << " vs " << args.model << "\n\n";
  md << "**Conclusion.** " << d.verdict.conclusion << "\n\n";
  md << "Command: `tribo gap diagnose --experiment " << args.experiment << " --model " << args.model << " --out " << args.out
     << (args.test.empty() ? "" : " --test " + args.test) << (args.quick ? " --quick" : "") << "`\n\n";
  md << "## Definition\n\n" << j["gap_definition"].get<std::string>()
     << ". Items are split by block (everything at one driven speed; a drive segment's level; three contiguous bins after a step) in order of "
        "speed: even blocks train, odd blocks held out"
     << (d.has_heldout ? "" : " (this bundle has a single unit: held-out numbers are in-sample)") << ".\n\n";
  md << "## Baseline after calibration\n\n";
  for (const auto& [k, v] : d.calibrated_params) {
    md << "- " << k << " = " << fmt(v, "%.4g");
    if (const auto u = d.rig_relative_uncertainty.find(k.substr(k.find('.') + 1)); k.rfind("rig.", 0) == 0 && u != d.rig_relative_uncertainty.end())
      md << " (refined within ± " << fmt(100.0 * u->second, "%.3g") << " % of the bundle's value)";
    md << "\n";
  }
  md << "\nFit: " << d.calibration_fit.termination << " after " << d.calibration_fit.iterations << " of "
     << d.calibration_fit.max_iterations << " iterations (Ceres), " << fmt(d.calibration_fit.wall_s, "%.0f") << " s. Predictions integrated at relative tolerance "
     << fmt(d.integration_tolerance, "%.1e") << " (1e-3 of the items' median relative noise).\n";
  md << "\nCalibration: " << d.calibration.starts << " starts searched, the best refined; the baseline leaves "
     << fmt(d.calibration.train_gap, "%.4g") << " on the training items, ";
  if (std::isfinite(d.calibration.train_floors()))
    md << fmt(d.calibration.train_floors(), "%.3g") << " times their noise floor (" << fmt(d.calibration.train_noise_floor, "%.3g") << ").\n";
  else
    md << "against no noise floor (the training items carry no noise estimate).\n";
  md << "The calibration weighs each observable's training items by 1/σ (σ: RMS, gap units; the items' noise plus what the first "
        "calibration left there; the candidates' fits give every observable the same share):";
  for (const auto& [observable, sigma] : d.calibration.fit_scale_by_observable) md << " " << observable << " " << fmt(sigma, "%.3g") << ";";
  md << "\n";
  const gap::StageTimes& st = d.stage_times;
  md << "\nWall time by stage: calibration " << fmt(st.calibration_s, "%.0f") << " s, candidates " << fmt(st.candidates_s, "%.0f")
     << " s, re-calibration " << fmt(st.recalibration_s, "%.0f") << " s, refinement " << fmt(st.refinement_s, "%.0f") << " s, confidence "
     << fmt(st.confidence_s, "%.0f") << " s.\n";
  md << "\nGap (all items) " << fmt(d.baseline.gap, "%.4g") << ", held-out " << fmt(d.baseline_heldout.gap, "%.4g") << ".\n\n";
  md << "| observable | gap |\n|---|---|\n";
  for (const auto& [k, v] : d.baseline.by_observable) md << "| " << k << " | " << fmt(v, "%.4g") << " |\n";
  md << "\n| phase | gap |\n|---|---|\n";
  for (const auto& [k, v] : d.baseline.by_phase) md << "| " << k << " | " << fmt(v, "%.4g") << " |\n";
  md << "\n| regime / speed | gap |\n|---|---|\n";
  for (const auto& [k, v] : d.baseline.by_regime) md << "| " << k << " | " << fmt(v, "%.4g") << " |\n";
  for (const auto& [k, v] : d.baseline.by_speed) md << "| " << k << " | " << fmt(v, "%.4g") << " |\n";
  md << "\n## Where the gap lies (share of the baseline's squared residual)\n\n| observable | where | share | worst item |\n|---|---|---|---|\n";
  for (std::size_t i = 0; i < d.localization.size() && i < 8; ++i) {
    const auto& l = d.localization[i];
    md << "| " << l.observable << " | " << l.where << " | " << fmt(100.0 * l.share, "%.1f %%") << " | " << l.worst_item << " |\n";
  }
  md << "\n## Candidates (best first)\n\n| effect | fitted parameters | train gap | held-out before | held-out after | evidence (nats ± se) | earns | fit (Ceres), wall time |\n|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : d.candidates) {
    std::string params;
    for (const auto& [k, v] : c.params) params += (params.empty() ? "" : ", ") + k + " = " + fmt(v, "%.3g");
    md << "| " << gap::verdict_name(c.effects) << " | " << params << " | " << fmt(c.train_gap, "%.4g") << " | " << fmt(c.heldout_gap_before, "%.4g")
       << " | " << fmt(c.heldout_gap_after, "%.4g") << " | " << fmt(c.evidence_nats, "%.1f") << " ± " << fmt(c.evidence_se_nats, "%.1f") << " | " << (c.earns ? "yes" : "no") << " | "
       << c.fit.termination << ", " << c.fit.iterations << "/" << c.fit.max_iterations << " iterations, " << fmt(c.fit.wall_s, "%.0f") << " s |\n";
  }
  md << "\n## Verdict\n\n`" << gap::verdict_name(d.verdict) << "`: held-out gap " << fmt(d.verdict.heldout_gap_before, "%.4g") << " -> "
     << fmt(d.verdict.heldout_gap_after, "%.4g") << " (bootstrap std " << fmt(d.verdict.heldout_gap_after_std, "%.2g") << "), confidence "
     << gap::confidence_text(d.verdict.confidence);
  if (gap::verdict_name(d.verdict) == "none" && std::isfinite(d.verdict.confidence))
    md << " (bootstrap agreement " << gap::confidence_text(d.verdict.confidence_bootstrap) << " times the reliability of \"none\")";
  if (!d.verdict.alike_mechanisms.empty()) {
    md << " (half the bootstrap agreement " << gap::confidence_text(d.verdict.confidence_bootstrap) << ": "
       << numerics::join(d.verdict.alike_mechanisms, ", ")
       << " explains the gap as well, by a mechanism constant-speed runs at one normal load cannot tell from the verdict's)";
  }
  if (!d.verdict.refitted.empty()) {
    md << " (refitted in every resample: " << numerics::join(d.verdict.refitted, ", ") << "; with every fit held: " << gap::confidence_text(d.verdict.confidence_fixed_fits) << ")";
  }
  md << ".\n\n";
  if (!d.proposed_tests.empty()) {
    md << "## Tests that would decide\n\nThe data do not tell `" << gap::verdict_name(d.verdict) << "` from "
       << "the candidates below (a mechanism alike at constant speed: only a hold or a heavier load can, and only those are listed for it). Each test is simulated with the verdict's model as the record (the rig's simulator, 1 % friction noise), "
          "analysed as a bundle and predicted with both fitted models; the separation is the gap between the predictions over the test's "
          "items in that test's floors — its noise, or what the verdict's model misses on its own record when that is more (two or more: the test decides).\n\n| against | test | what to run | separation (gap) | "
          "noise floor | separation (floors) |\n|---|---|---|---|---|---|\n";
    for (const auto& t : d.proposed_tests)
      md << "| " << t.other << " | " << t.test << " | " << t.description << " | " << fmt(t.gap, "%.3g") << " | " << fmt(t.noise_floor, "%.3g") << " | "
       << fmt(t.floors, "%.1f") << " |\n";
    md << "\n";
  }
  if (test) {
    md << "On the test block `" << args.test << "` (" << test->items << " items, neither fitted nor used to choose the verdict): gap "
       << fmt(test->gap_before, "%.4g") << " -> " << fmt(test->gap_after, "%.4g") << ", shrink " << fmt(100.0 * test->shrink(), "%.0f %%")
       << ", its noise floor " << fmt(test->noise_floor, "%.2g") << ".";
    if (!test->gap_beside.empty()) {
      md << " The candidates the held-out data did not tell from the verdict, on it:";
      for (const auto& [name, g] : test->gap_beside) md << " " << name << " " << fmt(g, "%.4g") << ";";
      if (!test->ruled_out.empty())
        md << " it rules out " << numerics::join(test->ruled_out, ", ") << " (each misses the record by " << fmt(test->decision_floors, "%.1f")
           << " noise floors or more beyond the nearest)";
      else
        md << " it rules none out (two noise floors beyond the nearest would, and only a hold or a load twice or half the diagnosed one parts mechanisms alike at constant speed)";
      if (!test->decided_for.empty())
        md << "; **it decides for `" << test->decided_for << "`**.";
      else
        md << "; " << numerics::join(test->standing, ", ") << " still stand, nearest first; the verdict after it: `" << test->verdict_after << "`.";
    }
    md << "\n\n";
  } else {
    md << "The held-out shrink is measured on the blocks that chose the verdict, so it is the winner's number; `--test DIR` measures it on a "
          "bundle of its own.\n\n";
  }
  md << "Plots: `gap_by_observable.png` (bar chart), `items.png` (measured vs simulated, before / after), `overlay.png` (traces).\n";
  return md.str();
}

// A bundle read for the command line: a malformed one is bad input (exit 2), its warnings go to stderr.
gap::ExperimentBundle read_bundle_or_exit(const std::string& dir) {
  gap::ExperimentBundle bundle;
  try {
    bundle = gap::read_bundle(dir);
  } catch (const std::invalid_argument& e) {
    throw InputError(e.what());
  }
  for (const auto& w : bundle.warnings) std::fprintf(stderr, "tribo: warning: %s\n", w.c_str());
  return bundle;
}

// The candidates to try: the defaults of the bundle's kind without `--candidates`; with it, plain
// names replace those defaults and "+name" adds to them (rate_and_state, which the catalogue tries
// on drive histories only, on a stick-slip record whose material is known to age so: paper, rock).
// Checked against the catalogue; an effect the model already has, or one named twice, is refused.
std::vector<std::string> chosen_candidates(const std::vector<std::string>& given, const rig::FrictionModel& model, const std::string& kind) {
  if (given.empty()) return gap::default_candidates(model, kind);
  const bool adding = given.front().rfind('+', 0) == 0;
  std::vector<std::string> out = adding ? gap::default_candidates(model, kind) : std::vector<std::string>{};
  for (const std::string& g : given) {
    if ((g.rfind('+', 0) == 0) != adding)
      throw InputError("--candidates: '" + g + "': either every name adds to the defaults (+name) or none does");
    const std::string name = adding ? g.substr(1) : g;
    try {
      rig::effect_info(name);
    } catch (const std::invalid_argument& e) {
      throw InputError(std::string("--candidates: ") + e.what());
    }
    if (model.has(name)) throw InputError("--candidates: the model already has '" + name + "'");
    if (std::count(out.begin(), out.end(), name)) {
      if (adding) continue;  // already a default of this kind
      throw InputError("--candidates: '" + name + "' named twice");
    }
    out.push_back(name);
  }
  return out;
}

void run_diagnose(const DiagnoseArgs& args) {
  // `--friction-channel` says how this machine measures friction: the test bundle's too.
  const auto read_as_measured = [&](const std::string& dir) {
    gap::ExperimentBundle b = read_bundle_or_exit(dir);
    if (!args.friction_channel.empty()) b.spring_force_channel = args.friction_channel == "spring_force";
    return b;
  };
  const gap::ExperimentBundle bundle = read_as_measured(args.experiment);
  std::optional<gap::ExperimentBundle> test;
  if (!args.test.empty()) {
    test = read_as_measured(args.test);
    // A constant-speed diagnosis may be tested on the slide-hold-slide it proposes (gap/discriminate.h).
    if (test->kind != bundle.kind && !(bundle.kind == "pin_on_disc" && test->kind == "slide_hold_slide"))
      throw InputError(args.test + "/experiment.toml: [rig] kind '" + test->kind + "' is not the diagnosed bundle's '" + bundle.kind + "'");
  }
  const GapModel model = load_gap_model(args.model);
  gap::DiagnosisOptions o = fitting_options(args.quick, args.seed);
  o.candidates = chosen_candidates(args.candidates, model.friction, bundle.kind);
  for (const std::string& key : model.missing_rig_keys) {
    const bool in_bundle = key == "stiffness_N_per_m" ? bundle.stiffness_N_per_m.has_value()
                           : key == "damping_N_s_per_m" ? bundle.damping_N_s_per_m.has_value()
                                                        : bundle.mass_kg.has_value();
    // Stiffness and damping nobody gives are fitted; the damping as a ratio ζ, since k moves too.
    // A left-out mass keeps the thesis value: with k fitted, only ω_n = √(k/M) and ζ matter.
    if (!in_bundle && key == "stiffness_N_per_m") o.calibrate_rig.push_back(key);
    if (!in_bundle && key == "damping_N_s_per_m") o.calibrate_rig.push_back("damping_ratio");
  }
  const rig::RigParameters rig = gap::apply_bundle_rig(bundle, model.rig);
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const int candidates = static_cast<int>(o.candidates.size());
  // Steps reported, at most: calibration, each candidate, the leaders refined (those that explain
  // something), a pair, its refinement and its two members refined from it, and the leaders'
  // refits for the resamples.
  Progress progress("gap: fitting", 1 + candidates + std::min(static_cast<int>(gap::kRefinedLeaders), candidates) + 4 + 1);
  o.progress = [&](const std::string& what) { progress.step(what); };
  gap::Diagnosis d;
  try {
    d = gap::diagnose(bundle, rig, model.friction, o);
  } catch (const std::invalid_argument& e) {
    throw InputError(args.experiment + ": " + e.what());
  }
  progress.done();
  // The model config is the config; the experiment bundle is named beside it, and its files (and
  // the test bundle's) are among the inputs with the model's law table.
  InputFiles inputs = model.input_files;
  inputs.insert(inputs.end(), bundle.files.begin(), bundle.files.end());
  if (test) inputs.insert(inputs.end(), test->files.begin(), test->files.end());
  nlohmann::json provenance = provenance_json(args.model, inputs);
  provenance["experiment"] = std::filesystem::absolute(args.experiment).string();
  provenance["seed"] = args.seed;
  if (!args.candidates.empty()) provenance["candidates"] = args.candidates;
  if (!args.friction_channel.empty()) provenance["friction_channel"] = args.friction_channel;
  nlohmann::json j = report_json(d);
  j["provenance"] = provenance;
  std::optional<gap::TestBlockGap> tb;
  if (test) {
    try {
      tb = gap::test_block_gap(*test, gap::apply_bundle_rig(*test, model.rig), d, args.seed, gap::apply_bundle_rig(bundle, model.rig));
    } catch (const std::invalid_argument& e) {
      throw InputError(args.test + ": " + e.what());
    }
    provenance["test"] = std::filesystem::absolute(args.test).string();
    j["provenance"] = provenance;
    j["test_block"] = {{"bundle", args.test}, {"items", tb->items}, {"gap_before", tb->gap_before}, {"gap_after", tb->gap_after},
                       {"noise_floor", tb->noise_floor}, {"shrink", tb->shrink()}, {"gap_beside", tb->gap_beside},
                       {"standing", tb->standing}, {"ruled_out", tb->ruled_out},
                       {"decided_for", tb->decided_for.empty() ? nlohmann::json() : nlohmann::json(tb->decided_for)},
                       {"verdict_after", tb->verdict_after.empty() ? nlohmann::json() : nlohmann::json(tb->verdict_after)},
                       {"decision_floors", numerics::finite_or_null(tb->decision_floors)}};
  }
  write_file_atomically(dir / "gap_report.json", j.dump(2) + "\n");
  write_file_atomically(dir / "report.md", markdown_report(d, args, j, tb));

  const gap::Comparison comparison(bundle, rig);
  std::vector<gap::SimulatedRun> before, after;
  comparison.predict(d.rig, d.calibrated, args.seed, &before);
  // The overlay shows the verdict's candidate (not merely the best-ranked one).
  if (const gap::Candidate* chosen = gap::verdict_candidate(d)) comparison.predict(chosen->rig, chosen->model, args.seed, &after);
  write_overlays(dir / "overlay.csv", bundle, before, after, rig.normal_load_N, provenance);
  std::printf("%s\nverdict: %s%s (held-out gap %.4g -> %.4g, confidence %s) -> %s\n", d.verdict.conclusion.c_str(),
              gap::verdict_name(d.verdict).c_str(), d.verdict.tentative ? ", tentative" : "", d.verdict.heldout_gap_before, d.verdict.heldout_gap_after,
              gap::confidence_text(d.verdict.confidence).c_str(), args.out.c_str());
  if (tb) {
    std::printf("test block %s: gap %.4g -> %.4g (shrink %.0f %%)", args.test.c_str(), tb->gap_before, tb->gap_after, 100.0 * tb->shrink());
    for (const auto& [name, g] : tb->gap_beside) std::printf("; %s %.4g", name.c_str(), g);
    if (!tb->ruled_out.empty())
      std::printf("; it rules out %s (%.1f noise floors or more)", numerics::join(tb->ruled_out, ", ").c_str(), tb->decision_floors);
    if (!tb->verdict_after.empty()) std::printf("; verdict after it: %s", tb->verdict_after.c_str());
    std::printf("\n");
  }
  if (args.plot && run_plot_script("gap", args.out) != 0)
    std::fprintf(stderr, "tribo: warning: plotting failed (needs python3-matplotlib)\n");
}

// `build`: the commit of this binary, recorded for a row diagnosed now (a resumed row keeps its own).
nlohmann::json row_json(const gap::SelftestRow& row, bool quick, const std::string& build) {
  nlohmann::json j = {{"generator", row.c.generator},   {"form", row.form},
          {"true_effect", row.c.true_effect}, {"model_effects", row.c.model_effects},
          {"seed", row.c.seed},               {"quick", quick},
          {"verdict", row.verdict},           {"heldout_gap_before", row.heldout_gap_before},
          {"heldout_gap_after", row.heldout_gap_after}, {"noise_floor", numerics::finite_or_null(row.noise_floor)},
          {"train_floors", numerics::finite_or_null(row.train_floors)},
          {"confidence", numerics::finite_or_null(row.confidence)},
          {"confidence_bootstrap", numerics::finite_or_null(row.confidence_bootstrap)},
          {"confidence_fixed_fits", numerics::finite_or_null(row.confidence_fixed_fits)},
          {"test_gap_before", numerics::finite_or_null(row.test_gap_before)}, {"test_gap_after", numerics::finite_or_null(row.test_gap_after)},
          {"correct", row.correct},           {"wall_s", row.wall_s},
          {"stage_wall_s", gap::stage_times_json(row.stage_times)}};
  nlohmann::json candidates = nlohmann::json::array();
  for (const gap::CandidateFigures& c : row.candidates)
    candidates.push_back({{"effect", c.effect}, {"evidence_nats", numerics::finite_or_null(c.evidence_nats)},
                          {"evidence_se_nats", numerics::finite_or_null(c.evidence_se_nats)}, {"heldout_gap", numerics::finite_or_null(c.heldout_gap)},
                          {"earns", c.earns}});
  j["candidates"] = candidates;
  j["verdict_adds"] = row.verdict_adds;
  j["indistinguishable_from"] = row.indistinguishable_from;
  j["alike_mechanisms"] = row.alike_mechanisms;
  j["proposal_checks"] = nlohmann::json::array();
  for (const gap::ProposalCheck& k : row.proposal_checks)
    j["proposal_checks"].push_back({{"against", k.against}, {"test", k.test}, {"separation_floors", numerics::finite_or_null(k.floors)},
                                    {"gap_verdict", k.gap_verdict}, {"gap_against", k.gap_against}, {"truth_nearer", k.truth_nearer},
                                    {"verdict_after", k.verdict_after.empty() ? nlohmann::json() : nlohmann::json(k.verdict_after)}});
  j["git_commit"] = row.git_commit.empty() ? build : row.git_commit;
  return j;
}

void run_selftest(const SelftestArgs& args) {
  make_output_dir(args.out);
  const std::filesystem::path dir(args.out);
  const gap::SelftestSet set = args.set == "validation" ? gap::SelftestSet::validation : gap::SelftestSet::development;
  std::vector<gap::SelftestCase> cases = gap::selftest_cases(args.quick, args.seed, set);
  if (args.generator != "both")
    std::erase_if(cases, [&](const gap::SelftestCase& c) { return c.generator != args.generator; });
  const std::vector<gap::SelftestRow> finished = finished_rows(dir / "cases.jsonl", args.quick);
  // A resumed set is one build's unless told otherwise: rows diagnosed by another build (another
  // commit, another uncommitted edit, or a build that did not record it) would mix two methods in
  // one confusion matrix.
  const std::string commit = build_identity();
  for (const gap::SelftestRow& r : finished)
    if (!args.mix_builds && r.git_commit != commit &&
        std::any_of(cases.begin(), cases.end(), [&](const gap::SelftestCase& c) { return gap::same_case(r.c, c); }))
        throw InputError((dir / "cases.jsonl").string() + ": the case " + r.c.true_effect + " (seed " + std::to_string(r.c.seed) +
                         ") was diagnosed by build '" + (r.git_commit.empty() ? "unrecorded" : r.git_commit) + "', this is '" + commit +
                         "': resume with --mix-builds to keep it, or use another --out");
  int resumed = 0;
  for (const auto& c : cases)
    resumed += std::any_of(finished.begin(), finished.end(), [&](const gap::SelftestRow& r) { return gap::same_case(r.c, c); });
  if (resumed) std::fprintf(stderr, "tribo: resuming: %d of %zu cases already in %s\n", resumed, cases.size(), (dir / "cases.jsonl").c_str());
  std::ofstream journal(dir / "cases.jsonl", std::ios::app);
  if (!journal) throw InputError((dir / "cases.jsonl").string() + ": cannot open the journal for appending");
  Progress progress(args.quick ? "gap selftest (quick)" : "gap selftest", static_cast<int>(cases.size()) - resumed);
  const gap::SelftestResult r = gap::run_selftest(
      cases, gap::synthetic_options(set), fitting_options(args.quick, args.seed),
      [&](const gap::SelftestRow& row) {
        journal << row_json(row, args.quick, commit).dump() << "\n" << std::flush;
        if (!journal) throw std::runtime_error((dir / "cases.jsonl").string() + ": writing the journal failed");
        progress.step(row.c.true_effect + " -> " + row.verdict);
      },
      finished);
  progress.done();
  // No config: the cases are compiled in and drawn from the seed.
  nlohmann::json provenance = provenance_json(std::filesystem::path());
  provenance["seed"] = args.seed;
  // One confusion matrix per generator (rows: true effect, columns: verdict).
  auto confusion_csv = [](const std::map<std::string, std::map<std::string, int>>& confusion) {
    std::set<std::string> verdicts;
    for (const auto& [t, row] : confusion)
      for (const auto& [v, n] : row) verdicts.insert(v);
    std::ostringstream table;
    table << "true \\ verdict";
    for (const auto& v : verdicts) table << "," << v;
    table << "\n";
    for (const auto& [t, row] : confusion) {
      table << t;
      for (const auto& v : verdicts) table << "," << (row.count(v) ? row.at(v) : 0);
      table << "\n";
    }
    return table.str();
  };
  write_csv_atomically(dir / "confusion.csv", confusion_csv(r.by_generator.count(gap::kRigGenerator) ? r.by_generator.at(gap::kRigGenerator).confusion : r.confusion), provenance);
  if (r.by_generator.count(gap::kIndependentGenerator))
    write_csv_atomically(dir / "confusion_independent.csv", confusion_csv(r.by_generator.at(gap::kIndependentGenerator).confusion), provenance);
  std::ostringstream reliability;
  reliability << "confidence_from,confidence_to,verdicts,right,fraction_right\n";
  for (const auto& b : r.reliability)
    reliability << b.lower << "," << b.upper << "," << b.verdicts << "," << b.right << ","
                << (b.verdicts ? static_cast<double>(b.right) / b.verdicts : std::nan("")) << "\n";
  write_csv_atomically(dir / "reliability.csv", reliability.str(), provenance);
  // The share named by the effect's strength in noise floors (gap::detection_table); the last bin is open.
  std::ostringstream detection;
  detection << "generator,signal_floors_from,signal_floors_to,effect_cases,named,named_or_listed\n";
  for (const auto& [g, bins] : r.detection)
    for (const gap::DetectionBin& b : bins) {
      detection << g << "," << b.lower_floors << ",";
      if (std::isfinite(b.upper_floors)) detection << b.upper_floors;
      else detection << "inf";
      detection << "," << b.effect_cases << "," << b.named << "," << b.named_or_listed << "\n";
    }
  write_csv_atomically(dir / "detection.csv", detection.str(), provenance);
  nlohmann::json j;
  j["provenance"] = provenance;
  j["quick"] = args.quick;
  j["set"] = args.set;
  j["seed"] = args.seed;
  j["identified_fraction"] = r.identified_fraction;
  j["controls_none_fraction"] = r.controls_none_fraction;
  j["mean_heldout_shrink"] = r.mean_shrink;
  j["mean_test_shrink"] = r.mean_test_shrink;
  j["confusion"] = r.confusion;
  for (const auto& [g, sum] : r.by_generator)
    j["by_generator"][g] = {{"identified_fraction", sum.identified_fraction}, {"controls_none_fraction", sum.controls_none_fraction},
                            {"effect_cases", sum.effect_cases}, {"controls", sum.controls},
                            {"visible_effect_cases", sum.visible_effect_cases},
                            {"visible_identified_fraction", numerics::finite_or_null(sum.visible_identified_fraction)},
                            {"named_or_indistinguishable_fraction", numerics::finite_or_null(sum.named_or_indistinguishable_fraction)},
                            {"mean_names_per_verdict", numerics::finite_or_null(sum.mean_names_per_verdict)},
                            {"deciding_proposals", sum.deciding_proposals}, {"deciding_proposals_for_truth", sum.deciding_proposals_for_truth},
                            {"named_after_proposed_tests", sum.named_after_proposed_tests},
                            {"truth_among_adds", sum.truth_among_adds},
                            {"tentative_verdicts", sum.tentative_verdicts}, {"tentative_right", sum.tentative_right},
                            {"mean_heldout_shrink", sum.mean_shrink}, {"mean_test_shrink", sum.mean_test_shrink},
                            {"confusion", sum.confusion}};
  j["reliability"] = nlohmann::json::array();
  for (const auto& b : r.reliability)
    j["reliability"].push_back({{"confidence_from", b.lower}, {"confidence_to", b.upper}, {"verdicts", b.verdicts}, {"right", b.right}});
  for (const auto& [g, bins] : r.detection)
    for (const gap::DetectionBin& b : bins)
      j["detection"][g].push_back({{"signal_floors_from", b.lower_floors}, {"signal_floors_to", numerics::finite_or_null(b.upper_floors)},
                                   {"effect_cases", b.effect_cases}, {"named", b.named}, {"named_or_listed", b.named_or_listed}});
  j["cases"] = nlohmann::json::array();
  for (const auto& row : r.rows) j["cases"].push_back(row_json(row, args.quick, commit));
  write_file_atomically(dir / "selftest.json", j.dump(2) + "\n");
  std::printf("%-12s %-24s %-18s %-40s %10s %10s %7s %6s %22s\n", "generator", "true effect", "model has", "verdict", "gap before", "gap after",
              "floors", "conf", "test block before/after");
  for (const auto& row : r.rows) {
    const std::string has = numerics::join(row.c.model_effects, "+");
    std::printf("%-12s %-24s %-18s %-40s %10.4f %10.4f %7.1f %5.0f%% %10.4f/%-11.4f%s\n", row.c.generator.c_str(), row.c.true_effect.c_str(),
                has.empty() ? "-" : has.c_str(), row.verdict.c_str(), row.heldout_gap_before, row.heldout_gap_after, row.signal_floors(),
                100.0 * row.confidence,
                row.test_gap_before, row.test_gap_after, row.correct ? "" : "  <- wrong");
  }
  for (const auto& [g, sum] : r.by_generator) {
    std::printf("\ngenerator %s: confusion matrix (rows: true effect, columns: verdict)\n%s", g.c_str(), confusion_csv(sum.confusion).c_str());
    std::printf("identified %.0f %% of %d withheld effects; controls answering none %.0f %% of %d\n", 100.0 * sum.identified_fraction, sum.effect_cases,
                100.0 * sum.controls_none_fraction, sum.controls);
    if (sum.visible_effect_cases)
      std::printf("  of the %d effects visible in their data (baseline held-out gap >= %g noise floors): identified %.0f %%\n",
                  sum.visible_effect_cases, gap::kVisibleSignalFloors, 100.0 * sum.visible_identified_fraction);
    if (sum.effect_cases)
      std::printf("  the verdict or a candidate the held-out data cannot tell from it: %.0f %% (%.1f names a verdict on average)\n",
                  100.0 * sum.named_or_indistinguishable_fraction, sum.mean_names_per_verdict);
    if (sum.deciding_proposals)
      std::printf("  proposed tests that decide (>= %g floors), run on the truth: %d of %d came out for it\n", gap::kDecidingFloors,
                  sum.deciding_proposals_for_truth, sum.deciding_proposals);
    if (sum.effect_cases)
      std::printf("  named once the proposed tests run on the truth are seen (their verdict after the record): %d of %d\n",
                  sum.named_after_proposed_tests, sum.effect_cases);
    if (sum.effect_cases)
      std::printf("  the truth among what the verdict adds (the hardening brings the locus a model lacks): %d of %d\n",
                  sum.truth_among_adds, sum.effect_cases);
    if (sum.tentative_verdicts)
      std::printf("  tentative verdicts (a candidate that halves the gap without earning): %d of %d right\n", sum.tentative_right,
                  sum.tentative_verdicts);
    for (const auto& [e, s] : sum.mean_shrink) {
      std::printf("  mean gap shrink, %s: held-out %.0f %%", e.c_str(), 100.0 * s);
      if (const auto t = sum.mean_test_shrink.find(e); t != sum.mean_test_shrink.end()) std::printf(", test block %.0f %%", 100.0 * t->second);
      std::printf("\n");
    }
  }
  std::printf("\nreliability over both generators (confidence bin -> fraction of verdicts right)\n");
  for (const auto& b : r.reliability)
    std::printf("  [%.1f, %.1f%s  %3d verdicts, %3d right%s\n", b.lower, b.upper, b.upper >= 1.0 ? "]" : ")", b.verdicts, b.right,
                b.verdicts ? fmt(100.0 * b.right / b.verdicts, " (%.0f %%)").c_str() : "");
  std::printf("-> %s\n", args.out.c_str());
}

}  // namespace

void add_gap_command(CLI::App& app) {
  CLI::App* gap = app.add_subcommand("gap", "Sim-to-real gap: where a model and measurements disagree, which effect closes it");
  gap->require_subcommand(1);

  auto diagnose_args = std::make_shared<DiagnoseArgs>();
  CLI::App* diagnose = gap->add_subcommand("diagnose", "Diagnose an experiment bundle (DESIGN §7) against a `tribo rig` model config");
  diagnose->add_option("--experiment", diagnose_args->experiment,
                       "Experiment bundle directory; its experiment.toml may state how well it knows the rig "
                       "([rig.relative_uncertainty] stiffness_N_per_m = 0.03, mass_kg, damping_N_s_per_m), and those "
                       "constants are refined within ± that fraction")
      ->required();
  diagnose->add_option("--model", diagnose_args->model, "Model TOML ([rig], [friction] as for `tribo rig`)")->required();
  diagnose->add_option("--test", diagnose_args->test,
                       "Test bundle of the same machine and kind (other runs, other speeds), or a test the diagnosis proposes (a "
                       "stiffer spring, another load, a slide-hold-slide: the calibrated rig is scaled as the bundle's told one): the "
                       "fitted baseline, the verdict's candidate and those named beside it predict it, on data no fit or verdict saw, and the report states which of them it rules out (two noise floors beyond the nearest) and the verdict after it");
  diagnose->add_option("--out", diagnose_args->out, "Output directory")->capture_default_str();
  diagnose->add_option("--seed", diagnose_args->seed, "Seed of random starts, bootstrap and instrument noise")->capture_default_str();
  diagnose->add_option("--candidates", diagnose_args->candidates,
                       "Catalogue effects to try, comma-separated (default: those the catalogue tries on the bundle's kind; "
                       "rate_and_state only on velocity steps and slide-hold-slide); +name adds to the defaults, e.g. "
                       "--candidates +rate_and_state on a stick-slip record of a material that ages so")
      ->delimiter(',');
  diagnose->add_option("--friction-channel", diagnose_args->friction_channel,
                       "How the records' friction was measured (the experiment's and the --test bundle's, over their "
                       "experiment.toml's [rig] friction_channel): inertia_corrected (the thesis' k (x + x''/wn^2), the default) "
                       "or spring_force (k x alone, a rig without an accelerometer); the simulation reads its own the same way")
      ->check(CLI::IsMember({"inertia_corrected", "spring_force"}));
  diagnose->add_flag("--quick", diagnose_args->quick, "Fewer iterations per fit");
  diagnose->add_flag("!--no-plots,!--no-plot", diagnose_args->plot, "Skip the PNG plots (--no-plot: the same, its earlier name)");
  diagnose->callback([diagnose_args] { run_diagnose(*diagnose_args); });

  auto selftest_args = std::make_shared<SelftestArgs>();
  CLI::App* selftest = gap->add_subcommand("selftest", "Withheld-effect validation on synthetic bundles: confusion matrix and gap shrink");
  selftest->add_option("--out", selftest_args->out, "Output directory (an interrupted run resumes from OUT/cases.jsonl)")->capture_default_str();
  selftest->add_option("--seed", selftest_args->seed, "Seed of the synthetic cases")->capture_default_str();
  selftest->add_flag("--quick", selftest_args->quick, "The reduced CI set (one seed: four effects and two controls from the rig's simulator, one effect and one control from the independent generator)");
  selftest->add_option("--set", selftest_args->set,
                       "development (the seeds, speeds and strengths the diagnosis was tuned on) or validation (drawn afresh: other "
                       "seeds, speeds and effect strengths; one case per effect and generator, two controls each)")
      ->check(CLI::IsMember({"development", "validation"}))
      ->capture_default_str();
  selftest->add_option("--generator", selftest_args->generator, "Cases of one generator only: rig (the rig's simulator), independent (gap/independent/) or both")
      ->check(CLI::IsMember({"rig", "independent", "both"}))
      ->capture_default_str();
  selftest->add_flag("--mix-builds", selftest_args->mix_builds,
                     "Resume from journal rows that another build diagnosed (refused by default: one set, one build)");
  selftest->callback([selftest_args] { run_selftest(*selftest_args); });

  add_gap_generate_command(*gap);
}

}  // namespace tribo::cli
