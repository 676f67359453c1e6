// How an output was made: tribo version and commit, the config file and its hash, the time and
// the thread count — written into every JSON result so a number can be traced to its inputs.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

namespace tribo::cli {

// FNV-1a 64-bit hash of the file's bytes, as 16 hex digits (identifies the inputs of a cached
// result; not a cryptographic digest). Throws InputError when the file cannot be read.
std::string config_hash(const std::filesystem::path& config);

// {"tribo_version", "git_commit", "config", "config_hash", "date_utc", "threads"}
nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash);

}  // namespace tribo::cli
