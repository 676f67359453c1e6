// Rig constants the bundle gives with a stated uncertainty are refined within it (issue 15), on
// data from the independent generator (gap/independent/: its own integrator, measuring chain and
// rig constants drawn within ± 3 % — damping ± 10 % — of what the bundle tells). A Coulomb rig
// told slightly wrong constants is the control no catalogue effect may explain: the calibration
// must take the error into the constants, not leave it for a mechanism.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gap/diagnosis.h"
#include "gap/independent/generator.h"
#include "rig/friction_model.h"

namespace tribo::gap {
namespace {

double relative_error(double value, double truth) { return std::abs(value / truth - 1.0); }

// The first control whose spring the bundle tells at least 2 % off, so the refinement has an error
// to find that the sensor noise (1 % of μk W, averaged over many cycles) does not hide.
independent::IndependentCase control_told_a_wrong_spring() {
  independent::GeneratorOptions go;
  go.speeds_m_per_s = {6e-3, 1.1e-2, 2.0e-2, 3.2e-2};
  go.duration_s = 1.5;
  for (std::uint64_t seed = 1; seed < 40; ++seed) {
    independent::IndependentCase c = independent::make_independent_case("none", seed, go);
    if (relative_error(c.told.stiffness_N_per_m, c.actual.stiffness_N_per_m) > 0.02) return c;
  }
  throw std::runtime_error("no seed below 40 draws a spring 2 % off");
}

TEST(RigRefinement, StatedUncertaintyLetsTheCalibrationFindTheSpringAndCloseTheGap) {
  const independent::IndependentCase c = control_told_a_wrong_spring();
  ASSERT_EQ(c.bundle.relative_uncertainty.at("stiffness_N_per_m"), 0.03);
  DiagnosisOptions o;
  o.max_iterations = 8;
  o.bootstrap_samples = 20;
  o.candidates = {"viscous_friction"};
  const rig::RigParameters told = apply_bundle_rig(c.bundle, rig::RigParameters{});
  const rig::FrictionModel model = rig::coulomb(c.model_mu_s, c.model_mu_k);
  const Diagnosis refined = diagnose(c.bundle, told, model, o);
  ExperimentBundle exact = c.bundle;
  exact.relative_uncertainty.clear();
  const Diagnosis fixed = diagnose(exact, told, model, o);

  const double k_told = c.told.stiffness_N_per_m, k_true = c.actual.stiffness_N_per_m, k_fit = refined.rig.stiffness_N_per_m;
  std::printf("k told %.6g, true %.6g (%+.2f %%), refined %.6g (%+.2f %% of true); M told %.5g true %.5g refined %.5g\n", k_told, k_true,
              100.0 * (k_told / k_true - 1.0), k_fit, 100.0 * (k_fit / k_true - 1.0), c.told.mass_kg, c.actual.mass_kg, refined.rig.mass_kg);
  std::printf("held-out gap: constants exact %.4g, refined %.4g; noise floor %.4g; verdicts %s, %s\n", fixed.baseline_heldout.gap,
              refined.baseline_heldout.gap, refined.verdict.noise_floor, verdict_name(fixed.verdict).c_str(),
              verdict_name(refined.verdict).c_str());
  // Within the stated box, and most of the way from the told value to the true one.
  EXPECT_LE(relative_error(k_fit, k_told), 0.03 + 1e-12);
  EXPECT_LT(relative_error(k_fit, k_true), 0.4 * relative_error(k_told, k_true));
  EXPECT_EQ(refined.calibrated_params.count("rig.stiffness_N_per_m"), 1u);
  EXPECT_EQ(fixed.calibrated_params.count("rig.stiffness_N_per_m"), 0u);
  EXPECT_DOUBLE_EQ(fixed.rig.stiffness_N_per_m, k_told);
  // The refined baseline leaves less for a mechanism to take, and still answers "none".
  EXPECT_LT(refined.baseline_heldout.gap, 0.8 * fixed.baseline_heldout.gap);
  EXPECT_EQ(verdict_name(refined.verdict), "none");
}

}  // namespace
}  // namespace tribo::gap
