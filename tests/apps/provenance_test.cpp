// The provenance block, a CSV's provenance beside it (hostile strings read back exactly), bundle
// CSVs with comment lines, output folders that take no files, and the CLI's shipped files found
// relative to an installed binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "apps/output.h"
#include "apps/provenance.h"
#include "gap/bundle.h"

namespace tribo::cli {
namespace {

namespace fs = std::filesystem;

class TempDir : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("tribo-provenance-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

using Provenance = TempDir;

TEST(BuildIdentity, IsTheCommitOfACleanBuildAndAddsTheExecutablesHashOtherwise) {
  // The key of caches and journals: a clean build's commit fixes its code; a "+dirty" or
  // "unknown" build's does not, so its identity also carries the executable's 64-bit FNV-1a hash
  // (16 hex digits). The same value all process long.
  const std::string commit = git_commit(), id = build_identity();
  if (commit != "unknown" && commit.find("+dirty") == std::string::npos) {
    EXPECT_EQ(id, commit);
  } else {
    ASSERT_EQ(id.size(), commit.size() + 17) << id;
    EXPECT_EQ(id.substr(0, commit.size() + 1), commit + "#");
    EXPECT_EQ(id.find_first_not_of("0123456789abcdef", commit.size() + 1), std::string::npos) << id;
  }
  EXPECT_EQ(build_identity(), id);
}

TEST_F(Provenance, BlockHasTheKeysAndHashesTheConfig) {
  const fs::path config = dir_ / "c.toml";
  std::ofstream(config) << "[rig]\nmass_kg = 1\n";
  const nlohmann::json p = provenance_json(config);
  for (const char* key : {"tribo_version", "git_commit", "config", "config_hash", "date_utc", "threads"})
    EXPECT_TRUE(p.contains(key)) << key;
  EXPECT_EQ(p["tribo_version"], TRIBO_EXPECTED_VERSION);  // project()'s, passed by CMake
  EXPECT_EQ(p["config"], fs::absolute(config).string());
  // FNV-1a 64 of the bytes, computed here independently of the implementation's loop order.
  std::uint64_t h = 14695981039346656037ULL;
  for (char c : std::string("[rig]\nmass_kg = 1\n")) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  EXPECT_EQ(p["config_hash"], hex);
  // A command without a config says so rather than inventing one.
  const nlohmann::json none = provenance_json(fs::path());
  EXPECT_TRUE(none["config"].is_null());
  EXPECT_TRUE(none["config_hash"].is_null());
}

TEST_F(Provenance, CsvIsPlainAndItsProvenanceBesideItReadsBackExactly) {
  nlohmann::json p = provenance_json(fs::path());
  p["seed"] = 18446744073709551615ULL;
  p["config"] = "/a path/with \"quotes\"\nand a newline # and a hash";
  p["git_commit"] = "123456789012";  // all digits: must come back a string, not a number
  p["command_line"] = {"tribo", "rig", "x.toml"};
  const fs::path csv = dir_ / "trace.csv";
  {
    CsvFile f(csv, p);
    f.stream() << "t_s,x_m\n0,1\n";
    f.commit();
  }
  std::ifstream in(csv);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first, "t_s,x_m");  // the column header is the first line: readers need no options
  ASSERT_TRUE(fs::exists(dir_ / "trace.csv.provenance.json"));
  const nlohmann::json beside = nlohmann::json::parse(std::ifstream(dir_ / "trace.csv.provenance.json"));
  EXPECT_EQ(beside.at("csv"), "trace.csv");
  EXPECT_EQ(beside.at("provenance"), p);
}

// A CSV left uncommitted (the run failed) leaves neither file behind.
TEST_F(Provenance, AnUncommittedCsvLeavesNothing) {
  { CsvFile f(dir_ / "x.csv", provenance_json(fs::path())); f.stream() << "a\n1\n"; }
  EXPECT_TRUE(fs::is_empty(dir_));
}

// gap/bundle.cpp reads experiment CSVs: a bundle whose files start with "# key: value" comment lines
// (tribo's own CSVs did before 2026-11-27; a logger may write them) reads back to the same data.
TEST_F(Provenance, ExperimentBundleWithHeaderReadsBack) {
  gap::ExperimentBundle b;
  b.name = "provenance";
  b.normal_load_N = 90.0;
  b.static_points = {{0.1, 0.30}, {1.0, 0.28}, {10.0, 0.26}};
  gap::Run r;
  r.run_id = "1";
  r.v_m_per_s = 1e-3;
  r.trace.t_s = {0.0, 0.1, 0.2, 0.3};
  r.trace.friction_N = {1.0, 2.0, 1.5, 1.7};
  b.runs.push_back(r);
  b.regimes = {{1e-3, "stick_slip", 1e-3, 100.0}};
  gap::write_bundle(b, dir_);
  const gap::ExperimentBundle plain = gap::read_bundle(dir_);

  const std::string header = "# tribo_version: 0.1.0\n# config: null\n# seed: 7\n";
  int prefixed = 0;
  for (const auto& e : fs::recursive_directory_iterator(dir_)) {
    if (e.path().extension() != ".csv") continue;
    std::ifstream in(e.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    std::ofstream(e.path()) << header << text;
    ++prefixed;
  }
  ASSERT_EQ(prefixed, 4);  // static_friction.csv, runs.csv, the trace, regimes.csv
  const gap::ExperimentBundle read = gap::read_bundle(dir_);
  ASSERT_EQ(read.static_points.size(), plain.static_points.size());
  for (std::size_t i = 0; i < read.static_points.size(); ++i) {
    EXPECT_EQ(read.static_points[i].phi_dot_per_s, plain.static_points[i].phi_dot_per_s);
    EXPECT_EQ(read.static_points[i].mu_s, plain.static_points[i].mu_s);
  }
  ASSERT_EQ(read.runs.size(), 1u);
  EXPECT_EQ(read.runs[0].trace.t_s, plain.runs[0].trace.t_s);
  EXPECT_EQ(read.runs[0].trace.friction_N, plain.runs[0].trace.friction_N);
  ASSERT_EQ(read.regimes.size(), 1u);
  EXPECT_EQ(read.regimes[0].regime, "stick_slip");
  EXPECT_TRUE(read.warnings.empty());
}

// An installed tribo takes its plotting script from <prefix>/share/tribo beside <prefix>/bin,
// wherever the prefix is; an uninstalled one from the source tree.
// An output folder that exists but takes no files is refused before any work, naming the folder.
// /proc/self is such a folder even for root (who writes through permission bits, so a chmod-ed
// temporary folder would not test this here).
TEST(OutputDir, AnExistingFolderThatTakesNoFilesIsRefusedUpFront) {
  ASSERT_TRUE(fs::is_directory("/proc/self"));
  try {
    make_output_dir("/proc/self");
    FAIL() << "a folder that takes no files was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("/proc/self: output directory is not writable"), std::string::npos) << e.what();
  }
}

TEST_F(Provenance, ShippedFilesAreFoundBesideAnInstalledBinary) {
  fs::create_directories(dir_ / "bin");
  fs::create_directories(dir_ / "share" / "tribo");
  std::ofstream(dir_ / "share" / "tribo" / "tribo_plots.py") << "# stand-in\n";
  EXPECT_EQ(shipped_file("tribo_plots.py", "tools/tribo_plots.py", dir_ / "bin" / "tribo"),
            (dir_ / "share" / "tribo" / "tribo_plots.py").lexically_normal());
  const fs::path in_source = shipped_file("tribo_plots.py", "tools/tribo_plots.py", dir_ / "build" / "apps" / "tribo");
  EXPECT_EQ(in_source, fs::path(TRIBO_SOURCE_DIR) / "tools" / "tribo_plots.py");
  EXPECT_TRUE(fs::exists(in_source));
}

}  // namespace
}  // namespace tribo::cli
