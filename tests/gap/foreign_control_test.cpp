// The do-no-harm case (issue 35): a Coulomb control from a rig simulator written outside this
// project (tests/gap/data/README.md) — its own integrator, event-dense sampling, 2 % scatter of
// the breakaway from cycle to cycle — diagnosed against a Coulomb model with μs and μk each about
// 10 % off. The calibration must find μs and μk, and no catalogue effect may be named: the verdict
// is "none". (Before the calibration stage and the likelihood: slip_transient at 76 %, μs 2 %
// below the truth after a 2-iteration calibration.)
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include <nlohmann/json.hpp>

#include "gap/diagnosis.h"
#include "rig/friction_model.h"

namespace tribo::gap {
namespace {

const std::filesystem::path kBundle = std::filesystem::path(TRIBO_SOURCE_DIR) / "tests/gap/data/foreign-coulomb-control";

TEST(ForeignControl, ACoulombRigFromAnotherSimulatorIsCalibratedAndAnswersNone) {
  const ExperimentBundle bundle = read_bundle(kBundle);
  const nlohmann::json truth = nlohmann::json::parse(std::ifstream(kBundle / "truth.json"));
  const double mu_s = truth.at("mu_s").get<double>(), mu_k = truth.at("mu_k").get<double>();
  DiagnosisOptions o;  // the defaults of `tribo gap diagnose`
  const rig::FrictionModel model = rig::coulomb(0.379, 0.198);  // model.toml
  const Diagnosis d = diagnose(bundle, apply_bundle_rig(bundle, rig::RigParameters{}), model, o);
  std::printf("calibrated mu_s %.4f (truth %.4f), mu_k %.4f (truth %.4f); train gap %.4f = %.2f floors; held-out %.4f, floor %.4f; "
              "verdict %s at %.2f\n",
              d.calibrated.baseline.mu_s, mu_s, d.calibrated.baseline.mu_k, mu_k, d.calibration.train_gap, d.calibration.train_floors(),
              d.baseline_heldout.gap, d.verdict.noise_floor, verdict_name(d.verdict).c_str(), d.verdict.confidence);
  for (const Candidate& c : d.candidates)
    std::printf("  %-40s held-out %.4f  evidence %.1f ± %.1f nats%s\n", verdict_name(c.effects).c_str(), c.heldout_gap_after, c.evidence_nats,
                c.evidence_se_nats, c.earns ? "  earns" : "");
  EXPECT_EQ(verdict_name(d.verdict), "none");
  // The record's breakaways scatter by 2 % and its readings are smoothed over a 20-ms stick
  // spacing at the fastest run: μs and μk within 3 % of the truth (the model started 6–7 % off;
  // measured 2026-11-26: μs 1.2 %, μk 3.0 % high — the excess μs − μk 0.7 % low).
  EXPECT_LT(std::abs(d.calibrated.baseline.mu_s / mu_s - 1.0), 0.03);
  EXPECT_LT(std::abs(d.calibrated.baseline.mu_k / mu_k - 1.0), 0.03);
}

}  // namespace
}  // namespace tribo::gap
