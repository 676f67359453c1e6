// One set of key names and one [surface] reader (issue 18): keys renamed for one name per quantity
// (`file` for a file, `normal_load_N` for the normal load) are refused with a message naming the
// file, the old key and the new one; the three commands that read a generated [surface] read the
// same surface from the same table; a drive table follows the bundle's CSV rules.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <utility>

#include "apps/config.h"
#include "apps/contact_run.h"
#include "apps/ehl_run.h"
#include "apps/homogenise_config.h"
#include "apps/reynolds_run.h"
#include "apps/rig_config.h"
#include "contact/surface.h"
#include "tests/apps/expect_message.h"

namespace tribo::cli {
namespace {

// Files of one test folder, beside each other: a config names its data files relative to itself.
std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = fixture::test_folder("tribo_config_keys_tests");
  std::ofstream(dir / name) << text;
  return dir / name;
}

using fixture::expect_all;
using fixture::input_error_of;

const std::string kSphere = "[surface]\nkind = \"sphere\"\nradius_m = 0.01\n[domain]\nsize_m = 1e-3\ngrid = 32\n"
                            "[material]\ne_star_Pa = 1.137e11\nhardness_Pa = 1.18e9\n";

TEST(RenamedKeys, ContactNormalAndTangentialLoadsNameTheNewKeys) {
  const auto normal = write_file("contact-normal.toml", kSphere + "[load]\nnormal_N = 1.0\n");
  expect_all(input_error_of([&] { load_contact_run(normal, false); }),
             {normal.string(), "key 'load.normal_N'", "use 'load.normal_load_N'"});
  const auto tangential = write_file("contact-tangential.toml", kSphere + "[load]\nnormal_load_N = 1.0\ntangential_N = 0.1\n");
  expect_all(input_error_of([&] { load_contact_run(tangential, false); }),
             {tangential.string(), "key 'load.tangential_N'", "use 'load.tangential_load_N'"});
  const ContactRun run = load_contact_run(write_file("contact-new.toml", kSphere + "[load]\nnormal_load_N = 1.0\n"), false);
  EXPECT_EQ(run.normal_load_N, 1.0);
}

TEST(RenamedKeys, ContactSurfaceFileIsFileNotPath) {
  write_file("heights.txt", "0 1\n1 0\n");
  const std::string rest = "[domain]\nsize_m = 1e-3\n[material]\ne_star_Pa = 1.137e11\n[load]\nnormal_load_N = 1e-3\n";
  const auto old = write_file("contact-path.toml", "[surface]\nkind = \"file\"\npath = \"heights.txt\"\n" + rest);
  expect_all(input_error_of([&] { load_contact_run(old, false); }), {old.string(), "key 'surface.path'", "use 'surface.file'"});
  const ContactRun run =
      load_contact_run(write_file("contact-file.toml", "[surface]\nkind = \"file\"\nfile = \"heights.txt\"\n" + rest), false);
  EXPECT_EQ(run.grid.nx, 2);
}

TEST(RenamedKeys, RoughPairContactLoadIsNormalLoad) {
  const auto old = write_file("rough.toml", "[geometry]\nkind = \"rough_pair\"\ncontact_load_N = 0.5\n"
                                            "correlation_length_m = 6.25e-5\n[grid]\nn = 16\n");
  expect_all(input_error_of([&] { load_reynolds_run(old); }),
             {old.string(), "key 'geometry.contact_load_N'", "use 'geometry.normal_load_N'"});
}

// An unknown table is refused before the rough pair's two 8192² surfaces (0.5 GB each) are
// generated and pressed together: were the keys checked after the work, this test would run for
// minutes or exhaust memory instead of returning the error at once.
TEST(UnknownKeys, RoughPairRefusesThemBeforeGeneratingItsSurfaces) {
  const auto bad = write_file("rough-unknown.toml", "[geometry]\nkind = \"rough_pair\"\nnormal_load_N = 0.5\n"
                                                    "correlation_length_m = 6.25e-5\n[grid]\nn = 8192\n[nxid]\nn = 128\n");
  expect_all(input_error_of([&] { load_reynolds_run(bad); }), {bad.string(), "'nxid'", "unknown key"});
}

// The grid's node count has an upper bound (8192 a side), so a typo does not allocate gigabytes
// while loading: 15226 asked for 1.8 GB (fuzz_reynolds_config, 2026-11-29).
TEST(UnknownKeys, ReynoldsGridAboveItsBoundIsRefusedWithTheKey) {
  const auto big = write_file("reynolds-big.toml", "[geometry]\ngap_m = 1e-6\n[grid]\nn = 15226\n");
  expect_all(input_error_of([&] { load_reynolds_run(big); }), {big.string(), "grid.n", "8192"});
}

// Counts narrowed to int have an upper bound: 4294967298 junction points wrapped to 2 and the
// curve came out with two points, silently.
TEST(UnknownKeys, CountsBeyondAnIntAreRefusedNotWrapped) {
  const auto points = write_file("contact-points.toml", kSphere + "[load]\nnormal_load_N = 1.0\n[junction]\npoints = 4294967298\n");
  expect_all(input_error_of([&] { load_contact_run(points, true); }), {points.string(), "junction.points", "10000"});
  const auto threads = write_file("contact-threads.toml", kSphere + "[load]\nnormal_load_N = 1.0\n[solver]\nthreads = 4294967297\n");
  expect_all(input_error_of([&] { load_contact_run(threads, false); }), {threads.string(), "solver.threads"});
}

// The point contact's solver keys: the linear solver is one of three names, the preconditioner's
// reach and the grid have bounds (513² is the largest grid Newton–Krylov is offered for), each
// refused with the file and the key; a valid choice reaches the options.
TEST(UnknownKeys, EhlPointSolverKeysAreCheckedAndReachTheOptions) {
  const std::string ball = "[contact]\ngeometry = \"point\"\nload_N = 10.0\nreduced_radius_m = 9.525e-3\n"
                           "reduced_modulus_Pa = 2.308e11\nmean_speed_m_per_s = 0.5\n"
                           "[lubricant]\nviscosity_Pa_s = 0.04\npressure_viscosity_per_Pa = 2e-8\neyring_stress_Pa = 5e6\n[solver]\n";
  const auto method = write_file("ehl-method.toml", ball + "linear_solver = \"lu\"\n");
  expect_all(input_error_of([&] { load_ehl_run(method); }), {method.string(), "solver.linear_solver", "newton_krylov"});
  const auto reach = write_file("ehl-reach.toml", ball + "preconditioner_reach = 17\n");
  expect_all(input_error_of([&] { load_ehl_run(reach); }), {reach.string(), "solver.preconditioner_reach", "16"});
  const auto grid = write_file("ehl-grid.toml", ball + "nodes_x = 514\n");
  expect_all(input_error_of([&] { load_ehl_run(grid); }), {grid.string(), "solver.nodes_x", "513"});
  const auto ncp = write_file("ehl-ncp.toml", ball + "complementarity = \"fb\"\n");
  expect_all(input_error_of([&] { load_ehl_run(ncp); }), {ncp.string(), "solver.complementarity", "fischer_burmeister"});
  const auto valid = write_file("ehl-krylov.toml", ball + "linear_solver = \"dense_lu\"\npreconditioner_reach = 3\nnodes_x = 257\n"
                                                          "complementarity = \"fischer_burmeister\"\n");
  const EhlRun run = load_ehl_run(valid);
  EXPECT_EQ(run.point_options.linear_solver, lubrication::EhlPointLinearSolver::dense_lu);
  EXPECT_EQ(run.point_options.preconditioner_reach, 3);
  EXPECT_EQ(run.point_options.nodes_x, 257);
  EXPECT_EQ(run.point_options.complementarity, lubrication::Complementarity::fischer_burmeister);
  EXPECT_EQ(load_ehl_run(write_file("ehl-default.toml", ball)).point_options.complementarity, lubrication::Complementarity::minimum);
}

TEST(RenamedKeys, FlowFactorSurfaceSizeAndGridLiveInDomain) {
  const std::string surface = "[surface]\nrms_height_m = 4.35e-7\ncorrelation_length_m = 6.25e-5\n";
  const auto size = write_file("ff-size.toml", surface + "size_m = 1e-3\n");
  expect_all(input_error_of([&] { load_flow_factor_run(size); }), {size.string(), "key 'surface.size_m'", "use 'domain.size_m'"});
  const auto grid = write_file("ff-grid.toml", surface + "grid = 64\n");
  expect_all(input_error_of([&] { load_flow_factor_run(grid); }), {grid.string(), "key 'surface.grid'", "use 'domain.grid'"});
}

// [micro_ehl]'s limiting shear stress reaches the films the homogenisation solves (the spots' through
// micro_ehl_options, a ball's through its options); absent, there is no limit.
TEST(MicroEhlConfig, TheLimitingShearStressReachesTheFilms) {
  const std::string surface = "[surface]\nrms_height_m = 1e-7\ncorrelation_length_m = 1e-5\n";
  const HomogeniseRun limited = load_homogenise_run(
      write_file("micro-ehl-limit.toml", surface + "[micro_ehl]\nlimiting_shear_stress_Pa = 1e6\nlimiting_shear_pressure_coefficient = 0.05\n"));
  const lubrication::MicroEhlOptions films = homogenise::micro_ehl_options(limited.options);
  EXPECT_EQ(films.limiting_shear.stress_Pa, 1e6);
  EXPECT_EQ(films.limiting_shear.pressure_coefficient, 0.05);
  EXPECT_EQ(limited.options.micro_ehl->limiting_shear.at(1e9), 1e6 + 0.05 * 1e9);
  const HomogeniseRun free = load_homogenise_run(write_file("micro-ehl-free.toml", surface + "[micro_ehl]\n"));
  EXPECT_FALSE(free.options.micro_ehl->limiting_shear.on());
}

// The same [surface] and [domain] tables give the same surface in contact, homogenise and
// flow-factors, with the defaults of apps/surface_config.h where keys are left out.
TEST(SurfaceConfig, ThreeCommandsReadOneSurface) {
  const std::string tables = "[surface]\nkind = \"gaussian\"\nrms_height_m = 4.35e-7\ncorrelation_length_m = 6.25e-5\n"
                             "[domain]\ngrid = 32\n";
  const HomogeniseRun h = load_homogenise_run(write_file("surface-h.toml", tables));
  const FlowFactorRun f = load_flow_factor_run(write_file("surface-f.toml", tables));
  const ContactRun c = load_contact_run(
      write_file("surface-c.toml", tables + "[material]\ne_star_Pa = 1.137e11\n[load]\nnormal_load_N = 1e-3\n"), false);
  for (const contact::GaussianSurfaceParams& p : {h.options.surface, f.options.surface}) {
    EXPECT_EQ(p.kind, contact::SpectrumKind::gaussian_acf);  // the default spectrum
    EXPECT_EQ(p.size_m, 1e-3);                               // the default size
    EXPECT_EQ(p.grid, 32);
    EXPECT_EQ(p.seed, 1u);
    EXPECT_EQ(p.rms_height_m, 4.35e-7);
    EXPECT_EQ(p.correlation_length_m, 6.25e-5);
    EXPECT_EQ(p.correlation_length_across_m, 0.0);
  }
  const Eigen::ArrayXXd gap0 = contact::gap_from_heights(contact::gaussian_surface(h.options.surface));
  ASSERT_EQ(c.gap0_m.rows(), gap0.rows());
  EXPECT_TRUE((c.gap0_m == gap0).all());
  // A Gaussian ACF has no default correlation length, in any of the three.
  const std::string no_length = "[surface]\nrms_height_m = 4.35e-7\n";
  const auto path = write_file("surface-no-length.toml", no_length);
  for (const std::string& e : {input_error_of([&] { load_homogenise_run(path); }), input_error_of([&] { load_flow_factor_run(path); })})
    expect_all(e, {"key 'surface.correlation_length_m'", "required"});
}

// [pin] tilt_rad: read for either shape, kept in law.json's pin; a negative or steep tilt is refused
// with the file and the key.
TEST(PinConfig, TiltIsReadAndASteepOrNegativeOneRefused) {
  const std::string surface = "[surface]\nkind = \"gaussian\"\nrms_height_m = 4.35e-7\ncorrelation_length_m = 6.25e-5\n";
  const HomogeniseRun run = load_homogenise_run(write_file("pin-tilt.toml", surface + "[pin]\ntilt_rad = 2.5e-4\n"));
  EXPECT_EQ(run.options.pin.tilt_rad, 2.5e-4);
  EXPECT_EQ(run.options.pin.shape, homogenise::PinShape::flat);
  for (const char* bad : {"-1e-4", "0.02"}) {
    const auto path = write_file("pin-tilt-bad.toml", surface + "[pin]\ntilt_rad = " + bad + "\n");
    expect_all(input_error_of([&] { load_homogenise_run(path); }), {path.string(), "key 'pin.tilt_rad'"});
  }
}

// [material] slider_expansion_per_K and slider_poisson_ratio (the face's thermal crown bound): read
// into the options; a negative expansion or a Poisson ratio of 0.5 or more refused with the file and
// the key.
TEST(MaterialConfig, TheSlidersThermoelasticConstantsAreReadAndOutOfRangeOnesRefused) {
  const std::string surface = "[surface]\nkind = \"gaussian\"\nrms_height_m = 4.35e-7\ncorrelation_length_m = 6.25e-5\n";
  const HomogeniseRun run = load_homogenise_run(
      write_file("material-brass.toml", surface + "[material]\nslider_expansion_per_K = 19.9e-6\nslider_poisson_ratio = 0.34\n"));
  EXPECT_EQ(run.options.slider_expansion_per_K, 19.9e-6);
  EXPECT_EQ(run.options.slider_poisson_ratio, 0.34);
  for (const auto& [key, bad] : {std::pair{"slider_expansion_per_K", "-1e-6"}, std::pair{"slider_poisson_ratio", "0.5"}}) {
    const auto path = write_file("material-bad.toml", surface + "[material]\n" + key + " = " + bad + "\n");
    expect_all(input_error_of([&] { load_homogenise_run(path); }), {path.string(), std::string("key 'material.") + key + "'"});
  }
}

// [pin] shape = "ball": its film grid read; without [micro_ehl] (the film's ηU axis and Eyring
// stress), with a tilt, or a film grid on a flat pin, refused with the file and the key.
TEST(PinConfig, ABallNeedsItsFilmsSpeedsAndHasNoTilt) {
  const std::string surface = "[surface]\nkind = \"gaussian\"\nrms_height_m = 5e-8\ncorrelation_length_m = 2e-6\n";
  const std::string films = "[micro_ehl]\nmin_speed_m_per_s = 1e-3\n";
  const HomogeniseRun run =
      load_homogenise_run(write_file("pin-ball.toml", surface + films + "[pin]\nshape = \"ball\"\nradius_m = 9.525e-3\nfilm_grid = 33\n"));
  EXPECT_EQ(run.options.pin.shape, homogenise::PinShape::ball);
  EXPECT_EQ(run.options.pin.film_grid, 33);
  const auto no_films = write_file("pin-ball-dry.toml", surface + "[pin]\nshape = \"ball\"\n");
  expect_all(input_error_of([&] { load_homogenise_run(no_films); }), {no_films.string(), "key 'pin.shape'", "[micro_ehl]"});
  const auto tilted = write_file("pin-ball-tilt.toml", surface + films + "[pin]\nshape = \"ball\"\ntilt_rad = 1e-4\n");
  expect_all(input_error_of([&] { load_homogenise_run(tilted); }), {tilted.string(), "key 'pin.tilt_rad'"});
  const auto flat = write_file("pin-flat-grid.toml", surface + "[pin]\nfilm_grid = 33\n");
  expect_all(input_error_of([&] { load_homogenise_run(flat); }), {flat.string(), "key 'pin.film_grid'"});
}

TEST(DriveTable, ReadByTheBundlesCsvRules) {
  // tribo's own provenance block above the columns, blanks around cells, an extra column.
  write_file("drive.csv", "# tribo_version: 0.1\n# seed: 1\nt_s, v_m_per_s, note\n0, 1e-3, a\n2, 3e-3, b\n");
  const auto config = write_file("drive.toml", "[drive]\nkind = \"table\"\nfile = \"drive.csv\"\n");
  const RigRun run = load_rig_run(config);
  EXPECT_DOUBLE_EQ(run.drive->speed_m_per_s(1.0), 2e-3);
  // A short row names the file and its line, under the config key that named the file.
  write_file("drive.csv", "t_s,v_m_per_s\n0,1e-3\n2\n");
  expect_all(input_error_of([&] { load_rig_run(config); }),
             {config.string(), "key 'drive.file'", "drive.csv:3: expected 2 values, found 1"});
}

}  // namespace
}  // namespace tribo::cli
