// How an output was made: tribo version and commit, the command line, the config file and its
// hash, the time and the thread count (and the seed, where the command has one) — written into
// every JSON result as "provenance" and beside every CSV (apps/output.h CsvFile), so that a
// number can be traced to the code and inputs that made it.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace tribo::cli {

// FNV-1a 64-bit hash of the file's bytes, as 16 hex digits (identifies the inputs of a cached
// result; not a cryptographic digest). Throws InputError when the file cannot be read.
std::string config_hash(const std::filesystem::path& config);
// The same hash of bytes in memory: a config that a sweep's point runs without writing it.
std::string bytes_hash(std::string_view bytes);

// The files a run read besides its config (a topography, a law table, a drive table, a bundle's
// files), for provenance_json's "inputs".
using InputFiles = std::vector<std::filesystem::path>;

// {"tribo_version", "git_commit", "command_line" (when recorded), "config", "config_hash",
// "inputs", "date_utc", "threads"}. `git_commit` is the commit the binary was built from, with
// "+dirty" when tracked files had changes. "inputs" lists {"path", "hash"} of the config (first,
// when there is one) and of every file in `inputs`, the hash over the file's bytes
// (config_hash), so that a result names the content it was computed from, not only its paths.
nlohmann::json provenance_json(const std::filesystem::path& config, const std::string& hash, const InputFiles& inputs = {});

// As above, hashing `config`; an empty path (a command without a config file) gives null config
// and config_hash.
nlohmann::json provenance_json(const std::filesystem::path& config, const InputFiles& inputs = {});

// The commit the binary was built from ("+dirty" when tracked files had changes, "unknown" outside a
// git checkout): provenance_json's "git_commit".
std::string git_commit();

// The build as the key a cache or journal keeps so that one build's results are not taken for
// another's: git_commit() for a clean build; for a "+dirty" or "unknown" one, whose commit does not
// fix its code, also a hash of the running executable ("abc123+dirty#0123…"), so that builds of two
// different uncommitted edits never take each other's results.
std::string build_identity();

// Records argv for provenance_json's "command_line" (called once, from main).
void record_command_line(int argc, const char* const* argv);

}  // namespace tribo::cli
