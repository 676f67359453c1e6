// The diagnosis end to end on a small bundle, twice (determinism): 52 s in Release, 4–5 min under
// the sanitizers, so left to the Release run (label `slow`); gap_tests keeps two full diagnoses
// (static points only, a homogenised base) under the sanitizers.
#include <gtest/gtest.h>

#include <cstdio>

#include "gap/diagnosis.h"
#include "gap/report.h"
#include "gap/synthesize.h"
#include "tests/gap/small_bundle.h"

namespace tribo::gap {
namespace {

// A report with the fits' wall times taken out: the machine's speed, not the diagnosis' result.
nlohmann::json without_wall_times(nlohmann::json j) {
  if (j.is_object()) {
    j.erase("wall_s");
    j.erase("stage_wall_s");
    for (auto& [key, value] : j.items()) value = without_wall_times(value);
  } else if (j.is_array()) {
    for (auto& value : j) value = without_wall_times(value);
  }
  return j;
}

// Traces only (no static points), viscous friction withheld: the diagnosis names it and the
// held-out gap shrinks by more than half. Same seed, same report (determinism).
TEST(Diagnosis, TracesOnlyNameViscousFrictionDeterministically) {
  const rig::RigParameters rig;
  rig::FrictionModel truth = rig::coulomb(0.32, 0.18);
  truth.set("viscous_friction", "coefficient_N_s_per_m", 60.0);
  SyntheticOptions so = small();
  so.speeds_m_per_s = {6e-3, 9e-3, 1.3e-2, 1.8e-2};  // below the speed where c = 60 N s/m stabilises sliding
  ExperimentBundle b = synthesize_bundle(rig, truth, so, 11);
  b.static_points.clear();
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.candidates = {"viscous_friction", "slip_transient", "hydrodynamic_lift"};
  o.seed = 4;
  const Diagnosis d = diagnose(b, rig, rig::coulomb(0.3, 0.2), o);
  ASSERT_EQ(verdict_name(d.verdict.effects), "viscous_friction") << report_json(d)["candidates"].dump(1);
  EXPECT_LT(d.verdict.heldout_gap_after, 0.5 * d.verdict.heldout_gap_before);
  EXPECT_NEAR(d.candidates.front().params.at("viscous_friction.coefficient_N_s_per_m"), 60.0, 20.0);  // 8 iterations on a piecewise-smooth cost
  // The bootstrap refitted the baseline and the two leaders, the verdict's first (diagnosis.h step 4).
  ASSERT_EQ(d.verdict.refitted.size(), 3u);
  EXPECT_EQ(d.verdict.refitted[0], "baseline");
  EXPECT_EQ(d.verdict.refitted[1], "viscous_friction");
  std::printf("confidence %.3f with refits, %.3f with the fits held\n", d.verdict.confidence, d.verdict.confidence_fixed_fits);
  const Diagnosis again = diagnose(b, rig, rig::coulomb(0.3, 0.2), o);
  EXPECT_EQ(without_wall_times(report_json(d)).dump(), without_wall_times(report_json(again)).dump());
}

}  // namespace
}  // namespace tribo::gap
