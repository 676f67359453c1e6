// Config loaders on hostile input (issue 18, fuzz/): counts that size allocations are bounded,
// files a config names must be regular files, and TOML parsed from memory reports the source; the
// state a resumed run reads (selftest journal, sweep results). Inputs also in
// fuzz/corpus/{rig_config,homogenise_config,selftest_journal,sweep_state}/.
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <vector>

#include "apps/config.h"
#include "apps/homogenise_config.h"
#include "apps/rig_config.h"
#include "apps/selftest_journal.h"
#include "apps/sweep_state.h"
#include "apps/sweep_spec.h"
#include "tests/apps/expect_message.h"

#include <filesystem>
#include <fstream>

namespace tribo::cli {
namespace {

const std::string kRig = "/nonexistent/tribo-tests/rig.toml";
const std::string kHomogenise = "/nonexistent/tribo-tests/homogenise.toml";

template <class Load>
std::string error_of(const std::string& text, const std::string& source, Load load) {
  return fixture::input_error_of([&] { load(parse_toml_text(text, source), source); });
}

std::string rig_error(const std::string& text) {
  return error_of(text, kRig, [](const toml::table& d, const std::string& p) { return load_rig_run(d, p); });
}
std::string homogenise_error(const std::string& text) {
  return error_of(text, kHomogenise, [](const toml::table& d, const std::string& p) { return load_homogenise_run(d, p); });
}

using fixture::expect_all;

TEST(ConfigHostile, MalformedTomlNamesSourceLineAndColumn) {
  expect_all(rig_error("[rig]\nmass_kg = = 1\n"), {kRig + ":2:", "malformed TOML"});
}

// A value is quoted as it was given, not at six fixed decimals: std::to_string printed a mass of
// -2e-7 kg as "-0.000000" and a rate of 1e-9 as "0.000000".
TEST(ConfigHostile, MessagesQuoteSmallValuesAsGiven) {
  expect_all(rig_error("[rig]\nmass_kg = -2e-7\n"), {"rig.mass_kg", "(got -2e-07)"});
  expect_all(rig_error("[friction]\nmu_s = 0.3\nmu_k = 0.30000000000000004\n"), {"mu_k", "must not exceed mu_s (0.3)"});
}

TEST(ConfigHostile, DriveTableMustBeARegularFile) {
  // file = "/dev/zero" was read line by line: one endless line, memory until killed.
  expect_all(rig_error("[drive]\nkind = \"table\"\nfile = \"/dev/zero\"\n"), {"/dev/zero", "not a regular file"});
  expect_all(rig_error("[drive]\nkind = \"table\"\nfile = \"/tmp\"\n"), {"/tmp", "not a regular file"});
}

TEST(ConfigHostile, HomogenisedLawTableMustBeARegularFile) {
  expect_all(rig_error("[friction]\nlaw = \"homogenised\"\ntable = \"/dev/zero\"\n"),
             {kRig, "key 'friction.table'", "not a regular file"});
}

TEST(ConfigHostile, CountsThatSizeAllocationsAreBounded) {
  // count = 1e9 speeds: an 8 GB vector before any check.
  const std::string surface = "[surface]\nrms_height_m = 1e-7\ncorrelation_length_m = 1e-5\n";
  expect_all(homogenise_error(surface + "[speeds]\ncount = 1000000000\n"), {"key 'speeds.count'", "must be at most 100000"});
  expect_all(homogenise_error(surface + "[domain]\ngrid = 1000000\n"), {"key 'domain.grid'", "must be at most 16384"});
  // Narrowed to int: 2^32 + 1 wrapped around to 1.
  expect_all(homogenise_error(surface + "[homogenise]\nrealisations = 4294967297\n"), {"key 'homogenise.realisations'", "at most"});
  expect_all(rig_error("[run]\nsamples_per_period = 4294967304\n"), {"key 'run.samples_per_period'", "at most"});
  EXPECT_EQ(homogenise_error(surface + "[speeds]\ncount = 3\n"), "");
}

// The micro-EHL table's ηU axis must cover the Stribeck curve's speeds (the law is never
// extrapolated), and its keys are checked like every other.
TEST(ConfigHostile, MicroEhlAxisMustReachTheStribeckSpeeds) {
  const std::string surface = "[surface]\nrms_height_m = 1e-7\ncorrelation_length_m = 1e-5\n";
  expect_all(homogenise_error(surface + "[speeds]\nmax_m_per_s = 2.0\n[micro_ehl]\nmax_speed_m_per_s = 1.0\n"),
             {kHomogenise, "key 'micro_ehl.max_speed_m_per_s'", "max_m_per_s = 2"});
  expect_all(homogenise_error(surface + "[micro_ehl]\ntip_roughness_m = -1e-9\n"), {"key 'micro_ehl.tip_roughness_m'"});
  expect_all(homogenise_error(surface + "[micro_ehl]\nspeeds_per_decade = 1000\n"), {"key 'micro_ehl.speeds_per_decade'", "at most"});
  expect_all(homogenise_error(surface + "[micro_ehl]\nlimiting_shear_pressure_coefficient = -0.05\n"),
             {"key 'micro_ehl.limiting_shear_pressure_coefficient'", "negative"});
  EXPECT_EQ(homogenise_error(surface + "[micro_ehl]\n"), "");
  expect_all(homogenise_error(surface + "[micro_ehl]\npressure_viscosity_law = \"free_volume\"\n"),
             {"key 'micro_ehl.pressure_viscosity_law'", "roelands", "barus"});
  // The films need α: the error names the key that set it to 0, not one of [micro_ehl]'s.
  expect_all(homogenise_error(surface + "[lubricant]\npressure_viscosity_per_Pa = 0.0\n[micro_ehl]\n"),
             {"key 'lubricant.pressure_viscosity_per_Pa'", "[micro_ehl]"});
}

TEST(ConfigHostile, SweepSizeIsBounded) {
  // count = 1e12 pushed 1e12 values; three axes of 1000 would enumerate 1e9 point configs.
  const auto dir = std::filesystem::temp_directory_path() / "tribo_cli_hostile_sweep";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "base.toml") << "[rig]\ndrive_speed_m_per_s = 1e-3\n";
  const auto error = [&](const std::string& axes) {
    std::ofstream(dir / "spec.toml") << "[base]\ncommand = \"rig\"\nconfig = \"base.toml\"\n" << axes;
    return fixture::input_error_of([&] { load_sweep_spec(dir / "spec.toml"); });
  };
  expect_all(error("[[axis]]\nkey = \"rig.mass_kg\"\nfrom = 1\nto = 2\ncount = 1000000000000\n"),
             {"key 'axis[0].count'", "at most 1000000"});
  std::string three;
  for (const char* k : {"rig.mass_kg", "rig.stiffness_N_per_m", "rig.damping_N_s_per_m"})
    three += std::string("[[axis]]\nkey = \"") + k + "\"\nfrom = 1\nto = 2\ncount = 1000\n";
  expect_all(error(three), {"key 'axis'", "more than 1000000 points"});
  EXPECT_EQ(error("[[axis]]\nkey = \"rig.mass_kg\"\nfrom = 1\nto = 2\ncount = 1000\n"), "");
  std::filesystem::remove_all(dir);
}

// A selftest journal line whose `quick` is not a boolean, or whose seed is a float, is not a row
// (a JSON type error escaped the resume; 1e300 was converted to an integer out of range); the
// valid row beside them is kept.
TEST(ConfigHostile, AJournalRowOfTheWrongTypesIsSkippedAndTheValidOneKept) {
  const auto file = std::filesystem::temp_directory_path() / "tribo-hostile-cases.jsonl";
  const std::string row = R"("true_effect":"none","model_effects":[],"verdict":"none","heldout_gap_before":0.1,"heldout_gap_after":0.1,"confidence":0.5)";
  std::ofstream(file) << "{\"quick\":1,\"seed\":3," << row << "}\n"
                      << "{\"quick\":true,\"seed\":1e300," << row << "}\n"
                      << "{\"quick\":true,\"seed\":7,\"confidence_bootstrap\":0.66,\"train_floors\":27.9,\"stage_wall_s\":{\"candidates\":12.5,\"refinement\":\"x\"},"
                      << R"("proposal_checks":[{"against":"squeeze_film","test":"stiffer_spring","separation_floors":5.2,"gap_verdict":0.1,)"
                      << R"("gap_against":0.08,"truth_nearer":true,"verdict_after":"squeeze_film"}],)" << row << "}\n";
  const std::vector<gap::SelftestRow> rows = finished_rows(file, true);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].c.seed, 7u);
  EXPECT_TRUE(rows[0].correct);
  EXPECT_EQ(rows[0].confidence_bootstrap, 0.66);  // a "none" row's agreement before the reliability of "none"
  EXPECT_EQ(rows[0].train_floors, 27.9);          // what the calibrated baseline left on the training items
  EXPECT_EQ(rows[0].stage_times.candidates_s, 12.5);  // a stage read back; one not a number, or missing, reads 0
  EXPECT_EQ(rows[0].stage_times.refinement_s, 0.0);
  EXPECT_EQ(rows[0].stage_times.calibration_s, 0.0);
  ASSERT_EQ(rows[0].proposal_checks.size(), 1u);  // a proposed test run on the truth, read back
  EXPECT_EQ(rows[0].proposal_checks[0].test, "stiffer_spring");
  EXPECT_EQ(rows[0].proposal_checks[0].floors, 5.2);
  EXPECT_TRUE(rows[0].proposal_checks[0].truth_nearer);
  EXPECT_EQ(rows[0].proposal_checks[0].verdict_after, "squeeze_film");  // the verdict once its record was seen; a journal from before has none
  EXPECT_TRUE(finished_rows(file, false).empty());
  std::filesystem::remove(file);
}

// What a verdict adds to the model (gap::Verdict::adds) is read back where the journal holds it, and
// derived from the verdict and the model's effects in a journal from before it: the hardened locus
// brings the locus a model lacks, a pair both its effects, "none" and "unexplained" nothing. A list
// of the wrong type skips the line as any other key of the wrong type does.
TEST(ConfigHostile, WhatTheVerdictAddsIsReadBackOrDerivedFromTheVerdict) {
  EXPECT_EQ(adds_of_verdict("strain_rate_hardening", {}), (std::vector<std::string>{"rate_dependent_static", "strain_rate_hardening"}));
  EXPECT_EQ(adds_of_verdict("strain_rate_hardening", {"rate_dependent_static"}), std::vector<std::string>{"strain_rate_hardening"});
  EXPECT_EQ(adds_of_verdict("thermal_thinning+squeeze_film", {}), (std::vector<std::string>{"thermal_thinning", "squeeze_film"}));
  EXPECT_TRUE(adds_of_verdict("none", {}).empty());
  EXPECT_TRUE(adds_of_verdict("unexplained", {}).empty());
  const auto file = std::filesystem::temp_directory_path() / "tribo-adds-cases.jsonl";
  const std::string row = R"("true_effect":"rate_dependent_static","model_effects":[],"verdict":"strain_rate_hardening",)"
                          R"("heldout_gap_before":0.1,"heldout_gap_after":0.01,"confidence":0.2,"quick":true)";
  std::ofstream(file) << "{\"seed\":1," << row << "}\n"
                      << "{\"seed\":2,\"verdict_adds\":[\"strain_rate_hardening\"]," << row << "}\n"
                      << "{\"seed\":3,\"verdict_adds\":7," << row << "}\n";
  const std::vector<gap::SelftestRow> rows = finished_rows(file, true);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].verdict_adds, (std::vector<std::string>{"rate_dependent_static", "strain_rate_hardening"}));
  EXPECT_TRUE(rows[0].truth_added());
  EXPECT_FALSE(rows[0].correct);  // the score counts the verdict alone
  EXPECT_EQ(rows[1].verdict_adds, std::vector<std::string>{"strain_rate_hardening"});  // as journalled
  EXPECT_FALSE(rows[1].truth_added());
  std::filesystem::remove(file);
}

// A resumed sweep's results.csv: a point id that is not a non-negative integer, or a point twice,
// is refused naming the file and line (it ended as "stoi" with no file, or exit status 1, or was
// taken silently); a sweep.json that is JSON but not an object is another sweep's.
TEST(ConfigHostile, ASweepsResultsWithABadOrRepeatedPointIdAreRefusedWithFileAndLine) {
  const auto dir = std::filesystem::temp_directory_path() / "tribo-hostile-sweep";
  std::filesystem::create_directories(dir);
  const auto rows_error = [&](const std::string& body) {
    std::ofstream(dir / "results.csv") << "point_id,x\n" << body;
    return fixture::input_error_of([&] { finished_sweep_rows(dir / "results.csv", "point_id,x"); });
  };
  expect_all(rows_error("0,1\nabc,2\n"), {"results.csv: line 3", "'abc'", "not a non-negative integer"});
  expect_all(rows_error("99999999999999999999,1\n"), {"results.csv: line 2", "not a non-negative integer"});
  expect_all(rows_error("-1,1\n"), {"line 2", "not a non-negative integer"});
  expect_all(rows_error("0,1\n0,2\n"), {"results.csv: line 3", "point 0 is there twice"});
  EXPECT_EQ(rows_error("0,1\n1,2\n2,3"), "");  // the torn last line dropped, not refused
  std::ofstream(dir / "sweep.json") << "[1]\n";
  try {
    read_sweep_json(dir, "a", "b", "");
    ADD_FAILURE() << "a sweep.json holding [1] was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("sweep.json"), std::string::npos) << e.what();
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace tribo::cli
