// `tribo sweep` specifications: a base command and config, axes over dotted config keys, and the
// outputs to tabulate (issue 17). Everything here is pure (no processes): the CLI in cmd_sweep.cpp
// runs the points.
//
//   [base]    command = "rig" | "contact" | "reynolds" | "ehl" | "homogenise";  config = "FILE.toml"
//             (relative to the spec's folder)
//             or the chain command = "homogenise+rig": config = the homogenise config, rig_config =
//             the rig config, whose [friction] is pointed at the point's own law.json
//   [base.set] "pin.shape" = "spherical" — values (any type) every point's config gets, before
//             the axes; dotted keys as an axis' ("homogenise:pin.shape" in a chain)
//   [[axis]]  key = "rig.drive_speed_m_per_s" (dotted, into the base config's tables); in a chain
//             the step comes first: "homogenise:surface.hurst", "rig:rig.drive_speed_m_per_s"
//             values = [ … ]                      or
//             from = …, to = …, count = N, scale = "linear" | "log"
//   [sweep]   combine = "product" (first axis slowest) | "zip" (axes of equal length)
//             jobs = 0 (points run at once per process, per MPI rank under mpirun; 0 = the cores it may use)
//             artefacts = false (true: every point keeps its command's traces and fields — trace.csv,
//             events.csv, *.npy; false: rig, contact and reynolds points write their JSON only)
//   [outputs] columns = ["summary.json:regime", "summary.json:peak_to_peak_m", …]
//             FILE:path — a value of the point's JSON output FILE, path dotted into its objects
//             and arrays ("law.json:stribeck.12.mu"); in a chain FILE is looked for in the rig
//             step's folder, then the homogenise step's, or named as "homogenise/law.json";
//             names = [ … ] (optional) — the columns' names, one per column
#pragma once

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tribo::cli {

struct SweepAxis {
  std::string key;              // as written: the results.csv column ("rig:rig.mass_kg" in a chain)
  std::vector<double> values;   // in order
  std::size_t step = 0;         // the chain step whose config the key addresses
  std::string config_key;       // dotted key inside that config ("rig.mass_kg")
};

// A [base.set] entry: a value every point's config of `step` gets at `config_key`.
struct SweepSetting {
  std::string key;              // as written ("homogenise:pin.shape" in a chain)
  std::size_t step = 0;
  std::string config_key;       // dotted key inside that step's config
  toml::array value;            // the value, as its one element (a string, number, boolean or array)
};

// One command of a point: a chain has two (homogenise, then rig), a plain sweep one.
struct SweepStep {
  std::string command;               // "rig", "contact", "reynolds", "homogenise"
  std::filesystem::path config;      // absolute
  std::string spec_key;              // the [base] key that named the config ("config", "rig_config")
};

struct SweepOutput {
  std::string file;             // e.g. "summary.json"
  std::string path;             // dotted, e.g. "rig.normal_load_N"
  std::string column;           // the results.csv column: the path's last name (+ index: "mu_12")
};

struct SweepSpec {
  std::filesystem::path spec_file;
  std::string command;                // [base] command, e.g. "rig" or "homogenise+rig"
  std::filesystem::path base_config;  // absolute; the first step's config
  std::vector<SweepStep> steps;       // run in order in the point's folder (a chain: one subfolder each)
  std::vector<SweepSetting> settings;  // [base.set], by key (a TOML table has no order)
  std::vector<SweepAxis> axes;
  bool zip = false;
  int jobs = 0;
  bool artefacts = false;             // the points' traces and fields are kept (on request only)
  std::vector<SweepOutput> outputs;
};

// Reads and checks a spec; throws InputError naming the file, key and reason (an axis key the base
// config does not hold, a log range through 0, zipped axes of unequal length, …).
SweepSpec load_sweep_spec(const std::filesystem::path& path);

// The points in order: point k's value of every axis (product: the last axis fastest).
std::vector<std::vector<double>> sweep_points(const SweepSpec& spec);

// The base config with point `values` set on the axes' keys, and every relative string that names
// an existing file beside the base config made absolute (so the config works from any folder).
// In a chain, `step` picks the config; the rig step's [friction] gets law = "homogenised" and
// table = "../homogenise/law.json" (the point's own law, relative so a sweep folder can move).
toml::table point_config(const SweepSpec& spec, const std::vector<double>& values, std::size_t step = 0);

// A [base.set] value as JSON (for sweep.json and --dry-run).
nlohmann::json setting_json(const SweepSetting& set);

// A chain's step folder inside the point's folder ("homogenise", "rig"); "" for a single command.
std::string step_folder(const SweepSpec& spec, std::size_t step);

// The value at `path` (dotted) of a JSON file as a CSV field (numbers with 17 digits, strings as
// is, booleans 1/0); throws std::runtime_error naming the file and path when absent.
std::string json_field(const std::filesystem::path& file, const std::string& path);
// The same on the JSON already parsed; `file` names it in errors.
std::string json_field(const nlohmann::json& json, const std::filesystem::path& file, const std::string& path);

}  // namespace tribo::cli
