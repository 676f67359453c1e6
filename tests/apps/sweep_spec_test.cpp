// `tribo sweep` specs (apps/sweep_spec.h): grid expansion (product with the last axis fastest, zip,
// log and linear ranges with exact end points), dotted keys into nested and new tables, relative
// file paths of the base config made absolute, and errors that name the key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "apps/config.h"
#include "apps/sweep_spec.h"

namespace tribo::cli {
namespace {

std::filesystem::path folder() {
  const auto dir = std::filesystem::temp_directory_path() / "tribo_sweep_spec_tests";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "base.toml") << "[rig]\nmass_kg = 1.0\n[friction]\nlaw = \"homogenised\"\ntable = \"law.json\"\n";
  std::ofstream(dir / "law.json") << "{}\n";
  return dir;
}

SweepSpec spec_from(const std::string& text) {
  const auto path = folder() / "spec.toml";
  std::ofstream(path) << "[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\n" << text;
  return load_sweep_spec(path);
}

TEST(SweepSpec, ProductRunsTheLastAxisFastestAndRangesEndExactlyWhereWritten) {
  const SweepSpec s = spec_from(
      "[[axis]]\nkey = \"rig.drive_speed_m_per_s\"\nfrom = 1e-4\nto = 1e-1\ncount = 4\nscale = \"log\"\n"
      "[[axis]]\nkey = \"rig.mass_kg\"\nfrom = 1.0\nto = 2.0\ncount = 3\n");
  const auto p = sweep_points(s);
  ASSERT_EQ(p.size(), 12u);
  EXPECT_EQ(p[0], (std::vector<double>{1e-4, 1.0}));
  EXPECT_EQ(p[1], (std::vector<double>{1e-4, 1.5}));
  EXPECT_EQ(p[11], (std::vector<double>{1e-1, 2.0}));  // end points exact, not 1e-4·1000^(3/3) rounded
  EXPECT_NEAR(p[3][0], 1e-3, 1e-18);                    // a decade per step
}

TEST(SweepSpec, ZipPairsAxesOfEqualLengthAndRefusesUnequalOnes) {
  const SweepSpec s = spec_from(
      "[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1, 2, 3]\n[[axis]]\nkey = \"run.seed\"\nvalues = [7, 8, 9]\n"
      "[sweep]\ncombine = \"zip\"\n");
  const auto p = sweep_points(s);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[2], (std::vector<double>{3, 9}));
  EXPECT_THROW(spec_from("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1, 2]\n[[axis]]\nkey = \"run.seed\"\nvalues = [7]\n"
                         "[sweep]\ncombine = \"zip\"\n"),
               InputError);
}

TEST(SweepSpec, PointConfigSetsDottedKeysCreatesTablesAndMakesFilePathsAbsolute) {
  const SweepSpec s = spec_from("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [2.5]\n[[axis]]\nkey = \"run.seed\"\nvalues = [4]\n");
  const toml::table c = point_config(s, {2.5, 4.0});
  EXPECT_EQ(c["rig"]["mass_kg"].value<double>(), 2.5);
  EXPECT_EQ(c["run"]["seed"].value_exact<int64_t>(), 4);  // integral values stay integers
  EXPECT_EQ(std::filesystem::path(*c["friction"]["table"].value<std::string>()), folder() / "law.json");
  EXPECT_EQ(c["friction"]["law"].value<std::string>(), "homogenised");  // not a file: unchanged
}

TEST(SweepSpec, OutputsReadJsonObjectsAndArraysAndNameTheColumnAfterTheLastKeyAndIndex) {
  const auto file = folder() / "out.json";
  std::ofstream(file) << R"({"regime": "stick_slip", "ok": true, "s": [{"mu": 0.25}, {"mu": 0.125}], "nan": null})";
  EXPECT_EQ(json_field(file, "regime"), "stick_slip");
  EXPECT_EQ(json_field(file, "ok"), "1");
  EXPECT_EQ(json_field(file, "s.1.mu"), "0.125");
  EXPECT_EQ(json_field(file, "nan"), "");  // a NaN written by nlohmann-json as null: an empty field
  EXPECT_THROW(json_field(file, "s.2.mu"), std::runtime_error);
  const SweepSpec s = spec_from("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"law.json:stribeck.13.mu\"]\n");
  EXPECT_EQ(s.outputs.front().column, "mu_13");
  const SweepSpec t = spec_from("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"law.json:wall_s\"]\n");
  EXPECT_EQ(t.outputs.front().column, "law_wall_s");  // the sweep's own wall_s keeps its name
}

TEST(SweepSpec, BadSpecsNameTheKey) {
  auto expect_error = [](const std::string& text, const std::string& fragment) {
    try {
      spec_from(text);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expect_error("", "axis");
  expect_error("[[axis]]\nkey = \"rig.mass_kg\"\nfrom = 0\nto = 1\nscale = \"log\"\n", "axis[0].scale");
  expect_error("[[axis]]\nkey = \"rig.mass_kg.x\"\nvalues = [1]\n", "not a table");
  expect_error("[[axis]]\nkey = \"rig\"\nvalues = [1]\n", "is a table");
  expect_error("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"regime\"]\n", "FILE:path");
}

}  // namespace
}  // namespace tribo::cli
