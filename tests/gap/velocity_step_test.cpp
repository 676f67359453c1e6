// The diagnosis of a velocity-step test on a machine nobody describes, simulated and measured
// (slow: minutes).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>

#include "gap/bundle.h"
#include "gap/compare.h"
#include "gap/diagnosis.h"
#include "gap/report.h"

namespace tribo::gap {
namespace {

// "Measured" velocity step 3 → 10 µm/s: the truth simulated under the drive history of a
// 10 Hz record and sampled there, plus sensor noise.
ExperimentBundle velocity_step_bundle(const rig::RigParameters& truth_rig, const rig::FrictionModel& truth, std::uint64_t seed) {
  ExperimentBundle b;
  b.kind = "velocity_step";
  Run run;
  run.run_id = "0";
  run.v_m_per_s = 3e-6;
  for (int i = 0; i <= 700; ++i) {  // 60 µm at 3 µm/s, then 500 µm at 10 µm/s, sampled at 10 Hz
    const double t = 0.1 * i, v = t < 20.0 ? 3e-6 : 1e-5;
    run.trace.t_s.push_back(t);
    run.trace.v_drive_m_per_s.push_back(v);
    run.trace.x_drive_m.push_back(t < 20.0 ? 3e-6 * t : 6e-5 + 1e-5 * (t - 20.0));
    run.trace.mu.push_back(truth.baseline.mu_k);  // placeholder until the truth is simulated below
  }
  b.runs.push_back(run);
  std::vector<SimulatedRun> sim;
  Comparison(b, truth_rig).predict(truth_rig, truth, seed, &sim);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 3e-4);  // the real BRAVA record's scatter is ≈ 7e-4
  Trace& tr = b.runs[0].trace;
  for (std::size_t i = 0; i < tr.t_s.size(); ++i) {
    const auto& t = sim[0].t_s;
    const std::size_t j = std::min<std::size_t>(std::lower_bound(t.begin(), t.end(), tr.t_s[i]) - t.begin(), t.size() - 1);
    tr.mu[i] = sim[0].mu[j] + noise(rng);
  }
  return b;
}

// A velocity-step test (as in rock-friction laboratories) on a machine whose stiffness and
// damping nobody gives: friction peaks after the step and decays over ≈ 10 µm of slip back to the
// same level (rate-and-state with a = b). The truth is the catalogue's slip_transient, armed at
// the breakaway that follows the re-lock at the step (compare.cpp); the diagnosis calibrates k and
// the damping ratio ζ, locates the gap after the step and names slip_transient, cutting the
// held-out gap by half.
TEST(Diagnosis, VelocityStepCalibratesStiffnessAndDampingAndNamesTheSlipTransient) {
  rig::RigParameters truth_rig;
  truth_rig.stiffness_N_per_m = 3e5;
  truth_rig.damping_N_s_per_m = 0.5 * 2.0 * std::sqrt(3e5 * truth_rig.mass_kg);  // ζ = 0.5
  rig::FrictionModel truth = rig::coulomb(0.619, 0.608);
  truth.set("slip_transient", "amplitude", 1.0);
  truth.set("slip_transient", "decay_distance_m", 1e-5);
  const ExperimentBundle b = velocity_step_bundle(truth_rig, truth, 7);

  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 50;
  o.calibrate_rig = {"stiffness_N_per_m", "damping_ratio"};
  o.candidates = {"slip_transient", "viscous_friction", "strain_rate_hardening"};
  const Diagnosis d = diagnose(b, rig::RigParameters{}, rig::coulomb(0.62, 0.6), o);
  ASSERT_EQ(verdict_name(d.verdict.effects), "slip_transient") << report_json(d)["candidates"].dump(1);
  // The baseline's misses all lie after the step, none before it (the training items see only
  // the first speed and the step's bins), and of its misses in friction after the step nearly all
  // in the transient's bins. Which Coulomb baseline fits train best depends on where the
  // re-calibration from the refined leaders starts (pipeline.h rebase): one that slides at the
  // steady level and misses only the transient (99.97 % of the squared residual in its bins,
  // 2026-11-28), or one with μs > μk, little damping and stick-slip in the steady window after the
  // step (97 % of it in the scatter there, since the slip transient's search starts from the step's
  // stable levels, 2026-12-07). Either misses the transient, not the levels.
  double after_step = 0.0, transient = 0.0, settled = 0.0;
  for (const auto& l : d.localization) {
    if (l.where.find("high v") != std::string::npos) after_step += l.share;
    if (l.observable != "mu_after_step") continue;
    (l.where.find("slip transient after step") != std::string::npos ? transient : settled) += l.share;
  }
  const std::string where = report_json(d)["localization"].dump(1);
  EXPECT_GT(after_step, 0.99) << where;
  EXPECT_GT(transient, 0.95 * (transient + settled)) << where;
  EXPECT_LT(d.verdict.heldout_gap_after, 0.5 * d.verdict.heldout_gap_before);
  // D_c within a factor 1.5 of the truth: noise 3e-4 on a 0.011 peak, eight LM iterations.
  const double dc = d.candidates.front().params.at("slip_transient.decay_distance_m");
  const std::string fitted = report_json(d)["candidates"][0]["params"].dump();
  EXPECT_GT(dc, 1e-5 / 1.5) << fitted;
  EXPECT_LT(dc, 1e-5 * 1.5) << fitted;
}

// The same machine with a rate-weakening rock (Ruina's slip law, b − a = β = 0.004): after the
// step up the peak decays to a level β ln(10/3) = 0.0048 below the old one. The search starts from
// what the step shows (gap/pipeline_candidates.cpp search_start): the peak, its 1/e distance and
// the stable level's fall per e-fold of speed. With β started mid-range instead (0.025, a fall of
// 0.030 across the step) that start lost to a grid point on the measured basalt step, which no
// fit left (held-out gap 1.52 against 0.066; docs/gap.md). Tolerances: β within a factor 1.5
// (0.0048 of level change against 3e-4 noise averaged over the steady windows' ≈ 100 samples
// each), D_c as above.
TEST(Diagnosis, VelocityStepOnARateWeakeningRockReadsTheStableLevelsFallAndNamesTheSlipLaw) {
  rig::RigParameters truth_rig;
  truth_rig.stiffness_N_per_m = 3e5;
  truth_rig.damping_N_s_per_m = 0.5 * 2.0 * std::sqrt(3e5 * truth_rig.mass_kg);  // ζ = 0.5
  const double beta = 0.004;
  rig::FrictionModel truth = rig::coulomb(0.619, 0.608);
  truth.set("slip_transient", "amplitude", 1.0);
  truth.set("slip_transient", "decay_distance_m", 1e-5);
  truth.set("slip_transient", "rate_weakening", beta);
  truth.set("slip_transient", "reference_speed_m_per_s", 1e-5);
  const ExperimentBundle b = velocity_step_bundle(truth_rig, truth, 11);
  const StepResponse step = Comparison(b, truth_rig).step_response();
  EXPECT_NEAR(step.stable_fall_per_efold(), beta, 0.25 * beta);

  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 50;
  o.calibrate_rig = {};  // the machine known: this test is about the friction
  o.candidates = {"slip_transient"};
  const Diagnosis d = diagnose(b, truth_rig, rig::coulomb(0.62, 0.6), o);
  ASSERT_EQ(verdict_name(d.verdict.effects), "slip_transient") << report_json(d)["candidates"].dump(1);
  EXPECT_LT(d.verdict.heldout_gap_after, 0.5 * d.verdict.heldout_gap_before);
  const auto& fitted = d.candidates.front().params;
  const std::string params = report_json(d)["candidates"][0]["params"].dump();
  EXPECT_GT(fitted.at("slip_transient.rate_weakening"), beta / 1.5) << params;
  EXPECT_LT(fitted.at("slip_transient.rate_weakening"), beta * 1.5) << params;
  EXPECT_GT(fitted.at("slip_transient.decay_distance_m"), 1e-5 / 1.5) << params;
  EXPECT_LT(fitted.at("slip_transient.decay_distance_m"), 1e-5 * 1.5) << params;
}

// The measured record (tests/gap/data/velstep-basalt-brava: basalt gouge, BRAVA, 3 → 10 µm/s)
// with the slip transient as the only candidate, as `tribo gap diagnose --candidates
// slip_transient` runs it: the stiffness and damping nobody gives are calibrated. The search starts
// from the step's own response; the fitted decay distance is the slider's slip, which the record's
// 1/e distance of load-point travel approximates on a stiff machine — within a factor 2. The
// transient takes the held-out gap to under a tenth (0.066 of 1.08 on 2026-12-07); with the start's
// β left mid-range (2026-12-06 to bd0d8fb) the fit stopped at a grid point and left 1.52 of 1.48.
TEST(MeasuredVelocityStep, TheSlipTransientFromTheStepsResponseTakesTheHeldOutGapBelowATenth) {
  const ExperimentBundle b = read_bundle(std::filesystem::path(TRIBO_SOURCE_DIR) / "tests/gap/data/velstep-basalt-brava");
  DiagnosisOptions o;  // the defaults of `tribo gap diagnose`
  o.calibrate_rig = {"stiffness_N_per_m", "damping_ratio"};
  o.candidates = {"slip_transient"};
  const Diagnosis d = diagnose(b, apply_bundle_rig(b, rig::RigParameters{}), rig::coulomb(0.62, 0.60), o);  // examples/gap-velstep-baseline.toml
  const StepResponse step = Comparison(b, rig::RigParameters{}).step_response();
  const std::string fitted = report_json(d)["candidates"].dump();
  ASSERT_EQ(verdict_name(d.verdict.effects), "slip_transient") << fitted;
  EXPECT_LT(d.verdict.heldout_gap_after, 0.1 * d.verdict.heldout_gap_before) << fitted;
  const double dc = d.candidates.front().params.at("slip_transient.decay_distance_m");
  EXPECT_GT(dc, step.decay_distance_m / 2.0) << fitted;
  EXPECT_LT(dc, step.decay_distance_m * 2.0) << fitted;
}

}  // namespace
}  // namespace tribo::gap
