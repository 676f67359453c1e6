#include "apps/selftest_journal.h"

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "rig/friction_model.h"

namespace tribo::cli {

std::vector<std::string> adds_of_verdict(const std::string& verdict, const std::vector<std::string>& model_effects) {
  if (verdict == "none" || verdict == "unexplained") return {};
  std::vector<std::string> effects;
  for (std::size_t from = 0, plus = 0; plus != std::string::npos; from = plus + 1) {
    plus = verdict.find('+', from);
    effects.push_back(verdict.substr(from, plus == std::string::npos ? std::string::npos : plus - from));
  }
  return rig::with_implied_effects(effects, model_effects);
}

// Rows of an earlier run of the same set (quick or full) from OUT/cases.jsonl, one JSON object a
// line, appended as each case finishes. A line cut short by a kill is skipped.
std::vector<gap::SelftestRow> finished_rows(const std::filesystem::path& file, bool quick) {
  std::vector<gap::SelftestRow> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line)) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) continue;
    // Without `quick`, of the other set, or a `quick` that is not a boolean: not a row of this run.
    if (const auto q = j.find("quick"); q == j.end() || !q->is_boolean() || q->get<bool>() != quick) continue;
    try {
      gap::SelftestRow r;
      r.c.true_effect = j.at("true_effect").get<std::string>();
      r.c.model_effects = j.at("model_effects").get<std::vector<std::string>>();
      // A seed is an unsigned integer: a float (1e300) would be converted out of range.
      if (!j.at("seed").is_number_unsigned()) continue;
      r.c.seed = j.at("seed").get<std::uint64_t>();
      r.c.generator = j.value("generator", std::string(gap::kRigGenerator));  // journals before issue 15: the rig's
      r.form = j.value("form", std::string());
      r.verdict = j.at("verdict").get<std::string>();
      r.heldout_gap_before = j.at("heldout_gap_before").get<double>();
      r.heldout_gap_after = j.at("heldout_gap_after").get<double>();
      r.confidence = j.at("confidence").is_null() ? std::nan("") : j.at("confidence").get<double>();  // null: not estimable
      r.wall_s = j.value("wall_s", 0.0);  // journals before it was recorded: 0
      // A number the row may lack (older journals) or hold as null (not estimable): NaN then.
      const auto number = [](const nlohmann::json& o, const char* key) {
        return o.contains(key) && o.at(key).is_number() ? o.at(key).get<double>() : std::nan("");
      };
      r.test_gap_before = number(j, "test_gap_before");
      r.test_gap_after = number(j, "test_gap_after");
      r.confidence_fixed_fits = number(j, "confidence_fixed_fits");
      r.confidence_bootstrap = number(j, "confidence_bootstrap");
      r.noise_floor = number(j, "noise_floor");
      r.train_floors = number(j, "train_floors");
      if (const auto t = j.find("stage_wall_s"); t != j.end() && t->is_object()) {
        const auto s = [&](const char* key) { return t->contains(key) && t->at(key).is_number() ? t->at(key).get<double>() : 0.0; };
        r.stage_times = {s("calibration"), s("candidates"), s("recalibration"), s("refinement"), s("confidence")};
      }
      r.correct = r.verdict == r.c.true_effect;
      r.git_commit = j.value("git_commit", std::string());
      r.verdict_adds = j.contains("verdict_adds") ? j.at("verdict_adds").get<std::vector<std::string>>()
                                                   : adds_of_verdict(r.verdict, r.c.model_effects);
      r.indistinguishable_from = j.value("indistinguishable_from", std::vector<std::string>{});
      r.alike_mechanisms = j.value("alike_mechanisms", std::vector<std::string>{});
      for (const nlohmann::json& k : j.value("proposal_checks", nlohmann::json::array()))
        r.proposal_checks.push_back({k.at("against").get<std::string>(), k.at("test").get<std::string>(), number(k, "separation_floors"),
                                     number(k, "gap_verdict"), number(k, "gap_against"), k.value("truth_nearer", false),
                                     k.contains("verdict_after") && k["verdict_after"].is_string() ? k["verdict_after"].get<std::string>() : std::string()});
      for (const nlohmann::json& c : j.value("candidates", nlohmann::json::array()))
        r.candidates.push_back({c.at("effect").get<std::string>(), number(c, "evidence_nats"), number(c, "evidence_se_nats"),
                                number(c, "heldout_gap"), c.value("earns", false)});
      rows.push_back(r);
    } catch (const nlohmann::json::exception&) {
      continue;
    }
  }
  return rows;
}

}  // namespace tribo::cli
