// Experiment bundles (DESIGN §7): round trip, any subset of files, and rejection of malformed
// input with the file, line and reason.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "gap/bundle.h"
#include "tests/gap/bundle_fixture.h"

namespace tribo::gap {
namespace {

namespace fs = std::filesystem;

class BundleTest : public BundleFixture {
 protected:
  BundleTest() : BundleFixture("tribo_gap_bundle_") {}
};

TEST_F(BundleTest, RoundTripKeepsEveryValue) {
  ExperimentBundle b;
  b.stiffness_N_per_m = 1.0e4;
  b.normal_load_N = 90.0;
  b.static_points = {{0.5, 0.31}, {2.0, 0.29}};
  gap::Run r;
  r.run_id = "a";
  r.v_m_per_s = 0.01;
  r.trace.t_s = {0.0, 0.1, 0.2};
  r.trace.x_m = {1e-3, 2e-3, 1.5e-3};
  r.trace.friction_N = {20.0, 25.0, 18.5};
  b.runs.push_back(r);
  b.regimes = {{0.01, "stick_slip", 1e-3, 100.0}};
  write_bundle(b, dir_);
  const ExperimentBundle c = read_bundle(dir_);
  ASSERT_TRUE(c.stiffness_N_per_m.has_value());
  EXPECT_DOUBLE_EQ(*c.stiffness_N_per_m, 1.0e4);
  EXPECT_FALSE(c.mass_kg.has_value());  // left out: to be calibrated or taken from the model
  ASSERT_EQ(c.static_points.size(), 2u);
  EXPECT_DOUBLE_EQ(c.static_points[1].mu_s, 0.29);
  ASSERT_EQ(c.runs.size(), 1u);
  EXPECT_EQ(c.runs[0].trace.friction_N, r.trace.friction_N);
  EXPECT_EQ(c.runs[0].trace.x_m, r.trace.x_m);
  ASSERT_EQ(c.regimes.size(), 1u);
  EXPECT_EQ(c.regimes[0].regime, "stick_slip");
  EXPECT_TRUE(c.warnings.empty());
}

// A written bundle reads back bit for bit, so that `tribo gap generate`'s files are the case the
// selftest diagnosed in memory: values that need all 17 significant digits of a double.
TEST_F(BundleTest, RoundTripIsExactToTheLastBit) {
  ExperimentBundle b;
  b.mass_kg = 1.0 / 3.0;
  b.stiffness_N_per_m = std::nextafter(1.0e4, 2.0e4);
  b.static_points = {{std::nextafter(0.5, 1.0), 0.1 + 0.2}};
  gap::Run r;
  r.run_id = "a";
  r.v_m_per_s = 0.01 / 3.0;
  r.trace.t_s = {0.0, 0.1 / 3.0, 0.2 / 3.0};
  r.trace.friction_N = {20.0 / 7.0, std::nextafter(25.0, 0.0), 18.5 / 3.0};
  b.runs.push_back(r);
  write_bundle(b, dir_);
  const ExperimentBundle c = read_bundle(dir_);
  EXPECT_EQ(*c.mass_kg, *b.mass_kg);
  EXPECT_EQ(*c.stiffness_N_per_m, *b.stiffness_N_per_m);
  EXPECT_EQ(c.static_points[0].phi_dot_per_s, b.static_points[0].phi_dot_per_s);
  EXPECT_EQ(c.static_points[0].mu_s, b.static_points[0].mu_s);
  EXPECT_EQ(c.runs[0].v_m_per_s, r.v_m_per_s);
  EXPECT_EQ(c.runs[0].trace.t_s, r.trace.t_s);
  EXPECT_EQ(c.runs[0].trace.friction_N, r.trace.friction_N);
}

TEST_F(BundleTest, OnlyStaticPointsOrOnlyTracesAreBundles) {
  write("static_friction.csv", "phi_dot_per_s,mu_s\n0.1,0.3\n1.0,0.28\n");
  EXPECT_EQ(read_bundle(dir_).static_points.size(), 2u);
  fs::remove(dir_ / "static_friction.csv");
  write("runs.csv", "run_id,v_m_per_s,file\n1,0.01,traces/a.csv\n");
  write("traces/a.csv", "t_s,friction_N\n0,1\n0.1,2\n0.2,1.5\n");
  EXPECT_EQ(read_bundle(dir_).runs.size(), 1u);
}

TEST_F(BundleTest, VelocityStepTraceWithMuAndDriveHistory) {
  write("experiment.toml", "[rig]\nkind = \"velocity_step\"\n[notes]\ntext = \"x\"\n");
  write("runs.csv", "run_id,v_m_per_s,file\n0,3e-6,traces/v.csv\n");
  write("traces/v.csv", "t_s,x_drive_m,v_drive_m_per_s,mu,normal_stress_Pa\n0,0,3e-6,0.6,2e7\n1,3e-6,3e-6,0.6,2e7\n2,1.3e-5,1e-5,0.61,2e7\n");
  const ExperimentBundle b = read_bundle(dir_);
  EXPECT_EQ(b.kind, "velocity_step");
  EXPECT_TRUE(b.runs[0].trace.has_drive_history());
  EXPECT_DOUBLE_EQ(b.runs[0].trace.mu[2], 0.61);
}

TEST_F(BundleTest, UnknownColumnsWarnAndAreIgnored) {
  write("static_friction.csv", "phi_dot_per_s,mu_s,operator\n0.1,0.3,7\n");
  const ExperimentBundle b = read_bundle(dir_);
  ASSERT_EQ(b.warnings.size(), 1u);
  EXPECT_NE(b.warnings[0].find("unknown column 'operator'"), std::string::npos);
}

TEST_F(BundleTest, MissingColumnIsRejectedWithFileAndLine) {
  write("static_friction.csv", "phi_dot_per_s\n0.1\n");
  EXPECT_NE(error().find("static_friction.csv:1: missing required column 'mu_s'"), std::string::npos) << error();
}

TEST_F(BundleTest, NonMonotonicTimeIsRejected) {
  write("runs.csv", "run_id,v_m_per_s,file\n1,0.01,traces/a.csv\n");
  write("traces/a.csv", "t_s,friction_N\n0,1\n0.2,2\n0.1,1.5\n");
  EXPECT_NE(error().find("a.csv:4: time t_s = 0.1 is not strictly increasing"), std::string::npos) << error();
}

TEST_F(BundleTest, NaNIsRejected) {
  write("static_friction.csv", "phi_dot_per_s,mu_s\n0.1,0.3\n0.2,nan\n");
  EXPECT_NE(error().find("static_friction.csv:3:"), std::string::npos) << error();
  EXPECT_NE(error().find("NaN"), std::string::npos) << error();
}

TEST_F(BundleTest, NegativeLoadIsRejected) {
  write("experiment.toml", "[rig]\nnormal_load_N = -5.0\n");
  write("static_friction.csv", "phi_dot_per_s,mu_s\n0.1,0.3\n");
  EXPECT_NE(error().find("experiment.toml:2: [rig] normal_load_N"), std::string::npos) << error();
  write("experiment.toml", "[rig]\n");
  write("runs.csv", "run_id,v_m_per_s,file\n1,0.01,traces/a.csv\n");
  write("traces/a.csv", "t_s,mu,normal_stress_Pa\n0,0.5,1e6\n1,0.5,-1e6\n2,0.5,1e6\n");
  EXPECT_NE(error().find("a.csv:3: negative normal load"), std::string::npos) << error();
}

// [rig.relative_uncertainty]: written and read back, and refused with the line and the reason
// when it names a key that cannot be refined, a constant [rig] does not give, or no fraction.
TEST_F(BundleTest, RelativeUncertaintyRoundTripsAndBadOnesAreRejected) {
  ExperimentBundle b;
  b.stiffness_N_per_m = 168.0;
  b.damping_N_s_per_m = 0.05;
  b.relative_uncertainty = {{"stiffness_N_per_m", 0.03}, {"damping_N_s_per_m", 0.5}};
  b.static_points = {{0.5, 0.31}};
  write_bundle(b, dir_);
  const ExperimentBundle c = read_bundle(dir_);
  EXPECT_EQ(c.relative_uncertainty, b.relative_uncertainty);
  EXPECT_TRUE(c.warnings.empty());

  const std::string rig = "[rig]\nstiffness_N_per_m = 168.0\n[rig.relative_uncertainty]\n";
  write("experiment.toml", rig + "normal_load_N = 0.02\n");
  EXPECT_NE(error().find("experiment.toml:4: [rig.relative_uncertainty] normal_load_N: only mass_kg"), std::string::npos) << error();
  write("experiment.toml", rig + "mass_kg = 0.02\n");
  EXPECT_NE(error().find("experiment.toml:4: [rig.relative_uncertainty] mass_kg: [rig] gives no mass_kg"), std::string::npos) << error();
  for (const char* u : {"0.0", "1.0", "-0.1", "nan", "\"3 %\""}) {
    write("experiment.toml", rig + "stiffness_N_per_m = " + u + "\n");
    EXPECT_NE(error().find("experiment.toml:4: [rig.relative_uncertainty] stiffness_N_per_m must be a fraction in (0, 1)"), std::string::npos)
        << u << ": " << error();
  }
  write("experiment.toml", "[rig]\nstiffness_N_per_m = 168.0\nrelative_uncertainty = 0.03\n");
  EXPECT_NE(error().find("experiment.toml:3: [rig] relative_uncertainty must be a table"), std::string::npos) << error();
}

// [rig] friction_channel: how the traces' friction was measured, written and read back, and
// refused with the line and the reason when it is neither reading.
TEST_F(BundleTest, FrictionChannelRoundTripsAndAnUnknownOneIsRejected) {
  ExperimentBundle b;
  b.static_points = {{0.5, 0.31}};
  write_bundle(b, dir_);
  EXPECT_FALSE(read_bundle(dir_).spring_force_channel);
  b.spring_force_channel = true;
  write_bundle(b, dir_);
  const ExperimentBundle c = read_bundle(dir_);
  EXPECT_TRUE(c.spring_force_channel);
  EXPECT_TRUE(c.warnings.empty());
  write("experiment.toml", "[rig]\nstiffness_N_per_m = 168.0\nfriction_channel = \"strain_gauge\"\n");
  EXPECT_NE(error().find("experiment.toml:3: [rig] friction_channel must be \"inertia_corrected\" or \"spring_force\""), std::string::npos)
      << error();
}

TEST_F(BundleTest, WrongNumberOfValuesAndEmptyBundleAreRejected) {
  EXPECT_NE(error().find("no data"), std::string::npos) << error();
  write("static_friction.csv", "phi_dot_per_s,mu_s\n0.1,0.3,4\n");
  EXPECT_NE(error().find("static_friction.csv:2: expected 2 values, found 3"), std::string::npos) << error();
}

}  // namespace
}  // namespace tribo::gap
