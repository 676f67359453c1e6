// `tribo sweep` specifications: a base command and config, axes over dotted config keys, and the
// outputs to tabulate (issue 17). Everything here is pure (no processes): the CLI in cmd_sweep.cpp
// runs the points.
//
//   [base]    command = "rig" | "contact" | "reynolds" | "homogenise";  config = "FILE.toml"
//             (relative to the spec's folder)
//   [[axis]]  key = "rig.drive_speed_m_per_s" (dotted, into the base config's tables)
//             values = [ … ]                      or
//             from = …, to = …, count = N, scale = "linear" | "log"
//   [sweep]   combine = "product" (first axis slowest) | "zip" (axes of equal length)
//             jobs = 0 (points run at once; 0 = one per core)
//   [outputs] columns = ["summary.json:regime", "summary.json:peak_to_peak_m", …]
//             FILE:path — a value of the point's JSON output FILE, path dotted into its objects
//             and arrays ("law.json:stribeck.12.mu")
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tribo::cli {

struct SweepAxis {
  std::string key;              // dotted config key
  std::vector<double> values;   // in order
};

struct SweepOutput {
  std::string file;             // e.g. "summary.json"
  std::string path;             // dotted, e.g. "rig.normal_load_N"
  std::string column;           // the results.csv column: the path's last name (+ index: "mu_12")
};

struct SweepSpec {
  std::filesystem::path spec_file;
  std::string command;
  std::filesystem::path base_config;  // absolute
  std::vector<SweepAxis> axes;
  bool zip = false;
  int jobs = 0;
  std::vector<SweepOutput> outputs;
};

// Reads and checks a spec; throws InputError naming the file, key and reason (an axis key the base
// config does not hold, a log range through 0, zipped axes of unequal length, …).
SweepSpec load_sweep_spec(const std::filesystem::path& path);

// The points in order: point k's value of every axis (product: the last axis fastest).
std::vector<std::vector<double>> sweep_points(const SweepSpec& spec);

// The base config with point `values` set on the axes' keys, and every relative string that names
// an existing file beside the base config made absolute (so the config works from any folder).
toml::table point_config(const SweepSpec& spec, const std::vector<double>& values);

// The value at `path` (dotted) of a JSON file as a CSV field (numbers with 17 digits, strings as
// is, booleans 1/0); throws std::runtime_error naming the file and path when absent.
std::string json_field(const std::filesystem::path& file, const std::string& path);

}  // namespace tribo::cli
