// The model `tribo gap diagnose --model MODEL.toml` starts from: [rig] and [friction] of a `tribo rig`
// config ([drive] and [run] are accepted and not used: the drive comes from the data).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "rig/friction_model.h"
#include "rig/parameters.h"

namespace tribo::cli {

struct GapModel {
  rig::RigParameters rig;
  rig::FrictionModel friction;
  std::vector<std::string> missing_rig_keys;       // rig keys the model leaves out: calibrated from the data
  std::vector<std::filesystem::path> input_files;  // read besides the config: a law table
};

// Bad input is an InputError naming file, key and reason.
GapModel load_gap_model(const std::filesystem::path& path);
// The same on a parsed document; `path` names it in errors and anchors relative file names.
GapModel load_gap_model(const toml::table& doc, const std::filesystem::path& path);

}  // namespace tribo::cli
