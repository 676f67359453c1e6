// The comparison and the diagnosis on small synthetic bundles whose truth is known.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gap/compare.h"
#include "gap/diagnosis.h"
#include "gap/selftest.h"

namespace tribo::gap {
namespace {

SyntheticOptions small() {
  SyntheticOptions o;
  o.speeds_m_per_s = {8e-3, 1.4e-2, 2.4e-2};
  o.duration_s = 1.5;
  return o;
}

rig::FrictionModel coulomb(double mu_s, double mu_k) {
  rig::FrictionModel m;
  m.baseline.mu_s = mu_s;
  m.baseline.mu_k = mu_k;
  return m;
}

// Like with like: the truth simulated through the same analysis reproduces its own "measured"
// observables to within the sensor noise (1 % of μk W, averaged over cycles), and a 10 % error in
// μs shows up as a gap of several per cent.
TEST(Comparison, TruthReproducesItsOwnMeasurementsAndMiscalibrationShows) {
  const rig::RigParameters rig;
  const rig::FrictionModel truth = coulomb(0.32, 0.2);
  const ExperimentBundle b = synthesize_bundle(rig, truth, small(), 3);
  const Comparison c(b, rig);
  ASSERT_GT(c.items().size(), 20u);
  auto rms = [&](const rig::FrictionModel& m) {
    const std::vector<double> r = c.residuals(c.predict(rig, m, 3));
    double s = 0.0;
    for (double x : r) s += x * x;
    return std::sqrt(s / static_cast<double>(r.size()));
  };
  EXPECT_LT(rms(truth), 0.01);
  EXPECT_GT(rms(coulomb(0.352, 0.2)), 0.05);
}

// The observables move nearly continuously with the model's parameters (extrema refined between
// samples, mean μ over whole cycles): on a scan of μk in steps of 0.4 % around the truth the
// residual has its minimum at the truth ± one step, falls towards it and rises after it, with
// reversals no larger than 0.001 (a tenth of a per cent of the observables' size; on a scan
// of viscous c before the refinement, sample-to-sample jumps reversed it by 0.002) for a
// least-squares fit to stall on.
TEST(Comparison, ResidualIsUnimodalOnAFineScanAroundTheTruth) {
  const rig::RigParameters rig;
  const rig::FrictionModel truth = coulomb(0.32, 0.2);
  const ExperimentBundle b = synthesize_bundle(rig, truth, small(), 3);
  const Comparison c(b, rig);
  std::vector<double> rms;
  for (int k = -5; k <= 5; ++k) {
    const std::vector<double> r = c.residuals(c.predict(rig, coulomb(0.32, 0.2 * (1.0 + 0.004 * k)), 3));
    double s = 0.0;
    for (double x : r) s += x * x;
    rms.push_back(std::sqrt(s / static_cast<double>(r.size())));
  }
  const auto lowest = static_cast<std::size_t>(std::min_element(rms.begin(), rms.end()) - rms.begin());
  EXPECT_LE(std::abs(static_cast<int>(lowest) - 5), 1);
  for (std::size_t k = 1; k < rms.size(); ++k) {
    if (k <= lowest) EXPECT_LT(rms[k], rms[k - 1] + 1e-3) << "step " << k;
    else EXPECT_GT(rms[k], rms[k - 1] - 1e-3) << "step " << k;
  }
}

// A bundle of static-friction points only, from a Coulomb rig: calibration recovers μs to 1 %
// (noise 1 % of μk W on each point, averaged over points) and nothing earns its parameters.
TEST(Diagnosis, StaticPointsOnlyCalibrateMuSAndAnswerNone) {
  const rig::RigParameters rig;
  ExperimentBundle b = synthesize_bundle(rig, coulomb(0.3, 0.2), small(), 5);
  b.runs.clear();
  DiagnosisOptions o;
  o.max_iterations = 6;
  const Diagnosis d = diagnose(b, rig, coulomb(0.36, 0.2), o);
  EXPECT_NEAR(d.calibrated.baseline.mu_s, 0.3, 0.003);
  EXPECT_TRUE(d.verdict.effects.empty()) << verdict_name(d.verdict.effects);
  EXPECT_LT(d.baseline.gap, 0.02);
}

// Traces only (no static points), viscous friction withheld: the diagnosis names it and the
// held-out gap shrinks by more than half. Same seed, same report (determinism).
TEST(Diagnosis, TracesOnlyNameViscousFrictionDeterministically) {
  const rig::RigParameters rig;
  rig::FrictionModel truth = coulomb(0.32, 0.18);
  truth.set("viscous_friction", "coefficient_N_s_per_m", 60.0);
  SyntheticOptions so = small();
  so.speeds_m_per_s = {6e-3, 9e-3, 1.3e-2, 1.8e-2};  // below the speed where c = 60 N s/m stabilises sliding
  ExperimentBundle b = synthesize_bundle(rig, truth, so, 11);
  b.static_points.clear();
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.candidates = {"viscous_friction", "slip_transient", "hydrodynamic_lift"};
  o.seed = 4;
  const Diagnosis d = diagnose(b, rig, coulomb(0.3, 0.2), o);
  ASSERT_EQ(verdict_name(d.verdict.effects), "viscous_friction") << report_json(d)["candidates"].dump(1);
  EXPECT_LT(d.verdict.heldout_gap_after, 0.5 * d.verdict.heldout_gap_before);
  EXPECT_NEAR(d.candidates.front().params.at("viscous_friction.coefficient_N_s_per_m"), 60.0, 20.0);  // 8 iterations on a piecewise-smooth cost
  const Diagnosis again = diagnose(b, rig, coulomb(0.3, 0.2), o);
  EXPECT_EQ(report_json(d).dump(), report_json(again).dump());
}

// Resuming an interrupted selftest: a case already in `finished` is taken as it was written (here
// a made-up verdict no diagnosis would give), is not handed to on_row again, and counts in the
// confusion matrix; no diagnosis runs, so this returns at once.
TEST(Selftest, FinishedCasesAreTakenNotDiagnosedAgain) {
  const SelftestCase c{"viscous_friction", {}, 42};
  SelftestRow earlier;
  earlier.c = c;
  earlier.verdict = "instrument";
  earlier.heldout_gap_before = 0.125;
  earlier.heldout_gap_after = 0.0625;
  int fresh_rows = 0;
  const SelftestResult r = run_selftest({c}, small(), DiagnosisOptions{}, [&](const SelftestRow&) { ++fresh_rows; }, {earlier});
  EXPECT_EQ(fresh_rows, 0);
  ASSERT_EQ(r.rows.size(), 1u);
  EXPECT_EQ(r.rows[0].verdict, "instrument");
  EXPECT_EQ(r.rows[0].heldout_gap_after, 0.0625);
  EXPECT_EQ(r.confusion.at("viscous_friction").at("instrument"), 1);
  EXPECT_EQ(r.identified_fraction, 0.0);
}

TEST(Diagnosis, RejectsInvalidOptions) {
  ExperimentBundle b;
  b.static_points = {{1.0, 0.3}};
  DiagnosisOptions o;
  o.calibrate_rig = {"colour"};
  EXPECT_THROW(diagnose(b, rig::RigParameters{}, coulomb(0.3, 0.2), o), std::invalid_argument);
}

}  // namespace
}  // namespace tribo::gap
