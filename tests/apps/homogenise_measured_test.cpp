// `tribo homogenise` on a measured topography (issue 36, item 5): [surface] kind = "file" reads a
// height map with contact/'s readers, and that one map flows through the BEM, the flow cells and
// the lift cells. Reference: the synthesised realisation written to a file and read back is the
// same surface, so its patch must equal the generated one's — column by column, to the round-off
// of the file's σ (the map's Rq is recomputed from its heights: 1e-15 relative).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "apps/config.h"
#include "apps/homogenise_config.h"
#include "contact/surface.h"
#include "contact/surface_io.h"
#include "homogenise/patch.h"
#include "tests/apps/expect_message.h"

namespace tribo::cli {
namespace {

std::filesystem::path measured_folder() {
  static const std::filesystem::path dir = [] {
    auto d = std::filesystem::temp_directory_path() / "tribo_homogenise_measured_tests";
    std::filesystem::create_directories(d);
    return d;
  }();
  return dir;
}

std::filesystem::path measured_config(const std::string& name, const std::string& surface_tables) {
  const std::filesystem::path p = measured_folder() / name;
  std::ofstream(p) << surface_tables
                   << "[pin]\nnormal_load_N = 93.86\n[speeds]\ncount = 3\n"
                      "[homogenise]\nrealisations = 1\nmin_contact_grid = 64\nseparation_ratios = [0.5, 1.0, 2.0, 4.0, 8.0]\n";
  return p;
}

const std::string kGenerated =
    "[surface]\nkind = \"gaussian\"\nspectrum = \"self_affine\"\nrms_height_m = 4.35e-7\nhurst = 0.8\n"
    "rolloff_wavelength_m = 6.25e-5\ncutoff_wavelength_m = 1.5625e-5\nseed = 3\n[domain]\nsize_m = 2.5e-4\ngrid = 32\n";

TEST(HomogeniseMeasured, AMapOfTheSynthesisedRealisationGivesItsPatch) {
  const HomogeniseRun generated = load_homogenise_run(measured_config("generated.toml", kGenerated));
  contact::write_npy(measured_folder() / "map.npy", contact::gaussian_surface(generated.options.surface));
  const HomogeniseRun measured =
      load_homogenise_run(measured_config("measured.toml", "[surface]\nkind = \"file\"\nfile = \"map.npy\"\n[domain]\nsize_m = 2.5e-4\n"));
  ASSERT_TRUE(measured.options.measured_heights_m);
  EXPECT_EQ(measured.options.surface.grid, 32);
  EXPECT_NEAR(measured.options.surface.rms_height_m, 4.35e-7, 1e-15 * 4.35e-7);
  ASSERT_EQ(measured.input_files.size(), 1u);
  EXPECT_EQ(measured.input_files[0].filename(), "map.npy");

  const homogenise::PatchResult a = homogenise::solve_patch(generated.options, 0);
  const homogenise::PatchResult b = homogenise::solve_patch(measured.options, 0);
  ASSERT_EQ(a.unconverged + b.unconverged, 0) << a.messages << b.messages;
  const double tol = 1e-9;  // the σ round-off above, through solves converged to 1e-8 … 1e-10
  EXPECT_NEAR(b.mu_s_max, a.mu_s_max, tol * a.mu_s_max);
  EXPECT_NEAR(b.mu_boundary, a.mu_boundary, tol * a.mu_boundary);
  for (std::size_t m = 0; m < a.separation_m.size(); ++m) {
    EXPECT_NEAR(b.solid_pressure_Pa[m], a.solid_pressure_Pa[m], tol * a.solid_pressure_Pa.front()) << m;
    EXPECT_NEAR(b.phi_x[m], a.phi_x[m], tol) << m;
    EXPECT_NEAR(b.lift_per_eta_u_per_m[m], a.lift_per_eta_u_per_m[m], tol * std::abs(a.lift_per_eta_u_per_m.front())) << m;
  }
}

std::string homogenise_error(const std::filesystem::path& config) {
  return fixture::input_error_of([&] { load_homogenise_run(config); });
}

TEST(HomogeniseMeasured, BadMapsAreRefusedNamingTheFileAndTheReason) {
  std::ofstream(measured_folder() / "wide.txt") << "0 1 2\n1 2 3\n";
  fixture::expect_all(homogenise_error(measured_config("wide.toml", "[surface]\nkind = \"file\"\nfile = \"wide.txt\"\n[domain]\nsize_m = 1e-4\n")),
                      {"wide.toml", "file", "2x3", "square"});
  std::ofstream(measured_folder() / "square.txt") << "0 1\n1 0\n";
  fixture::expect_all(homogenise_error(measured_config("nosize.toml", "[surface]\nkind = \"file\"\nfile = \"square.txt\"\n")),
                      {"nosize.toml", "no lateral size", "[domain] size_m"});
  std::ofstream(measured_folder() / "four.toml") << "[surface]\nkind = \"file\"\nfile = \"square.txt\"\n[domain]\nsize_m = 1e-4\n"
                                           "[homogenise]\nrealisations = 4\n";
  fixture::expect_all(homogenise_error(measured_folder() / "four.toml"), {"four.toml", "realisations", "one realisation"});
}

}  // namespace
}  // namespace tribo::cli
