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
#include "tests/apps/expect_message.h"

namespace tribo::cli {
namespace {

std::filesystem::path folder() {
  const auto dir = fixture::test_folder("tribo_sweep_spec_tests");
  std::ofstream(dir / "base.toml") << "[rig]\nmass_kg = 1.0\n[friction]\nlaw = \"homogenised\"\ntable = \"law.json\"\n";
  std::ofstream(dir / "law.json") << "{}\n";
  return dir;
}

SweepSpec spec_from(const std::string& text) {
  const auto path = folder() / "spec.toml";
  std::ofstream(path) << "[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\n" << text;
  return load_sweep_spec(path);
}

// A spec with its own [base] table and one axis.
SweepSpec spec_from_base(const std::string& base) {
  const auto path = folder() / "spec-base.toml";
  std::ofstream(path) << base << "[[axis]]\nkey = \"rig:rig.mass_kg\"\nvalues = [1]\n";
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

SweepSpec chain_from(const std::string& text,
                     const std::string& rig = "[rig]\nmass_kg = 1.0\n[friction]\nlaw = \"homogenised\"\n");

// [base.set]: values of any type that every point gets (a crowned pin for a crown-radius axis),
// applied before the axes, in the step they name.
TEST(SweepSpec, BaseSetPutsValuesOfAnyTypeIntoEveryPointBeforeTheAxes) {
  const auto path = folder() / "spec-set.toml";
  std::ofstream(path) << "[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\n[base.set]\n\"pin.shape\" = \"spherical\"\n"
                         "\"rig.mass_kg\" = 3.5\n\"run.quiet\" = true\n"
                         "[[axis]]\nkey = \"pin.crown_radius_m\"\nvalues = [11.3, 113]\n";
  const SweepSpec s = load_sweep_spec(path);
  ASSERT_EQ(s.settings.size(), 3u);
  for (const auto& point : sweep_points(s)) {
    const toml::table c = point_config(s, point);
    EXPECT_EQ(c["pin"]["shape"].value<std::string>(), "spherical");
    EXPECT_EQ(c["pin"]["crown_radius_m"].value<double>(), point[0]);
    EXPECT_EQ(c["rig"]["mass_kg"].value<double>(), 3.5);  // the base's 1.0 replaced
    EXPECT_EQ(c["run"]["quiet"].value<bool>(), true);
  }
  EXPECT_EQ(setting_json(s.settings[0]), nlohmann::json("spherical"));
  // In a chain a setting names its step, and stays out of the other step's config.
  const SweepSpec t = chain_from("[base.set]\n\"homogenise:pin.shape\" = \"spherical\"\n"
                                 "[[axis]]\nkey = \"homogenise:surface.hurst\"\nvalues = [0.6]\n");
  EXPECT_EQ(point_config(t, {0.6}, 0)["pin"]["shape"].value<std::string>(), "spherical");
  EXPECT_FALSE(point_config(t, {0.6}, 1)["pin"]);
}

TEST(SweepSpec, BadBaseSettingsNameTheKey) {
  auto expect_error = [](const std::string& set, const std::string& axis, std::initializer_list<std::string> fragments) {
    const auto path = folder() / "spec-bad-set.toml";
    std::ofstream(path) << "[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\n[base.set]\n" << set << axis;
    fixture::expect_all(fixture::input_error_of([&] { load_sweep_spec(path); }), fragments);
  };
  const std::string axis = "[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n";
  expect_error("\"rig.mass_kg.x\" = 1\n", axis, {"spec-bad-set.toml", "base.set.rig.mass_kg.x", "not a table"});
  expect_error("\"rig\" = 1\n", axis, {"base.set.rig", "is a table"});
  expect_error("[base.set.pin]\nshape = \"spherical\"\n", axis, {"base.set.pin", "whole dotted key"});
  expect_error("\"rig.mass_kg\" = 2\n", axis, {"axis[0].key", "set in [base.set] already"});
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
  const SweepSpec u = spec_from("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"law.json:stribeck.13.mu\"]\n"
                                "names = [\"mu_at_8.2e-4_m_per_s\"]\n");
  EXPECT_EQ(u.outputs.front().column, "mu_at_8.2e-4_m_per_s");
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
  expect_error("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"a.json:x\"]\nnames = [\"x\", \"y\"]\n",
               "outputs.names");
  expect_error("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[outputs]\ncolumns = [\"a.json:x\"]\nnames = [\"a,b\"]\n",
               "without commas");
  expect_error("[[axis]]\nkey = \"rig:rig.mass_kg\"\nvalues = [1]\n", "dotted config key");  // no chain, no step
  expect_error("[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [1]\n[[axis]]\nkey = \"rig.mass_kg\"\nvalues = [2]\n",
               "already an axis");
}

// The homogenise → rig chain: axes name their step, the rig step's friction points at the point's own
// law, and outputs may name a step's file.
SweepSpec chain_from(const std::string& text, const std::string& rig) {
  const auto dir = folder();
  std::ofstream(dir / "hom.toml") << "[surface]\nhurst = 0.8\n[homogenise]\nrealisations = 4\n";
  std::ofstream(dir / "chain-rig.toml") << rig;
  const auto path = dir / "chain.toml";
  std::ofstream(path) << "[base]\ncommand = \"homogenise+rig\"\nconfig = \"hom.toml\"\nrig_config = \"chain-rig.toml\"\n" << text;
  return load_sweep_spec(path);
}

TEST(SweepSpec, ChainAxesAddressEitherStepAndTheRigReadsThePointsOwnLaw) {
  const SweepSpec s = chain_from(
      "[[axis]]\nkey = \"homogenise:surface.hurst\"\nvalues = [0.6, 0.9]\n"
      "[[axis]]\nkey = \"rig:rig.drive_speed_m_per_s\"\nvalues = [1e-3]\n"
      "[outputs]\ncolumns = [\"law.json:junction.mu_s_max\", \"rig/summary.json:regime\"]\n");
  ASSERT_EQ(s.steps.size(), 2u);
  EXPECT_EQ(s.steps[0].command, "homogenise");
  EXPECT_EQ(s.steps[1].command, "rig");
  EXPECT_EQ(step_folder(s, 1), "rig");
  EXPECT_EQ(s.axes[0].step, 0u);
  EXPECT_EQ(s.axes[1].config_key, "rig.drive_speed_m_per_s");
  const toml::table h = point_config(s, {0.6, 1e-3}, 0);
  EXPECT_EQ(h["surface"]["hurst"].value<double>(), 0.6);
  EXPECT_FALSE(h["rig"]);  // the rig's axis stays out of the homogenise config
  const toml::table r = point_config(s, {0.6, 1e-3}, 1);
  EXPECT_EQ(r["rig"]["drive_speed_m_per_s"].value<double>(), 1e-3);
  EXPECT_EQ(r["rig"]["mass_kg"].value<double>(), 1.0);
  EXPECT_EQ(r["friction"]["law"].value<std::string>(), "homogenised");
  EXPECT_EQ(r["friction"]["table"].value<std::string>(), "../homogenise/law.json");
  EXPECT_EQ(s.outputs[1].file, "rig/summary.json");
  EXPECT_EQ(s.outputs[1].column, "regime");
  // A rig config without [friction] gets one.
  const SweepSpec t = chain_from("[[axis]]\nkey = \"homogenise:surface.hurst\"\nvalues = [0.6]\n", "[rig]\nmass_kg = 2.0\n");
  EXPECT_EQ(point_config(t, {0.6}, 1)["friction"]["table"].value<std::string>(), "../homogenise/law.json");
}

TEST(SweepSpec, BadChainSpecsNameTheFileAndKey) {
  auto expect_error = [](auto&& load, const std::string& fragment) {
    try {
      load();
      ADD_FAILURE() << "accepted a spec that should fail with '" << fragment << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  const std::string axis = "[[axis]]\nkey = \"homogenise:surface.hurst\"\nvalues = [0.6]\n";
  // an axis without its step, or with a step the chain does not have
  expect_error([] { chain_from("[[axis]]\nkey = \"surface.hurst\"\nvalues = [0.6]\n"); }, "axis[0].key");
  expect_error([] { chain_from("[[axis]]\nkey = \"contact:surface.hurst\"\nvalues = [0.6]\n"); }, "names its step");
  // the chain sets the rig's law file itself
  expect_error([] { chain_from("[[axis]]\nkey = \"rig:friction.table\"\nvalues = [1]\n"); }, "set by the chain");
  // a rig config with another law
  expect_error([&] { chain_from(axis, "[friction]\nlaw = \"coulomb\"\n"); }, "chain-rig.toml: key 'friction.law'");
  // the step's config decides what is a table
  expect_error([] { chain_from("[[axis]]\nkey = \"rig:rig\"\nvalues = [1]\n"); }, "is a table in");
  // an output from a step the chain does not have
  expect_error([&] { chain_from(axis + "[outputs]\ncolumns = [\"contact/x.json:a\"]\n"); }, "not a step of this chain");
  // the same key twice
  expect_error([&] { chain_from(axis + axis); }, "axis[1].key");
  // rig_config: required by the chain, missing file named, refused elsewhere
  expect_error([] { spec_from_base("[base]\ncommand = \"homogenise+rig\"\nconfig = \"hom.toml\"\n"); }, "base.rig_config");
  expect_error([] { spec_from_base("[base]\ncommand = \"homogenise+rig\"\nconfig = \"hom.toml\"\nrig_config = \"nope.toml\"\n"); },
               "no such file");
  expect_error([] { spec_from_base("[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\nrig_config = \"base.toml\"\n"); },
               "only used with");
  expect_error([] { spec_from_base("[base]\ncommand = \"homogenise-rig\"\nconfig = \"hom.toml\"\n"); }, "base.command");
}

}  // namespace
}  // namespace tribo::cli
