// The independent generator's drive-history bundles (gap/independent/generator.h) through the
// bundle writer and reader (gap/bundle.h): what the diagnosis reads is what was generated — the
// kind, the told rig and every trace column, the drive's record included. The writer keeps 10
// significant digits: values agree to 1e-9 of themselves (the quantised friction to its quantum).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "gap/bundle.h"
#include "gap/independent/generator.h"

namespace tribo::gap::independent {
namespace {

namespace fs = std::filesystem;

void expect_same_column(const std::vector<double>& written, const std::vector<double>& read, const char* name) {
  ASSERT_EQ(read.size(), written.size()) << name;
  for (std::size_t i = 0; i < written.size(); ++i)
    ASSERT_NEAR(read[i], written[i], 1e-9 * std::max(std::abs(written[i]), 1e-300)) << name << " row " << i;
}

// Writes the case's bundle, reads it back and compares: every kind the generator writes must read.
void expect_round_trip(const IndependentCase& c, const std::string& kind) {
  const fs::path dir = fs::temp_directory_path() / ("tribo_gap_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
  fs::remove_all(dir);
  write_bundle(c.bundle, dir);
  ExperimentBundle back;
  try {
    back = read_bundle(dir);
  } catch (const std::invalid_argument& e) {
    fs::remove_all(dir);
    FAIL() << "the " << kind << " bundle does not read back: " << e.what();
  }
  fs::remove_all(dir);
  EXPECT_EQ(back.kind, kind);
  // What was read, for provenance: experiment.toml, runs.csv and the one trace, in that order.
  ASSERT_EQ(back.files.size(), 3u);
  EXPECT_EQ(back.files[0].filename(), "experiment.toml");
  EXPECT_EQ(back.files[1].filename(), "runs.csv");
  EXPECT_EQ(back.files[2].parent_path().filename(), "traces");
  ASSERT_TRUE(back.stiffness_N_per_m && back.mass_kg && back.damping_N_s_per_m && back.normal_load_N);
  EXPECT_NEAR(*back.stiffness_N_per_m, c.told.stiffness_N_per_m, 1e-9 * c.told.stiffness_N_per_m);
  EXPECT_NEAR(*back.mass_kg, c.told.mass_kg, 1e-9 * c.told.mass_kg);
  EXPECT_NEAR(*back.damping_N_s_per_m, c.told.damping_N_s_per_m, 1e-9 * c.told.damping_N_s_per_m);
  EXPECT_NEAR(*back.normal_load_N, c.told.normal_load_N, 1e-9 * c.told.normal_load_N);
  ASSERT_EQ(back.runs.size(), 1u);
  const Run &w = c.bundle.runs[0], &r = back.runs[0];
  EXPECT_EQ(r.run_id, w.run_id);
  EXPECT_NEAR(r.v_m_per_s, w.v_m_per_s, 1e-9 * w.v_m_per_s);
  EXPECT_TRUE(r.trace.has_drive_history());
  expect_same_column(w.trace.t_s, r.trace.t_s, "t_s");
  expect_same_column(w.trace.friction_N, r.trace.friction_N, "friction_N");
  expect_same_column(w.trace.x_m, r.trace.x_m, "x_m");
  expect_same_column(w.trace.x_drive_m, r.trace.x_drive_m, "x_drive_m");
  expect_same_column(w.trace.v_drive_m_per_s, r.trace.v_drive_m_per_s, "v_drive_m_per_s");
}

// Two short holds (1 s, 3 s) and 10 D_c slides: the bundle's shape, not its physics (that is
// independent_generator_test.cpp's), in well under a second.
TEST(IndependentGeneratorBundle, SlideHoldSlideRoundTripsWithItsDriveColumns) {
  DriveHistoryOptions o;
  o.hold_times_s = {1.0, 3.0};
  o.slide_decay_lengths = 10.0;
  const IndependentCase c = make_slide_hold_slide_case("rate_and_state", 3, o);
  const std::vector<double>& v = c.bundle.runs[0].trace.v_drive_m_per_s;
  EXPECT_GT(std::count(v.begin(), v.end(), 0.0), 0);  // the holds are in the record
  expect_round_trip(c, "slide_hold_slide");
}

TEST(IndependentGeneratorBundle, VelocityStepRoundTripsWithItsDriveColumns) {
  DriveHistoryOptions o;
  o.slide_decay_lengths = 10.0;
  expect_round_trip(make_velocity_step_case("rate_and_state", 3, o), "velocity_step");
}

}  // namespace
}  // namespace tribo::gap::independent
