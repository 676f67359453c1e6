// `tribo ehl` [profile] file (issue 36): a measured trace as the line contact's stationary profile —
// levelled, Gaussian-filtered at the cut-off the solver's nodes resolve (ISO 16610-21, contact/profile.h)
// and placed on the domain. Reference: a trace that is a sampled waviness a cos(2π x/λ) must reach the
// solver as that waviness times the filter's closed-form transmission, the route whose solves the
// wavy-pin tests check against Westergaard (tests/lubrication/ehl_line_mixed_slow_test.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "apps/config.h"
#include "apps/ehl_run.h"
#include "contact/profile.h"
#include "contact/surface_io.h"
#include "tests/apps/expect_message.h"

namespace tribo::cli {
namespace {

constexpr double kAmplitude = 2.7e-8, kWavelength = 4.6e-5, kSpacing = 5e-7;  // 92 samples a wavelength
constexpr int kHalf = 20 * 92;  // the trace's half length in samples: 20 wavelengths (0.92 mm)

const std::string kContact =
    "[contact]\ngeometry = \"line\"\nload_per_length_N_per_m = 3e5\nreduced_radius_m = 0.01\nreduced_modulus_Pa = 2.26e11\n"
    "mean_speed_m_per_s = 1e-4\nslide_to_roll_ratio = 2.0\n[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2.2e-8\neyring_stress_Pa = 5e6\n"
    "[solver]\nnodes = 401\n";

// A waviness sampled with a crest at the middle sample, written as a one-column .npy (no lateral size).
std::filesystem::path write_wavy_trace(const std::filesystem::path& dir) {
  Eigen::ArrayXXd z(2 * kHalf + 1, 1);
  for (int k = 0; k < z.rows(); ++k) z(k, 0) = kAmplitude * std::cos(2.0 * std::numbers::pi * (k - kHalf) * kSpacing / kWavelength);
  const auto path = dir / "trace.npy";
  contact::write_npy(path, z);
  return path;
}

std::filesystem::path write_config(const std::filesystem::path& dir, const std::string& profile) {
  const auto path = dir / "ehl.toml";
  std::ofstream(path) << kContact << "[profile]\nboundary_friction_coefficient = 0.1\n" << profile;
  return path;
}

// The solver's samples against T a cos(2π x/λ), T = exp(−π (α λc/λ)²) for the default cut-off of 8
// node spacings (2.76 µm at 401 nodes: λ/λc = 2.08, T = 0.852). Tolerance 1e-3 a: levelling a
// symmetric whole-period cosine removes its mean a/n = 3e-4 a (n = 3681 samples; its slope is 0), the
// truncated, sampled window is the integral's to 1e-6.
TEST(EhlMeasuredProfile, ASampledWavinessReachesTheSolverAsTheWavinessTheFilterPasses) {
  const auto dir = fixture::test_folder("tribo_ehl_measured_profile");
  write_wavy_trace(dir);
  const EhlRun run = load_ehl_run(write_config(dir, "file = \"trace.npy\"\nspacing_m = 5e-7\ncentre_m = 9.2e-4\n"));
  ASSERT_TRUE(run.profile);
  const EhlRun::Profile& pr = *run.profile;
  ASSERT_EQ(run.input_files.size(), 1u);
  EXPECT_EQ(run.input_files[0].filename(), "trace.npy");
  const double b = pr.surface.x_m.empty() ? 0.0 : -pr.surface.x_m.front() / 4.5;  // the domain starts at −4.5 b (a sample before)
  const double node_spacing = 6.0 * b / 400.0;
  EXPECT_NEAR(*pr.cutoff_m, 8.0 * node_spacing, 0.01 * node_spacing);
  const double t = contact::gaussian_filter_transmission(kWavelength, *pr.cutoff_m);
  EXPECT_NEAR(t, 0.852, 0.001);
  ASSERT_GT(pr.surface.x_m.size(), 2000u);
  EXPECT_LE(pr.surface.x_m.front(), -4.5 * b + 1e-12);
  EXPECT_GE(pr.surface.x_m.back(), 1.5 * b - kSpacing);
  double worst = 0.0;
  for (std::size_t i = 0; i < pr.surface.x_m.size(); ++i)
    worst = std::max(worst, std::abs(pr.surface.height_m[i] - t * kAmplitude * std::cos(2.0 * std::numbers::pi * pr.surface.x_m[i] / kWavelength)));
  EXPECT_LT(worst, 1e-3 * kAmplitude);
  // Rq of a cosine is a/√2: as measured, and as the filter passes it (T a/√2); the domain holds
  // 24.0 wavelengths, so the part-period's bias is under 1 %.
  EXPECT_NEAR(pr.rq_m / (kAmplitude / std::sqrt(2.0)), 1.0, 0.01);
  EXPECT_NEAR(pr.filtered_rq_m / (t * kAmplitude / std::sqrt(2.0)), 1.0, 0.01);
}

TEST(EhlMeasuredProfile, BadTracesAndPlacementsAreRefusedWithTheKeyAndReason) {
  const auto dir = fixture::test_folder("tribo_ehl_measured_profile");
  write_wavy_trace(dir);
  contact::write_npy(dir / "map.npy", Eigen::ArrayXXd::Zero(64, 8));
  const auto expect = [&](const std::string& profile, std::initializer_list<std::string> fragments) {
    const auto config = write_config(dir, profile);
    fixture::expect_all(fixture::input_error_of([&] { load_ehl_run(config); }), fragments);
  };
  expect("file = \"trace.npy\"\namplitude_m = 1e-8\n", {"profile.amplitude_m", "not both"});
  expect("file = \"trace.npy\"\n", {"profile.file", "trace.npy", "no lateral size", "spacing_m"});
  expect("file = \"missing.npy\"\nspacing_m = 5e-7\n", {"profile.file", "missing.npy"});
  expect("file = \"map.npy\"\nspacing_m = 5e-7\n", {"profile.line", "64 x 8", "0 … 7"});
  expect("file = \"map.npy\"\nspacing_m = 5e-7\nline = 8\n", {"profile.line"});
  expect("file = \"trace.npy\"\nspacing_m = 5e-7\ncutoff_m = 1e-5\n", {"profile.cutoff_m", "8 node", "solver.nodes"});
  expect("file = \"trace.npy\"\nspacing_m = 5e-7\ncentre_m = 2e-4\n", {"profile.centre_m", "leaves the part the filter gives", "trace.npy"});
  expect("file = \"map.npy\"\nspacing_m = 5e-7\nline = 3\n", {"profile.file", "map.npy", "shorter than the filter's window"});
  expect("file = \"map.npy\"\nspacing_m = 2e-6\nline = 3\n", {"profile.centre_m", "map.npy"});  // 0.13 mm: shorter than the domain
  expect("file = \"trace.npy\"\nspacing_m = 5e-6\n", {"profile.file", "coarser than the solver's"});  // nodes 2.8 µm apart
}

}  // namespace
}  // namespace tribo::cli
